// Sixteen render windows opened, drawn and closed one after another, each on an X
// connection of its own, as scripts and test suites do. A display server that resets
// when its last client leaves (Xvfb without -noreset) refuses a client that connects
// during the reset, and VTK 9.1 then aborts the process ("bad X server connection").
// ./relief and CI start Xvfb with -noreset; this test guards that. The race itself is
// rare on some machines, so the test first asks the display directly: a property set on
// the root window by the only client must survive that client leaving, which a reset
// clears. The test runs alone (RUN_SERIAL), so that no other test's client keeps the
// display from resetting. Every window draws relief.
#include "ReliefScene.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <X11/Xatom.h>
#include <X11/Xlib.h>

#include <iostream>

namespace
{
constexpr const char* Probe = "VTK_RELIEF_RESET_PROBE";

// Sets the probe on the root window, or reads whether it is still there.
bool Probed(bool set)
{
  Display* display = XOpenDisplay(nullptr);
  if (!display)
  {
    return false;
  }
  const Atom probe = XInternAtom(display, Probe, set ? False : True);
  bool found = false;
  if (set)
  {
    long value = 1;
    XChangeProperty(display, DefaultRootWindow(display), probe, XA_INTEGER, 32, PropModeReplace,
      reinterpret_cast<unsigned char*>(&value), 1);
    XSync(display, False);
  }
  else if (probe != None)
  {
    Atom type;
    int format;
    unsigned long count;
    unsigned long remaining;
    unsigned char* data = nullptr;
    found = XGetWindowProperty(display, DefaultRootWindow(display), probe, 0, 1, True,
              XA_INTEGER, &type, &format, &count, &remaining, &data) == Success &&
      count == 1;
    XFree(data);
  }
  XCloseDisplay(display);
  return found;
}
}

int TestReliefManyWindows(int, char*[])
{
  int failures = 0;
  Probed(true);
  if (!Probed(false))
  {
    std::cerr << "ERROR: the display reset when its last client left: start Xvfb with "
                 "-noreset (xvfb-run -s '-screen 0 1280x1024x24 -noreset'), as ./relief does\n";
    ++failures;
  }

  auto square = ReliefScene::Square(2.0);
  auto heights = ReliefScene::ReadImage("bricks_height.png");
  // each window compiles its shaders (about 1.4 s on llvmpipe): the probe above decides, the
  // windows show that one connection after another keeps drawing
  constexpr int Windows = 16;
  for (int window = 0; window < Windows; ++window)
  {
    vtkNew<vtkRenderWindow> renderWindow;
    renderWindow->SetOffScreenRendering(1);
    auto renderer = ReliefScene::LitRenderer(renderWindow, 64, 48);
    vtkNew<vtkOpenGLReliefMapper> mapper;
    mapper->SetInputData(square);
    mapper->SetHeightMapData(heights);
    mapper->SetDisplayModeToSampleCount(); // red where relief was searched
    renderer->AddActor(ReliefScene::ReliefActor(mapper, ""));
    ReliefScene::ViewSquare(renderer, 30.0);
    renderWindow->Render();
    int relief = 0;
    const std::vector<unsigned char> pixels = ReliefScene::Pixels(renderWindow);
    for (size_t i = 0; i + 2 < pixels.size(); i += 3)
    {
      relief += pixels[i] > 0 && pixels[i + 1] == 0 && pixels[i + 2] == 0 ? 1 : 0;
    }
    if (relief < 500)
    {
      std::cerr << "ERROR: window " << window << " drew " << relief << " relief pixels\n";
      ++failures;
    }
    renderWindow->Finalize(); // closes its X connection
  }
  std::cout << Windows << " windows opened, drawn and closed\n";
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
