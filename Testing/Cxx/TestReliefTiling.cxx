// Texture coordinates up to 3 repeat the relief and its colour texture: brick courses
// run on across tile borders without seams, and far tiles are mipmapped, not noisy.
#include "ReliefTestScene.h"

#include "vtkActor.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

int TestReliefTiling(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  auto renderer = ReliefTestScene::LitRenderer(window, 400, 300);
  auto mapper = ReliefTestScene::ReliefMapper(ReliefTestScene::Square(3.0), "bricks_height.png", 0.015);
  renderer->AddActor(ReliefTestScene::ReliefActor(mapper, "bricks_color.png"));
  ReliefTestScene::ViewSquare(renderer, 55.0);
  window->Render();
  return !vtkRegressionTestImage(window);
}
