// Path features cut into a relief base (vtkReliefPathOnRelief.glsl): a saw cut and a
// crack through the bricks of bricks_height.png, a steel rod across them casting its
// shadow on them, at 50 degrees, lit by a scene light with self-shadows.
#include "ReliefPathScene.h"

#include "vtkNew.h"
#include "vtkOpenGLPathFeatureMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <iostream>

int TestReliefPathFeaturesOnRelief(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  auto mapper = ReliefPathScene::ShowPathFeaturesOnRelief(window, 500, 400, 50.0);
  window->Render();
  if (!mapper->GetDrawingReliefBase())
  {
    std::cerr << "ERROR: the height map was not drawn as the features' base\n";
    return EXIT_FAILURE;
  }
  return !vtkRegressionTestImage(window);
}
