"""Image comparisons of the ParaView tests: in any Python with ParaView's vtkmodules and
numpy (the drivers run in /usr/bin/python3, not in pvpython).
"""
import os


def load_png(path):
    """The image as a height x width x channels array of ints, top row first."""
    import numpy
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    if not os.path.exists(path):
        raise FileNotFoundError(path)
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    pixels = vtk_to_numpy(image.GetPointData().GetScalars())
    return pixels.reshape(height, width, -1)[::-1, :, :3].astype(numpy.int32)


def differing_pixels(first, second, levels):
    """The share of pixels whose channels differ by more than levels (of 255)."""
    if first.shape != second.shape:
        return 1.0
    return float((abs(first - second).max(axis=2) > levels).mean())
