// Texture coordinates up to 3 repeat the relief and its colour texture: brick courses
// run on across tile borders without seams, and far tiles are mipmapped, not noisy.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestReliefTiling(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  ReliefScene::ShowBricks(window, 400, 300, 55.0, 3.0, 0.015);
  window->Render();
  return !vtkRegressionTestImage(window);
}
