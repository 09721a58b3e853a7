// Relief on a flat square seen at 45 degrees: self-occlusion, lighting and shadows of
// the brick wall must look like real geometry.
#include "ReliefTestScene.h"

#include "vtkActor.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestReliefPlane45(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  auto renderer = ReliefTestScene::LitRenderer(window, 400, 300);
  auto mapper = ReliefTestScene::ReliefMapper(ReliefTestScene::Square(2.0), "bricks_height.png", 0.04);
  renderer->AddActor(ReliefTestScene::ReliefActor(mapper, "bricks_color.png"));
  ReliefTestScene::ViewSquare(renderer, 45.0);
  window->Render();
  int result = vtkRegressionTestImage(window);
  return !result;
}
