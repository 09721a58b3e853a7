// Shadows with other actors through VTK's shadow-map passes (Oliveira and Policarpo 2005, s3.5,
// Fig. 13): the shadow map is baked with the relief mapper's own shader, so it holds the relief's
// depth. A stone sphere over a plain floor under a spotlight, the flat frame (left) and the quadric
// frame (right): the quadric sphere's shadow has the stones' outline, the flat one the polygons'
// disc. Beside the baseline, the test checks that the quadric shadow is the smaller (light passes
// between the stones at its rim) and that both spheres do cast one; and that relief receives
// shadows: a plain sphere over a floor of rivets darkens the floor only when the shadow passes run.
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <iostream>

namespace
{
constexpr int Width = 800;
constexpr int Height = 400;

// Floor pixels in shadow in the half of the window starting at column `first`: darker
// than a tenth of full grey and not the background.
long ShadowPixels(const std::vector<unsigned char>& pixels, int first)
{
  long count = 0;
  for (int row = 0; row < Height; ++row)
  {
    for (int column = first; column < first + Width / 2; ++column)
    {
      const unsigned char* rgb = &pixels[3 * (static_cast<size_t>(row) * Width + column)];
      count += rgb[0] < 25 && rgb[1] < 25 && rgb[2] < 25 ? 1 : 0;
    }
  }
  return count;
}

// Pixels of a relief floor under a plain sphere that the sphere's shadow darkens: lit
// without the shadow-map passes, less than half as bright with them.
long ReceivedShadowPixels()
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(300, 300);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  ReliefScene::AddSpotlight(renderer);
  auto floor = ReliefScene::Square(2.0);
  auto floorMapper = ReliefScene::ReliefMapper(floor, "rivets_height.png", 0.05);
  renderer->AddActor(ReliefScene::ReliefActor(floorMapper, ""));
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(0.0, 0.0, 0.3);
  ball->SetRadius(0.15);
  vtkNew<vtkPolyDataMapper> ballMapper;
  ballMapper->SetInputConnection(ball->GetOutputPort());
  vtkNew<vtkActor> ballActor;
  ballActor->SetMapper(ballMapper);
  renderer->AddActor(ballActor);
  renderer->GetActiveCamera()->SetPosition(0.0, -1.5, 2.0);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->ResetCameraClippingRange();

  window->Render();
  const std::vector<unsigned char> unshadowed = ReliefScene::Pixels(window);
  ReliefScene::UseShadowMaps(renderer);
  window->Render();
  const std::vector<unsigned char> shadowed = ReliefScene::Pixels(window);
  long count = 0;
  for (size_t k = 0; k + 2 < shadowed.size(); k += 3)
  {
    const int before = unshadowed[k] + unshadowed[k + 1] + unshadowed[k + 2];
    const int after = shadowed[k] + shadowed[k + 1] + shadowed[k + 2];
    count += before > 150 && after < before / 2 ? 1 : 0;
  }
  return count;
}
}

int TestReliefQuadricShadows(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  ReliefScene::ShowQuadricShadows(window, Width, Height);
  window->Render();

  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  const long flatShadow = ShadowPixels(pixels, 0);
  const long quadricShadow = ShadowPixels(pixels, Width / 2);
  std::cout << "shadow pixels: flat frame " << flatShadow << ", quadric frame " << quadricShadow
            << "\n";
  int failures = 0;
  if (!(flatShadow > 5000 && quadricShadow > 5000))
  {
    std::cerr << "ERROR: a relief sphere casts no shadow through the shadow-map passes\n";
    ++failures;
  }
  if (!(quadricShadow < 0.95 * flatShadow))
  {
    std::cerr << "ERROR: the quadric frame's shadow is not carved by its relief\n";
    ++failures;
  }
  const long received = ReceivedShadowPixels();
  std::cout << "relief floor pixels darkened by a plain sphere's shadow: " << received << "\n";
  if (!(received > 1000))
  {
    std::cerr << "ERROR: relief receives no shadow through the shadow-map passes\n";
    ++failures;
  }
  const int image = vtkRegressionTestImage(window);
  return failures == 0 && image == vtkTesting::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
