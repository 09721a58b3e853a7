// vtkOpenGLQuadricReliefMapper: cobblestones on a coarse sphere and torus carve their
// outlines (Oliveira and Policarpo 2005, Fig. 9 and 15), where the flat frame keeps the polygons'.
// The baseline shows both shapes; beside it the test checks that the outline really moves (pixels
// the flat frame covers are uncovered), that NaN quadrics draw as the flat frame does, that a
// quadric array of the wrong size or type is recomputed with one warning, that quadrics without
// their hull's lifts are lifted as vtkLocalQuadricFilter lifts them, that a grid search falls
// back to LinearBinary with one warning, and that a mesh without texture coordinates gives one
// error and draws plainly.
#include "ReliefChecks.h"
#include "ReliefEventRecorder.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkLocalQuadricFilter.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkStringArray.h"

#include <cmath>
#include <iostream>
#include <limits>
#include <vector>

namespace
{
// The mapper of a shape in its own viewport, seen from the side, lit from the upper left.
template <typename Mapper>
vtkSmartPointer<Mapper> Show(vtkRenderWindow* window, vtkPolyData* shape, double left, double right)
{
  auto mapper = vtkSmartPointer<Mapper>::New();
  ReliefScene::SetStones(mapper, shape, 0.06);
  auto renderer = ReliefScene::LitRenderer(window, 600, 300);
  renderer->SetViewport(left, 0.0, right, 1.0);
  // the actor's default properties: the mapper leaves out the back faces of closed shapes
  renderer->AddActor(ReliefScene::ReliefActor(mapper, "stones_color.png"));
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 3.0, 1.2);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  renderer->ResetCameraClippingRange();
  return mapper;
}

// Pixels of the window that show the background colour (the renderer's, 0.1 0.12 0.16).
long BackgroundPixels(vtkRenderWindow* window)
{
  window->Render();
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  long count = 0;
  for (size_t k = 0; k + 2 < pixels.size(); k += 3)
  {
    count += std::abs(pixels[k] - 26) <= 1 && std::abs(pixels[k + 1] - 31) <= 1 &&
        std::abs(pixels[k + 2] - 41) <= 1
      ? 1
      : 0;
  }
  return count;
}

double MeanDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  double sum = 0.0;
  for (size_t k = 0; k < a.size(); ++k)
  {
    sum += std::abs(int(a[k]) - int(b[k]));
  }
  return sum / static_cast<double>(a.size());
}
}

int TestReliefQuadricSilhouette(int argc, char* argv[])
{
  ReliefChecks check;

  // the outline moves: the flat frame covers pixels the quadric frame carves away
  auto sphere = ReliefScene::Sphere(24);
  auto torus = ReliefScene::Torus(48);
  {
    vtkNew<vtkRenderWindow> flatWindow;
    flatWindow->SetOffScreenRendering(1);
    Show<vtkOpenGLReliefMapper>(flatWindow, sphere, 0.0, 0.5);
    Show<vtkOpenGLReliefMapper>(flatWindow, torus, 0.5, 1.0);
    vtkNew<vtkRenderWindow> curvedWindow;
    curvedWindow->SetOffScreenRendering(1);
    Show<vtkOpenGLQuadricReliefMapper>(curvedWindow, sphere, 0.0, 0.5);
    Show<vtkOpenGLQuadricReliefMapper>(curvedWindow, torus, 0.5, 1.0);
    const long flat = BackgroundPixels(flatWindow);
    const long curved = BackgroundPixels(curvedWindow);
    std::cout << "background pixels: flat frame " << flat << ", quadric frame " << curved << "\n";
    check(curved > flat + 2000, "the quadric frame carves the outline");
  }

  // NaN coefficients are a plane: the image of the flat frame
  {
    auto nanSphere = vtkSmartPointer<vtkPolyData>::New();
    nanSphere->DeepCopy(sphere);
    vtkNew<vtkFloatArray> quadrics;
    quadrics->SetName(vtkLocalQuadricFilter::QuadricArrayName());
    quadrics->SetNumberOfComponents(2);
    quadrics->SetNumberOfTuples(nanSphere->GetNumberOfPoints());
    quadrics->Fill(std::numeric_limits<float>::quiet_NaN());
    nanSphere->GetPointData()->AddArray(quadrics);
    vtkNew<vtkRenderWindow> flatWindow;
    flatWindow->SetOffScreenRendering(1);
    Show<vtkOpenGLReliefMapper>(flatWindow, sphere, 0.0, 1.0);
    vtkNew<vtkRenderWindow> nanWindow;
    nanWindow->SetOffScreenRendering(1);
    Show<vtkOpenGLQuadricReliefMapper>(nanWindow, nanSphere, 0.0, 1.0);
    flatWindow->Render();
    nanWindow->Render();
    const double difference =
      MeanDifference(ReliefScene::Pixels(flatWindow), ReliefScene::Pixels(nanWindow));
    std::cout << "NaN quadrics against the flat frame: mean difference " << difference
              << " levels\n";
    check(difference < 0.5, "NaN quadrics draw as the flat frame");
  }

  // quadrics of the mesh's own, without their hull's lifts: lifted as the filter lifts them
  {
    vtkNew<vtkLocalQuadricFilter> quadrics;
    quadrics->SetInputData(sphere);
    quadrics->Update();
    auto withLifts = vtkSmartPointer<vtkPolyData>::New();
    withLifts->DeepCopy(quadrics->GetOutput());
    auto withoutLifts = vtkSmartPointer<vtkPolyData>::New();
    withoutLifts->DeepCopy(withLifts);
    withoutLifts->GetPointData()->RemoveArray(vtkLocalQuadricFilter::HullLiftArrayName());
    auto unlifted = vtkSmartPointer<vtkPolyData>::New();
    unlifted->DeepCopy(withLifts);
    vtkDataArray* zero = unlifted->GetPointData()->GetArray(vtkLocalQuadricFilter::HullLiftArrayName());
    zero->Fill(0.0);
    std::vector<unsigned char> images[3];
    vtkPolyData* meshes[3] = { withLifts, withoutLifts, unlifted };
    for (int k = 0; k < 3; ++k)
    {
      vtkNew<vtkRenderWindow> window;
      window->SetOffScreenRendering(1);
      Show<vtkOpenGLQuadricReliefMapper>(window, meshes[k], 0.0, 1.0);
      window->Render();
      images[k] = ReliefScene::Pixels(window);
    }
    const double computed = MeanDifference(images[0], images[1]);
    const double none = MeanDifference(images[0], images[2]);
    std::cout << "lifts computed from the mesh's quadrics against the filter's: " << computed
              << " levels; no lift: " << none << "\n";
    check(computed < 0.01, "quadrics without lifts are lifted as the filter lifts them");
    check(none > 10.0 * std::max(computed, 0.01), "the lifts move the hull");
  }

  // bad quadric arrays and grid searches: one warning each, then it draws
  vtkNew<vtkRenderWindow> window;
  auto badSphere = vtkSmartPointer<vtkPolyData>::New();
  badSphere->DeepCopy(sphere);
  vtkNew<vtkFloatArray> wrong;
  wrong->SetName(vtkLocalQuadricFilter::QuadricArrayName());
  wrong->SetNumberOfComponents(3);
  wrong->SetNumberOfTuples(badSphere->GetNumberOfPoints());
  wrong->Fill(1.0);
  badSphere->GetPointData()->AddArray(wrong);
  auto sphereMapper = Show<vtkOpenGLQuadricReliefMapper>(window, badSphere, 0.0, 0.5);
  auto torusMapper = Show<vtkOpenGLQuadricReliefMapper>(window, torus, 0.5, 1.0);
  vtkNew<ReliefEventRecorder> messages;
  sphereMapper->AddObserver(vtkCommand::WarningEvent, messages);
  sphereMapper->AddObserver(vtkCommand::ErrorEvent, messages);
  window->Render();
  window->Render();
  check(messages->Count(vtkCommand::WarningEvent) == 1 &&
      messages->AnyMessageContains(vtkLocalQuadricFilter::QuadricArrayName()),
    "a quadric array of the wrong size: one warning");
  // an array of the right name but no numbers: the same
  vtkNew<vtkStringArray> words;
  words->SetName(vtkLocalQuadricFilter::QuadricArrayName());
  words->SetNumberOfValues(badSphere->GetNumberOfPoints());
  badSphere->GetPointData()->RemoveArray(vtkLocalQuadricFilter::QuadricArrayName());
  badSphere->GetPointData()->AddArray(words);
  badSphere->Modified();
  messages->Clear();
  window->Render();
  window->Render();
  check(messages->Count(vtkCommand::WarningEvent) == 1 &&
      messages->AnyMessageContains("vtkStringArray"),
    "a quadric array of strings: one warning");
  messages->Clear();
  sphereMapper->SetSearchMethodToConeStep();
  window->Render();
  window->Render();
  check(messages->Count(vtkCommand::WarningEvent) == 1 && messages->AnyMessageContains("ConeStep"),
    "a grid search: one warning");
  check(sphereMapper->GetActiveSearchMethod() == vtkOpenGLReliefMapper::LINEAR_BINARY,
    "a grid search falls back to LinearBinary");
  sphereMapper->SetSearchMethodToLinearBinary();
  window->Render();

  // a mesh without texture coordinates: one error naming them, and it draws plainly
  {
    auto bare = vtkSmartPointer<vtkPolyData>::New();
    bare->DeepCopy(sphere);
    bare->GetPointData()->SetTCoords(nullptr);
    vtkNew<vtkRenderWindow> bareWindow;
    bareWindow->SetOffScreenRendering(1);
    auto bareMapper = Show<vtkOpenGLQuadricReliefMapper>(bareWindow, bare, 0.0, 1.0);
    vtkNew<ReliefEventRecorder> errors;
    bareMapper->AddObserver(vtkCommand::ErrorEvent, errors);
    bareMapper->AddObserver(vtkCommand::WarningEvent, errors);
    const long background = BackgroundPixels(bareWindow);
    bareWindow->Render();
    check(errors->Count(vtkCommand::ErrorEvent) == 1 &&
        errors->AnyMessageContains("texture coordinates"),
      "a mesh without texture coordinates: one error");
    check(background < 300L * 600L - 2000L, "a mesh without texture coordinates draws plainly");
  }

  const int image = vtkRegressionTestImage(window);
  return check.Passed() && image == vtkTesting::PASSED ? EXIT_SUCCESS : EXIT_FAILURE;
}
