// vtkOpenGLReliefImpostorMapper's AutomaticResolution and CompressColours: the capture
// follows the impostor's size on screen (small far off, raised and captured again when
// drawn larger, never lowered by drawing smaller), the user's own resolutions are kept,
// and compressed colours take a sixth of their bytes, with pictures close to the
// uncompressed ones.
#include "ReliefChecks.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkElevationFilter.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefImpostorMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkReliefImpostorFilter.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace
{
constexpr int Size = 400;

// The camera `distance` radii from the unit sphere, whose padded box (2.04 a side, about
// 2.9 across as seen) then spans about 1200 / distance pixels of the window.
void Place(vtkRenderer* renderer, double distance)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetViewAngle(30.0);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, -distance, 0.3 * distance);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCameraClippingRange();
}
}

int TestReliefImpostorResolution(int, char*[])
{
  ReliefChecks check;

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(sphere->GetOutputPort());
  elevation->SetLowPoint(0.0, 0.0, -0.5);
  elevation->SetHighPoint(0.0, 0.0, 0.5);
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Size, Size);
  window->SetMultiSamples(0);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkOpenGLReliefImpostorMapper> mapper;
  mapper->SetInputConnection(elevation->GetOutputPort());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->AddActor(actor);
  vtkReliefImpostorFilter* filter = mapper->GetImpostorFilter();

  // far off (the box spans about 20 pixels): the least resolution
  Place(renderer, 60.0);
  window->Render();
  std::cout << "far: depth " << filter->GetDepthResolution() << "^2, colour "
            << filter->GetColourResolution() << "^2, " << mapper->GetTextureBytes()
            << " bytes\n";
  check(mapper->GetAutomaticResolution(), "AutomaticResolution is on by default");
  constexpr int least = vtkOpenGLReliefImpostorMapper::MinimumAutomaticResolution;
  check(filter->GetDepthResolution() == least && filter->GetColourResolution() == 2 * least,
    "a small impostor is captured at the least resolution");
  check(mapper->GetDrawingImpostor(), "the impostor is drawn");
  const vtkIdType farBytes = mapper->GetTextureBytes();

  // near (the box spans about 200 pixels): raised to 256 and captured again
  Place(renderer, 6.0);
  window->Render();
  std::cout << "near: depth " << filter->GetDepthResolution() << "^2, colour "
            << filter->GetColourResolution() << "^2, " << mapper->GetTextureBytes()
            << " bytes\n";
  check(filter->GetDepthResolution() == 256 && filter->GetColourResolution() == 512,
    "a larger impostor raises the resolution to the power of two above its span");
  check(mapper->GetTextureBytes() > 8 * farBytes, "the larger capture is uploaded");

  // far again: kept, not captured again
  Place(renderer, 60.0);
  window->Render();
  check(filter->GetDepthResolution() == 256, "drawing smaller keeps the resolution");

  // compressed colours: a sixth of their bytes, and the same picture within noise
  Place(renderer, 6.0);
  window->Render();
  const std::vector<unsigned char> compressedPixels = ReliefScene::Pixels(window);
  const vtkIdType compressedBytes = mapper->GetTextureBytes();
  mapper->CompressColoursOff();
  window->Render();
  const std::vector<unsigned char> plainPixels = ReliefScene::Pixels(window);
  const vtkIdType plainBytes = mapper->GetTextureBytes();
  // over the pixels the sphere covers (the background is black in both)
  double squares = 0.0;
  size_t covered = 0;
  for (size_t k = 0; k + 2 < plainPixels.size(); k += 3)
  {
    if (plainPixels[k] + plainPixels[k + 1] + plainPixels[k + 2] == 0)
    {
      continue;
    }
    ++covered;
    for (size_t c = k; c < k + 3; ++c)
    {
      const double difference = (compressedPixels[c] - plainPixels[c]) / 255.0;
      squares += difference * difference;
    }
  }
  const double rmse = std::sqrt(squares / std::max<size_t>(3 * covered, 1));
  check(covered > 10000, "the sphere covers the window's middle");
  std::cout << "colours: " << compressedBytes << " bytes compressed, " << plainBytes
            << " plain; RMSE between their pictures " << rmse << "\n";
  // colours at 512^2 with mipmaps: 8.4 MB as RGBA, 1 MB as DXT1; a GL without S3TC holds
  // them as RGBA either way
  if (compressedBytes == plainBytes)
  {
    std::cout << "this GL has no S3TC: colours are not compressed\n";
  }
  else
  {
    check(plainBytes - compressedBytes > 7000000, "compressed colours take far fewer bytes");
  }
  check(rmse < 0.02, "compressed colours look like the plain ones"); // 0.010 measured
  mapper->CompressColoursOn();

  // the user's own resolution is kept, and turns AutomaticResolution off
  filter->SetDepthResolution(100);
  window->Render();
  check(!mapper->GetAutomaticResolution() && filter->GetDepthResolution() == 100 &&
      filter->GetColourResolution() == 512,
    "setting the filter's resolution turns AutomaticResolution off and keeps it");
  mapper->AutomaticResolutionOn();
  Place(renderer, 60.0);
  window->Render();
  check(filter->GetDepthResolution() == least, "turning it on again starts from the least");

  mapper->ReleaseGraphicsResources(window);

  // shadow maps: the baker draws through the spotlight's camera, which frames the sphere
  // large (about 370 of 400 pixels); the capture keeps to what the view needs
  vtkNew<vtkRenderWindow> shadowWindow;
  shadowWindow->SetSize(Size, Size);
  shadowWindow->SetMultiSamples(0);
  vtkNew<vtkRenderer> shadowRenderer;
  shadowWindow->AddRenderer(shadowRenderer);
  ReliefScene::AddSpotlight(shadowRenderer);
  ReliefScene::UseShadowMaps(shadowRenderer);
  vtkNew<vtkOpenGLReliefImpostorMapper> shadowed;
  shadowed->SetInputConnection(elevation->GetOutputPort());
  vtkNew<vtkActor> shadowedActor;
  shadowedActor->SetMapper(shadowed);
  shadowRenderer->AddActor(shadowedActor);
  Place(shadowRenderer, 60.0);
  shadowWindow->Render();
  std::cout << "under shadow maps, far: depth " << shadowed->GetImpostorFilter()->GetDepthResolution()
            << "^2\n";
  check(shadowed->GetImpostorFilter()->GetDepthResolution() == least,
    "the shadow baker's camera does not raise the resolution");
  shadowed->ReleaseGraphicsResources(shadowWindow);
  return check.Passed() ? EXIT_SUCCESS : EXIT_FAILURE;
}
