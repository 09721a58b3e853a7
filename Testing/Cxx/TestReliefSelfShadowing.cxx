// The same rivets under a low light, self-shadowing on (left) and off (right): only the
// left half may show the rivets' shadows on the plate and in the scratch.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestReliefSelfShadowing(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  ReliefScene::ShowSelfShadowing(window, 500, 250);
  window->Render();
  return !vtkRegressionTestImage(window);
}
