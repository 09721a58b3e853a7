"""A brick torus: vtkRelief's Python usage, rendered offscreen into a PNG.

Run with VTK's Python and the built package on the path, under an X display:
    PYTHONPATH=build/lib/python3/dist-packages /usr/bin/python3 Examples/Python/relief_bricks.py out.png
"""
import os
import sys

from vtkmodules.vtkFiltersSources import vtkSuperquadricSource
from vtkmodules.vtkFiltersTexture import vtkTransformTextureCoords
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkLight, vtkRenderWindow, vtkRenderer,
                                         vtkTexture, vtkWindowToImageFilter)
from vtkrelief import vtkOpenGLReliefMapper, vtkOpenImageIOReader

data = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Data")
height, color = vtkOpenImageIOReader(), vtkOpenImageIOReader()
height.SetFileName(os.path.join(data, "bricks_height.png"))  # 16-bit, white = high
color.SetFileName(os.path.join(data, "bricks_color.png"))

torus = vtkSuperquadricSource()  # coarse: 16 x 16 quads; the relief adds the detail
torus.SetToroidal(True)
tiles = vtkTransformTextureCoords()  # 8 tiles around the ring, 2 around the tube
tiles.SetInputConnection(torus.GetOutputPort())
tiles.SetScale(8, 2, 1)

mapper = vtkOpenGLReliefMapper()
mapper.SetInputConnection(tiles.GetOutputPort())
mapper.SetHeightMapConnection(height.GetOutputPort())
mapper.SetDepthScale(0.03)  # world depth of the mortar below the brick faces
texture = vtkTexture()
texture.SetInputConnection(color.GetOutputPort())
texture.InterpolateOn()
texture.MipmapOn()
actor = vtkActor()
actor.SetMapper(mapper)
actor.SetTexture(texture)

renderer = vtkRenderer()
renderer.AddActor(actor)
light = vtkLight()  # a scene light from the upper left: the relief shadows itself
light.SetPosition(-1, 1, 1)
renderer.AddLight(light)
renderer.GetActiveCamera().Elevation(40)
renderer.ResetCamera()
window = vtkRenderWindow()
window.SetOffScreenRendering(1)
window.SetSize(800, 600)
window.AddRenderer(renderer)
window.Render()

grab = vtkWindowToImageFilter()
grab.SetInput(window)
writer = vtkPNGWriter()
writer.SetFileName(sys.argv[1] if len(sys.argv) > 1 else "relief_bricks.png")
writer.SetInputConnection(grab.GetOutputPort())
writer.Write()
