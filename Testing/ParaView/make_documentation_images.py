"""The guide's ParaView pictures (./relief paraview images [DIR]), into DIR:

- paraview_gui.png: ParaView's own window (the Qt client, under this X display) running
  Examples/ParaView/relief_bricks.py, "Relief Surface" chosen in its toolbar;
- paraview_two_ranks.png: the parallel test's brick wall, drawn by pvbatch on 2 MPI
  ranks, each holding half of the cells;
- paraview_rank_split.png: the same cells coloured by the rank that holds them.

  python3 make_documentation_images.py PLUGIN DATA DIR
"""
import os
import subprocess
import sys
import tempfile
import time

import numpy
from vtkmodules.util.numpy_support import numpy_to_vtk
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGWriter

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import relief_paraview_programs as programs  # noqa: E402

plugin, data, output = sys.argv[1:4]
here = os.path.dirname(os.path.abspath(__file__))
example = os.path.join(here, "..", "..", "Examples", "ParaView", "relief_bricks.py")
mpiexec = programs.MPIEXEC
pvbatch = programs.program("pvbatch")
paraview = programs.program("paraview")
os.makedirs(output, exist_ok=True)


def write_png(pixels, path):
    """pixels: height x width x 3 uint8, top row first."""
    image = vtkImageData()
    image.SetDimensions(pixels.shape[1], pixels.shape[0], 1)
    image.GetPointData().SetScalars(numpy_to_vtk(pixels[::-1].reshape(-1, 3).copy()))
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputData(image)
    writer.Write()


def screen(display):
    """The X screen as height x width x RGB, read by xwd: a TrueColor ZPixmap whose
    pixels take bits_per_pixel / 8 bytes (Xvfb's 24-bit screen: 3), rows padded to
    bytes_per_line."""
    dump = subprocess.run(["xwd", "-root", "-silent", "-display", display],
                          check=True, capture_output=True).stdout
    header = numpy.frombuffer(dump[:100], dtype=">u4")
    header_size, width, height = int(header[0]), int(header[4]), int(header[5])
    pixel_bytes, bytes_per_line, colours = int(header[11]) // 8, int(header[12]), int(header[19])
    start = header_size + 12 * colours
    rows = numpy.frombuffer(dump[start:start + bytes_per_line * height], dtype=numpy.uint8)
    pixels = rows.reshape(height, bytes_per_line)[:, :pixel_bytes * width]
    pixels = pixels.reshape(height, width, pixel_bytes)
    least_significant_first = int(header[7]) == 0  # blue, green, red
    return pixels[:, :, [2, 1, 0]] if least_significant_first else pixels[:, :, -3:]


def gui(path):
    """ParaView's window once the example has drawn and the screen has stopped changing."""
    display = os.environ["DISPLAY"]
    environment = dict(os.environ, PV_PLUGIN_PATH=os.path.dirname(plugin))
    with tempfile.TemporaryDirectory() as settings:
        # a fresh user: no saved layout, no welcome dialog
        environment["HOME"] = settings
        client = subprocess.Popen([paraview, "--script=" + example], env=environment)
        try:
            previous, still = None, 0
            for _ in range(90):
                time.sleep(2)
                current = screen(display)
                still = still + 1 if previous is not None and (current == previous).all() else 0
                previous = current
                if still >= 3 and current.std() > 10:
                    break
            # the window alone, not the empty screen around it
            used = previous.any(axis=2)  # the screen around it is black
            rows, columns = numpy.flatnonzero(used.any(axis=1)), numpy.flatnonzero(used.any(axis=0))
            write_png(previous[rows[0]:rows[-1] + 1, columns[0]:columns[-1] + 1], path)
        finally:
            programs.stop(client)


render = os.path.join(here, "relief_paraview_render.py")
for name, options in (("paraview_two_ranks", []), ("paraview_rank_split", ["--ranks-coloured"])):
    subprocess.run(mpiexec + ["-n", "2", pvbatch, "--force-offscreen-rendering", render,
                              "--plugin", plugin, "--data", data, "--redistribute", "--output",
                              os.path.join(output, name + ".png")] + options, check=True)
    os.remove(os.path.join(output, name + ".json"))
gui(os.path.join(output, "paraview_gui.png"))
print("relief: wrote the ParaView pictures into", output)
