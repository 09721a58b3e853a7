// The search method property: every method by name, unknown ones refused; switching
// methods back and forth leaks no shader programs or textures; an acceleration image
// that does not fit is reported once and the search falls back to LinearBinary; a
// height map larger than OpenGL takes is reported with the limit.
#include "ReliefEventRecorder.h"
#include "ReliefScene.h"

#include "vtkImageData.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkTextureObject.h"
#include "vtk_glew.h"

#include <cstring>
#include <iostream>

namespace
{
const int Methods[] = { vtkOpenGLReliefMapper::LINEAR, vtkOpenGLReliefMapper::LINEAR_BINARY,
  vtkOpenGLReliefMapper::SECANT, vtkOpenGLReliefMapper::EXACT_DDA,
  vtkOpenGLReliefMapper::MAXIMUM_MIPMAP };

// GL objects alive in the window's context, counted by name.
int LivePrograms()
{
  int count = 0;
  for (GLuint name = 1; name < 4096; ++name)
  {
    count += glIsProgram(name) ? 1 : 0;
  }
  return count;
}

int LiveTextures()
{
  int count = 0;
  for (GLuint name = 1; name < 4096; ++name)
  {
    count += glIsTexture(name) ? 1 : 0;
  }
  return count;
}
}

int TestReliefSearchMethods(int, char*[])
{
  int failures = 0;
  auto check = [&failures](bool condition, const char* what) {
    if (!condition)
    {
      std::cerr << "FAILED: " << what << "\n";
      ++failures;
    }
  };

  vtkNew<vtkRenderWindow> window;
  auto mapper = ReliefScene::ShowThinFeatures(window, 160, 120, 60.0, vtkOpenGLReliefMapper::LINEAR);
  vtkNew<ReliefEventRecorder> messages;
  mapper->AddObserver(vtkCommand::ErrorEvent, messages);
  mapper->AddObserver(vtkCommand::WarningEvent, messages);

  // names
  const char* names[] = { "Linear", "LinearBinary", "Secant", "ExactDDA", "MaximumMipmap" };
  for (int k = 0; k < 5; ++k)
  {
    mapper->SetSearchMethod(Methods[k]);
    check(std::strcmp(mapper->GetSearchMethodAsString(), names[k]) == 0, "method names");
  }
  mapper->SetSearchMethod(42);
  check(messages->Count(vtkCommand::ErrorEvent) == 1 &&
      mapper->GetSearchMethod() == vtkOpenGLReliefMapper::MAXIMUM_MIPMAP,
    "an unknown method is an error and changes nothing");
  messages->Clear();

  // leaks: after one round of every method, more rounds create no GL objects
  window->Render();
  for (int method : Methods)
  {
    mapper->SetSearchMethod(method);
    window->Render();
    check(mapper->GetActiveSearchMethod() == method, "each method is the one searched with");
  }
  const int programs = LivePrograms();
  const int textures = LiveTextures();
  for (int round = 0; round < 10; ++round)
  {
    for (int method : Methods)
    {
      mapper->SetSearchMethod(method);
      window->Render();
    }
  }
  std::cout << "GL programs " << programs << " -> " << LivePrograms() << ", textures " << textures
            << " -> " << LiveTextures() << "\n";
  check(LivePrograms() == programs, "switching methods leaks no shader programs");
  check(LiveTextures() == textures, "switching methods leaks no textures");
  check(messages->Events.empty(), "switching methods is silent");

  // a precomputed pyramid is used as it is; one of the wrong size makes LinearBinary search
  mapper->SetSearchMethodToMaximumMipmap();
  vtkNew<vtkMaximumMipmapFilter> pyramid;
  pyramid->SetInputConnection(mapper->GetReliefTextureFilter()->GetOutputPort());
  mapper->SetAccelerationConnection(pyramid->GetOutputPort());
  window->Render();
  check(messages->Events.empty() &&
      mapper->GetActiveSearchMethod() == vtkOpenGLReliefMapper::MAXIMUM_MIPMAP,
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
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
