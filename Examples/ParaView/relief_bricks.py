"""A brick wall drawn with the plugin's "Relief Surface", in any of ParaView's programs.

With the plugin found through PV_PLUGIN_PATH (or given as the first argument):

  export PV_PLUGIN_PATH=$PWD/build-paraview/lib/paraview-5.11/plugins/Relief
  pvpython Examples/ParaView/relief_bricks.py [--output wall.png]
  mpiexec -n 4 pvbatch Examples/ParaView/relief_bricks.py --redistribute --output wall.png
  paraview --script=Examples/ParaView/relief_bricks.py

A plane of 24x24 quads gets texture coordinates from Texture Map to Plane, laid out so
that the bricks tile twice each way; "Relief Surface" draws the bricks' height map below
it, coloured by their colour map. --redistribute spreads the cells over the MPI ranks
with D3 first (each cell on one rank), as a large dataset would be spread.
"""
import argparse
import os

from paraview.simple import (CreateTexture, D3, GetActiveViewOrCreate, LoadPlugin, Plane,
                             Render, SaveScreenshot, Show, TextureMaptoPlane)

# ParaView's GUI runs --script files without __file__: then from the project's folder
HERE = os.path.dirname(os.path.abspath(globals().get("__file__") or
                                       "Examples/ParaView/relief_bricks.py"))
DATA = os.path.join(HERE, "..", "..", "Data")
SIZE = [480, 360]


def load_plugin(plugin, remote):
    """The plugin on the client and, connected to a server, on the server too."""
    LoadPlugin(plugin, remote=False, ns=globals())
    if remote:
        LoadPlugin(plugin, remote=True, ns=globals())


def tiled_plane():
    """A unit plane whose texture coordinates run from 0 to 2 each way."""
    plane = Plane(XResolution=24, YResolution=24)
    # Point1 and Point2 are where s and t reach 1: half way across, two tiles in all
    return TextureMaptoPlane(Input=plane, Automatic=0, Origin=[-0.5, -0.5, 0.0],
                             Point1=[0.0, -0.5, 0.0], Point2=[-0.5, 0.0, 0.0])


def brick_wall(data=DATA, redistribute=False):
    """The wall's source, view and display, rendered."""
    source = tiled_plane()
    if redistribute:
        source = D3(Input=source, BoundaryMode="Assign cells uniquely")
    view = GetActiveViewOrCreate("RenderView")
    view.ViewSize = SIZE
    view.OrientationAxesVisibility = 0
    view.Background = [0.32, 0.34, 0.43]
    display = Show(source, view)
    display.Representation = "Relief Surface"
    display.Texture = CreateTexture(os.path.join(data, "bricks_color.png"))
    display.ReliefHeightMap = CreateTexture(os.path.join(data, "bricks_height.png"))
    display.ReliefDepthScale = 0.04  # world units: 8% of a tile
    Render(view)  # paraview.simple resets the camera at a view's first render
    view.CameraPosition = [0.0, -1.25, 0.9]
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraViewUp = [0.0, 0.0, 1.0]
    view.CameraViewAngle = 30
    Render(view)
    return source, view, display


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("plugin", nargs="?", help="Relief.so, unless PV_PLUGIN_PATH finds it")
    parser.add_argument("--output", help="save the view into this PNG")
    parser.add_argument("--redistribute", action="store_true")
    arguments, _ = parser.parse_known_args()
    if arguments.plugin:
        load_plugin(arguments.plugin, remote=False)
    source, view, display = brick_wall(redistribute=arguments.redistribute)
    if arguments.output:
        SaveScreenshot(arguments.output, view, ImageResolution=SIZE)
