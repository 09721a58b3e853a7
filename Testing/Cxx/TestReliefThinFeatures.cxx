// Walls and spikes one texel wide (Baboud and Decoret 2006, Fig. 11) under each search method, at
// the angle given: the fixed-step methods show their misses, the exact ones none. Arguments before
// VTK's test options: the method (as GetSearchMethodAsString names it) and the angle from the
// normal in degrees; or "Methods N", which checks that the N methods CMake read from
// vtkReliefSearchMethod.cxx, one test each, are all the methods there are.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkReliefSearchMethod.h"
#include "vtkRenderWindow.h"

#include <cstdlib>
#include <iostream>
#include <string>

int TestReliefThinFeatures(int argc, char* argv[])
{
  if (argc > 2 && std::string(argv[1]) == "Methods")
  {
    const int described = vtkReliefSearchMethod::GetNumberOfMethods();
    if (std::atoi(argv[2]) != described)
    {
      std::cerr << "ERROR: CMake found " << argv[2] << " search methods in "
                << "vtkReliefSearchMethod.cxx, which describes " << described
                << "; keep each entry's first line as its pattern in Testing/Cxx/CMakeLists.txt\n";
      return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
  }
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
