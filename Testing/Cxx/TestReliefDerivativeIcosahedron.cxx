// icosahedron.ply: twenty faces meeting at 42-degree creases, texture coordinates from a
// spherical projection, no normals. Expected, as Tichenor (2012) reports it: "an object embedded
// in a faceted crystal": each face shows the stones through its own flat frame, and the
// stones break at every edge.
#include "ReliefScene.h"

#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"

int TestReliefDerivativeIcosahedron(int argc, char* argv[])
{
  vtkNew<vtkRenderWindow> window;
  if (!ReliefScene::ShowDerivativeMesh(window, 400, 300, "icosahedron.ply", false))
  {
    return EXIT_FAILURE;
  }
  window->Render();
  return !vtkRegressionTestImage(window);
}
