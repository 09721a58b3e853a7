// vtkCompositeReliefMapper draws each polygonal block of a multiblock dataset with a relief
// mapper made like its prototype: two blocks draw exactly what two actors of relief
// mappers draw, share one relief texture, follow the prototype's settings (its relief
// texture filter's too) without new block mappers, and a colour map's edit keeps them,
// take its frame with new ones, report a block's warning once for all blocks, and
// release the GL objects of the block mappers a new input replaces.
// No baseline image: renders are compared.
#include "ReliefChecks.h"
#include "ReliefEventRecorder.h"
#include "ReliefLiveGLObjects.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCompositeReliefMapper.h"
#include "vtkImageData.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
vtkSmartPointer<vtkPolyData> SquareAt(double x)
{
  vtkNew<vtkTransform> shift;
  shift->Translate(x, 0.0, 0.0);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(ReliefScene::Square(2.0));
  moved->SetTransform(shift);
  moved->Update();
  return moved->GetOutput();
}

vtkSmartPointer<vtkMultiBlockDataSet> TwoSquares()
{
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetBlock(0, SquareAt(-0.55));
  blocks->SetBlock(1, SquareAt(0.55));
  return blocks;
}

int LiveTextures(vtkRenderWindow* window)
{
  window->MakeCurrent();
  return ReliefLiveGLObjects::Textures();
}
}

int TestCompositeReliefMapper(int, char*[])
{
  ReliefChecks check;
  vtkSmartPointer<vtkImageData> heights = ReliefScene::HeightImage(64, 64, [](int i, int j) {
    return static_cast<float>(
      std::sin(2.0 * vtkMath::Pi() * i / 16.0) * std::sin(2.0 * vtkMath::Pi() * j / 16.0));
  });

  // the reference: one relief mapper per square
  vtkNew<vtkRenderWindow> window;
  auto renderer = ReliefScene::LitRenderer(window, 320, 200);
  std::vector<vtkSmartPointer<vtkActor>> separate;
  for (double x : { -0.55, 0.55 })
  {
    vtkNew<vtkOpenGLReliefMapper> mapper;
    mapper->SetInputData(SquareAt(x));
    mapper->SetHeightMapData(heights);
    mapper->SetDepthScale(0.08);
    auto actor = ReliefScene::ReliefActor(mapper, "");
    renderer->AddActor(actor);
    separate.push_back(actor);
  }
  ReliefScene::ViewSquare(renderer, 45.0);
  renderer->GetActiveCamera()->Zoom(0.5);
  window->Render();
  const std::vector<unsigned char> reference = ReliefScene::Pixels(window);
  const int texturesOfOneRelief = LiveTextures(window);
  for (vtkActor* actor : separate)
  {
    renderer->RemoveActor(actor);
  }
  separate.clear();
  window->Render();
  const int texturesWithoutRelief = LiveTextures(window);

  // the same two squares as the blocks of one dataset
  vtkNew<vtkCompositeReliefMapper> composite;
  vtkNew<ReliefEventRecorder> messages;
  composite->AddObserver(vtkCommand::WarningEvent, messages);
  composite->AddObserver(vtkCommand::ErrorEvent, messages);
  composite->SetInputDataObject(TwoSquares());
  vtkNew<vtkLookupTable> colours; // as ParaView gives one, then edits it
  composite->SetLookupTable(colours);
  composite->GetReliefMapper()->SetHeightMapData(heights);
  composite->GetReliefMapper()->SetDepthScale(0.08);
  auto actor = ReliefScene::ReliefActor(composite, "");
  renderer->AddActor(actor);
  window->Render();
  check(composite->GetNumberOfBlockMappers() == 2, "a relief mapper per block");
  check(ReliefScene::Pixels(window) == reference, "two blocks draw as two relief mappers");
  check(LiveTextures(window) == texturesOfOneRelief, "the blocks share one relief texture");
  check(composite->GetBlockMapper(0)->GetTextureBytes() ==
      vtkOpenGLReliefMapper::GetTextureBytesInUse(window),
    "one block's textures are all the window holds");

  // a setting of the prototype reaches the blocks, which stay
  vtkOpenGLReliefMapper* first = composite->GetBlockMapper(0);
  composite->GetReliefMapper()->SetDepthScale(0.0);
  window->Render();
  check(composite->GetBlockMapper(0) == first, "a setting keeps the block mappers");
  check(first->GetDepthScale() == 0.0, "and reaches them");
  check(ReliefScene::Pixels(window) != reference, "and changes the picture");
  composite->GetReliefMapper()->SetDepthScale(0.08);
  composite->GetReliefMapper()->GetReliefTextureFilter()->SetInputConventionToDepth();
  window->Render();
  check(first->GetReliefTextureFilter()->GetInputConvention() == vtkReliefTextureFilter::DEPTH,
    "the relief texture filter's settings reach the blocks");
  composite->GetReliefMapper()->GetReliefTextureFilter()->SetInputConventionToHeight();
  colours->SetHueRange(0.2, 0.8);
  window->Render();
  check(composite->GetBlockMapper(0) == first, "a colour map's edit keeps the block mappers");
  composite->GetReliefMapper()->SetSearchMethodToExactDDA();
  window->Render();
  check(first->GetSearchMethod() == vtkOpenGLReliefMapper::EXACT_DDA, "the search method too");
  // ExactDDA reads no cone map: the heights alone
  const int texturesOfHeights = LiveTextures(window);
  check(texturesOfHeights == texturesOfOneRelief - 1, "Automatic's cone map released");

  // another frame: new block mappers of its class
  vtkNew<vtkOpenGLQuadricReliefMapper> quadric;
  quadric->CopyReliefSettings(composite->GetReliefMapper());
  composite->SetReliefMapper(quadric);
  window->Render();
  check(composite->GetNumberOfBlockMappers() == 2 &&
      vtkOpenGLQuadricReliefMapper::SafeDownCast(composite->GetBlockMapper(1)),
    "another frame makes block mappers of its class");
  check(quadric->GetSearchMethod() == vtkOpenGLReliefMapper::EXACT_DDA,
    "CopyReliefSettings copies the search method");
  check(LiveTextures(window) == texturesOfHeights,
    "the replaced block mappers' textures are released (" + std::to_string(LiveTextures(window)) +
      " GL textures, " + std::to_string(texturesOfHeights) + " with one height texture)");
  composite->SetReliefMapper(nullptr);
  check(messages->AnyMessageContains("SetReliefMapper(nullptr)") &&
      composite->GetReliefMapper() == quadric.Get(),
    "a null prototype is refused with an error");

  // a block's warning, once for both blocks
  vtkNew<vtkOpenGLReliefMapper> flat;
  composite->SetReliefMapper(flat); // no height map
  messages->Clear();
  window->Render();
  check(messages->Count(vtkCommand::WarningEvent) == 1,
    "the blocks' missing height map is one warning, not one a block (" +
      std::to_string(messages->Count(vtkCommand::WarningEvent)) + ")");
  check(LiveTextures(window) == texturesWithoutRelief, "no height map, no relief texture");

  // a new input: new block mappers, the old ones' GL objects released
  flat->SetHeightMapData(heights);
  composite->SetInputDataObject(SquareAt(0.0));
  window->Render();
  check(composite->GetNumberOfBlockMappers() == 1, "a plain vtkPolyData is one block");
  check(LiveTextures(window) == texturesOfOneRelief, "one relief texture again");
  composite->SetInputDataObject(TwoSquares());
  window->Render();
  check(LiveTextures(window) == texturesOfOneRelief, "the replaced block's texture released");

  renderer->RemoveActor(actor);
  window->Render();
  composite->ReleaseGraphicsResources(window);
  check(LiveTextures(window) == texturesWithoutRelief, "released with the window's resources");
  return check.Passed() ? EXIT_SUCCESS : EXIT_FAILURE;
}
