// Mappers of one window whose height map is the same data share its textures: four
// actors on one height image upload one relief texture and draw exactly what four with
// copies of it draw; settings that change the relief texture, other data, a
// modification, another window and another search method each get their own; an
// acceleration image, built or precomputed, is shared as well; a bad height map shared
// by four is reported once; and the textures go with the last mapper that releases them.
// No baseline image: renders are compared.
#include "ReliefChecks.h"
#include "ReliefEventRecorder.h"
#include "ReliefLiveGLObjects.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkConeStepMapFilter.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
constexpr int Actors = 4;

vtkSmartPointer<vtkImageData> Bumps()
{
  return ReliefScene::HeightImage(64, 64, [](int i, int j) {
    return static_cast<float>(
      std::sin(2.0 * vtkMath::Pi() * i / 16.0) * std::sin(2.0 * vtkMath::Pi() * j / 16.0));
  });
}

// Texture names alive in the window's context.
int LiveTextures(vtkRenderWindow* window)
{
  window->MakeCurrent();
  return ReliefLiveGLObjects::Textures();
}
}

int TestReliefSharedTextures(int, char*[])
{
  ReliefChecks check;

  vtkNew<vtkRenderWindow> window;
  auto renderer = ReliefScene::LitRenderer(window, 240, 240);
  vtkNew<ReliefEventRecorder> messages;
  std::vector<vtkSmartPointer<vtkOpenGLReliefMapper>> mappers;
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (int k = 0; k < Actors; ++k)
  {
    auto mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
    mapper->SetInputData(ReliefScene::Square(1.0));
    mapper->SetDepthScale(0.05);
    // the depth texture alone first; the acceleration images below
    mapper->SetSearchMethodToLinearBinary();
    mapper->AddObserver(vtkCommand::ErrorEvent, messages);
    mapper->AddObserver(vtkCommand::WarningEvent, messages);
    auto actor = ReliefScene::ReliefActor(mapper, "");
    actor->SetPosition(1.1 * (k % 2), 1.1 * (k / 2), 0.0);
    actor->VisibilityOff();
    renderer->AddActor(actor);
    mappers.push_back(mapper);
    actors.push_back(actor);
  }
  ReliefScene::ViewSquare(renderer, 30.0);
  window->Render();
  const int texturesWithoutRelief = LiveTextures(window);
  for (vtkActor* actor : actors)
  {
    actor->VisibilityOn();
  }
  renderer->ResetCamera();
  auto bytesInUse = [&window]() { return vtkOpenGLReliefMapper::GetTextureBytesInUse(window); };

  // each its own copy of the heights: four textures
  vtkSmartPointer<vtkImageData> heights = Bumps();
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    vtkNew<vtkImageData> copy;
    copy->DeepCopy(heights);
    mapper->SetHeightMapData(copy);
  }
  window->Render();
  const std::vector<unsigned char> unshared = ReliefScene::Pixels(window);
  const vtkIdType one = mappers[0]->GetTextureBytes();
  std::cout << "copies: " << bytesInUse() << " bytes in use, " << one << " a mapper\n";
  check(one > 0 && bytesInUse() == Actors * one, "four copies of the heights are four textures");
  check(LiveTextures(window) == texturesWithoutRelief + Actors, "four depth textures in GL");

  // one image: one texture, the same picture
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    mapper->SetHeightMapData(heights);
  }
  window->Render();
  std::cout << "one image: " << bytesInUse() << " bytes in use\n";
  check(bytesInUse() == one, "four mappers of one height image share one texture");
  check(LiveTextures(window) == texturesWithoutRelief + 1, "one depth texture in GL");
  bool sameBytes = true;
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    sameBytes = sameBytes && mapper->GetTextureBytes() == one;
  }
  check(sameBytes, "each mapper reports the shared texture's bytes");
  check(ReliefScene::Pixels(window) == unshared, "shared, the relief draws exactly as copies do");

  // what makes the relief texture differ is not shared
  mappers[1]->GetReliefTextureFilter()->SetInputConventionToDepth();
  window->Render();
  check(bytesInUse() == 2 * one, "another convention is another texture");
  check(ReliefScene::Pixels(window) != unshared, "and draws another relief");
  mappers[1]->GetReliefTextureFilter()->SetInputConventionToHeight();
  window->Render();
  check(bytesInUse() == one, "back to the same settings, shared again");
  heights->Modified();
  window->Render();
  check(bytesInUse() == one, "a modified height map is made again, once, and the old released");

  // acceleration images: one built for all, released when no mapper searches with it
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    mapper->SetSearchMethodToConeStep();
  }
  window->Render();
  const vtkIdType withCones = mappers[0]->GetTextureBytes();
  std::cout << "ConeStep: " << bytesInUse() << " bytes in use, " << withCones << " a mapper\n";
  check(withCones > one && bytesInUse() == withCones, "one cone map built for four mappers");
  check(LiveTextures(window) == texturesWithoutRelief + 2, "a depth texture and a cone map in GL");
  mappers[1]->SetSearchMethodToAutomatic();
  window->Render();
  check(bytesInUse() == withCones && LiveTextures(window) == texturesWithoutRelief + 2,
    "Automatic reads ConeStep's cone map, not a copy");
  mappers[1]->SetSearchMethodToConeStep();
  mappers[0]->SetSearchMethodToMaximumMipmap();
  window->Render();
  check(bytesInUse() == withCones + mappers[0]->GetTextureBytes() - one,
    "another method's image besides it");
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    mapper->SetSearchMethodToLinearBinary();
  }
  window->Render();
  check(bytesInUse() == one, "images no mapper reads are released");

  // a precomputed one, given to all, is uploaded once
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputData(heights);
  vtkNew<vtkConeStepMapFilter> cones;
  cones->SetInputConnection(relief->GetOutputPort());
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    mapper->SetSearchMethodToConeStep();
    mapper->SetAccelerationConnection(cones->GetOutputPort());
  }
  window->Render();
  check(bytesInUse() == withCones, "a precomputed cone map given to four is uploaded once");
  check(mappers[3]->GetActiveSearchMethod() == vtkOpenGLReliefMapper::CONE_STEP,
    "and searched with");
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    mapper->SetSearchMethodToLinearBinary();
    mapper->SetAccelerationConnection(nullptr);
  }
  window->Render();

  // another window has its own
  {
    vtkNew<vtkRenderWindow> other;
    auto otherRenderer = ReliefScene::LitRenderer(other, 120, 120);
    vtkNew<vtkOpenGLReliefMapper> mapper;
    mapper->SetInputData(ReliefScene::Square(1.0));
    mapper->SetHeightMapData(heights);
    mapper->SetSearchMethodToLinearBinary();
    otherRenderer->AddActor(ReliefScene::ReliefActor(mapper, ""));
    ReliefScene::ViewSquare(otherRenderer, 30.0);
    other->Render();
    std::cout << "another window: " << vtkOpenGLReliefMapper::GetTextureBytesInUse(other)
              << " bytes in use there, " << bytesInUse() << " here\n";
    check(vtkOpenGLReliefMapper::GetTextureBytesInUse(other) == one && bytesInUse() == one,
      "another window uploads its own copy");
    other->Finalize();
    check(vtkOpenGLReliefMapper::GetTextureBytesInUse(other) == 0 && bytesInUse() == one,
      "which goes when that window closes, and this one's stays");
  }
  window->Render();
  check(messages->Events.empty(), "silent so far");

  // a bad height map shared by four is said once, however many frames
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(8, 8, 2);
  volume->AllocateScalars(VTK_FLOAT, 1);
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    mapper->SetHeightMapData(volume);
  }
  window->Render();
  window->Render();
  check(messages->Count(vtkCommand::ErrorEvent) == 1 && messages->AnyMessageContains("not 2D"),
    "a 3D height map shared by four mappers is one error");
  check(bytesInUse() == 0, "and uploads nothing");
  messages->Clear();

  // released with the last
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    mapper->SetHeightMapData(heights);
  }
  window->Render();
  for (int k = 0; k + 1 < Actors; ++k)
  {
    mappers[k]->ReleaseGraphicsResources(window);
  }
  check(bytesInUse() == one, "kept while a mapper holds it");
  mappers[Actors - 1]->ReleaseGraphicsResources(window);
  check(bytesInUse() == 0, "released with the last mapper");
  const int texturesAfterRelease = LiveTextures(window);
  std::cout << "GL textures without relief " << texturesWithoutRelief << ", after release "
            << texturesAfterRelease << "\n";
  check(texturesAfterRelease == texturesWithoutRelief, "no texture left in the context");
  check(messages->Events.empty(), "silent throughout");
  return check.Passed() ? EXIT_SUCCESS : EXIT_FAILURE;
}
