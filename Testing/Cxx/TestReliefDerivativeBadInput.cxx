// Bad input to vtkOpenGLDerivativeReliefMapper: where the screen-space derivatives hold no
// texture mapping (texture coordinates constant or collinear over a triangle, zero-area
// triangles) and where the normals have no direction (zero, NaN), the fragments are
// shaded plainly: no NaN, no black pixel, relief everywhere else, and nothing to say.
// A mesh without texture coordinates is drawn plainly with one error.
#include "ReliefEventRecorder.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLDerivativeReliefMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"

#include <cmath>
#include <iostream>
#include <limits>

namespace
{
int failures = 0;
void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "ERROR: derivative bad input check failed: " << what << "\n";
    ++failures;
  }
}

// A 16x16-quad square of side 1 in the xy plane, texture coordinates tiled twice, +z normals.
vtkSmartPointer<vtkPolyData> Grid()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.5, -0.5, 0.0);
  plane->SetPoint1(0.5, -0.5, 0.0);
  plane->SetPoint2(-0.5, 0.5, 0.0);
  plane->SetResolution(16, 16);
  plane->Update();
  auto grid = vtkSmartPointer<vtkPolyData>::New();
  grid->DeepCopy(plane->GetOutput());
  ReliefScene::TileTextureCoordinates(grid, 2.0, 2.0);
  return grid;
}

// Points of the grid with x < 0 (the left half), each passed to `change`.
template <typename Change>
void ChangeLeftHalf(vtkPolyData* grid, Change change)
{
  for (vtkIdType id = 0; id < grid->GetNumberOfPoints(); ++id)
  {
    double point[3];
    grid->GetPoint(id, point);
    if (point[0] < -1e-6)
    {
      change(id, point);
    }
  }
}

struct Census
{
  int Relief = 0;   // SampleCount mode: red, relief searched
  int NoSearch = 0; // SampleCount mode: black, shaded plainly by the relief shader
  int Plain = 0;    // SampleCount mode: the actor's green, drawn without relief
  int Black = 0;    // shaded: covered pixels with no light at all (NaN shows so)
  int BadDepth = 0; // shaded: covered pixels whose depth is not finite
  int Errors = 0;
  int Warnings = 0;
};

vtkRenderWindow* Window = nullptr;

Census Render(vtkPolyData* mesh)
{
  vtkNew<vtkOpenGLDerivativeReliefMapper> mapper;
  vtkNew<ReliefEventRecorder> recorder;
  mapper->AddObserver(vtkCommand::ErrorEvent, recorder);
  mapper->AddObserver(vtkCommand::WarningEvent, recorder);
  mapper->SetInputData(mesh);
  mapper->SetHeightMapData(ReliefScene::ReadImage("bricks_height.png"));
  mapper->SetDepthScale(0.05);

  Window->GetRenderers()->RemoveAllItems();
  auto renderer = ReliefScene::LitRenderer(Window, 160, 120);
  renderer->SetBackground(0.0, 0.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.0, 1.0, 0.0);
  actor->GetProperty()->SetAmbient(0.3);
  renderer->AddActor(actor);
  ReliefScene::ViewSquare(renderer, 30.0);

  Census census;
  Window->Render();
  const ReliefMetrics::Capture shaded = ReliefScene::Capture(Window, renderer);
  for (size_t pixel = 0; pixel < shaded.EyeDepth.size(); ++pixel)
  {
    const float* rgb = &shaded.Rgb[3 * pixel];
    if (rgb[2] > 0.5f && rgb[0] == 0.0f && rgb[1] == 0.0f)
    {
      continue; // background
    }
    census.Black += rgb[0] == 0.0f && rgb[1] == 0.0f && rgb[2] == 0.0f ? 1 : 0;
    census.BadDepth += std::isfinite(shaded.EyeDepth[pixel]) ? 0 : 1;
  }
  mapper->SetDisplayModeToSampleCount();
  Window->Render();
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(Window);
  for (size_t i = 0; i + 2 < pixels.size(); i += 3)
  {
    const int r = pixels[i], g = pixels[i + 1], b = pixels[i + 2];
    census.Relief += b == 0 && g == 0 && r > 0 ? 1 : 0;
    census.NoSearch += b == 0 && g == 0 && r == 0 ? 1 : 0;
    census.Plain += b == 0 && g > 0 && r == 0 ? 1 : 0;
  }
  census.Errors = recorder->Count(vtkCommand::ErrorEvent);
  census.Warnings = recorder->Count(vtkCommand::WarningEvent);
  std::cout << "relief " << census.Relief << ", shaded plainly " << census.NoSearch
            << ", drawn plainly " << census.Plain << "; black " << census.Black
            << ", bad depth " << census.BadDepth << "; errors " << census.Errors
            << ", warnings " << census.Warnings << "\n";
  return census;
}

constexpr int HalfCovered = 2500; // the square covers about 9000 of the 19200 pixels

void CheckHalfPlain(const Census& census, const std::string& what)
{
  Check(census.NoSearch > HalfCovered, what + ": the left half is shaded plainly");
  Check(census.Relief > HalfCovered, what + ": the right half keeps its relief");
  Check(census.Black == 0 && census.BadDepth == 0, what + ": no black pixel, no bad depth");
  Check(census.Errors == 0 && census.Warnings == 0, what + ": nothing to report");
}

void ConstantTextureCoordinates()
{
  auto grid = Grid();
  vtkDataArray* tcoords = grid->GetPointData()->GetTCoords();
  ChangeLeftHalf(grid, [&](vtkIdType id, const double*) { tcoords->SetTuple2(id, 0.3, 0.7); });
  CheckHalfPlain(Render(grid), "constant texture coordinates");
}

void CollinearTextureCoordinates()
{
  auto grid = Grid();
  vtkDataArray* tcoords = grid->GetPointData()->GetTCoords();
  ChangeLeftHalf(grid, [&](vtkIdType id, const double* point) {
    const double along = point[0] + point[1];
    tcoords->SetTuple2(id, along, 2.0 * along);
  });
  CheckHalfPlain(Render(grid), "collinear texture coordinates");
}

void ZeroAreaTriangles()
{
  // every point of the left half moved onto the middle line: its triangles have no area
  // and are never rasterized (no fragment, so no frame to fail); the triangles that span
  // the middle line and the right half keep their relief, silently
  auto grid = Grid();
  ChangeLeftHalf(grid, [&](vtkIdType id, const double* point) {
    grid->GetPoints()->SetPoint(id, 0.0, point[1], point[2]);
  });
  const Census census = Render(grid);
  Check(census.Relief > HalfCovered, "zero-area triangles: the right half keeps its relief");
  Check(census.Black == 0 && census.BadDepth == 0, "zero-area triangles: no black pixel");
  Check(census.Errors == 0 && census.Warnings == 0, "zero-area triangles: nothing to report");
}

void NormalsWithoutDirection()
{
  // zero and NaN normals fall back on the face's: relief everywhere, lit
  auto grid = Grid();
  vtkDataArray* normals = grid->GetPointData()->GetNormals();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  ChangeLeftHalf(grid, [&](vtkIdType id, const double* point) {
    const bool zero = point[1] < 0.0;
    normals->SetTuple3(id, zero ? 0.0 : nan, zero ? 0.0 : nan, zero ? 0.0 : nan);
  });
  const Census census = Render(grid);
  Check(census.Relief > 2 * HalfCovered, "normals without direction: relief everywhere");
  Check(census.Black == 0 && census.BadDepth == 0, "normals without direction: no black pixel");
}

void NoTextureCoordinates()
{
  auto grid = Grid();
  grid->GetPointData()->SetTCoords(nullptr);
  const Census census = Render(grid);
  Check(census.Errors == 1, "one error for a mesh without texture coordinates");
  Check(census.Plain > 2 * HalfCovered && census.Relief == 0, "the mesh is drawn plainly");
}
}

int TestReliefDerivativeBadInput(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  Window = window;
  ConstantTextureCoordinates();
  CollinearTextureCoordinates();
  ZeroAreaTriangles();
  NormalsWithoutDirection();
  NoTextureCoordinates();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
