// Cobblestones on a coarse torus: the tangent frame follows the curved surface, so the
// stones keep their shape all around and their shadows fall away from the light.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestReliefCurvedMesh(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  ReliefScene::ShowTorus(window, 400, 300);
  window->Render();
  return !vtkRegressionTestImage(window);
}
