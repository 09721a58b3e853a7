// vtkOpenGLReliefImpostorMapper's bad input (issue 19 item 5), each case drawn three
// times: one clear message, said once, and sane pixels: an empty mesh (nothing drawn), a
// flat mesh (its box thickened, the impostor drawn), a mesh without colour (in the
// actor's colour, as VTK's mapper draws it, and nothing said), invalid frustum
// parameters and resolutions (the mesh drawn instead), a search method that cannot
// search an impostor, out-of-range steps, and a camera inside the box (seen
// from inside; with ConservativeDepth, true depth instead, said once); and a wireframe
// representation, which draws the mesh's edges.
#include "ReliefEventRecorder.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefImpostorMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkProperty.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkReliefImpostorFilter.h"
#include "vtkSphereSource.h"

#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

namespace
{
constexpr int Size = 120;

struct Outcome
{
  long Covered = 0;     // pixels not of the background
  double Brightness = 0.0; // their mean, 0 to 1
  bool Drawn = false;   // the impostor, not the mesh
};

struct Case
{
  const char* Name;
  vtkSmartPointer<vtkPolyData> Mesh;
  std::function<void(vtkOpenGLReliefImpostorMapper*, vtkCamera*, vtkActor*)> Setup;
  const char* Message; // said once, or null: nothing said
  std::function<bool(const Outcome&)> Sane;
};

Outcome Draw(const Case& test, ReliefEventRecorder* recorder)
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Size, Size);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.2, 0.3, 0.4);
  window->AddRenderer(renderer);
  vtkNew<vtkOpenGLReliefImpostorMapper> mapper;
  mapper->AddObserver(vtkCommand::ErrorEvent, recorder);
  mapper->AddObserver(vtkCommand::WarningEvent, recorder);
  mapper->SetInputData(test.Mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(1.0, -2.0, 1.5);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  test.Setup(mapper, camera, actor);
  renderer->ResetCameraClippingRange();
  for (int frame = 0; frame < 3; ++frame)
  {
    window->Render();
  }
  Outcome outcome;
  outcome.Drawn = mapper->GetDrawingImpostor();
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  double sum = 0.0;
  for (size_t k = 0; k + 2 < pixels.size(); k += 3)
  {
    const bool background = std::abs(pixels[k] - 51) <= 1 && std::abs(pixels[k + 1] - 77) <= 1 &&
      std::abs(pixels[k + 2] - 102) <= 1;
    if (!background)
    {
      ++outcome.Covered;
      sum += (pixels[k] + pixels[k + 1] + pixels[k + 2]) / (3.0 * 255.0);
    }
  }
  outcome.Brightness = outcome.Covered ? sum / outcome.Covered : 0.0;
  return outcome;
}

// The camera in a corner of the impostor's box, outside the object, looking at its middle.
void LookFromACorner(vtkOpenGLReliefImpostorMapper* mapper, vtkCamera* camera)
{
  const double* box = mapper->GetBounds();
  camera->SetPosition(box[0] + 0.05 * (box[1] - box[0]), box[2] + 0.05 * (box[3] - box[2]),
    box[5] - 0.05 * (box[5] - box[4]));
  camera->SetFocalPoint(0.0, 0.0, 0.0);
}

vtkSmartPointer<vtkPolyData> Source(vtkPolyDataAlgorithm* source)
{
  source->Update();
  return source->GetOutput();
}
}

int TestReliefImpostorBadInput(int, char*[])
{
  vtkSmartPointer<vtkPolyData> object = ReliefScene::ImpostorObject(32);
  vtkNew<vtkSphereSource> sphereSource;
  vtkSmartPointer<vtkPolyData> sphere = Source(sphereSource); // no scalars
  vtkNew<vtkPlaneSource> planeSource;
  planeSource->SetResolution(4, 4);
  vtkSmartPointer<vtkPolyData> plane = Source(planeSource);
  vtkNew<vtkPolyData> empty;
  auto nothing = [](vtkOpenGLReliefImpostorMapper*, vtkCamera*, vtkActor*) {};
  auto drawn = [](const Outcome& o) { return o.Drawn && o.Covered > 1500 && o.Brightness > 0.1; };
  auto meshDrawn = [](const Outcome& o) { return !o.Drawn && o.Covered > 1500; };
  const std::vector<Case> cases = {
    { "EmptyMesh", empty, nothing, "mesh is empty",
      [](const Outcome& o) { return !o.Drawn && o.Covered == 0; } },
    { "FlatMesh",
      plane,
      [](vtkOpenGLReliefImpostorMapper* mapper, vtkCamera*, vtkActor*) {
        mapper->GetImpostorFilter()->SetPadding(0.0); // a box of zero thickness
      },
      "flat along z", drawn },
    // as VTK's mapper draws it: in the actor's colour (white), and nothing said
    { "NoColour", sphere, nothing, nullptr,
      [](const Outcome& o) { return o.Drawn && o.Covered > 1500 && o.Brightness > 0.4; } },
    { "ApexDistance",
      object,
      [](vtkOpenGLReliefImpostorMapper* mapper, vtkCamera*, vtkActor*) {
        mapper->GetImpostorFilter()->SetProjectionToReversePerspective();
        mapper->GetImpostorFilter()->SetApexDistance(0.5);
      },
      "The mesh itself is drawn", meshDrawn },
    { "ZeroResolution",
      object,
      [](vtkOpenGLReliefImpostorMapper* mapper, vtkCamera*, vtkActor*) {
        mapper->GetImpostorFilter()->SetDepthResolution(0);
      },
      "The mesh itself is drawn", meshDrawn },
    { "ConeStep",
      object,
      [](vtkOpenGLReliefImpostorMapper* mapper, vtkCamera*, vtkActor*) {
        mapper->SetSearchMethod(vtkOpenGLReliefMapper::CONE_STEP);
      },
      "cannot search an impostor", drawn },
    { "LinearSteps",
      object,
      [](vtkOpenGLReliefImpostorMapper* mapper, vtkCamera*, vtkActor*) {
        mapper->SetSearchMethod(vtkOpenGLReliefMapper::LINEAR_BINARY);
        mapper->SetLinearSteps(1000000);
      },
      "out of [1, 4096]", drawn },
    { "CameraInside",
      object,
      [](vtkOpenGLReliefImpostorMapper* mapper, vtkCamera* camera, vtkActor*) {
        LookFromACorner(mapper, camera);
      },
      nullptr, drawn },
    { "CameraInsideConservative",
      object,
      [](vtkOpenGLReliefImpostorMapper* mapper, vtkCamera* camera, vtkActor*) {
        mapper->ConservativeDepthOn();
        LookFromACorner(mapper, camera);
      },
      "camera is inside", drawn },
    // not bad input, but not the impostor's either: the mesh's wireframe, as VTK draws it
    { "Wireframe",
      object,
      [](vtkOpenGLReliefImpostorMapper*, vtkCamera*, vtkActor* actor) {
        actor->GetProperty()->SetRepresentationToWireframe();
      },
      nullptr, [](const Outcome& o) { return !o.Drawn && o.Covered > 500; } },
  };
  int failures = 0;
  for (const Case& test : cases)
  {
    vtkNew<ReliefEventRecorder> recorder;
    const Outcome outcome = Draw(test, recorder);
    int said = 0;
    for (const std::string& message : recorder->Messages)
    {
      said += test.Message && message.find(test.Message) != std::string::npos ? 1 : 0;
    }
    const bool messageRight = test.Message ? said == 1 : recorder->Messages.empty();
    const bool pixelsRight = test.Sane(outcome);
    std::cout << test.Name << ": " << outcome.Covered << " pixels covered, brightness "
              << outcome.Brightness << (outcome.Drawn ? ", impostor" : ", no impostor") << "; "
              << recorder->Messages.size() << " messages\n";
    for (const std::string& message : recorder->Messages)
    {
      std::cout << "  " << message;
    }
    if (!messageRight || !pixelsRight)
    {
      std::cerr << test.Name << ": " << (messageRight ? "" : "the message is not said once; ")
                << (pixelsRight ? "" : "the pixels are not sane") << "\n";
      ++failures;
    }
  }
  return failures == 0 ? 0 : 1;
}
