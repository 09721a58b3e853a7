// torus.obj without its normals: points and texture coordinates only, as many PLY scans
// and STL exports come. The derivative frame is each face's own (flat shading), and the
// texture tears at the edges, a little at this mesh's creases of 11 and 22 degrees
// (Tichenor's 2012 limit, measured in Documentation/results.md); no normals are computed.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

#include <iostream>

int TestReliefDerivativeNoNormals(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  auto mapper = ReliefScene::ShowDerivativeMesh(window, 400, 300, "torus.obj", false);
  if (!mapper)
  {
    return EXIT_FAILURE;
  }
  window->Render();
  vtkPointData* surface = mapper->GetReliefSurface()->GetPointData();
  if (surface->GetTangents() || surface->GetNormals())
  {
    std::cerr << "ERROR: the derivative mapper computed a frame for a mesh without normals\n";
    return EXIT_FAILURE;
  }
  return !vtkRegressionTestImage(window);
}
