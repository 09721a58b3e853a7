"""vtkOpenGLPathFeatureMapper from Python, in a VTK pipeline: a circle from
vtkRegularPolygonSource is the path of a groove on a plane; the groove lies where the
source says, follows the source when it changes, and takes its material's colour. On a
sphere, vtkOpenGLQuadricPathFeatureMapper lets a groove around its equator notch the
outline.

Run by ctest as: TestReliefPathFeaturesPython.py -D <Data dir> -T <temp dir>,
with VTK's /usr/bin/python3 and PYTHONPATH set to the built vtkrelief package.
"""
import argparse
import sys
import unittest

import numpy

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkIntArray
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkImagingSources import vtkImageCanvasSource2D
from vtkmodules.vtkFiltersSources import (vtkPlaneSource, vtkRegularPolygonSource,
                                          vtkTexturedSphereSource)
from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the OpenGL factories)

from vtkrelief import vtkOpenGLPathFeatureMapper, vtkOpenGLQuadricPathFeatureMapper

parser = argparse.ArgumentParser()
parser.add_argument("-D", dest="data", required=True)
parser.add_argument("-T", dest="temporary", required=True)
ARGUMENTS, _ = parser.parse_known_args()

SIZE = 200


def circle_paths(radius):
    """A circle around the texture's centre, as a polyline in (u, v)."""
    circle = vtkRegularPolygonSource()
    circle.SetCenter(0.5, 0.5, 0.0)
    circle.SetRadius(radius)
    circle.SetNumberOfSides(96)
    circle.GeneratePolygonOff()
    circle.GeneratePolylineOn()
    return circle


class PathFeaturesInAPipeline(unittest.TestCase):
    def setUp(self):
        # the unit square seen from straight above, texture coordinates (x, y)
        self.plane = vtkPlaneSource()
        self.plane.SetOrigin(0, 0, 0)
        self.plane.SetPoint1(1, 0, 0)
        self.plane.SetPoint2(0, 1, 0)
        self.circle = circle_paths(0.3)
        self.mapper = vtkOpenGLPathFeatureMapper()
        self.mapper.SetInputConnection(self.plane.GetOutputPort())
        self.mapper.SetPathsConnection(self.circle.GetOutputPort())
        self.mapper.SetDepthScale(0.05)
        self.mapper.GetPathFeatureTextureFilter().SetDefaultWidth(0.06)
        actor = vtkActor()
        actor.SetMapper(self.mapper)
        actor.GetProperty().SetColor(0.8, 0.8, 0.8)
        self.renderer = vtkRenderer()
        self.renderer.AddActor(actor)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(SIZE, SIZE)
        self.window.SetMultiSamples(0)
        self.window.AddRenderer(self.renderer)
        camera = self.renderer.GetActiveCamera()
        camera.ParallelProjectionOn()
        camera.SetFocalPoint(0.5, 0.5, 0)
        camera.SetPosition(0.5, 0.5, 2)
        camera.SetParallelScale(0.5)
        self.renderer.ResetCameraClippingRange(-0.2, 1.2, -0.2, 1.2, -0.2, 0.2)

    def tearDown(self):
        self.window.Finalize()

    def depths(self):
        self.window.Render()
        values = vtkFloatArray()
        self.window.GetZbufferData(0, 0, SIZE - 1, SIZE - 1, values)
        return vtk_to_numpy(values).reshape(SIZE, SIZE)

    def groove_radius(self, depths):
        """Where along the row through the centre the surface is deepest, from it."""
        row = depths[SIZE // 2, SIZE // 2:]
        return (numpy.argmax(row) + 0.5) / SIZE

    def test_groove_follows_its_source(self):
        depths = self.depths()
        plain = depths[5, 5]
        self.assertAlmostEqual(self.groove_radius(depths), 0.3, delta=1.5 / SIZE)
        self.assertGreater(depths.max(), plain)  # cut in: farther from the camera
        self.circle.SetRadius(0.15)
        self.assertAlmostEqual(self.groove_radius(self.depths()), 0.15, delta=1.5 / SIZE)
        self.assertGreater(self.mapper.GetTextureBytes(), 0)
        self.assertLess(self.mapper.GetTextureBytes(), 64 * 1024)

    def test_material_colours_the_groove(self):
        self.circle.Update()
        circle = self.circle.GetOutput()
        material = vtkIntArray()
        material.SetName("Material")
        material.InsertNextValue(0)
        circle.GetCellData().AddArray(material)
        features = self.mapper.GetPathFeatureTextureFilter()
        self.assertEqual(features.AddMaterial(0.9, 0.1, 0.1, 0.0, 1.0), 0)
        self.mapper.SetPathsData(circle)
        self.window.Render()
        capture = vtkWindowToImageFilter()
        capture.SetInput(self.window)
        capture.ReadFrontBufferOff()
        capture.Update()
        pixels = vtk_to_numpy(capture.GetOutput().GetPointData().GetScalars())
        pixels = pixels.reshape(SIZE, SIZE, -1)
        groove = pixels[SIZE // 2, int(0.8 * SIZE)]  # (u 0.8, v 0.5): on the circle
        plain = pixels[5, 5]
        self.assertGreater(int(groove[0]), 2 * int(groove[1]))  # red
        self.assertLess(abs(int(plain[0]) - int(plain[1])), 8)  # the actor's grey

    def test_grooves_cut_into_a_height_map(self):
        # a step: high (white) for u < 0.5, half a DepthScale down beyond, from a VTK source
        step = vtkImageCanvasSource2D()
        step.SetScalarTypeToUnsignedChar()
        step.SetNumberOfScalarComponents(1)
        step.SetExtent(0, 63, 0, 63, 0, 0)
        step.SetDrawColor(128)
        step.FillBox(0, 63, 0, 63)
        step.SetDrawColor(255)
        step.FillBox(0, 31, 0, 63)
        flat = self.depths()
        self.mapper.SetHeightMapConnection(step.GetOutputPort())
        depths = self.depths()
        self.assertTrue(self.mapper.GetDrawingReliefBase())
        high, low = depths[20, int(0.2 * SIZE)], depths[20, int(0.8 * SIZE)]
        self.assertAlmostEqual(high, flat[20, int(0.2 * SIZE)], places=5)  # the top
        self.assertGreater(low, high)  # the low ground lies deeper
        # the groove, 1 deep below the plane, cuts the high ground and the low alike (at
        # pixels as far from the circle's centre, u = 0.1975 and 0.8025)
        centre, left, right = SIZE // 2, int(0.2 * SIZE) - 1, SIZE - int(0.2 * SIZE)
        self.assertGreater(depths[centre, right], low)
        self.assertGreater(depths[centre, left], high)
        self.assertAlmostEqual(depths[centre, left], depths[centre, right], places=5)
        # and without the height map, the flat base again
        self.mapper.SetHeightMapData(None)
        self.mapper.RemoveAllInputConnections(1)
        self.assertFalse(numpy.abs(self.depths() - flat).max() > 1e-6)
        self.assertFalse(self.mapper.GetDrawingReliefBase())


def equator_path():
    """A line around a textured sphere's equator: v = 0.5, u from 0 to 1."""
    points = vtkPoints()
    points.InsertNextPoint(0.0, 0.5, 0.0)
    points.InsertNextPoint(1.0, 0.5, 0.0)
    lines = vtkCellArray()
    lines.InsertNextCell(2)
    lines.InsertCellPoint(0)
    lines.InsertCellPoint(1)
    path = vtkPolyData()
    path.SetPoints(points)
    path.SetLines(lines)
    return path


class PathFeaturesOnACurvedSurface(unittest.TestCase):
    def outline_widths(self, mapper):
        """Per row, how many pixels the sphere covers, seen from the side."""
        sphere = vtkTexturedSphereSource()
        sphere.SetThetaResolution(24)
        sphere.SetPhiResolution(12)
        mapper.SetInputConnection(sphere.GetOutputPort())
        mapper.SetPathsData(equator_path())
        mapper.GetPathFeatureTextureFilter().SetDefaultWidth(0.06)
        mapper.SetDepthScale(0.08)
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(SIZE, SIZE)
        window.SetMultiSamples(0)
        window.AddRenderer(renderer)
        camera = renderer.GetActiveCamera()
        camera.ParallelProjectionOn()
        camera.SetFocalPoint(0, 0, 0)
        camera.SetPosition(0, -3, 0)
        camera.SetViewUp(0, 0, 1)
        camera.SetParallelScale(0.6)
        renderer.ResetCameraClippingRange()
        window.Render()
        values = vtkFloatArray()
        window.GetZbufferData(0, 0, SIZE - 1, SIZE - 1, values)
        window.Finalize()
        covered = vtk_to_numpy(values).reshape(SIZE, SIZE) < 1.0
        return covered.sum(axis=1)

    def test_groove_notches_the_outline(self):
        flat = self.outline_widths(vtkOpenGLPathFeatureMapper())
        curved = self.outline_widths(vtkOpenGLQuadricPathFeatureMapper())
        middle = SIZE // 2
        # the equator's row and rows a little above and below, beside the groove
        near = [middle - 12, middle + 12]
        # the quadric frame cuts the groove out of the outline, 2 x 0.08 deep of a 0.5
        # radius over 1.2 across 200 pixels: about 27 pixels narrower
        self.assertLess(curved[middle], min(curved[k] for k in near) - 15)
        # the tangent frame keeps the polygons' outline there
        self.assertGreaterEqual(flat[middle], min(flat[k] for k in near))


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
