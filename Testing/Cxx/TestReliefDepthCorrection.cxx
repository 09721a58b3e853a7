// Depth correction, checked against geometry: relief whose every texel is at depth 1
// must fill the z-buffer exactly as a plain square moved DepthScale below the polygon,
// in perspective and parallel projection, for an actor that is scaled and rotated.
// Without depth correction the two must differ, so the check can fail.
#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkWindowToImageFilter.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
constexpr double DepthScale = 0.1;
constexpr int Size = 100;

enum class Surface
{
  Relief,
  ReliefWithoutCorrection,
  PlaneBelow
};

std::vector<float> DepthBuffer(vtkRenderWindow* window, Surface surface, bool parallel)
{
  vtkNew<vtkPlaneSource> square;
  square->SetOrigin(-0.5, -0.5, 0.0);
  square->SetPoint1(0.5, -0.5, 0.0);
  square->SetPoint2(-0.5, 0.5, 0.0);
  vtkNew<vtkActor> actor;
  actor->SetScale(2.0, 0.5, 3.0);
  actor->RotateX(30.0);
  actor->RotateZ(20.0);
  vtkNew<vtkImageData> deepest; // 8-bit zeros: height 0 everywhere, depth 1
  deepest->SetDimensions(64, 64, 1);
  deepest->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  deepest->GetPointData()->GetScalars()->Fill(0.0);
  vtkNew<vtkOpenGLReliefMapper> relief;
  vtkNew<vtkPolyDataMapper> plain;
  if (surface == Surface::PlaneBelow)
  {
    // DepthScale is in world units; the actor scales model z by 3
    square->SetCenter(0.0, 0.0, -DepthScale / 3.0);
    plain->SetInputConnection(square->GetOutputPort());
    actor->SetMapper(plain);
  }
  else
  {
    relief->SetInputConnection(square->GetOutputPort());
    relief->SetHeightMapData(deepest);
    relief->SetDepthScale(DepthScale);
    relief->SetDepthCorrection(surface == Surface::Relief);
    actor->SetMapper(relief);
  }

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 0.0, 2.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->Elevation(35.0);
  camera->Azimuth(20.0);
  camera->SetParallelProjection(parallel);
  camera->SetParallelScale(0.6);
  camera->SetViewAngle(20.0);
  camera->SetClippingRange(0.5, 4.0);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToZBuffer();
  capture->Update();
  vtkDataArray* depths = capture->GetOutput()->GetPointData()->GetScalars();
  std::vector<float> buffer(depths->GetNumberOfTuples());
  for (vtkIdType i = 0; i < depths->GetNumberOfTuples(); ++i)
  {
    buffer[i] = static_cast<float>(depths->GetComponent(i, 0));
  }
  return buffer;
}

// Largest z-buffer difference over pixels both surfaces cover, and how many there are.
std::pair<double, int> Difference(const std::vector<float>& a, const std::vector<float>& b)
{
  double largest = 0.0;
  int covered = 0;
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (a[i] < 1.0f && b[i] < 1.0f)
    {
      largest = std::max(largest, std::abs(static_cast<double>(a[i]) - b[i]));
      ++covered;
    }
  }
  return { largest, covered };
}
}

int TestReliefDepthCorrection(int, char*[])
{
  // one window for all renders: opening many X connections in a row is itself flaky
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Size, Size);
  window->SetMultiSamples(0);
  int failures = 0;
  for (bool parallel : { false, true })
  {
    const std::vector<float> plane = DepthBuffer(window, Surface::PlaneBelow, parallel);
    const auto corrected = Difference(DepthBuffer(window, Surface::Relief, parallel), plane);
    const auto uncorrected =
      Difference(DepthBuffer(window, Surface::ReliefWithoutCorrection, parallel), plane);
    std::cout << (parallel ? "parallel" : "perspective") << ": max |z relief - z plane| "
              << corrected.first << " over " << corrected.second << " pixels; without correction "
              << uncorrected.first << "\n";
    // LinearBinary 10+5 puts the hit within 1/320 of depth 1: far below 1e-3 in z
    if (corrected.second < Size * Size / 10 || corrected.first > 1e-3 ||
      uncorrected.first < 5e-3)
    {
      std::cerr << "Depth correction check failed\n";
      ++failures;
    }
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
