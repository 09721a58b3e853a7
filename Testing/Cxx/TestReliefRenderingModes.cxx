// Relief under VTK's other rendering modes, each compared with a rendering that must
// look the same: a back face against the same square reversed and seen from the front,
// edges on against edges off (also on the quadric mapper's hull), and scalars coloured through a texture against VTK's own
// mapper.
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkReverseSense.h"

#include <cstdlib>
#include <iostream>
#include <vector>

namespace
{
vtkRenderWindow* Window = nullptr;

std::vector<unsigned char> Render(vtkActor* actor, const double cameraPosition[3], bool light)
{
  Window->GetRenderers()->RemoveAllItems();
  auto renderer = ReliefScene::LitRenderer(Window, 160, 160);
  if (light)
  {
    vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0))->SetPosition(1.0, 1.0, -1.0);
  }
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(cameraPosition[0], cameraPosition[1], cameraPosition[2]);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera();
  Window->Render();
  return ReliefScene::Pixels(Window);
}

// Fraction of pixels whose colours differ by more than `tolerance` (summed over RGB).
double Differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b,
  int tolerance)
{
  int differing = 0;
  for (size_t i = 0; i + 2 < a.size(); i += 3)
  {
    const int difference =
      std::abs(a[i] - b[i]) + std::abs(a[i + 1] - b[i + 1]) + std::abs(a[i + 2] - b[i + 2]);
    differing += difference > tolerance ? 1 : 0;
  }
  return static_cast<double>(differing) / (a.size() / 3);
}

// Fraction of pixels that one image covers and the other leaves to the background (the
// renderer's 0.1 0.12 0.16).
double CoverageDiffering(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  auto background = [](const std::vector<unsigned char>& image, size_t i) {
    return std::abs(image[i] - 26) <= 1 && std::abs(image[i + 1] - 31) <= 1 &&
      std::abs(image[i + 2] - 41) <= 1;
  };
  int differing = 0;
  for (size_t i = 0; i + 2 < a.size(); i += 3)
  {
    differing += background(a, i) != background(b, i) ? 1 : 0;
  }
  return static_cast<double>(differing) / (a.size() / 3);
}

vtkSmartPointer<vtkActor> BricksActor(vtkPolyData* surface, double depthScale)
{
  auto mapper = ReliefScene::ReliefMapper(surface, "bricks_height.png", depthScale);
  mapper->SetSelfShadowing(false);
  return ReliefScene::ReliefActor(mapper, "");
}

int failures = 0;
void Check(bool condition, const char* what, double measured)
{
  std::cout << what << ": " << measured << "\n";
  if (!condition)
  {
    std::cerr << "Rendering mode check failed: " << what << "\n";
    ++failures;
  }
}
}

int TestReliefRenderingModes(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  Window = window;

  // The back of a square is relief carved into its back: exactly the front of the
  // same square with its cells and normals reversed.
  const double behind[3] = { 0.3, 0.6, -1.2 };
  auto square = ReliefScene::Square(1.0);
  const auto back = Render(BricksActor(square, 0.08), behind, true);
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputData(square);
  reverse->ReverseCellsOn();
  reverse->ReverseNormalsOn();
  reverse->Update();
  const auto reversedFront = Render(BricksActor(reverse->GetOutput(), 0.08), behind, true);
  Check(Differing(back, reversedFront, 30) < 0.01,
    "back face against the reversed square, fraction of pixels differing",
    Differing(back, reversedFront, 30));

  // Edges add their lines through a geometry shader; the relief around them must stay.
  const double front[3] = { 0.0, -0.6, 1.0 };
  auto withoutEdges = BricksActor(square, 0.05);
  const auto plainEdges = Render(withoutEdges, front, false);
  auto withEdges = BricksActor(square, 0.05);
  withEdges->GetProperty()->EdgeVisibilityOn();
  withEdges->GetProperty()->SetEdgeColor(1.0, 1.0, 0.0);
  const auto shownEdges = Render(withEdges, front, false);
  Check(Differing(plainEdges, shownEdges, 60) < 0.06,
    "edges on against edges off, fraction of pixels differing",
    Differing(plainEdges, shownEdges, 60));

  // The quadric mapper's hull takes VTK's edges geometry shader as it takes its own, the
  // outline included: the coarse sphere's relief and outline stay with edges on.
  auto quadricActor = [](bool edges) {
    vtkNew<vtkOpenGLQuadricReliefMapper> mapper;
    mapper->SetInputData(ReliefScene::Sphere(24));
    mapper->SetHeightMapData(ReliefScene::ReadImage("bricks_height.png"));
    mapper->SetDepthScale(0.005);
    auto actor = ReliefScene::ReliefActor(mapper, "");
    actor->GetProperty()->SetEdgeVisibility(edges);
    actor->GetProperty()->SetEdgeColor(1.0, 1.0, 0.0);
    return actor;
  };
  // (a coarse sphere's edges tint a good part of its pixels: compare what is covered)
  const auto sphereWithoutEdges = Render(quadricActor(false), front, false);
  const auto sphereWithEdges = Render(quadricActor(true), front, false);
  Check(CoverageDiffering(sphereWithoutEdges, sphereWithEdges) < 0.002,
    "quadric relief, edges on against edges off, fraction of pixels covered by one only",
    CoverageDiffering(sphereWithoutEdges, sphereWithEdges));

  // Scalars mapped through a colour texture keep their colour on relief.
  auto colored = ReliefScene::Square(1.0);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetName("Scalars");
  scalars->SetNumberOfTuples(colored->GetNumberOfPoints());
  scalars->Fill(0.0);
  colored->GetPointData()->SetScalars(scalars);
  auto scalarActor = [&](vtkMapper* mapper) {
    mapper->SetScalarRange(0.0, 1.0);
    mapper->InterpolateScalarsBeforeMappingOn();
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    actor->GetProperty()->SetAmbient(1.0);
    actor->GetProperty()->SetDiffuse(0.0);
    actor->GetProperty()->SetSpecular(0.0);
    return actor;
  };
  vtkNew<vtkPolyDataMapper> plainMapper;
  plainMapper->SetInputData(colored);
  auto reliefMapper = ReliefScene::ReliefMapper(colored, "bricks_height.png", 0.05);
  const double above[3] = { 0.0, 0.0, 1.0 };
  const auto plainColors = Render(scalarActor(plainMapper), above, false);
  const auto reliefColors = Render(scalarActor(reliefMapper), above, false);
  Check(Differing(plainColors, reliefColors, 6) < 0.01,
    "scalar colours on relief against VTK's mapper, fraction of pixels differing",
    Differing(plainColors, reliefColors, 6));
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
