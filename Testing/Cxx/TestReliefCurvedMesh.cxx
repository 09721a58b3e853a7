// Cobblestones on a coarse torus: the tangent frame follows the curved surface, so the
// stones keep their shape all around and their shadows fall away from the light.
#include "ReliefTestScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestReliefCurvedMesh(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  auto renderer = ReliefTestScene::LitRenderer(window, 400, 300);
  auto mapper = ReliefTestScene::ReliefMapper(ReliefTestScene::Torus(), "stones_height.png", 0.03);
  renderer->AddActor(ReliefTestScene::ReliefActor(mapper, "stones_color.png"));
  renderer->GetActiveCamera()->SetPosition(0.0, -1.0, 0.8);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Dolly(1.4);
  renderer->ResetCameraClippingRange();
  window->Render();
  return !vtkRegressionTestImage(window);
}
