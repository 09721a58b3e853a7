// Bricks on a flat square seen 45 degrees away from its normal: self-occlusion,
// per-pixel lighting and self-shadows of the relief must read as real geometry.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestReliefPlane45(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  ReliefScene::ShowBricks(window, 400, 300, 45.0);
  window->Render();
  return !vtkRegressionTestImage(window);
}
