// The same rivets under a low light, self-shadowing on (left) and off (right): only the
// left half may show the rivets' shadows on the plate and in the scratch.
#include "ReliefTestScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestReliefSelfShadowing(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  for (bool shadows : { true, false })
  {
    auto renderer = ReliefTestScene::LitRenderer(window, 500, 250);
    renderer->SetViewport(shadows ? 0.0 : 0.5, 0.0, shadows ? 0.5 : 1.0, 1.0);
    vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
    light->SetPosition(-1.0, 0.4, 0.35); // low, so shadows are long
    auto mapper =
      ReliefTestScene::ReliefMapper(ReliefTestScene::Square(1.0), "rivets_height.png", 0.08);
    mapper->SetSelfShadowing(shadows);
    mapper->SetLinearSteps(32);
    renderer->AddActor(ReliefTestScene::ReliefActor(mapper, ""));
    ReliefTestScene::ViewSquare(renderer, 20.0);
  }
  window->Render();
  return !vtkRegressionTestImage(window);
}
