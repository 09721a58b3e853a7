"""The brick wall drawn by pvbatch on 1 MPI rank and on 2, its cells split between them
by D3: ParaView composites the ranks' images by depth (IceT), and the relief's fragments
write their true depth, so the two images must agree.

Measured (llvmpipe, each cell on one rank): the images are identical. The tolerance,
0.05% of the pixels differing by more than 2 of 255, leaves room only for what splitting
cells at the ranks' border does (D3's "Divide cells": 14 pixels of 172,800, by at most 5):
a relief mapper that wrote the polygon's depth, not the hit's, or one that differed
across pieces, fails it. Both images are also held against the committed baseline.

  python3 TestReliefParaViewParallel.py PLUGIN DATA BASELINE OUTPUT_DIR
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import relief_paraview_images as images  # noqa: E402
import relief_paraview_programs as programs  # noqa: E402

plugin, data, baseline, output = sys.argv[1:5]
render = os.path.join(os.path.dirname(os.path.abspath(__file__)), "relief_paraview_render.py")
mpiexec = programs.MPIEXEC
pvbatch = programs.program("pvbatch")
failures = []


def run(ranks):
    image = os.path.join(output, "TestReliefParaViewParallel%d.png" % ranks)
    subprocess.run(mpiexec + ["-n", str(ranks), pvbatch, "--force-offscreen-rendering",
                              render, "--plugin", plugin, "--data", data, "--output", image,
                              "--redistribute"], check=True, timeout=300)
    with open(os.path.splitext(image)[0] + ".json") as report:
        facts = json.load(report)
    if facts["messages"]:
        failures.append("%d ranks: messages %s" % (ranks, facts["messages"]))
    return images.load_png(image), facts["ranks_with_cells"]


one, ranks_of_one = run(1)
two, ranks_of_two = run(2)
if ranks_of_two != 2:
    failures.append("the cells lie on %d ranks of 2" % ranks_of_two)
share = images.differing_pixels(one, two, 2)
print("1 against 2 ranks: %.4f%% of the pixels differ by more than 2 levels" % (100 * share))
if share > 0.0005:
    failures.append("2 ranks differ from 1 in %.3f%% of the pixels" % (100 * share))
reference = images.load_png(baseline)
for ranks, image in ((1, one), (2, two)):
    share = images.differing_pixels(image, reference, 8)
    print("%d ranks against the baseline: %.4f%% differ by more than 8" % (ranks, 100 * share))
    if share > 0.001:
        failures.append("%d ranks differ from the baseline in %.3f%%" % (ranks, 100 * share))
for failure in failures:
    print("FAILED:", failure)
sys.exit(1 if failures else 0)
