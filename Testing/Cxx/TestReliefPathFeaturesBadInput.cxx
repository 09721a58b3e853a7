// Bad path-feature input given to vtkOpenGLPathFeatureMapper: each case gets its message
// (the filter's, through the mapper's observers), once over two renders, and sane pixels
// (the scene lights every covered pixel: none black, every depth finite), with the
// features that are valid still cut in and the plain surface where none is.
#include "ReliefEventRecorder.h"
#include "ReliefPathFixtures.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLPathFeatureMapper.h"
#include "vtkOpenGLQuadricPathFeatureMapper.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
using namespace ReliefPathFixtures;

int Failures = 0;
void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "ERROR: path-feature bad input check failed: " << what << "\n";
    ++Failures;
  }
}

struct Census
{
  int Covered = 0;
  int Black = 0;
  int BadDepth = 0;
  int Cut = 0; // covered pixels deeper than the polygon: a feature drawn
  int Errors = 0;
  int Warnings = 0;
  vtkSmartPointer<ReliefEventRecorder> Messages;

  bool Says(const std::string& text) const { return this->Messages->AnyMessageContains(text); }
};

// Renders the unit square with `mapper` from straight above, twice.
Census Render(vtkRenderWindow* window, vtkOpenGLPathFeatureMapper* mapper)
{
  auto recorder = vtkSmartPointer<ReliefEventRecorder>::New();
  mapper->AddObserver(vtkCommand::ErrorEvent, recorder);
  mapper->AddObserver(vtkCommand::WarningEvent, recorder);
  mapper->SetInputData(ReliefScene::Square(1.0));
  mapper->SetDepthScale(0.05);
  window->GetRenderers()->RemoveAllItems();
  auto renderer = ReliefScene::LitRenderer(window, 160, 160);
  renderer->SetBackground(0.0, 0.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.0, 1.0, 0.0);
  actor->GetProperty()->SetAmbient(0.3);
  renderer->AddActor(actor);
  ReliefScene::ViewSquare(renderer, 0.0);
  window->Render();
  window->Render();
  const ReliefMetrics::Capture shaded = ReliefScene::Capture(window, renderer);
  Census census;
  auto background = [&](size_t pixel) {
    const float* rgb = &shaded.Rgb[3 * pixel];
    return rgb[2] == 1.0f && rgb[0] == 0.0f && rgb[1] == 0.0f;
  };
  double nearest = 1e30;
  for (size_t pixel = 0; pixel < shaded.EyeDepth.size(); ++pixel)
  {
    if (!background(pixel) && std::isfinite(shaded.EyeDepth[pixel]))
    {
      nearest = std::min(nearest, static_cast<double>(shaded.EyeDepth[pixel]));
    }
  }
  for (size_t pixel = 0; pixel < shaded.EyeDepth.size(); ++pixel)
  {
    if (background(pixel))
    {
      continue;
    }
    const float* rgb = &shaded.Rgb[3 * pixel];
    ++census.Covered;
    census.Black += rgb[0] == 0.0f && rgb[1] == 0.0f && rgb[2] == 0.0f ? 1 : 0;
    census.BadDepth += std::isfinite(shaded.EyeDepth[pixel]) ? 0 : 1;
    // deeper than the plain surface by a tenth of the depth scale
    census.Cut += shaded.EyeDepth[pixel] > nearest + 0.005 ? 1 : 0;
  }
  census.Errors = recorder->Count(vtkCommand::ErrorEvent);
  census.Warnings = recorder->Count(vtkCommand::WarningEvent);
  census.Messages = recorder;
  std::cout << "covered " << census.Covered << " (black " << census.Black << ", bad depth "
            << census.BadDepth << ", cut " << census.Cut << "); errors " << census.Errors
            << ", warnings " << census.Warnings << "\n";
  for (const std::string& message : recorder->Messages)
  {
    std::cout << "  said: " << message;
  }
  return census;
}

void CheckSane(const Census& census, const std::string& what)
{
  Check(census.Covered > 10000, what + ": the square is drawn");
  Check(census.Black == 0 && census.BadDepth == 0, what + ": no black pixel, no bad depth");
}

// A groove along v = 0.5 that is valid, beside the bad paths.
PathSpec ValidGroove()
{
  return { { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1 };
}

vtkSmartPointer<vtkOpenGLPathFeatureMapper> MapperOf(const std::vector<PathSpec>& paths)
{
  auto mapper = vtkSmartPointer<vtkOpenGLPathFeatureMapper>::New();
  mapper->SetPathsData(PathsData(paths));
  return mapper;
}

void CheckOneMessage(vtkRenderWindow* window, const std::vector<PathSpec>& paths,
  unsigned long event, const std::string& text, const std::string& what)
{
  const Census census = Render(window, MapperOf(paths));
  const int count = event == vtkCommand::ErrorEvent ? census.Errors : census.Warnings;
  Check(census.Errors + census.Warnings == 1 && count == 1 && census.Says(text),
    what + ": one message that says \"" + text + "\"");
  Check(census.Cut > 500, what + ": the valid groove is cut in");
  CheckSane(census, what);
}
}

int TestReliefPathFeaturesBadInput(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);

  // no paths at all, and an empty set: the plain surface, nothing to say
  for (bool connected : { false, true })
  {
    auto mapper = vtkSmartPointer<vtkOpenGLPathFeatureMapper>::New();
    if (connected)
    {
      mapper->SetPathsData(PathsData({}));
    }
    const Census census = Render(window, mapper);
    Check(census.Errors == 0 && census.Warnings == 0, "no features: nothing to report");
    Check(census.Cut == 0, "no features: the plain surface");
    CheckSane(census, "no features");
  }

  const PathSpec groove = ValidGroove();
  CheckOneMessage(window, { groove, { { { 0.1, 0.2 }, { 0.9, 0.2 } }, 0.0 } },
    vtkCommand::WarningEvent, "\"Width\"", "a zero width");
  CheckOneMessage(window, { groove, { { { 0.1, 0.2 }, { 0.9, 0.2 } }, -0.1 } },
    vtkCommand::WarningEvent, "\"Width\"", "a negative width");
  CheckOneMessage(window, { groove, { { { 0.3, 0.2 }, { 0.3, 0.2 } }, 0.05 } },
    vtkCommand::WarningEvent, "needs a length", "a path of one point");
  CheckOneMessage(window, { groove, { { { 0.1, 0.2 }, { 0.4, 0.2 }, { 0.4, 0.2 } }, 0.05 } },
    vtkCommand::WarningEvent, "zero-length", "a zero-length segment");
  CheckOneMessage(window, { groove, { { { 0.1, 0.2 }, { 0.9, 0.2 } }, 0.05, 4 } },
    vtkCommand::WarningEvent, "profile out of", "an unknown profile");
  CheckOneMessage(window,
    { groove, { { { 0.1, 0.1 }, { 0.9, 0.3 }, { 0.9, 0.1 }, { 0.2, 0.3 } }, 0.05 } },
    vtkCommand::WarningEvent, "cross themselves", "a self-crossing path");
  // more elements in one cell than the shader holds
  std::vector<PathSpec> crowded{ groove };
  for (int k = 0; k < 40; ++k)
  {
    crowded.push_back({ { { 0.5 + 0.001 * k, 0.05 }, { 0.5 + 0.001 * k, 0.3 } }, 0.02 });
  }
  CheckOneMessage(window, crowded, vtkCommand::ErrorEvent, "Set GridResolution to",
    "an overfull cell");
  // a profile of one point, for the default groove
  {
    auto mapper = MapperOf({ groove });
    mapper->SetProfilesData(ProfilesData({ { { 0.0, 1.0 } } }));
    const Census census = Render(window, mapper);
    Check(census.Errors == 1 && census.Warnings == 0 && census.Says("fewer than two points"),
      "a one-point profile: one error");
    Check(census.Cut > 500, "a one-point profile: drawn with the default groove");
    CheckSane(census, "a one-point profile");
  }
  // an unknown material: the actor's property
  {
    auto paths = PathsData({ groove });
    vtkNew<vtkIntArray> materials;
    materials->SetName("Material");
    materials->InsertNextValue(3);
    paths->GetCellData()->AddArray(materials);
    auto mapper = vtkSmartPointer<vtkOpenGLPathFeatureMapper>::New();
    mapper->SetPathsData(paths);
    const Census census = Render(window, mapper);
    Check(census.Warnings == 1 && census.Errors == 0 && census.Says("actor's property"),
      "an unknown material: one warning");
    Check(census.Cut > 500, "an unknown material: drawn");
    CheckSane(census, "an unknown material");
  }
  // a path beyond [0, 1]: tiled, nothing to say
  {
    const Census census = Render(window, MapperOf({ { { { 2.1, -1.5 }, { 2.9, -1.5 } }, 0.1 } }));
    Check(census.Errors == 0 && census.Warnings == 0, "a path beyond the tile: silent");
    Check(census.Cut > 500, "a path beyond the tile: drawn where it tiles to");
    CheckSane(census, "a path beyond the tile");
  }
  // a height map that holds nothing, given as the relief base: said once by the relief
  // texture filter, the features drawn on the flat base
  {
    auto mapper = MapperOf({ groove });
    vtkNew<vtkImageData> empty;
    mapper->SetHeightMapData(empty);
    const Census census = Render(window, mapper);
    Check(census.Errors + census.Warnings == 1 && census.Says("input image is empty"),
      "an empty height map: one message");
    Check(!mapper->GetDrawingReliefBase(), "an empty height map: no relief base");
    Check(census.Cut > 500, "an empty height map: the groove cut into the flat base");
    CheckSane(census, "an empty height map");
  }
  // a height map given to the quadric frame's mapper, which takes no relief base: said
  // once, the features drawn on the flat base
  {
    vtkNew<vtkOpenGLQuadricPathFeatureMapper> quadric;
    auto recorder = vtkSmartPointer<ReliefEventRecorder>::New();
    quadric->AddObserver(vtkCommand::WarningEvent, recorder);
    quadric->AddObserver(vtkCommand::ErrorEvent, recorder);
    quadric->SetInputData(ReliefScene::Square(1.0));
    quadric->SetPathsData(PathsData({ groove }));
    quadric->SetHeightMapData(ReliefScene::ReadImage("waves_height.png"));
    window->GetRenderers()->RemoveAllItems();
    auto renderer = ReliefScene::LitRenderer(window, 160, 160);
    vtkNew<vtkActor> actor;
    actor->SetMapper(quadric);
    renderer->AddActor(actor);
    ReliefScene::ViewSquare(renderer, 0.0);
    window->Render();
    window->Render();
    Check(recorder->Messages.size() == 1 && recorder->AnyMessageContains("no relief base"),
      "a height map on the quadric frame: one warning");
  }
  return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
