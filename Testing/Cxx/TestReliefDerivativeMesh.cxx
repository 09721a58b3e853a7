// Stones on torus.obj as a modeller exports it: texture coordinates and normals, no
// tangents. vtkOpenGLDerivativeReliefMapper builds the frame from screen-space
// derivatives, measuring depth along the interpolated normals: the stones keep their
// shape all around the torus, smoothly shaded, and the surface it draws holds no tangents.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <iostream>

int TestReliefDerivativeMesh(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  auto mapper = ReliefScene::ShowDerivativeMesh(window, 400, 300, "torus.obj", true);
  if (!mapper)
  {
    return EXIT_FAILURE;
  }
  window->Render();
  vtkPointData* surface = mapper->GetReliefSurface()->GetPointData();
  if (surface->GetTangents() || !surface->GetNormals())
  {
    std::cerr << "ERROR: the derivative mapper's surface should keep the file's normals and "
                 "have no tangents\n";
    return EXIT_FAILURE;
  }
  return !vtkRegressionTestImage(window);
}
