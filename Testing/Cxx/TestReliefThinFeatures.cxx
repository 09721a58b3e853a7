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
#include <cstring>
#include <iostream>

int TestReliefThinFeatures(int argc, char* argv[])
{
  int method = -1;
  for (int candidate = 0; argc > 2 && candidate < 16; ++candidate)
  {
    const char* name = vtkOpenGLReliefMapper::GetSearchMethodAsString(candidate);
    method = name && std::strcmp(name, argv[1]) == 0 ? candidate : method;
  }
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
