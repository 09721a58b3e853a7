"""Tests of vtkRelief's wrapped API: classes, properties, the reader and the relief
texture, and a sample-count render read back into numpy.

Run by ctest as: TestReliefPython.py -D <Data dir> -T <temp dir>,
with VTK's /usr/bin/python3 and PYTHONPATH set to the built vtkrelief package.
"""
import argparse
import os
import sys
import unittest

import numpy

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.util.vtkConstants import VTK_FLOAT, VTK_STRING, VTK_UNSIGNED_SHORT
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkMultiBlockDataSet
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkFiltersTexture import vtkTextureMapToSphere
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkFiltersGeneral import vtkPassSelectedArrays
from vtkmodules.vtkIOGeometry import vtkOBJReader
from vtkmodules.vtkIOPLY import vtkPLYReader
from vtkmodules.vtkRenderingCore import (vtkActor, vtkRenderWindow, vtkRenderer,
                                         vtkWindowToImageFilter)

import vtkrelief
from vtkrelief import (vtkCompositeReliefMapper, vtkConeStepMapFilter, vtkLocalQuadricFilter,
                       vtkMaximumMipmapFilter, vtkSlopeMipmapFilter,
                       vtkOpenGLDerivativeReliefMapper, vtkOpenGLQuadricReliefMapper,
                       vtkOpenGLReliefMapper, vtkReliefSurfaceFilter,
                       vtkOpenImageIOReader, vtkReliefDisplacementFilter,
                       vtkReliefTangentFrameFilter, vtkReliefTextureFilter,
                       vtkSafetyRadiusFilter)

parser = argparse.ArgumentParser()
parser.add_argument("-D", dest="data", required=True)
parser.add_argument("-T", dest="temporary", required=True)
ARGUMENTS, _ = parser.parse_known_args()


class MessageRecorder:
    """Collects the texts of the warnings or errors an object reports."""

    def __init__(self, vtk_object, event):
        self.messages = []
        vtk_object.AddObserver(event, self.record)

    @calldata_type(VTK_STRING)
    def record(self, caller, event, message):
        self.messages.append(message)


def read_image(name):
    reader = vtkOpenImageIOReader()
    reader.SetFileName(os.path.join(ARGUMENTS.data, name))
    reader.Update()
    return reader.GetOutput()


def window_pixels(window):
    """The window rendered, read back as one row of ints a pixel."""
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    return vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars()).astype(int)


class TestReliefPython(unittest.TestCase):
    def test_classes_come_from_the_package(self):
        for cls in (vtkOpenGLReliefMapper, vtkOpenImageIOReader, vtkReliefTextureFilter,
                    vtkReliefTangentFrameFilter, vtkMaximumMipmapFilter,
                    vtkSafetyRadiusFilter, vtkConeStepMapFilter, vtkReliefDisplacementFilter,
                    vtkLocalQuadricFilter, vtkOpenGLQuadricReliefMapper,
                    vtkOpenGLDerivativeReliefMapper, vtkReliefSurfaceFilter,
                    vtkCompositeReliefMapper):
            self.assertIs(getattr(vtkrelief, cls.__name__), cls)
            self.assertEqual(cls().GetClassName(), cls.__name__)

    def test_search_method_round_trips(self):
        mapper = vtkOpenGLReliefMapper()
        self.assertEqual(mapper.GetSearchMethodAsString(), "Automatic")
        self.assertEqual(mapper.GetScreenTolerance(), 0.5)
        mapper.SetScreenTolerance(2.0)
        self.assertEqual(mapper.GetScreenTolerance(), 2.0)
        mapper.SetSearchMethodToLinear()
        self.assertEqual(mapper.GetSearchMethod(), vtkOpenGLReliefMapper.LINEAR)
        self.assertEqual(mapper.GetSearchMethodAsString(), "Linear")
        mapper.SetSearchMethodToAutomatic()
        self.assertEqual(mapper.GetSearchMethod(), vtkOpenGLReliefMapper.AUTOMATIC)
        mapper.SetSearchMethodToLinearBinary()
        self.assertEqual(mapper.GetSearchMethodAsString(), "LinearBinary")

        errors = MessageRecorder(mapper, vtkCommand.ErrorEvent)
        mapper.SetSearchMethod(42)
        self.assertEqual(len(errors.messages), 1)
        self.assertEqual(mapper.GetSearchMethod(), vtkOpenGLReliefMapper.LINEAR_BINARY)

        # what Automatic steps long runs over: the cone map by default, or the slope pyramid
        self.assertEqual(mapper.GetAutomaticAccelerationAsString(), "ConeStep")
        mapper.SetAutomaticAccelerationToSlopeMipmap()
        self.assertEqual(mapper.GetAutomaticAcceleration(), vtkOpenGLReliefMapper.SLOPE_MIPMAP)
        mapper.SetAutomaticAcceleration(vtkOpenGLReliefMapper.EXACT_DDA)
        self.assertEqual(len(errors.messages), 2)
        self.assertEqual(mapper.GetAutomaticAccelerationAsString(), "SlopeMipmap")

    def test_each_method_names_the_filter_of_its_acceleration_image(self):
        expected = {vtkOpenGLReliefMapper.SAFETY_RADIUS: vtkSafetyRadiusFilter,
                    vtkOpenGLReliefMapper.CONE_STEP: vtkConeStepMapFilter,
                    vtkOpenGLReliefMapper.MAXIMUM_MIPMAP: vtkMaximumMipmapFilter,
                    vtkOpenGLReliefMapper.AUTOMATIC: vtkConeStepMapFilter,
                    vtkOpenGLReliefMapper.ROBUST_BINARY: vtkSafetyRadiusFilter,
                    vtkOpenGLReliefMapper.SLOPE_MIPMAP: vtkSlopeMipmapFilter}
        for method in range(vtkOpenGLReliefMapper.SLOPE_MIPMAP + 1):
            made = vtkOpenGLReliefMapper.NewAccelerationFilter(method)
            if method in expected:
                self.assertIsInstance(made, expected[method])
                self.assertEqual(made.GetReferenceCount(), 1)  # ours alone: no leak
            else:
                self.assertIsNone(made)

    def test_step_counts_are_clamped_with_a_warning(self):
        mapper = vtkOpenGLReliefMapper()
        warnings = MessageRecorder(mapper, vtkCommand.WarningEvent)
        mapper.SetLinearSteps(64)
        self.assertEqual(mapper.GetLinearSteps(), 64)
        self.assertEqual(warnings.messages, [])
        for asked, kept in ((0, 1), (-5, 1), (513, 512), (100000, 512)):
            mapper.SetLinearSteps(asked)
            self.assertEqual(mapper.GetLinearSteps(), kept)
        self.assertEqual(len(warnings.messages), 4)
        self.assertIn("LinearSteps", warnings.messages[0])

        mapper.SetBinarySteps(33)
        self.assertEqual(mapper.GetBinarySteps(), 32)
        self.assertEqual(len(warnings.messages), 5)

    def test_uniform_properties_round_trip(self):
        mapper = vtkOpenGLReliefMapper()
        mapper.SetDepthScale(0.125)
        self.assertEqual(mapper.GetDepthScale(), 0.125)

        self.assertTrue(mapper.GetFootprintShading())
        mapper.FootprintShadingOff()
        self.assertFalse(mapper.GetFootprintShading())

        self.assertTrue(mapper.GetSelfShadowing())
        mapper.SelfShadowingOff()
        self.assertFalse(mapper.GetSelfShadowing())
        mapper.SetSelfShadowing(True)
        self.assertTrue(mapper.GetSelfShadowing())

        self.assertEqual(mapper.GetDisplayMode(), vtkOpenGLReliefMapper.SHADED)
        mapper.SetDisplayModeToSampleCount()
        self.assertEqual(mapper.GetDisplayMode(), vtkOpenGLReliefMapper.SAMPLE_COUNT)
        errors = MessageRecorder(mapper, vtkCommand.ErrorEvent)
        mapper.SetDisplayMode(7)
        self.assertEqual(len(errors.messages), 1)
        self.assertEqual(mapper.GetDisplayMode(), vtkOpenGLReliefMapper.SAMPLE_COUNT)

    def test_reader_keeps_sixteen_bits(self):
        image = read_image("bricks_height.png")
        self.assertEqual(image.GetDimensions(), (512, 512, 1))
        self.assertEqual(image.GetScalarType(), VTK_UNSIGNED_SHORT)
        self.assertEqual(image.GetNumberOfScalarComponents(), 1)
        self.assertGreater(image.GetScalarRange()[1], 255)  # more than 8 bits of levels

    def test_relief_texture_holds_normals_and_depth(self):
        relief = vtkReliefTextureFilter()
        relief.SetInputData(read_image("bricks_height.png"))
        relief.Update()
        texture = relief.GetOutput()
        self.assertEqual(texture.GetDimensions(), (512, 512, 1))
        self.assertEqual(texture.GetScalarType(), VTK_FLOAT)
        texels = vtk_to_numpy(texture.GetPointData().GetScalars())
        self.assertEqual(texels.shape, (512 * 512, 4))
        depth = texels[:, 3]
        self.assertGreaterEqual(depth.min(), 0.0)
        self.assertLessEqual(depth.max(), 1.0)
        # white = high: brick faces (h about 0.8) are shallow, mortar (h < 0.05) deep
        self.assertLess(depth.min(), 0.25)
        self.assertGreater(depth.max(), 0.9)

    def test_displacement_pipeline_makes_the_relief_geometry(self):
        # reader -> relief texture -> displacement of a plane: what the ground truth is
        reader = vtkOpenImageIOReader()
        reader.SetFileName(os.path.join(ARGUMENTS.data, "bricks_height.png"))
        relief = vtkReliefTextureFilter()
        relief.SetInputConnection(reader.GetOutputPort())
        plane = vtkPlaneSource()
        displacement = vtkReliefDisplacementFilter()
        displacement.SetInputConnection(plane.GetOutputPort())
        displacement.SetReliefConnection(relief.GetOutputPort())
        displacement.SetDepthScale(0.1)
        displacement.SetMaximumEdgeTexels(8.0)
        displacement.Update()
        mesh = displacement.GetOutput()
        # 512 texels across, edges of at most 8: 7 halvings of the diagonal
        self.assertEqual(displacement.GetSubdivisionLevels(), 7)
        self.assertLessEqual(displacement.GetLongestEdgeTexels(), 8.0)
        heights = vtk_to_numpy(mesh.GetPoints().GetData())[:, 2]
        # sunk between 0 and DepthScale, mortar deep and brick faces shallow
        self.assertGreaterEqual(heights.min(), -0.1 - 1e-6)
        self.assertLessEqual(heights.max(), 1e-6)
        self.assertLess(heights.min(), -0.09)
        self.assertGreater(heights.max(), -0.025)
        self.assertIsNotNone(mesh.GetPointData().GetNormals())

    def test_local_quadrics_of_a_sphere_in_a_pipeline(self):
        # sphere -> texture coordinates -> quadrics: a = b = -1 / (2 r) away from the poles
        sphere = vtkSphereSource()
        sphere.SetRadius(2.0)
        sphere.SetThetaResolution(96)
        sphere.SetPhiResolution(48)
        texture = vtkTextureMapToSphere()
        texture.SetInputConnection(sphere.GetOutputPort())
        texture.PreventSeamOff()
        quadrics = vtkLocalQuadricFilter()
        quadrics.SetInputConnection(texture.GetOutputPort())
        quadrics.Update()
        mesh = quadrics.GetOutput()
        coefficients = vtk_to_numpy(
            mesh.GetPointData().GetArray(vtkLocalQuadricFilter.QuadricArrayName()))
        heights = vtk_to_numpy(mesh.GetPoints().GetData())[:, 2]
        middle = numpy.abs(heights) < 1.0  # away from the poles, where u turns around
        self.assertGreater(middle.sum(), 1000)
        numpy.testing.assert_allclose(coefficients[middle], -0.25, rtol=0.03)
        count = mesh.GetFieldData().GetArray(vtkLocalQuadricFilter.FallbackCountArrayName())
        self.assertEqual(count.GetValue(0), quadrics.GetNumberOfFallbacks())
        # the curved frame's mapper is a relief mapper whose quadric filter is configurable
        mapper = vtkOpenGLQuadricReliefMapper()
        self.assertIsInstance(mapper, vtkOpenGLReliefMapper)
        mapper.GetLocalQuadricFilter().SetNeighbourhoodRings(2)
        self.assertEqual(mapper.GetLocalQuadricFilter().GetNeighbourhoodRings(), 2)
        self.assertEqual(mapper.GetDistanceModeAsString(), "Approximate")
        mapper.SetDistanceModeToExact()
        self.assertEqual(mapper.GetDistanceMode(), vtkOpenGLQuadricReliefMapper.EXACT)
        errors = MessageRecorder(mapper, vtkCommand.ErrorEvent)
        mapper.SetDistanceMode(7)  # unknown: one error, nothing changes
        self.assertEqual(len(errors.messages), 1)
        self.assertIn("SetDistanceModeToExact", errors.messages[0])
        self.assertEqual(mapper.GetDistanceModeAsString(), "Exact")


class TestSampleCountRender(unittest.TestCase):
    """The sample-count display mode, read back: red = height samples per pixel."""

    @classmethod
    def setUpClass(cls):
        plane = vtkPlaneSource()  # unit square, texture coordinates [0, 1]^2
        cls.mapper = vtkOpenGLReliefMapper()
        cls.mapper.SetInputConnection(plane.GetOutputPort())
        cls.mapper.SetHeightMapData(read_image("bricks_height.png"))
        cls.mapper.SetDepthScale(0.05)
        cls.mapper.SetDisplayModeToSampleCount()
        cls.mapper.FootprintShadingOff()  # the samples of the view ray's search alone
        actor = vtkActor()
        actor.SetMapper(cls.mapper)
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        # pure blue behind: red and green 0, and blue tells background from relief
        renderer.SetBackground(0.0, 0.0, 1.0)
        renderer.GetActiveCamera().Elevation(-45)  # oblique, so that rays cross texels
        renderer.ResetCamera()
        cls.window = vtkRenderWindow()
        cls.window.SetOffScreenRendering(1)
        cls.window.SetMultiSamples(0)  # no blending of counts at the edges
        cls.window.SetSize(200, 150)
        cls.window.AddRenderer(renderer)

    @classmethod
    def tearDownClass(cls):
        cls.window.Finalize()

    def render(self, name):
        """Pixels of a fresh render as a (height, width, 3) array; also saved to -T."""
        self.window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.Update()
        writer = vtkPNGWriter()
        writer.SetFileName(os.path.join(ARGUMENTS.temporary, name + ".png"))
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()
        width, height, _ = grab.GetOutput().GetDimensions()
        pixels = vtk_to_numpy(grab.GetOutput().GetPointData().GetScalars())
        return pixels.reshape(height, width, -1)[:, :, :3].astype(int)

    def split(self, pixels):
        covered = pixels[:, :, 2] == 0
        fraction = covered.mean()
        self.assertGreater(fraction, 0.1, "the relief covers almost nothing")
        self.assertLess(fraction, 0.9, "the relief covers almost everything")
        background = pixels[~covered]
        self.assertTrue((background[:, 0] == 0).all(), "background red must be 0")
        self.assertTrue((background[:, 2] == 255).all())
        relief = pixels[covered]
        self.assertTrue((relief[:, 1] == 0).all(), "sample-count green must be 0")
        return relief[:, 0]

    def test_linear_binary_and_linear_counts(self):
        self.mapper.SetSearchMethodToLinearBinary()
        self.mapper.SetLinearSteps(10)
        self.mapper.SetBinarySteps(5)
        samples = self.split(self.render("TestReliefPython_LinearBinary"))
        self.assertGreaterEqual(samples.min(), 1)
        self.assertLessEqual(samples.max(), 15)
        # rays into the mortar (depth > 0.9) take all 10 linear steps, then 5 binary ones
        self.assertEqual(samples.max(), 15)
        linear_binary_mean = samples.mean()

        self.mapper.SetSearchMethodToLinear()
        samples = self.split(self.render("TestReliefPython_Linear"))
        self.assertGreaterEqual(samples.min(), 1)
        self.assertEqual(samples.max(), 10)
        self.assertLess(samples.mean(), linear_binary_mean)

        self.mapper.SetLinearSteps(4)  # a uniform: takes effect without a rebuild
        samples = self.split(self.render("TestReliefPython_Linear4"))
        self.assertEqual(samples.max(), 4)
        self.mapper.SetLinearSteps(10)

    def test_precomputed_cone_map_in_a_pipeline(self):
        # the pipeline computes the cone map once, as ParaView would, and the mapper
        # takes it on port 2 instead of building its own
        self.mapper.SetSearchMethodToExactDDA()
        exact_mean = self.split(self.render("TestReliefPython_ExactDDA")).mean()
        cones = vtkConeStepMapFilter()
        cones.SetInputConnection(self.mapper.GetReliefTextureFilter().GetOutputPort())
        self.mapper.SetAccelerationConnection(cones.GetOutputPort())
        self.mapper.SetSearchMethodToConeStep()
        errors = MessageRecorder(self.mapper, vtkCommand.ErrorEvent)
        samples = self.split(self.render("TestReliefPython_ConeStep"))
        self.assertEqual(errors.messages, [])
        self.assertEqual(self.mapper.GetActiveSearchMethod(), vtkOpenGLReliefMapper.CONE_STEP)
        self.assertEqual(cones.GetOutput().GetNumberOfScalarComponents(), 2)
        self.assertLess(samples.mean(), exact_mean)
        self.mapper.SetAccelerationConnection(None)


class TestDerivativeRender(unittest.TestCase):
    """Tangent-free relief on files read in a pipeline, read back from the window."""

    def render(self, mapper, sample_count):
        mapper.SetHeightMapData(read_image("stones_height.png"))
        mapper.SetDepthScale(0.03)
        if sample_count:
            mapper.SetDisplayModeToSampleCount()
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        renderer.SetBackground(0.0, 0.0, 1.0)
        renderer.GetActiveCamera().Elevation(30)
        renderer.ResetCamera()
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetMultiSamples(0)
        window.SetSize(160, 120)
        window.AddRenderer(renderer)
        self.addCleanup(window.Finalize)
        return lambda: window_pixels(window)

    def test_ply_without_normals_in_a_pipeline(self):
        reader = vtkPLYReader()
        reader.SetFileName(os.path.join(ARGUMENTS.data, "icosahedron.ply"))
        mapper = vtkOpenGLDerivativeReliefMapper()
        mapper.SetInputConnection(reader.GetOutputPort())
        errors = MessageRecorder(mapper, vtkCommand.ErrorEvent)
        pixels = self.render(mapper, sample_count=True)()
        samples = pixels[pixels[:, 2] == 0][:, 0]
        self.assertGreater(len(samples), 2000)
        self.assertTrue((samples > 0).all(), "every face is searched")
        surface = mapper.GetReliefSurface().GetPointData()
        self.assertIsNone(surface.GetTangents())
        self.assertIsNone(surface.GetNormals())
        self.assertEqual(errors.messages, [])

    def test_quadric_mapper_decides_which_faces_carry_relief(self):
        reader = vtkOBJReader()  # a closed torus, its texture seams duplicated
        reader.SetFileName(os.path.join(ARGUMENTS.data, "torus.obj"))
        mapper = vtkOpenGLQuadricReliefMapper()
        mapper.SetInputConnection(reader.GetOutputPort())
        pixels = self.render(mapper, sample_count=True)
        one_sided = pixels()
        self.assertTrue(mapper.GetBackFacesLeftOut(), "closed, seen from outside")
        surface = mapper.GetReliefSurface().GetPointData()
        self.assertIsNotNone(surface.GetArray(vtkLocalQuadricFilter.QuadricArrayName()))
        mapper.TwoSidedReliefOn()
        two_sided = pixels()
        self.assertFalse(mapper.GetBackFacesLeftOut())
        # the back faces fill the outlines the relief carves
        def covered(image):
            return (image != [0, 0, 255]).any(axis=1)
        self.assertGreater(covered(two_sided).sum(), covered(one_sided).sum() + 50)

    def test_compute_normals_smooths_a_mesh_without_them(self):
        reader = vtkOBJReader()
        reader.SetFileName(os.path.join(ARGUMENTS.data, "torus.obj"))
        strip = vtkPassSelectedArrays()  # the file's normals left out, its points kept
        strip.SetInputConnection(reader.GetOutputPort())
        strip.GetPointDataArraySelection().EnableArray("TCoords")
        mapper = vtkOpenGLDerivativeReliefMapper()
        mapper.SetInputConnection(strip.GetOutputPort())
        pixels = self.render(mapper, sample_count=False)
        flat = pixels()
        self.assertIsNone(mapper.GetReliefSurface().GetPointData().GetNormals())
        mapper.ComputeNormalsOn()
        smooth = pixels()
        self.assertIsNotNone(mapper.GetReliefSurface().GetPointData().GetNormals())
        # the same triangles drawn, shaded smoothly instead of facet by facet
        def covered(image):
            return (image != [0, 0, 255]).any(axis=1)
        self.assertTrue((covered(flat) == covered(smooth)).all())
        self.assertGreater(numpy.abs(flat - smooth)[covered(flat)].mean(), 2.0)
        mapper.ComputeNormalsOff()
        self.assertTrue((pixels() == flat).all(), "off again: the flat frame again")


class TestCompositeRender(unittest.TestCase):
    """A multiblock pipeline drawn with relief: one relief mapper per block, set up once."""

    def test_each_block_is_drawn_with_the_prototype_settings(self):
        blocks = vtkMultiBlockDataSet()
        for index, x in enumerate((-0.55, 0.55)):
            plane = vtkPlaneSource()
            plane.SetCenter(x, 0.0, 0.0)
            plane.Update()
            blocks.SetBlock(index, plane.GetOutput())
        mapper = vtkCompositeReliefMapper()
        mapper.SetInputDataObject(blocks)
        mapper.GetReliefMapper().SetHeightMapData(read_image("stones_height.png"))
        mapper.GetReliefMapper().SetDepthScale(0.05)
        warnings = MessageRecorder(mapper, vtkCommand.WarningEvent)
        actor = vtkActor()
        actor.SetMapper(mapper)
        renderer = vtkRenderer()
        renderer.AddActor(actor)
        renderer.GetActiveCamera().Elevation(-40)
        renderer.ResetCamera()
        window = vtkRenderWindow()
        window.SetOffScreenRendering(1)
        window.SetSize(200, 120)
        window.AddRenderer(renderer)
        self.addCleanup(window.Finalize)

        relief = window_pixels(window)
        self.assertEqual(mapper.GetNumberOfBlockMappers(), 2)
        self.assertEqual(warnings.messages, [])
        mapper.GetReliefMapper().SetDepthScale(0.0)
        flat = window_pixels(window)
        self.assertEqual(mapper.GetBlockMapper(1).GetDepthScale(), 0.0)
        self.assertGreater((abs(relief - flat).max(axis=1) > 16).mean(), 0.05)


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0]], verbosity=2)
