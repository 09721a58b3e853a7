// Bricks on a flat square seen 75 degrees away from its normal: self-occlusion,
// per-pixel lighting and self-shadows of the relief must read as real geometry.
#include "ReliefTestScene.h"

#include "vtkActor.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestReliefPlane75(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  auto renderer = ReliefTestScene::LitRenderer(window, 400, 300);
  auto mapper =
    ReliefTestScene::ReliefMapper(ReliefTestScene::Square(2.0), "bricks_height.png", 0.04);
  renderer->AddActor(ReliefTestScene::ReliefActor(mapper, "bricks_color.png"));
  ReliefTestScene::ViewSquare(renderer, 75.0);
  window->Render();
  return !vtkRegressionTestImage(window);
}
