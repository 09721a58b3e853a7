"""vtkReliefImpostorFilter from Python, in a VTK pipeline: a sphere coloured by
vtkElevationFilter captured as six height fields; each slice's texels read back on the
sphere, its top seen from +z in the colour high elevation takes, and a change of the
source's radius reaching the capture.

Run by ctest as: TestReliefImpostorPython.py -D <Data dir> -T <temp dir>,
with VTK's /usr/bin/python3 and PYTHONPATH set to the built vtkrelief package.
"""
import sys
import unittest

import numpy

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkFiltersCore import vtkElevationFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource

from vtkrelief import vtkReliefImpostorFilter

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


class ImpostorFilterFromPython(unittest.TestCase):
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
            self.assertLess(numpy.abs(radii - 0.5).max(), 0.5 * FACETED)

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
        self.assertLess(numpy.abs(radii - 0.25).max(), 0.25 * FACETED)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]])
