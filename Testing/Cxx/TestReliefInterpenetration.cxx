// A plain sphere sunk deep into a relief wall. With depth correction (left) the bricks
// cut the sphere along their true outline and the sphere shows down in the mortar
// grooves; without it (right) the flat polygon cuts the sphere as a small disc.
#include "ReliefTestScene.h"

#include "vtkActor.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"

int TestReliefInterpenetration(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.0, 0.0, -0.12);
  sphere->SetRadius(0.15);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  for (bool correction : { true, false })
  {
    auto renderer = ReliefTestScene::LitRenderer(window, 500, 250);
    renderer->SetViewport(correction ? 0.0 : 0.5, 0.0, correction ? 0.5 : 1.0, 1.0);
    auto mapper =
      ReliefTestScene::ReliefMapper(ReliefTestScene::Square(1.0), "bricks_height.png", 0.15);
    mapper->SetLinearSteps(24);
    mapper->SetDepthCorrection(correction);
    renderer->AddActor(ReliefTestScene::ReliefActor(mapper, "bricks_color.png"));
    vtkNew<vtkActor> ball;
    ball->SetMapper(sphereMapper);
    ball->GetProperty()->SetColor(0.3, 0.6, 0.95);
    renderer->AddActor(ball);
    ReliefTestScene::ViewSquare(renderer, 50.0);
  }
  window->Render();
  return !vtkRegressionTestImage(window);
}
