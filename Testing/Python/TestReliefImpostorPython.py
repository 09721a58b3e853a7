"""vtkReliefImpostorFilter from Python, in a VTK pipeline: a sphere coloured by
vtkElevationFilter captured as six height fields; each slice's texels read back on the
sphere (those along its outline within half a texel of it), its top seen from +z in the
colour high elevation takes, and a change of the source's radius reaching the capture;
and vtkOpenGLReliefImpostorMapper drawing that pipeline's sphere where VTK's own mapper
draws it, in the colours of its scalars.

Run by ctest as: TestReliefImpostorPython.py -D <Data dir> -T <temp dir>,
with VTK's /usr/bin/python3 and PYTHONPATH set to the built vtkrelief package.
"""
import sys
import unittest

import numpy

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkElevationFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkRenderingCore import (vtkActor, vtkPolyDataMapper, vtkRenderWindow,
                                         vtkRenderer, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL render window)

from vtkrelief import vtkOpenGLReliefImpostorMapper, vtkReliefImpostorFilter

RESOLUTION = 64
# the polygonal sphere lies within this share of its radius (64 facets around)
FACETED = 1.0 - numpy.cos(numpy.pi / 64) ** 2 + 1e-6


def world_points(capture, view):
    """The world points the texels of slice `view` met, through its projection."""
    depths = vtk_to_numpy(capture.GetDepthOutput().GetPointData().GetScalars())
    depths = depths.reshape(-1, RESOLUTION, RESOLUTION)[view]
    matrix = numpy.array([0.0] * 16)
    capture.GetViewProjection(view, matrix)
    inverse = numpy.linalg.inv(matrix.reshape(4, 4))
    j, i = numpy.nonzero(depths < 1.0)
    cube = numpy.stack([(i + 0.5) / RESOLUTION, (j + 0.5) / RESOLUTION, depths[j, i],
                        numpy.ones(len(i))])
    world = inverse @ cube
    return (world[:3] / world[3]).T


def texel(capture):
    """A depth texel's side in world units."""
    box = capture.GetBox()
    return (box[1] - box[0]) / RESOLUTION


class ImpostorFilterFromPython(unittest.TestCase):
    def assertOnSphere(self, radii, radius, side):
        """Texels whose centre the sphere covers read back on it; those it only reaches
        into, along its outline, at most half a texel's diagonal outside it."""
        self.assertGreater(radii.min(), radius * (1.0 - FACETED))
        self.assertLess(radii.max(), radius + 0.71 * side)
        on_surface = numpy.abs(radii - radius) < radius * FACETED
        self.assertGreater(on_surface.mean(), 0.85)

    def setUp(self):
        self.sphere = vtkSphereSource()
        self.sphere.SetThetaResolution(64)
        self.sphere.SetPhiResolution(64)
        elevation = vtkElevationFilter()
        elevation.SetInputConnection(self.sphere.GetOutputPort())
        elevation.SetLowPoint(0.0, 0.0, -0.5)
        elevation.SetHighPoint(0.0, 0.0, 0.5)
        self.capture = vtkReliefImpostorFilter()
        self.capture.SetInputConnection(elevation.GetOutputPort())
        self.capture.SetDepthResolution(RESOLUTION)
        self.capture.SetColourResolution(RESOLUTION)

    def test_slices_read_back_on_the_sphere(self):
        self.capture.Update()
        self.assertLess(self.capture.GetUnseenSurfaceFraction(), 0.01)
        for view in range(6):
            radii = numpy.linalg.norm(world_points(self.capture, view), axis=1)
            self.assertGreater(len(radii), RESOLUTION * RESOLUTION // 2)
            self.assertOnSphere(radii, 0.5, texel(self.capture))

    def test_colour_from_the_scalars(self):
        self.capture.Update()
        colours = vtk_to_numpy(self.capture.GetColourOutput().GetPointData().GetScalars())
        colours = colours.reshape(6, RESOLUTION, RESOLUTION, 4)
        top = colours[4, RESOLUTION // 2, RESOLUTION // 2]  # +z: high, blue in VTK's table
        bottom = colours[5, RESOLUTION // 2, RESOLUTION // 2]  # -z: low, red
        self.assertGreater(int(top[2]), 200)
        self.assertGreater(int(bottom[0]), 200)
        self.assertEqual(int(colours[4, 0, 0, 3]), 0)  # beside the sphere: nothing

    def test_the_pipeline_updates_the_capture(self):
        self.capture.Update()
        self.sphere.SetRadius(0.25)
        self.capture.Update()
        radii = numpy.linalg.norm(world_points(self.capture, 4), axis=1)
        self.assertOnSphere(radii, 0.25, texel(self.capture))


def rendered(mapper):
    """The RGB pixels of `mapper`'s actor in a 160 x 160 view, black background, and
    the bytes of its textures (an impostor's) while the window lives."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(160, 160)
    renderer = vtkRenderer()
    window.AddRenderer(renderer)
    actor = vtkActor()
    actor.SetMapper(mapper)
    renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(1.0, -2.0, 1.5)
    camera.SetViewUp(0.0, 0.0, 1.0)
    renderer.ResetCamera(-0.5, 0.5, -0.5, 0.5, -0.5, 0.5)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    image = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
    textures = mapper.GetTextureBytes() if hasattr(mapper, "GetTextureBytes") else 0
    return image.reshape(160, 160, -1)[:, :, :3].astype(float), textures


class ImpostorMapperFromPython(unittest.TestCase):
    def test_the_impostor_draws_the_sphere(self):
        sphere = vtkSphereSource()
        sphere.SetThetaResolution(64)
        sphere.SetPhiResolution(64)
        elevation = vtkElevationFilter()
        elevation.SetInputConnection(sphere.GetOutputPort())
        elevation.SetLowPoint(0.0, 0.0, -0.5)
        elevation.SetHighPoint(0.0, 0.0, 0.5)
        mesh = vtkPolyDataMapper()
        mesh.SetInputConnection(elevation.GetOutputPort())
        impostor = vtkOpenGLReliefImpostorMapper()
        impostor.SetInputConnection(elevation.GetOutputPort())
        truth, _ = rendered(mesh)
        drawn, textures = rendered(impostor)
        self.assertTrue(impostor.GetDrawingImpostor())
        # captured at the resolution its size on screen asks for: its box spans more than
        # 128 of the 160 pixels, so 256 depth texels a side, colour twice that
        self.assertTrue(impostor.GetAutomaticResolution())
        self.assertEqual(impostor.GetImpostorFilter().GetDepthResolution(), 256)
        self.assertEqual(impostor.GetImpostorFilter().GetColourResolution(), 512)
        self.assertGreater(textures, 0)
        self.assertEqual(impostor.GetTextureBytes(), 0)  # released with the window
        covered = truth.sum(axis=2) > 0
        self.assertGreater(covered.mean(), 0.2)
        # the outline within a pixel or two, the colours close
        outline = numpy.logical_xor(covered, drawn.sum(axis=2) > 0).mean()
        self.assertLess(outline, 0.01)
        both = covered & (drawn.sum(axis=2) > 0)
        error = numpy.sqrt(numpy.mean((truth[both] - drawn[both]) ** 2)) / 255.0
        self.assertLess(error, 0.05)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
