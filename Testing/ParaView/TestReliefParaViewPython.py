"""The plugin in pvpython (ParaView's built-in session), as a user drives it:

- "Relief Surface" is offered for polygonal and for unstructured data, and its defaults
  are Automatic search, the tangent frame, self-shadowing, a depth of 2% of the data's
  largest extent;
- without a height map: the plain surface, and one warning in ParaView's output window
  that names the property to set;
- with the bricks' maps: the committed baseline, drawn by no plain Surface, and a
  selection in the view passes (ParaView names its id arrays on every representation);
- a height map from a pipeline's image source (a Texture proxy fed by Wavelet);
- the other frames and an exact search draw the relief too, without messages;
- Robust Binary's Safety Radius Tolerance reaches the mapper, and so does Automatic
  Acceleration.

  pvpython TestReliefParaViewPython.py PLUGIN DATA BASELINE OUTPUT_DIR
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import relief_paraview_images as images  # noqa: E402
import relief_paraview_scene as scene  # noqa: E402

from paraview import servermanager  # noqa: E402
from paraview.simple import (CleantoGrid, ClearSelection, Hide, Render,  # noqa: E402
                             SaveScreenshot, SelectSurfaceCells, Show, Wavelet)
from vtkmodules.vtkCommonCore import VTK_STRING, vtkOutputWindow  # noqa: E402
from vtkmodules.util.misc import calldata_type  # noqa: E402

plugin, data, baseline, output = sys.argv[1:5]
failures = []
messages = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAILED:", what, flush=True)


@calldata_type(VTK_STRING)
def record(window, event, text):
    messages.append(text)


for event in ("WarningEvent", "ErrorEvent"):
    vtkOutputWindow.GetInstance().AddObserver(event, record)


def screenshot(view, name):
    path = os.path.join(output, name + ".png")
    SaveScreenshot(path, view, ImageResolution=scene.SIZE)
    return images.load_png(path)


scene.load_plugin(plugin, remote=False)
source, view, display = scene.brick_wall(data)
relief = screenshot(view, "TestReliefParaViewPython")
check(not messages, "the wall draws without messages: %s" % messages)
share = images.differing_pixels(relief, images.load_png(baseline), 8)
print("against the baseline: %.4f%% differ by more than 8" % (100 * share))
check(share <= 0.001, "the wall matches the baseline (%.3f%% differ)" % (100 * share))

# a selection: ParaView's view tells every representation its id arrays around it
SelectSurfaceCells(Rectangle=[100, 100, 300, 250], View=view)
ClearSelection()
Render(view)
check(not messages, "a selection passes without messages: %s" % messages)

display.Representation = "Surface"
Render(view)
plain = screenshot(view, "TestReliefParaViewPythonSurface")
check(images.differing_pixels(relief, plain, 8) > 0.05, "relief is not the textured Surface")

# the types offered, and the defaults, on polygonal and unstructured data
for data_source in (scene.tiled_plane(), CleantoGrid(Input=scene.tiled_plane())):
    shown = Show(data_source, view)
    kind = data_source.GetDataInformation().GetDataSetTypeAsString()
    check("Relief Surface" in shown.GetProperty("Representation").Available,
          "Relief Surface is offered for %s" % kind)
    shown.Representation = "Relief Surface"
    check(abs(shown.ReliefDepthScale - 0.02) < 1e-9,
          "the default depth is 2%% of the extent (%g)" % shown.ReliefDepthScale)
    check(shown.ReliefSearchMethod == "Automatic", "Automatic by default")
    check(shown.ReliefFrame == "Tangent", "the tangent frame by default")
    check(shown.ReliefSelfShadowing == 1, "self-shadowing by default")
    check(shown.ReliefScreenTolerance == 0.5, "half a pixel by default")
    check(shown.ReliefAutomaticAcceleration == "Cone Step", "over cones by default")
    Hide(data_source, view)

# no height map: the plain surface, one warning naming the property
display.Representation = "Relief Surface"
bricks = display.ReliefHeightMap
display.ReliefHeightMap = None
Render(view)
Render(view)
without = screenshot(view, "TestReliefParaViewPythonNoHeightMap")
warnings = [text for text in messages if "No height map" in text]
check(len(warnings) == 1 and "Relief Surface's Height Map" in warnings[0],
      "one warning naming the Height Map (%s)" % messages)
check(images.differing_pixels(without, plain, 8) < 0.001, "without heights, the plain Surface")
messages.clear()

# heights from the pipeline: a Texture proxy whose input is an image source
waves = Wavelet(WholeExtent=[0, 127, 0, 127, 0, 0], Maximum=255.0)
proxies = servermanager.ProxyManager()
heights = servermanager._getPyProxy(proxies.NewProxy("textures", "Texture"))
heights.Input = waves
proxies.RegisterProxy("textures", "wavelet heights", heights.SMProxy)
display.ReliefHeightMap = heights
Render(view)
piped = screenshot(view, "TestReliefParaViewPythonPipeline")
check(not messages, "a pipeline's image is a height map: %s" % messages)
check(images.differing_pixels(piped, plain, 8) > 0.05 and
      images.differing_pixels(piped, relief, 8) > 0.05, "and draws its own relief")

# the other frames, two exact searches: relief near the tangent frame's, no messages
display.ReliefHeightMap = bricks
for setting, value in (("ReliefFrame", "Quadric"), ("ReliefFrame", "Derivative"),
                       ("ReliefSearchMethod", "Exact DDA"),
                       ("ReliefSearchMethod", "Slope Mipmap")):
    default = display.GetPropertyValue(setting)
    display.SetPropertyWithName(setting, value)
    Render(view)
    image = screenshot(view, "TestReliefParaViewPython" + value.replace(" ", ""))
    display.SetPropertyWithName(setting, default)
    near = images.differing_pixels(image, relief, 32)
    print("%s %s: %.3f%% differ from the default by more than 32" % (setting, value, 100 * near))
    check(not messages, "%s %s draws without messages: %s" % (setting, value, messages))
    check(near < 0.05 and images.differing_pixels(image, plain, 8) > 0.05,
          "%s %s draws the relief" % (setting, value))
    messages.clear()

# Robust Binary's error bound: at e = 0 the exact relief; at e = 1 (the whole depth) its
# jumps pass through the bricks, so the picture changes when the value reaches the mapper
display.ReliefSearchMethod = "Robust Binary"
robust = {}
for tolerance in (0.0, 1.0):
    display.ReliefSafetyRadiusTolerance = tolerance
    Render(view)
    robust[tolerance] = screenshot(view, "TestReliefParaViewPythonRobustBinary%g" % tolerance)
display.ReliefSearchMethod = "Automatic"
display.ReliefSafetyRadiusTolerance = 0.0
check(not messages, "Robust Binary draws without messages: %s" % messages)
check(images.differing_pixels(robust[0.0], relief, 32) < 0.05,
      "Robust Binary at e = 0 draws the relief")
loose = images.differing_pixels(robust[1.0], robust[0.0], 8)
print("Robust Binary: %.3f%% of pixels change from e = 0 to e = 1" % (100 * loose))
check(loose > 0.01, "Safety Radius Tolerance reaches the mapper")

# Automatic over the slope pyramid: its hits end elsewhere within the tolerance, which
# moves some pixels (1.0% by more than 8 on this scene drawn by the mapper in VTK), and
# draws the relief
display.ReliefAutomaticAcceleration = "Slope Mipmap"
Render(view)
slopes = screenshot(view, "TestReliefParaViewPythonAutomaticOverSlopes")
display.ReliefAutomaticAcceleration = "Cone Step"
check(not messages, "Automatic over Slope Mipmap draws without messages: %s" % messages)
moved = images.differing_pixels(slopes, relief, 8)
print("Automatic over Slope Mipmap: %.3f%% of pixels differ by more than 8" % (100 * moved))
check(moved > 0.002, "Automatic Acceleration reaches the mapper")
check(images.differing_pixels(slopes, relief, 32) < 0.01, "and draws the relief")

if failures:
    sys.exit(1)
