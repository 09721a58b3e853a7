"""The ParaView tests' scene, in pvpython and pvbatch.

The scene is the example's brick wall (Examples/ParaView/relief_bricks.py): tiled
texture coordinates, "Relief Surface" with the bricks' maps, at 55 degrees; redistributed,
its cells split over the MPI ranks by D3 (an unstructured grid, so that representation's
"Relief Surface" is the one drawn). RedistributeDataSet would be the newer filter, but in
Debian's ParaView 5.11 it loses the cells bound for rank 1 (an XML parse error there).

Image comparisons: relief_paraview_images.py.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..",
                                "Examples", "ParaView"))
from relief_bricks import SIZE, brick_wall, load_plugin, tiled_plane  # noqa: E402,F401


def ranks_with_cells(source):
    """The highest rank holding cells of source's output, plus one: on 2 ranks, 2 where
    both hold cells (rank 0 holds some wherever any rank does)."""
    from paraview.simple import Delete, ProcessIdScalars
    ids = ProcessIdScalars(Input=source)
    ids.UpdatePipeline()
    low, high = ids.PointData["ProcessId"].GetRange()
    Delete(ids)
    return int(high - low) + 1
