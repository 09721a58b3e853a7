// Walls and spikes one texel wide (seed 002 Fig. 11) under each search method, at the
// angle given: the fixed-step methods show their misses, the exact ones none.
// Arguments before VTK's test options: the method (as GetSearchMethodAsString names
// it) and the angle from the normal in degrees.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <cstdlib>
#include <iostream>

int TestReliefThinFeatures(int argc, char* argv[])
{
  const int method = argc > 2 ? ReliefScene::SearchMethodNamed(argv[1]) : -1;
  if (method < 0)
  {
    std::cerr << "usage: TestReliefThinFeatures METHOD ANGLE [VTK test options]\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderWindow> window;
  ReliefScene::ShowThinFeatures(window, 400, 300, std::atof(argv[2]), method);
  window->Render();
  return !vtkRegressionTestImage(window);
}
