// The search method property: every method by name, unknown ones refused; switching
// methods back and forth leaks no shader programs or textures; Automatic steps over the
// acceleration AutomaticAcceleration names, and no other; an acceleration image
// that does not fit is reported once and the search falls back to LinearBinary; a
// height map larger than OpenGL takes is reported with the limit.
#include "ReliefChecks.h"
#include "ReliefEventRecorder.h"
#include "ReliefLiveGLObjects.h"
#include "ReliefScene.h"

#include "vtkConeStepMapFilter.h"
#include "vtkImageData.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkSlopeMipmapFilter.h"
#include "vtkTextureObject.h"

#include <cstring>
#include <iostream>

namespace
{
// Sum of the red channel after a render: the sample counts in SampleCount display mode.
long RedSum(vtkRenderWindow* window)
{
  window->Render();
  const int* size = window->GetSize();
  unsigned char* pixels = window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 1);
  long sum = 0;
  for (int k = 0; k < size[0] * size[1]; ++k)
  {
    sum += pixels[3 * k];
  }
  delete[] pixels;
  return sum;
}
}

int TestReliefSearchMethods(int, char*[])
{
  ReliefChecks check;

  vtkNew<vtkRenderWindow> window;
  auto mapper = ReliefScene::ShowThinFeatures(window, 160, 120, 60.0, vtkOpenGLReliefMapper::LINEAR);
  vtkNew<ReliefEventRecorder> messages;
  mapper->AddObserver(vtkCommand::ErrorEvent, messages);
  mapper->AddObserver(vtkCommand::WarningEvent, messages);

  // names
  const std::vector<int>& methods = ReliefScene::SearchMethods();
  const char* names[] = { "Linear", "LinearBinary", "Secant", "ExactDDA", "SafetyRadius",
    "ConeStep", "MaximumMipmap", "Automatic", "RobustBinary",
    "SlopeMipmap" };
  check(methods.size() == std::size(names), "every method is listed");
  for (size_t k = 0; k < methods.size(); ++k)
  {
    mapper->SetSearchMethod(methods[k]);
    check(std::strcmp(mapper->GetSearchMethodAsString(), names[k]) == 0, "method names");
  }
  const int before = mapper->GetSearchMethod();
  mapper->SetSearchMethod(42);
  check(messages->Count(vtkCommand::ErrorEvent) == 1 && mapper->GetSearchMethod() == before,
    "an unknown method is an error and changes nothing");
  messages->Clear();

  // leaks: after one round of every method, more rounds create no GL objects
  window->Render();
  for (int method : methods)
  {
    mapper->SetSearchMethod(method);
    window->Render();
    check(mapper->GetActiveSearchMethod() == method, "each method is the one searched with");
  }
  const int programs = ReliefLiveGLObjects::Programs();
  const int textures = ReliefLiveGLObjects::Textures();
  for (int round = 0; round < 10; ++round)
  {
    for (int method : methods)
    {
      mapper->SetSearchMethod(method);
      window->Render();
    }
  }
  std::cout << "GL programs " << programs << " -> " << ReliefLiveGLObjects::Programs()
            << ", textures " << textures << " -> " << ReliefLiveGLObjects::Textures() << "\n";
  check(ReliefLiveGLObjects::Programs() == programs, "switching methods leaks no shader programs");
  check(ReliefLiveGLObjects::Textures() == textures, "switching methods leaks no textures");
  check(messages->Events.empty(), "switching methods is silent");

  // nothing of one method's state leaks into the next: after all the switching, each
  // method takes, pixel for pixel, the samples a mapper that never searched otherwise
  // takes (an acceleration texture re-uploaded in the previous method's pixel format
  // once left ConeStep reading zero-width cones: exact, but stepping cell by cell)
  mapper->SetDisplayModeToSampleCount();
  for (int method : methods)
  {
    vtkNew<vtkRenderWindow> alone;
    ReliefScene::ShowThinFeatures(alone, 160, 120, 60.0, method)->SetDisplayModeToSampleCount();
    mapper->SetSearchMethod(method);
    const long expected = RedSum(alone);
    const long actual = RedSum(window);
    if (actual != expected)
    {
      std::cerr << vtkOpenGLReliefMapper::GetSearchMethodAsString(method) << ": red sum "
                << actual << " after switching, " << expected << " alone\n";
    }
    check(actual == expected, "each method samples as it does alone");
  }

  // Automatic over the slope pyramid: its own samples, as a new mapper's; refused for any
  // other method; switching back and forth leaks nothing
  check(mapper->GetAutomaticAcceleration() == vtkOpenGLReliefMapper::CONE_STEP,
    "Automatic steps over cones by default");
  mapper->SetSearchMethodToAutomatic();
  const long overCones = RedSum(window);
  mapper->SetAutomaticAccelerationToSlopeMipmap();
  check(std::strcmp(mapper->GetAutomaticAccelerationAsString(), "SlopeMipmap") == 0,
    "AutomaticAcceleration's name");
  const long overSlopes = RedSum(window);
  vtkNew<vtkRenderWindow> alone;
  auto fresh =
    ReliefScene::ShowThinFeatures(alone, 160, 120, 60.0, vtkOpenGLReliefMapper::AUTOMATIC);
  fresh->SetDisplayModeToSampleCount();
  fresh->SetAutomaticAccelerationToSlopeMipmap();
  std::cout << "Automatic's red sum over cones " << overCones << ", over slopes " << overSlopes
            << " (alone " << RedSum(alone) << ")\n";
  check(overSlopes != overCones && overSlopes == RedSum(alone),
    "Automatic over slopes samples as it does alone, unlike over cones");
  mapper->SetAutomaticAcceleration(vtkOpenGLReliefMapper::MAXIMUM_MIPMAP);
  check(messages->Count(vtkCommand::ErrorEvent) == 1 &&
      messages->AnyMessageContains("neither ConeStep nor SlopeMipmap") &&
      mapper->GetAutomaticAcceleration() == vtkOpenGLReliefMapper::SLOPE_MIPMAP,
    "another acceleration for Automatic is an error and changes nothing");
  messages->Clear();
  // a render makes the window's context current again, for the counts
  check(RedSum(window) == overSlopes, "the refused value left Automatic over slopes");
  const int automaticPrograms = ReliefLiveGLObjects::Programs();
  const int automaticTextures = ReliefLiveGLObjects::Textures();
  for (int round = 0; round < 5; ++round)
  {
    mapper->SetAutomaticAccelerationToConeStep();
    RedSum(window);
    mapper->SetAutomaticAccelerationToSlopeMipmap();
    RedSum(window);
  }
  std::cout << "GL programs " << automaticPrograms << " -> " << ReliefLiveGLObjects::Programs()
            << ", textures " << automaticTextures << " -> " << ReliefLiveGLObjects::Textures()
            << ", messages " << messages->Events.size() << "\n";
  check(ReliefLiveGLObjects::Programs() == automaticPrograms &&
      ReliefLiveGLObjects::Textures() == automaticTextures && messages->Events.empty(),
    "switching Automatic's acceleration leaks nothing, silently");
  check(RedSum(window) == overSlopes, "and samples as before after");
  mapper->SetAutomaticAccelerationToConeStep();
  mapper->SetDisplayModeToShaded();

  // a precomputed image, made in the pipeline from the mapper's relief texture, is used as
  // it is, silently
  auto precomputedIsAccepted = [&](vtkAlgorithm* filter, int method) {
    mapper->SetSearchMethod(method);
    filter->SetInputConnection(mapper->GetReliefTextureFilter()->GetOutputPort());
    mapper->SetAccelerationConnection(filter->GetOutputPort());
    window->Render();
    return messages->Events.empty() && mapper->GetActiveSearchMethod() == method;
  };

  // one of the wrong size makes LinearBinary search
  vtkNew<vtkMaximumMipmapFilter> pyramid;
  check(precomputedIsAccepted(pyramid, vtkOpenGLReliefMapper::MAXIMUM_MIPMAP),
    "a precomputed pyramid is accepted");
  vtkNew<vtkImageData> wrongSize;
  wrongSize->SetDimensions(10, 10, 1);
  wrongSize->AllocateScalars(VTK_FLOAT, 1);
  mapper->SetAccelerationData(wrongSize);
  window->Render();
  window->Render();
  check(messages->Count(vtkCommand::ErrorEvent) == 1 && messages->AnyMessageContains("96x64"),
    "a pyramid of the wrong size is one error naming the size needed");
  check(messages->Count(vtkCommand::WarningEvent) == 1 &&
      messages->AnyMessageContains("LinearBinary"),
    "one warning of the fallback");
  check(mapper->GetActiveSearchMethod() == vtkOpenGLReliefMapper::LINEAR_BINARY,
    "the fallback is LinearBinary");
  messages->Clear();
  vtkNew<vtkImageData> wrongType;
  wrongType->SetDimensions(96, 64, 1);
  wrongType->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  mapper->SetAccelerationData(wrongType);
  window->Render();
  check(messages->Count(vtkCommand::ErrorEvent) == 1 &&
      mapper->GetActiveSearchMethod() == vtkOpenGLReliefMapper::LINEAR_BINARY,
    "a pyramid of the wrong type is an error, and LinearBinary searches");
  mapper->SetAccelerationConnection(nullptr);
  window->Render();
  check(mapper->GetActiveSearchMethod() == vtkOpenGLReliefMapper::MAXIMUM_MIPMAP,
    "without a given pyramid the mapper builds its own");
  messages->Clear();

  // the cone map has two components: one of one is refused, naming the filter
  mapper->SetSearchMethodToConeStep();
  vtkNew<vtkImageData> oneComponent;
  oneComponent->SetDimensions(64, 64, 1);
  oneComponent->AllocateScalars(VTK_FLOAT, 1);
  mapper->SetAccelerationData(oneComponent);
  window->Render();
  check(messages->Count(vtkCommand::ErrorEvent) == 1 &&
      messages->AnyMessageContains("vtkConeStepMapFilter") &&
      messages->AnyMessageContains("2 component(s)") &&
      mapper->GetActiveSearchMethod() == vtkOpenGLReliefMapper::LINEAR_BINARY,
    "a one-component cone map is an error naming the filter, and LinearBinary searches");
  messages->Clear();
  vtkNew<vtkConeStepMapFilter> cones;
  check(precomputedIsAccepted(cones, vtkOpenGLReliefMapper::CONE_STEP),
    "a precomputed cone map is accepted");
  mapper->SetAccelerationConnection(nullptr);

  // Automatic reads the image of its acceleration: a slope pyramid over slopes, and a
  // cone map, which a slope pyramid is not, over cones
  vtkNew<vtkSlopeMipmapFilter> slopes;
  mapper->SetAutomaticAccelerationToSlopeMipmap();
  check(precomputedIsAccepted(slopes, vtkOpenGLReliefMapper::AUTOMATIC),
    "a precomputed slope pyramid is accepted by Automatic over slopes");
  mapper->SetAutomaticAccelerationToConeStep();
  window->Render();
  check(messages->Count(vtkCommand::ErrorEvent) == 1 &&
      messages->AnyMessageContains("vtkConeStepMapFilter") &&
      mapper->GetActiveSearchMethod() == vtkOpenGLReliefMapper::LINEAR_BINARY,
    "and refused by Automatic over cones, naming the filter it needs");
  messages->Clear();
  mapper->SetAccelerationConnection(nullptr);

  // a negative safety tolerance is clamped to 0 with one warning; a new tolerance
  // rebuilds the radii without a message
  mapper->SetSearchMethodToSafetyRadius();
  mapper->SetSafetyRadiusTolerance(-0.5);
  check(messages->Count(vtkCommand::WarningEvent) == 1 &&
      messages->AnyMessageContains("SafetyRadiusTolerance") &&
      mapper->GetSafetyRadiusTolerance() == 0.0,
    "a negative safety tolerance becomes 0 with a warning");
  messages->Clear();
  mapper->SetDisplayModeToSampleCount();
  const long exactSamples = RedSum(window);
  mapper->SetSafetyRadiusTolerance(0.05);
  const long tolerantSamples = RedSum(window);
  std::cout << "SafetyRadius samples (red sum): e = 0 " << exactSamples << ", e = 0.05 "
            << tolerantSamples << "\n";
  check(messages->Events.empty() &&
      mapper->GetActiveSearchMethod() == vtkOpenGLReliefMapper::SAFETY_RADIUS &&
      tolerantSamples < exactSamples,
    "a new safety tolerance rebuilds the radii, and larger radii take fewer samples");
  mapper->SetDisplayModeToShaded();
  messages->Clear();

  // a height map wider than OpenGL takes
  const int limit =
    vtkTextureObject::GetMaximumTextureSize(vtkOpenGLRenderWindow::SafeDownCast(window));
  vtkNew<vtkImageData> tooWide;
  tooWide->SetDimensions(limit + 1, 1, 1);
  tooWide->AllocateScalars(VTK_FLOAT, 1);
  mapper->SetHeightMapData(tooWide);
  window->Render();
  window->Render();
  check(messages->Count(vtkCommand::ErrorEvent) == 1 &&
      messages->AnyMessageContains(std::to_string(limit)),
    "a height map beyond the GL limit is one error naming the limit");
  return check.Passed() ? EXIT_SUCCESS : EXIT_FAILURE;
}
