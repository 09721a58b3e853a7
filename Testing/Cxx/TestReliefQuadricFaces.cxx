// Which faces of vtkOpenGLQuadricReliefMapper carry relief, with the actors' default
// properties (vtkOpenGLReliefMapper::SetTwoSidedRelief). Against the relief as real
// geometry (silhouette error: 1 is no better than the polygons' outline, 0 is perfect):
// - closed shapes (a coarse sphere and torus) and an open one (a cylinder without caps,
//   its seam on the outline) carve their outlines as well as with back faces culled by
//   hand; so does a closed shape whose back faces the mapper may not cull (a clipping
//   plane could open it), where each back fragment decides for itself;
// - the inside of an open piece of cylinder is drawn as two-sided relief draws it, where
//   culling by hand loses it;
// - a camera inside a closed sphere sees its inside, through a translucent one its far
//   side shows, and a mirrored one is drawn whole;
// - TwoSidedRelief on fills the outlines again, which shows that the views test them.
#include "ReliefMetrics.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkPlane.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <functional>
#include <iostream>
#include <string>

namespace
{
constexpr double DepthScale = 0.05;
int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "ERROR: " << what << "\n";
    ++Failures;
  }
}

enum class Faces
{
  Default,
  CulledByHand,
  Undecided, // a far clipping plane keeps the mapper from culling
  TwoSided
};

struct Scene
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkImageData> Heights;
  vtkSmartPointer<vtkImageData> Relief;
};

ReliefMetrics::Capture Show(Scene& scene, vtkActor* actor)
{
  scene.Renderer->RemoveAllViewProps();
  scene.Renderer->AddActor(actor);
  scene.Window->Render();
  return ReliefScene::Capture(scene.Window, scene.Renderer);
}

vtkSmartPointer<vtkActor> ReliefActor(Scene& scene, vtkPolyData* coarse, Faces faces)
{
  vtkNew<vtkOpenGLQuadricReliefMapper> mapper;
  mapper->SetInputData(coarse);
  mapper->SetHeightMapData(scene.Heights);
  mapper->SetDepthScale(DepthScale);
  mapper->SetSelfShadowing(false);
  mapper->SetLinearSteps(32);
  mapper->SetBinarySteps(6);
  mapper->SetTwoSidedRelief(faces == Faces::TwoSided);
  if (faces == Faces::Undecided)
  {
    vtkNew<vtkPlane> far;
    far->SetOrigin(0.0, 0.0, -100.0);
    far->SetNormal(0.0, 0.0, 1.0);
    mapper->AddClippingPlane(far);
  }
  auto actor = ReliefScene::ReliefActor(mapper, "");
  actor->GetProperty()->SetBackfaceCulling(faces == Faces::CulledByHand);
  return actor;
}

vtkSmartPointer<vtkActor> PlainActor(vtkPolyData* mesh)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  return ReliefScene::ReliefActor(mapper, "");
}

// Silhouette errors of the four face choices on `make`'s shape at `facets`, the truth
// made at 256 facets, seen as `aim` sets the camera.
struct Errors
{
  double Default, CulledByHand, Undecided, TwoSided;
  bool LeftOut; // the default's mapper left out the back faces
};

Errors Measure(Scene& scene, const std::function<vtkSmartPointer<vtkPolyData>(int)>& make,
  int facets, const std::function<void(vtkRenderer*)>& aim, const std::string& name)
{
  auto coarse = make(facets);
  auto truthMesh = ReliefScene::DisplacedMesh(make(256), scene.Relief, DepthScale, 0.5);
  aim(scene.Renderer);
  scene.Renderer->ResetCameraClippingRange(truthMesh->GetBounds());
  const ReliefMetrics::Capture truth = Show(scene, PlainActor(truthMesh));
  const ReliefMetrics::Capture polygons = Show(scene, PlainActor(coarse));
  bool leftOut = false;
  auto error = [&](Faces faces) {
    auto actor = ReliefActor(scene, coarse, faces);
    const ReliefMetrics::Capture capture = Show(scene, actor);
    if (faces == Faces::Default)
    {
      leftOut = static_cast<vtkOpenGLReliefMapper*>(actor->GetMapper())->GetBackFacesLeftOut();
    }
    return ReliefMetrics::SilhouetteError(capture, polygons, truth);
  };
  const Errors errors = { error(Faces::Default), error(Faces::CulledByHand),
    error(Faces::Undecided), error(Faces::TwoSided), leftOut };
  std::cout << name << ": silhouette error by default " << errors.Default
            << ", back faces culled by hand " << errors.CulledByHand << ", undecided "
            << errors.Undecided << ", two-sided " << errors.TwoSided
            << (errors.LeftOut ? "; back faces left out" : "; back faces drawn") << "\n";
  return errors;
}

std::function<void(vtkRenderer*)> From(double azimuth, double elevation, const double frame[6])
{
  return [=](vtkRenderer* renderer) {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, -3.0, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(30.0);
    camera->Azimuth(azimuth);
    camera->Elevation(elevation);
    camera->OrthogonalizeViewUp();
    renderer->ResetCamera(const_cast<double*>(frame));
  };
}

void CarvedOutlines(Scene& scene)
{
  const double sphereFrame[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  const double cylinderFrame[6] = { -0.4, 0.4, -0.4, 0.4, -0.5, 0.5 };
  const double torusFrame[6] = { -0.5, 0.5, -0.15, 0.15, -0.5, 0.5 };
  struct Case
  {
    std::string Name;
    std::function<vtkSmartPointer<vtkPolyData>(int)> Make;
    int Facets;
    std::function<void(vtkRenderer*)> Aim;
    bool Closed; // the mapper leaves out the back faces
  };
  const Case cases[] = {
    { "sphere 24x12", ReliefScene::Sphere, 24, From(35.0, 30.0, sphereFrame), true },
    { "torus 32x16", ReliefScene::Torus, 32, From(70.0, -20.0, torusFrame), true },
    // azimuth 0: the seam of the cylinder lies on its right outline
    { "cylinder without caps, 48 around",
      [](int facets) { return ReliefScene::Cylinder(facets); }, 48,
      From(0.0, 10.0, cylinderFrame), false },
  };
  for (const Case& c : cases)
  {
    const Errors errors = Measure(scene, c.Make, c.Facets, c.Aim, c.Name);
    Check(errors.TwoSided > 0.9, c.Name + ": two-sided relief fills the outline");
    Check(errors.Default < errors.TwoSided - 0.3, c.Name + ": the default carves the outline");
    Check(errors.Default <= errors.CulledByHand + 0.02,
      c.Name + ": the default carves as well as back faces culled by hand");
    Check(errors.Undecided <= errors.CulledByHand + 0.02,
      c.Name + ": back fragments that decide for themselves carve as well");
    Check(errors.LeftOut == c.Closed,
      c.Name + (c.Closed ? ": closed, its back faces left out" : ": open, its back faces drawn"));
  }
}

void InsideOfAnOpenPiece(Scene& scene)
{
  auto piece = [](int facets) { return ReliefScene::Cylinder(facets, 150.0); };
  auto aim = [](vtkRenderer* renderer) {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(-0.8, -2.2, 2.4);
    camera->SetFocalPoint(0.0, 0.25, 0.9);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(35.0);
  };
  const Errors errors = Measure(scene, piece, 32, aim, "inside of an open piece");
  Check(errors.CulledByHand > 2.0, "the view sees the piece's inside, which culling loses");
  Check(errors.Default <= errors.TwoSided + 0.05, "the default draws the inside");
}

void InsideAClosedSphere(Scene& scene)
{
  // from the centre, and from near the wall looking along it, where the back faces are
  // seen at grazing angles: every pixel sees the inside
  auto sphere = ReliefScene::Sphere(24);
  const double views[][3] = { { 0.0, 0.0, 0.0 }, { 0.0, -0.47, 0.0 } };
  for (const auto& eye : views)
  {
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->SetPosition(eye[0], eye[1], eye[2]);
    camera->SetFocalPoint(eye[0] + 1.0, eye[1], eye[2]);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(90.0);
    scene.Renderer->ResetCameraClippingRange(sphere->GetBounds());
    auto actor = ReliefActor(scene, sphere, Faces::Default);
    const ReliefMetrics::Capture inside = Show(scene, actor);
    long covered = 0;
    for (size_t pixel = 0; pixel < inside.EyeDepth.size(); ++pixel)
    {
      covered += inside.Covers(pixel) ? 1 : 0;
    }
    const double coverage = static_cast<double>(covered) / inside.EyeDepth.size();
    std::cout << "inside a closed sphere, from (" << eye[0] << ", " << eye[1] << ", " << eye[2]
              << "): " << coverage << " of the view covered\n";
    Check(coverage > 0.99, "a camera inside a closed sphere sees its inside");
    Check(!static_cast<vtkOpenGLReliefMapper*>(actor->GetMapper())->GetBackFacesLeftOut(),
      "inside a closed sphere its back faces are drawn");
  }
}

void TranslucentShapes(Scene& scene)
{
  // through a translucent closed sphere its far side shows: the mapper draws its back
  // faces, as VTK does, and the image differs from the one with back faces culled by hand
  auto sphere = ReliefScene::Sphere(24);
  const double frame[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
  From(35.0, 30.0, frame)(scene.Renderer);
  scene.Renderer->ResetCameraClippingRange(frame[0], frame[1], frame[2], frame[3], frame[4],
    frame[5]);
  auto translucent = [&](Faces faces) {
    auto actor = ReliefActor(scene, sphere, faces);
    actor->GetProperty()->SetOpacity(0.5);
    return Show(scene, actor).Rgb;
  };
  const std::vector<float> drawn = translucent(Faces::Default);
  const std::vector<float> culled = translucent(Faces::CulledByHand);
  double difference = 0.0;
  for (size_t k = 0; k < drawn.size(); ++k)
  {
    difference += std::abs(drawn[k] - culled[k]);
  }
  difference /= static_cast<double>(drawn.size());
  std::cout << "translucent sphere: mean difference " << difference
            << " from back faces culled by hand\n";
  Check(difference > 0.001, "a translucent closed sphere shows its far side");

  // a mirroring actor turns the windings round: its back faces are not left out, and the
  // sphere (symmetric) covers what it covers unmirrored
  auto covered = [&](bool mirror) {
    auto actor = ReliefActor(scene, sphere, Faces::Default);
    actor->SetScale(mirror ? -1.0 : 1.0, 1.0, 1.0);
    const ReliefMetrics::Capture capture = Show(scene, actor);
    long count = 0;
    for (size_t pixel = 0; pixel < capture.EyeDepth.size(); ++pixel)
    {
      count += capture.Covers(pixel) ? 1 : 0;
    }
    Check(static_cast<vtkOpenGLReliefMapper*>(actor->GetMapper())->GetBackFacesLeftOut() == !mirror,
      mirror ? "a mirrored closed sphere keeps its back faces" : "the sphere's are left out");
    return count;
  };
  const long plain = covered(false);
  const long mirrored = covered(true);
  std::cout << "sphere: " << plain << " pixels covered, mirrored " << mirrored << "\n";
  Check(std::abs(mirrored - plain) < plain / 50, "a mirrored closed sphere is drawn whole");
}
}

int TestReliefQuadricFaces(int, char*[])
{
  Scene scene;
  scene.Window = vtkSmartPointer<vtkRenderWindow>::New();
  scene.Window->SetOffScreenRendering(1);
  scene.Renderer = ReliefScene::LitRenderer(scene.Window, 300, 300);
  scene.Heights = ReliefScene::ResizedHeightMap("stones_height.png", 64);
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputData(scene.Heights);
  relief->Update();
  scene.Relief = relief->GetOutput();

  CarvedOutlines(scene);
  InsideOfAnOpenPiece(scene);
  InsideAClosedSphere(scene);
  TranslucentShapes(scene);
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
