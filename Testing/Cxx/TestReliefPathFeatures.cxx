// The path-feature showcase at 50 degrees: mortar joints meeting at ends and corners, a
// crack narrowing to nothing across them, a protruding bead bridging nothing (it has no
// priority over the slot it crosses, which cuts through it), an overhanging dovetail
// slot, a ring of quadratic arcs; lit by a scene light with self-shadows.
#include "ReliefPathScene.h"

#include "vtkNew.h"
#include "vtkOpenGLPathFeatureMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestReliefPathFeatures(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  ReliefPathScene::ShowPathFeatures(window, 500, 400, 50.0);
  window->Render();
  return !vtkRegressionTestImage(window);
}
