// TestReliefBadInput <Tangent|Quadric|Derivative> <Case>: one kind of bad input given to
// one relief mapper (vtkOpenGLReliefMapper, vtkOpenGLQuadricReliefMapper or
// vtkOpenGLDerivativeReliefMapper). Each case gets the message it states, once, and sane
// pixels: where relief cannot be drawn the surface is shaded plainly, never black (the
// scene lights every covered pixel), never at a depth that is not finite; elsewhere the
// relief stays. The cases are listed in Cases below; CMake registers one test for each
// case and mapper.
//
// The mesh is a 16x16-quad unit square, texture tiled twice, with bricks 0.05 deep. Each
// render is read twice: shaded (black pixels, depths), then in SampleCount mode, where
// red pixels searched the relief, black ones were shaded plainly by the relief shader
// and the actor's green ones were drawn without relief at all.
#include "ReliefEventRecorder.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLDerivativeReliefMapper.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iostream>
#include <limits>
#include <string>

namespace
{
int Failures = 0;
void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "ERROR: bad input check failed: " << what << "\n";
    ++Failures;
  }
}

constexpr double Infinity = std::numeric_limits<double>::infinity();
constexpr double NotANumber = std::numeric_limits<double>::quiet_NaN();
constexpr int HalfCovered = 2500; // the square covers about 9000 of the 19200 pixels

std::string MapperName;
vtkRenderWindow* Window = nullptr;

// A new mapper of the kind under test, with the bricks.
vtkSmartPointer<vtkOpenGLReliefMapper> NewMapper()
{
  vtkSmartPointer<vtkOpenGLReliefMapper> mapper;
  if (MapperName == "Quadric")
  {
    mapper = vtkSmartPointer<vtkOpenGLQuadricReliefMapper>::New();
  }
  else if (MapperName == "Derivative")
  {
    mapper = vtkSmartPointer<vtkOpenGLDerivativeReliefMapper>::New();
  }
  else
  {
    mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
  }
  mapper->SetHeightMapData(ReliefScene::ReadImage("bricks_height.png"));
  mapper->SetDepthScale(0.05);
  return mapper;
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
void ChangeLeftHalf(vtkPolyData* grid, const std::function<void(vtkIdType, const double*)>& change)
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
  int Covered = 0;  // shaded: pixels other than the background
  int Black = 0;    // shaded: covered pixels with no light at all (NaN shows so)
  int BadDepth = 0; // shaded: covered pixels whose depth is not finite
  int Relief = 0;   // SampleCount: red, relief searched
  int NoSearch = 0; // SampleCount: black, shaded plainly by the relief shader
  int Plain = 0;    // SampleCount: the actor's green, drawn without relief
  int MaxSamples = 0;
  int Errors = 0;
  int Warnings = 0;
  std::vector<std::string> Messages;

  bool Says(const std::string& text) const
  {
    for (const std::string& message : this->Messages)
    {
      if (message.find(text) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
};

// Renders `mesh` with `mapper` on a blue background, shaded then by sample count, each
// twice (messages come once, not once per frame), and reports what it shows and says.
Census Render(vtkPolyData* mesh, vtkOpenGLReliefMapper* mapper)
{
  vtkNew<ReliefEventRecorder> recorder;
  mapper->AddObserver(vtkCommand::ErrorEvent, recorder);
  mapper->AddObserver(vtkCommand::WarningEvent, recorder);
  mapper->SetInputData(mesh);

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
  mapper->SetDisplayModeToShaded();
  Window->Render();
  Window->Render();
  const ReliefMetrics::Capture shaded = ReliefScene::Capture(Window, renderer);
  for (size_t pixel = 0; pixel < shaded.EyeDepth.size(); ++pixel)
  {
    const float* rgb = &shaded.Rgb[3 * pixel];
    if (rgb[2] == 1.0f && rgb[0] == 0.0f && rgb[1] == 0.0f)
    {
      continue; // background
    }
    ++census.Covered;
    census.Black += rgb[0] == 0.0f && rgb[1] == 0.0f && rgb[2] == 0.0f ? 1 : 0;
    census.BadDepth += std::isfinite(shaded.EyeDepth[pixel]) ? 0 : 1;
  }
  mapper->SetDisplayModeToSampleCount();
  Window->Render();
  Window->Render();
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(Window);
  for (size_t i = 0; i + 2 < pixels.size(); i += 3)
  {
    const int r = pixels[i], g = pixels[i + 1], b = pixels[i + 2];
    census.Relief += b == 0 && g == 0 && r > 0 ? 1 : 0;
    census.NoSearch += b == 0 && g == 0 && r == 0 ? 1 : 0;
    census.Plain += b == 0 && g > 0 && r == 0 ? 1 : 0;
    census.MaxSamples = b == 0 && g == 0 ? std::max(census.MaxSamples, r) : census.MaxSamples;
  }
  census.Errors = recorder->Count(vtkCommand::ErrorEvent);
  census.Warnings = recorder->Count(vtkCommand::WarningEvent);
  census.Messages = recorder->Messages;
  std::cout << "covered " << census.Covered << " (black " << census.Black << ", bad depth "
            << census.BadDepth << "); relief " << census.Relief << " (up to "
            << census.MaxSamples << " samples), shaded plainly " << census.NoSearch
            << ", drawn plainly " << census.Plain << "; errors " << census.Errors
            << ", warnings " << census.Warnings << "\n";
  for (const std::string& message : census.Messages)
  {
    std::cout << "  said: " << message;
  }
  return census;
}

void CheckSane(const Census& census, const std::string& what)
{
  Check(census.Black == 0 && census.BadDepth == 0, what + ": no black pixel, no bad depth");
}

void CheckOneWarning(const Census& census, const std::string& text, const std::string& what)
{
  Check(census.Errors == 0 && census.Warnings == 1 && census.Says(text),
    what + ": one warning that says \"" + text + "\"");
}

// One warning that says `text`, relief on the whole square, sane pixels.
void CheckWarnedWithRelief(const Census& census, const std::string& text, const std::string& what)
{
  CheckOneWarning(census, text, what);
  Check(census.Relief > 2 * HalfCovered, what + ": relief on the whole square");
  CheckSane(census, what);
}

void CheckSilent(const Census& census, const std::string& what)
{
  Check(census.Errors == 0 && census.Warnings == 0, what + ": nothing to report");
}

// A depth scale the mapper cannot draw: one warning, the whole square shaded plainly.
void CheckFlat(double depthScale, const std::string& text)
{
  auto mapper = NewMapper();
  mapper->SetDepthScale(depthScale);
  const std::string what = "DepthScale " + std::to_string(depthScale);
  const Census census = Render(Grid(), mapper);
  CheckOneWarning(census, text, what);
  Check(census.NoSearch > 2 * HalfCovered && census.Relief == 0, what + ": drawn flat");
  CheckSane(census, what);
}

//------------------------------------------------------------------------------
void DepthScaleNotFinite()
{
  for (double depthScale : { Infinity, -Infinity, NotANumber })
  {
    CheckFlat(depthScale, "not a world depth");
  }
}

void DepthScaleNotPositive()
{
  for (double depthScale : { 0.0, -0.1 })
  {
    CheckFlat(depthScale, "Set a positive world depth");
  }
}

void DepthScaleHuge()
{
  CheckFlat(1e6, "deeper than the whole mesh");
}

void TextureCoordinatesNotFinite()
{
  auto grid = Grid();
  vtkDataArray* tcoords = grid->GetPointData()->GetTCoords();
  ChangeLeftHalf(grid, [&](vtkIdType id, const double* point) {
    const double bad = point[1] < 0.0 ? NotANumber : Infinity;
    tcoords->SetTuple2(id, bad, 0.5);
  });
  const Census census = Render(grid, NewMapper());
  CheckOneWarning(census, "texture coordinates that are not finite", "texture coordinates");
  Check(census.NoSearch > HalfCovered, "texture coordinates: the left half is shaded plainly");
  Check(census.Relief > HalfCovered, "texture coordinates: the right half keeps its relief");
  CheckSane(census, "texture coordinates");
}

void NormalsWithoutDirection()
{
  // zero and NaN normals: the surface's own normal stands in, relief everywhere, lit
  auto grid = Grid();
  vtkDataArray* normals = grid->GetPointData()->GetNormals();
  ChangeLeftHalf(grid, [&](vtkIdType id, const double* point) {
    const double bad = point[1] < 0.0 ? 0.0 : NotANumber;
    normals->SetTuple3(id, bad, bad, bad);
  });
  CheckWarnedWithRelief(Render(grid, NewMapper()), "normals without a direction", "normals");
}

void PointsNotFinite()
{
  auto grid = Grid();
  grid->GetPoints()->SetPoint(40, NotANumber, 0.0, 0.0);
  grid->GetPoints()->SetPoint(41, 0.0, Infinity, 0.0);
  // the triangles around them are left out, a few of the 512
  CheckWarnedWithRelief(Render(grid, NewMapper()), "are not finite", "points");
}

void CellsReferToMissingPoints()
{
  // a broken file: two quads name points the mesh does not have (VTK's OBJ reader passes
  // such face indices through); the mapper leaves them out instead of reading past
  auto grid = Grid();
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell : { 10, 100 })
  {
    grid->GetPolys()->GetCellAtId(cell, ids);
    ids->SetId(1, cell == 10 ? 100000 : -3);
    grid->GetPolys()->ReplaceCellAtId(cell, ids);
  }
  auto mapper = NewMapper();
  double bounds[6];
  mapper->SetInputData(grid);
  mapper->GetBounds(bounds);
  Check(bounds[0] == -0.5 && bounds[1] == 0.5 && bounds[2] == -0.5 && bounds[3] == 0.5 &&
      bounds[4] == 0.0 && bounds[5] == 0.0,
    "broken cells: the bounds are the square's");
  const Census census = Render(grid, mapper);
  Check(census.Errors == 1 && census.Warnings == 0 && census.Says("refer to points"),
    "broken cells: one error");
  Check(census.Relief > 2 * HalfCovered, "broken cells: the other cells keep their relief");
  CheckSane(census, "broken cells");
}

void MeshWithoutNormals()
{
  auto grid = Grid();
  grid->GetPointData()->SetNormals(nullptr);
  const Census census = Render(grid, NewMapper());
  CheckSilent(census, "no normals");
  Check(census.Relief > 2 * HalfCovered, "no normals: relief everywhere");
  CheckSane(census, "no normals");
}

// Texture coordinates that map no area on the left half (constant or collinear): no
// direction for the relief there, and rays that would run without end (assimp's
// spider.obj: 1292 of its 1368 triangles, 19 s a frame). Shaded plainly, with one
// warning; relief on the right half.
void CheckDegenerateLeftHalf(vtkPolyData* grid, const std::string& what)
{
  const Census census = Render(grid, NewMapper());
  CheckOneWarning(census, "texture coordinates without area", what);
  Check(census.Relief > HalfCovered, what + ": the right half keeps its relief");
  Check(census.NoSearch > HalfCovered, what + ": the left half is shaded plainly");
  CheckSane(census, what);
}

void TextureCoordinatesDegenerate()
{
  auto constant = Grid();
  vtkDataArray* tcoords = constant->GetPointData()->GetTCoords();
  ChangeLeftHalf(constant, [&](vtkIdType id, const double*) { tcoords->SetTuple2(id, 0.3, 0.7); });
  CheckDegenerateLeftHalf(constant, "constant texture coordinates");

  auto collinear = Grid();
  tcoords = collinear->GetPointData()->GetTCoords();
  ChangeLeftHalf(collinear, [&](vtkIdType id, const double* point) {
    const double along = point[0] + point[1];
    tcoords->SetTuple2(id, along, 2.0 * along);
  });
  CheckDegenerateLeftHalf(collinear, "collinear texture coordinates");
}

void TrianglesWithoutArea()
{
  // every point of the left half moved onto the middle line: its triangles have no area
  // and are never rasterized
  auto grid = Grid();
  ChangeLeftHalf(grid, [&](vtkIdType id, const double* point) {
    grid->GetPoints()->SetPoint(id, 0.0, point[1], point[2]);
  });
  const Census census = Render(grid, NewMapper());
  CheckSilent(census, "zero-area triangles");
  Check(census.Relief > HalfCovered, "zero-area triangles: the right half keeps its relief");
  CheckSane(census, "zero-area triangles");
}

void NoTextureCoordinates()
{
  auto grid = Grid();
  grid->GetPointData()->SetTCoords(nullptr);
  const Census census = Render(grid, NewMapper());
  Check(census.Errors == 1 && census.Warnings == 0 && census.Says("vtkTextureMapToPlane") &&
      census.Says("vtkTextureMapToSphere"),
    "no texture coordinates: one error naming the filters that map them");
  Check(census.Plain > 2 * HalfCovered && census.Relief == 0, "no texture coordinates: plain");
  CheckSane(census, "no texture coordinates");
}

void NoPolygons()
{
  // lines beside polygons: relief on the polygons, nothing to say
  auto grid = Grid();
  vtkNew<vtkCellArray> lines;
  const vtkIdType edge[2] = { 0, 1 };
  lines->InsertNextCell(2, edge);
  grid->SetLines(lines);
  Census census = Render(grid, NewMapper());
  CheckSilent(census, "lines beside polygons");
  Check(census.Relief > 2 * HalfCovered, "lines beside polygons: relief on the polygons");

  // lines alone: one error
  auto linesOnly = vtkSmartPointer<vtkPolyData>::New();
  linesOnly->SetPoints(grid->GetPoints());
  linesOnly->GetPointData()->SetTCoords(grid->GetPointData()->GetTCoords());
  linesOnly->SetLines(lines);
  census = Render(linesOnly, NewMapper());
  Check(census.Errors == 1 && census.Warnings == 0 && census.Says("no polygons"),
    "lines alone: one error");
}

void EmptyMesh()
{
  vtkNew<vtkPolyData> empty;
  const Census census = Render(empty, NewMapper());
  CheckSilent(census, "an empty mesh, as VTK's own mappers draw it");
  Check(census.Covered == 0, "an empty mesh draws nothing");
}

void NoHeightMap()
{
  auto mapper = NewMapper();
  mapper->SetHeightMapData(nullptr);
  const Census census = Render(Grid(), mapper);
  CheckOneWarning(census, "SetHeightMapConnection", "no height map");
  Check(census.Plain > 2 * HalfCovered && census.Relief == 0, "no height map: plain");
  CheckSane(census, "no height map");
}

void HeightMapNot2D()
{
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(8, 8, 8);
  volume->AllocateScalars(VTK_FLOAT, 1);
  vtkNew<vtkImageData> empty;
  for (vtkImageData* image :
    { static_cast<vtkImageData*>(volume), static_cast<vtkImageData*>(empty) })
  {
    auto mapper = NewMapper();
    mapper->SetHeightMapData(image);
    const Census census = Render(Grid(), mapper);
    Check(census.Errors == 1 && census.Warnings == 0, "a 3D or empty height map: one error");
    Check(census.Plain > 2 * HalfCovered && census.Relief == 0,
      "a 3D or empty height map: plain");
    CheckSane(census, "a 3D or empty height map");
  }
}

void HeightMapNotFinite()
{
  auto heights = ReliefScene::HeightImage(
    64, 64, [](int i, int j) { return 0.5f + 0.4f * std::sin(0.3f * (i + 64 * j)); });
  auto* values = static_cast<float*>(heights->GetScalarPointer());
  values[5] = std::numeric_limits<float>::quiet_NaN();
  values[700] = std::numeric_limits<float>::infinity();
  values[1400] = -std::numeric_limits<float>::infinity();
  auto mapper = NewMapper();
  mapper->SetHeightMapData(heights);
  mapper->FootprintShadingOff(); // the samples of one search
  const Census census = Render(Grid(), mapper);
  CheckWarnedWithRelief(census, "non-finite height(s)", "NaN and infinite heights");
  // the display counts up to 255 samples a pixel
  Check(census.MaxSamples < 255, "NaN and infinite heights: the default search ends");
  mapper->SetSearchMethodToLinearBinary();
  const Census fixed = Render(Grid(), mapper);
  Check(fixed.MaxSamples <= 15, "NaN and infinite heights: every search ends within its steps");
  CheckSane(fixed, "NaN and infinite heights, LinearBinary");
}

void StepsOutOfRange()
{
  auto mapper = NewMapper();
  vtkNew<ReliefEventRecorder> recorder;
  mapper->AddObserver(vtkCommand::WarningEvent, recorder);
  mapper->SetLinearSteps(100000);
  Check(mapper->GetLinearSteps() == 512, "LinearSteps clamps to 512");
  mapper->SetLinearSteps(0);
  Check(mapper->GetLinearSteps() == 1, "LinearSteps clamps to 1");
  mapper->SetBinarySteps(-3);
  Check(mapper->GetBinarySteps() == 0, "BinarySteps clamps to 0");
  mapper->SetBinarySteps(99);
  Check(mapper->GetBinarySteps() == 32, "BinarySteps clamps to 32");
  Check(recorder->Count(vtkCommand::WarningEvent) == 4, "each clamp warns");
  mapper->SetBinarySteps(0);
  mapper->SetSearchMethodToLinearBinary(); // the method that takes the steps
  mapper->FootprintShadingOff();           // the samples of one search
  const Census census = Render(Grid(), mapper);
  Check(census.Relief > 2 * HalfCovered && census.MaxSamples == 1,
    "one linear step and no bisection take exactly one sample");
  CheckSane(census, "one step");
}

void ScreenToleranceOutOfRange()
{
  auto mapper = NewMapper();
  vtkNew<ReliefEventRecorder> recorder;
  mapper->AddObserver(vtkCommand::WarningEvent, recorder);
  mapper->SetScreenTolerance(-1.0);
  Check(mapper->GetScreenTolerance() == 0.0, "a screen tolerance below 0 becomes 0");
  mapper->SetScreenTolerance(NotANumber);
  Check(mapper->GetScreenTolerance() == 0.5, "a screen tolerance that is NaN becomes 0.5");
  for (double pixels : { 1000.0, Infinity })
  {
    mapper->SetScreenTolerance(pixels);
    Check(mapper->GetScreenTolerance() == 100.0, "a screen tolerance above 100 becomes 100");
  }
  Check(recorder->Count(vtkCommand::WarningEvent) == 4, "each tolerance out of [0, 100] warns");
  for (double pixels : { 0.0, 100.0 })
  {
    // exact everywhere, and no search at all: the relief is drawn either way
    mapper->SetScreenTolerance(pixels);
    const Census census = Render(Grid(), mapper);
    Check(census.Relief > 2 * HalfCovered, "a screen tolerance of 0 or 100 draws the relief");
    CheckSane(census, "a screen tolerance of 0 or 100");
  }
}

void SafetyRadiusToleranceOutOfRange()
{
  auto mapper = NewMapper();
  vtkNew<ReliefEventRecorder> recorder;
  mapper->AddObserver(vtkCommand::WarningEvent, recorder);
  for (double tolerance : { -0.5, NotANumber })
  {
    mapper->SetSafetyRadiusTolerance(tolerance);
    Check(mapper->GetSafetyRadiusTolerance() == 0.0, "a tolerance below 0 or NaN becomes 0");
  }
  for (double tolerance : { 2.0, Infinity })
  {
    mapper->SetSafetyRadiusTolerance(tolerance);
    Check(mapper->GetSafetyRadiusTolerance() == 1.0, "a tolerance above 1 becomes 1");
  }
  Check(recorder->Count(vtkCommand::WarningEvent) == 4, "each tolerance out of [0, 1] warns");
}

const struct
{
  const char* Name;
  void (*Run)();
} Cases[] = {
  { "DepthScaleNotFinite", DepthScaleNotFinite },
  { "DepthScaleNotPositive", DepthScaleNotPositive },
  { "DepthScaleHuge", DepthScaleHuge },
  { "TextureCoordinatesNotFinite", TextureCoordinatesNotFinite },
  { "TextureCoordinatesDegenerate", TextureCoordinatesDegenerate },
  { "TrianglesWithoutArea", TrianglesWithoutArea },
  { "NormalsWithoutDirection", NormalsWithoutDirection },
  { "MeshWithoutNormals", MeshWithoutNormals },
  { "PointsNotFinite", PointsNotFinite },
  { "CellsReferToMissingPoints", CellsReferToMissingPoints },
  { "NoTextureCoordinates", NoTextureCoordinates },
  { "NoPolygons", NoPolygons },
  { "EmptyMesh", EmptyMesh },
  { "NoHeightMap", NoHeightMap },
  { "HeightMapNot2D", HeightMapNot2D },
  { "HeightMapNotFinite", HeightMapNotFinite },
  { "StepsOutOfRange", StepsOutOfRange },
  { "ScreenToleranceOutOfRange", ScreenToleranceOutOfRange },
  { "SafetyRadiusToleranceOutOfRange", SafetyRadiusToleranceOutOfRange },
};
}

int TestReliefBadInput(int argc, char* argv[])
{
  // the test driver passes -D, -T and -V with their values; the two words are first
  if (argc < 3)
  {
    std::cerr << "ERROR: usage: TestReliefBadInput <Tangent|Quadric|Derivative> <case>, or "
                 "TestReliefBadInput Cases <count>\n";
    return EXIT_FAILURE;
  }
  // CMake registers the cases it reads from the table above: as many as there are
  if (std::strcmp(argv[1], "Cases") == 0)
  {
    const int registered = std::atoi(argv[2]);
    const int count = static_cast<int>(sizeof(Cases) / sizeof(Cases[0]));
    if (registered != count)
    {
      std::cerr << "ERROR: CMake registered " << registered << " bad-input cases of the "
                << count << " in TestReliefBadInput.cxx: keep each on one line of the table\n";
      return EXIT_FAILURE;
    }
    return EXIT_SUCCESS;
  }
  MapperName = argv[1];
  if (MapperName != "Tangent" && MapperName != "Quadric" && MapperName != "Derivative")
  {
    std::cerr << "ERROR: unknown mapper " << MapperName << "\n";
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  Window = window;
  for (const auto& c : Cases)
  {
    if (std::strcmp(c.Name, argv[2]) == 0)
    {
      c.Run();
      return Failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
    }
  }
  std::cerr << "ERROR: unknown case " << argv[2] << "\n";
  return EXIT_FAILURE;
}
