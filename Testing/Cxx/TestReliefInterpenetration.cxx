// A plain sphere sunk deep into a relief wall. With depth correction (left) the bricks
// cut the sphere along their true outline and the sphere shows down in the mortar
// grooves; without it (right) the flat polygon cuts the sphere as a small disc.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestReliefInterpenetration(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  ReliefScene::ShowInterpenetration(window, 500, 250);
  window->Render();
  return !vtkRegressionTestImage(window);
}
