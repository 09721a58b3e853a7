// The README's C++ example: bricks on a torus, written to relief_hello.png.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkOpenImageIOReader.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSuperquadricSource.h"
#include "vtkWindowToImageFilter.h"

#include <string>

int main(int argc, char* argv[])
{
  const std::string data = argc > 1 ? argv[1] : "Data";
  vtkNew<vtkSuperquadricSource> surface; // has normals and texture coordinates
  surface->ToroidalOn();
  vtkNew<vtkOpenImageIOReader> heights;
  heights->SetFileName((data + "/bricks_height.png").c_str()); // white = high
  vtkNew<vtkOpenGLReliefMapper> mapper;
  mapper->SetInputConnection(surface->GetOutputPort());
  mapper->SetHeightMapConnection(heights->GetOutputPort());
  mapper->SetDepthScale(0.05); // world units at depth 1
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->GetActiveCamera()->Elevation(50.0);
  renderer->ResetCamera();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(capture->GetOutputPort());
  writer->SetFileName("relief_hello.png");
  writer->Write();
  return 0;
}
