"""Runs ReliefBench --quick on the accuracy study (one search method), the stability
sweeps, the quadric, derivative, shading, automatic, impostor, robust and exact-search
studies, and checks what it writes: the results table (every expected row, every figure
a finite number, the truth error-free, the exact search closer to the truth than the
dense mesh and the mesh than the bare polygons), a table per sweep, the quadric and
derivative studies' rows, the automatic study's table and checks, the impostor study's
rows, the robust study's rows and its bound, the exact searches' rows, and every
chart."""
import argparse
import math
import os
import subprocess
import sys

from vtkmodules.vtkIOImage import vtkPNGReader

EXPECTED_ROWS = ["ConeStep", "dense mesh", "coarse polygons", "ground truth"]
FIGURE_COLUMNS = range(2, 13)  # wrong pixels .. GPU MB
CHARTS = ["accuracy_time.png", "accuracy_samples.png", "sweep_angle.png", "sweep_width.png",
          "sweep_curvature.png", "sweep_saddle.png", "sweep_crease.png", "sweep_depth.png",
          "quadric_silhouette_error.png", "derivative_accuracy.png", "derivative_frame_error.png",
          "derivative_seam_colour_crease.png", "derivative_seam_depth_crease.png",
          "derivative_seam_colour_view.png", "derivative_seam_depth_view.png",
          "automatic_samples.png", "automatic_wrong.png", "impostor_cost.png",
          "impostor_error.png"]
QUADRIC_FRAMES = ["flat", "quadric, approximate distance", "quadric, exact distance"]
DERIVATIVE_FRAMES = ["tangent", "derivative"]
SEAM_FRAMES = ["tangent, smooth normals", "tangent, split normals", "derivative, ComputeNormals",
               "derivative, no normals"]
SWEEPS = ["view angle", "wall width", "sphere radius", "k of the saddle", "crease angle",
          "DepthScale"]


def fail(message):
    print("ERROR: " + message)
    sys.exit(1)


def table_rows(text):
    rows = {}
    for line in text.splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if line.startswith("| ") and cells[0] in EXPECTED_ROWS:
            rows[cells[0]] = cells
    return rows


def figure(cell):
    if cell in ("-", ">= 255"):
        return None
    value = float(cell)
    if not math.isfinite(value):
        fail("a figure is not finite: " + cell)
    return value


def check_sweep(text, parameter):
    """The sweep's table: a row per value, each cell "wrong / wrong depth", both shares."""
    lines = text.splitlines()
    header = [i for i, line in enumerate(lines) if line.startswith("| " + parameter)]
    if not header:
        fail("no table for the sweep over " + parameter)
    rows = 0
    for line in lines[header[0] + 2:]:
        if not line.startswith("| "):
            break
        for cell in line.strip().strip("|").split("|")[1:]:
            for value in cell.split("/"):
                number = figure(value.strip())
                if number is None or not number >= 0.0:
                    fail("a share out of range in the sweep over %s: %s" % (parameter, line))
        rows += 1
    if rows < 2:
        fail("the sweep over %s has %d values" % (parameter, rows))


def check_quadric(text):
    """The quadric study: a row per shape, number of facets (quick: one), depth scale (two),
    view (three, and quick one of the torus's inner side) and frame, each figure finite."""
    if "## Curved surfaces" not in text:
        fail("no quadric study in the results")
    rows = [line.split("|")[1:-1] for line in text.splitlines()
            if line.startswith("| ") and line.count("|") == 11
            and line.split("|")[5].strip() in QUADRIC_FRAMES]
    expected = (3 * 3 + 1) * 2 * len(QUADRIC_FRAMES)
    if len(rows) != expected:
        fail("the quadric study has %d rows, not %d" % (len(rows), expected))
    for cells in rows:
        figure(cells[1])
        figure(cells[2])
        figure(cells[5])
        for count in cells[6].split(","):
            figure(count)
        for cell in cells[7:]:
            figure(cell)


def check_derivative(text):
    """The derivative study: accuracy rows per shape, view and frame; seam rows per crease
    (quick: 3) and view (quick: 2, one shared with the crease sweep) and frame; every
    figure finite; the frames agree on the plane."""
    if "## Tangent-free relief" not in text:
        fail("no derivative study in the results")
    lines = [line.split("|")[1:-1] for line in text.splitlines() if line.startswith("| ")]
    accuracy = [cells for cells in lines if len(cells) == 10
                and cells[2].strip() in DERIVATIVE_FRAMES]
    if len(accuracy) != 2 * 3 * 2:
        fail("the derivative study has %d accuracy rows, not 12" % len(accuracy))
    for cells in accuracy:
        for cell in cells[3:]:
            figure(cell.strip())
        if cells[0].strip() == "plane" and cells[2].strip() == "derivative":
            if figure(cells[8].strip()) != 0.0:
                fail("the derivative frame differs from the tangent frame on the plane")
    seams = [cells for cells in lines if len(cells) == 6 and cells[1].strip() in SEAM_FRAMES]
    if len(seams) != (3 + 2) * len(SEAM_FRAMES):
        fail("the derivative study has %d seam rows, not 20" % len(seams))
    for cells in seams:
        for cell in cells[2:]:
            figure(cell.strip())


def read_png(path, what):
    """The image at path, its width and height; fails when there is none."""
    if not os.path.isfile(path):
        fail("no %s at %s" % (what, path))
    reader = vtkPNGReader()
    reader.SetFileName(path)
    reader.Update()
    image = reader.GetOutput()
    width, height, _ = image.GetDimensions()
    return image, width, height


def check_chart(path):
    image, width, height = read_png(path, "chart")
    if (width, height) != (900, 600):
        fail("%s is %dx%d, not 900x600" % (path, width, height))
    low, high = image.GetPointData().GetScalars().GetRange(0)
    if low == high:
        fail(path + " is blank")


def check_quadric_picture(path):
    """The quadric study's picture: four square panels across (the truth, then the
    polygons', flat and quadric frames' coverage), five rows, not blank."""
    image, width, height = read_png(path, "picture")
    if width % 4 or height % 5 or width // 4 != height // 5:
        fail("%s is %dx%d, not 4 by 5 square panels" % (path, width, height))
    low, high = image.GetPointData().GetScalars().GetRange(0)
    if low == high:
        fail(path + " is blank")


def check_shading(text):
    """The printed shading table: a row per map and view, every figure a number, and its
    summary line."""
    if "Up to 80 degrees, the largest luminance bias is" not in text:
        fail("the bench printed no shading summary")
    rows = [line for line in text.splitlines() if line.startswith("| steps |")]
    if len(rows) < 2:
        fail("the shading table has %d rows of the steps map, not 2 or more" % len(rows))
    for row in rows:
        cells = [cell.strip() for cell in row.strip().strip("|").split("|")]
        for cell in cells[1:10]:
            figure(cell)


def check_impostors(text):
    """The impostor study: a row per instance count (quick: 1 and 4), each figure finite,
    the impostor drawn (its silhouette error below the boxes', samples taken)."""
    if "## Relief impostors" not in text:
        fail("no impostor section")
    section = text.split("## Relief impostors", 1)[1].split("### Cost", 1)[0]
    rows = [[cell.strip() for cell in line.strip().strip("|").split("|")]
            for line in section.splitlines() if line.startswith("| a quarter")]
    if [row[1] for row in rows] != ["1", "4"]:
        fail("the impostor table lacks its instance rows: %s" % rows)
    for row in rows:
        for cell in row[3:5] + row[6:9] + row[10:11]:
            figure(cell.rstrip("x%"))
        if not figure(row[6]) < 1.0 or not figure(row[10]) > 0.0:
            fail("the impostor was not drawn: %s" % row)
        # the capture's resolution, chosen by its size on screen, and its bytes
        texels = int(figure(row[11].split("^", 1)[0]))
        if texels not in (64, 128, 256, 512):
            fail("the impostor's automatic resolution is not 64 to 512: %s" % row)
        if not figure(row[12].split(" ", 1)[0]) > 0.0:
            fail("the impostor's textures take no bytes: %s" % row)


def check_robust(text):
    """The robust study (quick: 32^2 and 64^2 at 45 degrees): a row per size and setting,
    every figure finite, samples taken, and SafetyRadius within its bound on every ray."""
    if "## The robust search" not in text:
        fail("no robust search section")
    section = text.split("## The robust search", 1)[1]
    rows = [[cell.strip() for cell in line.strip().strip("|").split("|")]
            for line in section.splitlines() if line.startswith("| ") and "x" in line[:12]]
    rows = [row for row in rows if row[0] in ("32x32", "64x64")]
    methods = {row[2] for row in rows}
    if len(rows) != 18 or methods != {"LinearBinary 10+5", "ExactDDA", "SafetyRadius",
                                       "RobustBinary"}:
        fail("the robust study lacks rows: %s" % rows)
    for row in rows:
        for cell in row[5:8] + row[9:10]:
            figure(cell)
        if not figure(row[5]) > 0.0:
            fail("a robust study row took no samples: %s" % row)
        if row[2] == "SafetyRadius" and row[8] != "0":
            fail("SafetyRadius broke its bound: %s" % row)


def check_exact(text):
    """The exact searches' two tables (quick: 32^2 and 64^2 at 80 degrees; the stones
    resampled to each size, then the same relief at each size): a row per method in each,
    the means finite and positive, and no exact search off the brute-force hit."""
    if "## Exact searches" not in text:
        fail("no exact searches section")
    section = text.split("## Exact searches", 1)[1]
    rows = [[cell.strip() for cell in line.strip().strip("|").split("|")]
            for line in section.splitlines() if line.startswith("| ") and "80" in line]
    methods = [row[0] for row in rows]
    if methods != ["LinearBinary 10+5 (not exact)", "ConeStep", "MaximumMipmap",
                   "SlopeMipmap"] * 2:
        fail("the exact searches' table lacks rows: %s" % methods)
    for row in rows:
        for cell in row[2:5]:
            if not figure(cell) > 0.0:
                fail("an exact searches' row took no samples: %s" % row)
        if row[0] != "LinearBinary 10+5 (not exact)" and row[-1] != "0":
            fail("an exact search missed the brute-force hit: %s" % row)


def check_automatic(text):
    """The automatic study's table for the steps map: a row per setting, each cell
    "wrong % / samples" at each angle, Automatic's rows among them, and its checks."""
    if "## Automatic quality" not in text:
        fail("no automatic quality section")
    section = text.split("## Automatic quality", 1)[1]
    rows = {}
    for line in section.splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if line.startswith("| ") and " / " in line:
            rows[cells[0]] = cells
    for name in ("ConeStep", "LinearBinary 10+5 steps", "**Automatic 0.5 pixels**"):
        if name not in rows:
            fail("the automatic study has no row for " + name)
        for cell in rows[name][1:-1]:
            wrong, samples = (figure(part) for part in cell.split(" / "))
            if not 0.0 <= wrong <= 100.0 or samples <= 0.0:
                fail("an automatic study cell out of range: " + cell)
    if "Pareto:" not in section or "Automatic 0.5 pixels: wrong pixels at most" not in section:
        fail("the automatic study states no checks")


def check_sharing(text):
    """The printed table of many actors on one height map (the --report section): one
    row for one actor and one for several, every figure a number, and several mappers of
    one height map holding the textures of one: they share them."""
    if "Many actors on one" not in text:
        fail("the bench printed no table of many actors")
    section = text.split("Many actors on one", 1)[1]
    rows = {}
    for line in section.splitlines():
        cells = [cell.strip() for cell in line.strip().strip("|").split("|")]
        if line.startswith("| ") and cells[0].isdigit():
            rows[cells[0]] = cells
    if "1" not in rows or "4" not in rows:
        fail("the sharing table lacks the rows for 1 and 4 actors: %s" % sorted(rows))
    for name in ("1", "4"):
        figure(rows[name][1])
        if not rows[name][2].endswith(" MiB"):
            fail("process memory without its unit: " + rows[name][2])
        figure(rows[name][2][:-len(" MiB")])
        for column, what in ((3, "first"), (4, "next")):
            if figure(rows[name][column]) <= 0:
                fail("a %s frame that took no time: %s" % (what, rows[name][column]))
    one = figure(rows["1"][1])
    four = figure(rows["4"][1])
    if one <= 0 or four != one:
        fail("4 actors on one height map hold %s texture bytes, 1 holds %s: not shared"
             % (four, one))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--bench", required=True)
    parser.add_argument("--data", required=True)
    parser.add_argument("--output", required=True)
    arguments = parser.parse_args()
    os.makedirs(arguments.output, exist_ok=True)
    results = os.path.join(arguments.output, "results.md")
    for stale in [results] + [os.path.join(arguments.output, "images", c) for c in CHARTS]:
        if os.path.exists(stale):
            os.remove(stale)
    command = [arguments.bench, "--data", arguments.data, "--quick", "--only",
               "accuracy,sweeps,quadric,derivative,shading,automatic,sharing,impostors,"
               "robust,exact",
               "--method", "cone-step", "--results", results]
    run = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(run.stdout)
    if run.returncode != 0:
        fail("the bench exited with %d" % run.returncode)
    if not os.path.isfile(results):
        fail("no results at " + results)
    with open(results) as file:
        text = file.read()
    if "Machine:" not in text or "VTK" not in text:
        fail("the results do not name the machine and versions")
    rows = table_rows(text.split("## Stability", 1)[0])  # the accuracy table's rows
    for name in EXPECTED_ROWS:
        if name not in rows:
            fail("no row for " + name)
        for column in FIGURE_COLUMNS:
            figure(rows[name][column])
    wrong = {name: figure(rows[name][2]) for name in EXPECTED_ROWS}
    if wrong["ground truth"] != 0.0:
        fail("the ground truth differs from itself")
    if not wrong["ConeStep"] < wrong["dense mesh"] < wrong["coarse polygons"]:
        fail("wrong pixels out of order: an exact search should beat the dense mesh of "
             "equal detail, and the mesh the bare polygons: %s" % wrong)
    for sweep in SWEEPS:
        check_sweep(text, sweep)
    check_quadric(text)
    check_derivative(text)
    for chart in CHARTS:
        check_chart(os.path.join(arguments.output, "images", chart))
    check_quadric_picture(os.path.join(arguments.output, "images", "quadric_outlines.png"))
    check_shading(run.stdout)
    check_automatic(text)
    check_impostors(text)
    check_robust(text)
    check_exact(text)
    check_sharing(run.stdout)
    print("bench smoke run: results and charts well formed")


if __name__ == "__main__":
    main()
