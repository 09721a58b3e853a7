// Every bad input the relief mapper handles: a clear error or warning, the program
// keeps working, and the scene still draws (plainly where relief cannot be drawn).
// The window is read back in SampleCount mode on a blue background: relief pixels are
// pure red (the sample count), plain pixels are the actor's green.
#include "ReliefEventRecorder.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkSphereSource.h"

#include <cmath>
#include <iostream>
#include <limits>

namespace
{
struct PixelCensus
{
  int Relief = 0;       // red only: relief drawn, red = samples
  int ZeroSamples = 0;  // black: relief path with no search
  int Plain = 0;        // green: drawn without relief
  int MaxSamples = 0;
  int MinSamples = 256;
};

struct Outcome
{
  PixelCensus Pixels;
  int Errors = 0;
  int Warnings = 0;
  std::vector<std::string> Messages;
};

// One window for every case: opening many X connections in a row is itself flaky.
vtkRenderWindow* Window = nullptr;

// Renders `surface` twice with `mapper` and reports what the window shows and what the
// mapper said.
Outcome Render(vtkPolyData* surface, vtkOpenGLReliefMapper* mapper)
{
  vtkNew<ReliefEventRecorder> recorder;
  // the mapper reports its internal filters' messages as its own
  mapper->AddObserver(vtkCommand::ErrorEvent, recorder);
  mapper->AddObserver(vtkCommand::WarningEvent, recorder);
  mapper->SetInputData(surface);
  mapper->SetDisplayModeToSampleCount();

  vtkRenderWindow* window = Window;
  window->GetRenderers()->RemoveAllItems();
  auto renderer = ReliefScene::LitRenderer(window, 160, 120);
  renderer->SetBackground(0.0, 0.0, 1.0);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.0, 1.0, 0.0);
  actor->GetProperty()->SetAmbient(1.0);
  renderer->AddActor(actor);
  ReliefScene::ViewSquare(renderer, 30.0);
  window->Render();
  window->Render(); // messages come once, not once per frame

  Outcome outcome;
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  for (size_t i = 0; i + 2 < pixels.size(); i += 3)
  {
    const int r = pixels[i], g = pixels[i + 1], b = pixels[i + 2];
    if (b > 0)
    {
      continue; // background
    }
    if (g > 0 && r == 0)
    {
      ++outcome.Pixels.Plain;
    }
    else if (g == 0 && r > 0)
    {
      ++outcome.Pixels.Relief;
      outcome.Pixels.MaxSamples = std::max(outcome.Pixels.MaxSamples, r);
      outcome.Pixels.MinSamples = std::min(outcome.Pixels.MinSamples, r);
    }
    else if (g == 0 && r == 0)
    {
      ++outcome.Pixels.ZeroSamples;
    }
  }
  outcome.Errors = recorder->Count(vtkCommand::ErrorEvent);
  outcome.Warnings = recorder->Count(vtkCommand::WarningEvent);
  outcome.Messages = recorder->Messages;
  std::cout << "pixels: relief " << outcome.Pixels.Relief << " (samples "
            << outcome.Pixels.MinSamples << " to " << outcome.Pixels.MaxSamples << "), no search "
            << outcome.Pixels.ZeroSamples << ", plain " << outcome.Pixels.Plain << "; errors "
            << outcome.Errors << ", warnings " << outcome.Warnings << "\n";
  return outcome;
}

bool Contains(const Outcome& outcome, const std::string& text)
{
  for (const std::string& message : outcome.Messages)
  {
    if (message.find(text) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

int failures = 0;
void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "Bad input check failed: " << what << "\n";
    ++failures;
  }
}

vtkSmartPointer<vtkOpenGLReliefMapper> BricksMapper()
{
  auto mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
  mapper->SetHeightMapData(ReliefScene::ReadImage("bricks_height.png"));
  mapper->SetDepthScale(0.05);
  return mapper;
}

constexpr int Covered = 4000; // the square covers about 9000 of the 19200 pixels

void MeshWithoutTextureCoordinates()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.4);
  sphere->Update();
  Outcome outcome = Render(sphere->GetOutput(), BricksMapper());
  Check(outcome.Errors == 1, "one error for a mesh without texture coordinates");
  Check(Contains(outcome, "vtkTextureMapToPlane") && Contains(outcome, "vtkTextureMapToSphere"),
    "the error names the filters that make texture coordinates");
  Check(outcome.Pixels.Plain > 2000 && outcome.Pixels.Relief == 0, "the sphere still renders plainly");
}

void MeshWithLinesAndVertices()
{
  // a square with a line along one edge: relief on the triangles, no crash
  auto square = ReliefScene::Square(2.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType edge[2] = { 0, 1 };
  lines->InsertNextCell(2, edge);
  square->SetLines(lines);
  Outcome outcome = Render(square, BricksMapper());
  Check(outcome.Errors == 0, "lines beside polygons are no error");
  Check(outcome.Pixels.Relief > Covered, "relief is drawn on the polygons of a mesh with lines");

  auto linesOnly = vtkSmartPointer<vtkPolyData>::New();
  linesOnly->SetPoints(square->GetPoints());
  linesOnly->GetPointData()->SetTCoords(square->GetPointData()->GetTCoords());
  linesOnly->SetLines(lines);
  outcome = Render(linesOnly, BricksMapper());
  Check(outcome.Errors == 1 && Contains(outcome, "no polygons"), "one error for lines alone");
}

void MeshWithoutNormals()
{
  auto square = ReliefScene::Square(2.0);
  square->GetPointData()->SetNormals(nullptr);
  Outcome outcome = Render(square, BricksMapper());
  Check(outcome.Errors == 0 && outcome.Warnings == 0, "normals are computed silently");
  Check(outcome.Pixels.Relief > Covered, "relief is drawn with computed normals");
}

void NoHeightMap()
{
  auto mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
  Outcome outcome = Render(ReliefScene::Square(2.0), mapper);
  Check(outcome.Errors == 0 && outcome.Warnings == 1, "one warning without a height map");
  Check(Contains(outcome, "SetHeightMapConnection"), "the warning says how to give one");
  Check(outcome.Pixels.Plain > Covered, "the square renders plainly without a height map");
}

void HeightMapNot2D()
{
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(8, 8, 8);
  volume->AllocateScalars(VTK_FLOAT, 1);
  vtkNew<vtkImageData> empty;
  for (vtkImageData* image : { static_cast<vtkImageData*>(volume), static_cast<vtkImageData*>(empty) })
  {
    auto mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
    mapper->SetHeightMapData(image);
    Outcome outcome = Render(ReliefScene::Square(2.0), mapper);
    Check(outcome.Errors == 1, "one error for a 3D or empty height map");
    Check(outcome.Pixels.Plain > Covered, "the square renders plainly with a 3D or empty height map");
  }
}

void NonFiniteHeights()
{
  vtkNew<vtkImageData> heights;
  heights->SetDimensions(64, 64, 1);
  heights->AllocateScalars(VTK_FLOAT, 1);
  auto* values = static_cast<float*>(heights->GetScalarPointer());
  for (int i = 0; i < 64 * 64; ++i)
  {
    values[i] = 0.5f + 0.4f * std::sin(0.3f * i);
  }
  values[5] = std::numeric_limits<float>::quiet_NaN();
  values[700] = std::numeric_limits<float>::infinity();
  values[1400] = -std::numeric_limits<float>::infinity();
  auto mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
  mapper->SetHeightMapData(heights);
  mapper->SetDepthScale(0.05);
  Outcome outcome = Render(ReliefScene::Square(2.0), mapper);
  Check(outcome.Errors == 0 && outcome.Warnings == 1, "one warning for NaN and Inf heights");
  Check(outcome.Pixels.Relief > Covered, "relief is drawn from the clamped heights");
  Check(outcome.Pixels.MaxSamples <= 15, "every search ends within its steps");
}

void NonPositiveDepthScale()
{
  for (double depthScale : { 0.0, -0.1 })
  {
    auto mapper = BricksMapper();
    mapper->SetDepthScale(depthScale);
    Outcome outcome = Render(ReliefScene::Square(2.0), mapper);
    Check(outcome.Warnings == 1 && Contains(outcome, "DepthScale"), "one warning for DepthScale <= 0");
    Check(outcome.Pixels.ZeroSamples > Covered && outcome.Pixels.Relief == 0,
      "DepthScale <= 0 draws the surface flat, with no search");
  }
}

void StepsOutOfRange()
{
  auto mapper = BricksMapper();
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
  Outcome outcome = Render(ReliefScene::Square(2.0), mapper);
  Check(outcome.Pixels.Relief > Covered && outcome.Pixels.MaxSamples == 1,
    "one linear step and no bisection take exactly one sample");
}
}

int TestReliefBadInput(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  Window = window;
  MeshWithoutTextureCoordinates();
  MeshWithLinesAndVertices();
  MeshWithoutNormals();
  NoHeightMap();
  HeightMapNot2D();
  NonFiniteHeights();
  NonPositiveDepthScale();
  StepsOutOfRange();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
