"""Renders the tests' brick wall (relief_paraview_scene) and saves it.

  pvbatch relief_paraview_render.py --plugin P --data D --output O [--redistribute]
  pvpython relief_paraview_render.py ... --server PORT   # through pvserver on 127.0.0.1

It also writes O with .json for .png: the number of ranks holding cells, and the
messages of ParaView's output window. --ranks-coloured draws the plain surface coloured
by the rank that holds each cell instead (for the guide).
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import relief_paraview_scene as scene  # noqa: E402

from paraview.simple import (ColorBy, Connect, GetActiveViewOrCreate, Hide,  # noqa: E402
                             ProcessIdScalars, Render, SaveScreenshot, Show)
from vtkmodules.vtkCommonCore import VTK_STRING, vtkOutputWindow  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402

parser = argparse.ArgumentParser()
parser.add_argument("--plugin", required=True)
parser.add_argument("--data", required=True)
parser.add_argument("--output", required=True)
parser.add_argument("--redistribute", action="store_true")
parser.add_argument("--server", type=int, help="the port of a pvserver on 127.0.0.1")
parser.add_argument("--ranks-coloured", action="store_true",
                    help="draw the plain surface coloured by the rank holding each cell")
arguments = parser.parse_args()

messages = []


@calldata_type(VTK_STRING)
def record(window, event, text):
    messages.append(text)


for event in ("WarningEvent", "ErrorEvent"):
    vtkOutputWindow.GetInstance().AddObserver(event, record)
if arguments.server:
    Connect("127.0.0.1", arguments.server)
scene.load_plugin(arguments.plugin, remote=bool(arguments.server))
if arguments.server:
    # the server's ranks render and IceT composites them, however small the data (by
    # default ParaView draws data under 20 MB on the client)
    GetActiveViewOrCreate("RenderView").RemoteRenderThreshold = 0
source, view, display = scene.brick_wall(arguments.data, arguments.redistribute)
if arguments.ranks_coloured:
    Hide(source, view)
    ranks = Show(ProcessIdScalars(Input=source), view)
    ColorBy(ranks, ("POINTS", "ProcessId"))
    Render(view)
SaveScreenshot(arguments.output, view, ImageResolution=scene.SIZE)
with open(os.path.splitext(arguments.output)[0] + ".json", "w") as report:
    json.dump({"ranks_with_cells": scene.ranks_with_cells(source), "messages": messages},
              report)
