#include "ReliefSweeps.h"

#include "ReliefChart.h"
#include "ReliefMetrics.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkPolyDataNormals.h"
#include "vtkPoints.h"
#include "vtkPointData.h"
#include "vtkPlaneSource.h"
#include "vtkMath.h"
#include "vtkFloatArray.h"
#include "vtkCellArray.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexturedSphereSource.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <tuple>
#include <vector>

namespace
{
// One scene of a sweep: the quantity's value and what is drawn.
struct Case
{
  double Value;
  vtkSmartPointer<vtkPolyData> Surface; // what the relief mapper draws
  vtkSmartPointer<vtkPolyData> Fine;    // the same surface regenerated finely for the truth
                                        // (parametric surfaces), or null: Surface subdivided
  vtkSmartPointer<vtkImageData> Heights;
  double DepthScale;
  double Angle; // view angle from +z, degrees
  double Dolly; // after ViewSquare's framing: above 1 comes closer
};

struct Sweep
{
  std::string Name;      // a title
  std::string Parameter; // the x axis
  std::string File;      // chart file name
  std::string Failure;   // what the chart shows failing, for the reader
  bool Silhouettes;      // chart all wrong pixels, not only those with a wrong depth
  std::vector<Case> Cases;
};

// A method's error in one case: all wrong pixels (coverage or depth), and the share of
// the pixels both cover whose depth is wrong (the search's own failures).
struct Error
{
  double Wrong;
  double WrongDepth;
};

vtkSmartPointer<vtkImageData> Stones(int size)
{
  return ReliefScene::ResizedHeightMap("stones_height.png", size);
}

// A 64x64 height image (white = high) of walls `width` texels wide every 16 texels along
// both axes, rising from a low floor: Baboud and Decoret's (2006) Fig. 11, feature width as a
// parameter.
vtkSmartPointer<vtkImageData> Walls(int width)
{
  return ReliefScene::HeightImage(
    64, 64, [=](int i, int j) { return i % 16 < width || j % 16 < width ? 1.0f : 0.2f; });
}

// A sphere of `radius` whose texture tiles keep one texel the same world size at every
// radius, so only the curvature under the relief changes.
vtkSmartPointer<vtkPolyData> Sphere(double radius, int theta, int phi)
{
  vtkNew<vtkTexturedSphereSource> source;
  source->SetRadius(radius);
  source->SetThetaResolution(theta);
  source->SetPhiResolution(phi);
  source->Update();
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(source->GetOutput());
  ReliefScene::TileTextureCoordinates(sphere, 4.0 * radius, 2.0 * radius);
  return sphere;
}

// The saddle z = k (x^2 - y^2) over the unit square, `resolution` quads a side, texture
// coordinates 2 tiles across, normals of the surface itself.
vtkSmartPointer<vtkPolyData> Saddle(double k, int resolution)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.5, -0.5, 0.0);
  plane->SetPoint1(0.5, -0.5, 0.0);
  plane->SetPoint2(-0.5, 0.5, 0.0);
  plane->SetResolution(resolution, resolution);
  plane->Update();
  auto saddle = vtkSmartPointer<vtkPolyData>::New();
  saddle->DeepCopy(plane->GetOutput());
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(saddle->GetNumberOfPoints());
  for (vtkIdType id = 0; id < saddle->GetNumberOfPoints(); ++id)
  {
    double p[3];
    saddle->GetPoint(id, p);
    p[2] = k * (p[0] * p[0] - p[1] * p[1]);
    saddle->GetPoints()->SetPoint(id, p);
    double n[3] = { -2.0 * k * p[0], 2.0 * k * p[1], 1.0 };
    vtkMath::Normalize(n);
    normals->SetTuple(id, n);
  }
  saddle->GetPointData()->SetNormals(normals);
  ReliefScene::TileTextureCoordinates(saddle, 2.0, 2.0);
  return saddle;
}

// Two unit squares sharing the edge x = 0, the second folded down about it by `crease`
// degrees: a ridge. Texture coordinates run on across the fold (2 x 1 tiles); the
// normals are averaged at the ridge, not split, so the relief bends round it.
vtkSmartPointer<vtkPolyData> Ridge(double crease)
{
  const double radians = vtkMath::RadiansFromDegrees(crease);
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> quads;
  for (int column = 0; column < 3; ++column) // x = -1, 0, then 1 folded down
  {
    const double x = column < 2 ? column - 1.0 : std::cos(radians);
    const double z = column < 2 ? 0.0 : -std::sin(radians);
    for (int row = 0; row < 2; ++row)
    {
      points->InsertNextPoint(x, row - 0.5, z);
      tcoords->InsertNextTuple2(column, row);
    }
  }
  for (vtkIdType column = 0; column < 2; ++column)
  {
    const vtkIdType quad[4] = { 2 * column, 2 * column + 2, 2 * column + 3, 2 * column + 1 };
    quads->InsertNextCell(4, quad);
  }
  vtkNew<vtkPolyData> ridge;
  ridge->SetPoints(points);
  ridge->SetPolys(quads);
  ridge->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(ridge);
  normals->SplittingOff();
  normals->Update();
  return normals->GetOutput();
}

std::vector<Sweep> Sweeps(bool quick)
{
  auto pick = [&](std::vector<double> all, std::vector<double> few) { return quick ? few : all; };
  auto square = ReliefScene::Square(4.0);
  auto stones = Stones(64);
  std::vector<Sweep> sweeps;

  Sweep angle{ "Error against view angle", "view angle from the normal (degrees)",
    "sweep_angle.png",
    "The steeper the view, the longer each ray's run through the relief and the more "
    "ridges a fixed step passes over; the exact searches stay exact in depth. Near "
    "edge-on the outline takes over: the sunken truth covers pixels the flat polygon does "
    "not, and the reverse, whatever the search.",
    false };
  for (double value : pick({ 0, 30, 50, 65, 75, 80, 85, 89 }, { 0, 60, 85 }))
  {
    angle.Cases.push_back({ value, square, nullptr, stones, 0.05, value, 3.0 });
  }
  sweeps.push_back(angle);

  Sweep width{ "Error against feature width", "wall width (texels)", "sweep_width.png",
    "Fixed steps pass through walls narrower than a step's footprint; Linear alone is "
    "off in depth by up to a step wherever it hits, which wide walls show most.",
    false };
  for (double value : pick({ 1, 2, 3, 4, 8 }, { 1, 4 }))
  {
    const auto walls = Walls(static_cast<int>(value));
    width.Cases.push_back({ value, ReliefScene::Square(1.0), nullptr, walls, 0.05, 45.0, 3.0 });
  }
  sweeps.push_back(width);

  Sweep curvature{ "Error against curvature", "sphere radius (1 / curvature)",
    "sweep_curvature.png",
    "On a curved surface the flat frame keeps the polygons' outline (the relief cannot "
    "carve the silhouette) and measures depth below flat facets rather than the curved "
    "surface (the truth: the sphere regenerated finely, then displaced), whatever the "
    "search: what the quadric frame of Oliveira and Policarpo (2005) fixes.",
    true };
  for (double value : pick({ 0.25, 0.5, 1.0, 2.0 }, { 0.5, 2.0 }))
  {
    // facets of one size at every radius (64 around the unit sphere): the smaller the
    // sphere, the further its flat facets sag below it
    const int around = std::max(8, static_cast<int>(64.0 * value));
    curvature.Cases.push_back({ value, Sphere(value, around, around / 2),
      Sphere(value, 512, 256), stones, 0.03, 0.0, 0.8 });
  }
  sweeps.push_back(curvature);

  Sweep saddle{ "Error against saddle curvature", "k of the saddle z = k (x^2 - y^2)",
    "sweep_saddle.png",
    "A saddle curves both ways: the flat frame measures depth below flat triangles, and "
    "the truth (the saddle regenerated finely, then displaced) bends away from them.",
    true };
  for (double value : pick({ 0.0, 0.25, 0.5, 1.0 }, { 0.0, 1.0 }))
  {
    saddle.Cases.push_back(
      { value, Saddle(value, 8), Saddle(value, 256), stones, 0.03, 30.0, 1.0 });
  }
  sweeps.push_back(saddle);

  Sweep crease{ "Error against crease angle", "crease angle (degrees)", "sweep_crease.png",
    "Two faces meet at a ridge with their normals averaged there, as on a smooth-shaded "
    "mesh: the relief is searched below each flat face while the truth follows the "
    "interpolated normals, and the sharper the fold, the further they part.",
    true };
  for (double value : pick({ 0, 15, 30, 45, 60, 90 }, { 0, 45 }))
  {
    crease.Cases.push_back({ value, Ridge(value), nullptr, stones, 0.05, 30.0, 1.0 });
  }
  sweeps.push_back(crease);

  Sweep depth{ "Error against depth scale", "DepthScale (world units at depth 1)",
    "sweep_depth.png",
    "Deeper relief lengthens every ray: fixed step counts fall behind, exact searches "
    "do not.",
    false };
  for (double value : pick({ 0.01, 0.02, 0.05, 0.1, 0.2 }, { 0.01, 0.1 }))
  {
    depth.Cases.push_back({ value, square, nullptr, stones, value, 45.0, 3.0 });
  }
  sweeps.push_back(depth);
  return sweeps;
}

// The errors of every search method in one case.
// The ground truths built so far, by surface, height map and depth scale: the cases of
// the view-angle sweep share one, of millions of triangles.
using TruthKey = std::tuple<vtkPolyData*, vtkImageData*, double>;
using Truths = std::map<TruthKey, vtkSmartPointer<vtkPolyData>>;

vtkPolyData* TruthOf(const Case& scene, Truths& truths)
{
  vtkPolyData* surface = scene.Fine ? scene.Fine : scene.Surface;
  vtkSmartPointer<vtkPolyData>& truth =
    truths[TruthKey(surface, scene.Heights, scene.DepthScale)];
  if (!truth)
  {
    vtkNew<vtkReliefTextureFilter> relief;
    relief->SetInputData(scene.Heights);
    relief->Update();
    truth = ReliefScene::DisplacedMesh(surface, relief->GetOutput(), scene.DepthScale, 0.5);
  }
  return truth;
}

std::vector<Error> Errors(
  const Case& scene, vtkRenderWindow* window, vtkRenderer* renderer, Truths& truths)
{
  renderer->RemoveAllViewProps();
  vtkNew<vtkPolyDataMapper> truthMapper;
  truthMapper->SetInputData(TruthOf(scene, truths));
  auto truth = ReliefScene::ReliefActor(truthMapper, "");
  vtkNew<vtkOpenGLReliefMapper> mapper;
  mapper->SetInputData(scene.Surface);
  mapper->SetHeightMapData(scene.Heights);
  mapper->SetDepthScale(scene.DepthScale);
  mapper->SetSelfShadowing(false); // the stock mapper casts no shadows
  mapper->SetFootprintShading(false); // the search's samples alone
  auto reliefActor = ReliefScene::ReliefActor(mapper, "");
  // framed on the coarse surface alone: the truth's sunken bounds would aim the camera
  // below the surface, and behind it at grazing angles
  renderer->AddActor(reliefActor);
  ReliefScene::ViewSquare(renderer, scene.Angle);
  renderer->GetActiveCamera()->Dolly(scene.Dolly);
  renderer->AddActor(truth);
  renderer->ResetCameraClippingRange();

  reliefActor->VisibilityOff();
  window->Render();
  const ReliefMetrics::Capture truthCapture = ReliefScene::Capture(window, renderer);
  truth->VisibilityOff();
  reliefActor->VisibilityOn();
  std::vector<Error> errors;
  for (int method : ReliefScene::SearchMethods())
  {
    mapper->SetSearchMethod(method);
    window->Render();
    const ReliefMetrics::Capture capture = ReliefScene::Capture(window, renderer);
    errors.push_back({ ReliefMetrics::WrongPixelFraction(capture, truthCapture, scene.DepthScale),
      ReliefMetrics::MeasureDepthError(capture, truthCapture, scene.DepthScale).FractionAbove });
  }
  return errors;
}

std::string Table(const Sweep& sweep, const std::vector<std::vector<Error>>& errors)
{
  std::ostringstream table;
  table << "| " << sweep.Parameter << " |";
  for (int method : ReliefScene::SearchMethods())
  {
    table << " " << vtkOpenGLReliefMapper::GetSearchMethodAsString(method) << " |";
  }
  table << "\n| ---: |";
  for (size_t m = 0; m < ReliefScene::SearchMethods().size(); ++m)
  {
    table << " ---: |";
  }
  table << "\n" << std::setprecision(3);
  for (size_t c = 0; c < sweep.Cases.size(); ++c)
  {
    table << "| " << sweep.Cases[c].Value << " |";
    for (const Error& error : errors[c])
    {
      table << " " << error.Wrong << " / " << error.WrongDepth << " |";
    }
    table << "\n";
  }
  return table.str();
}

// True when two lines of errors are within 1% of each other everywhere: one line on a
// log chart.
bool Indistinguishable(const std::vector<double>& a, const std::vector<double>& b)
{
  for (size_t i = 0; i < a.size(); ++i)
  {
    if (std::abs(a[i] - b[i]) > 0.01 * std::max(a[i], b[i]))
    {
      return false;
    }
  }
  return true;
}

// One line per method; methods whose errors are within 1% of each other in every case
// share a line (and a legend entry) rather than hide one another.
void Chart(
  const Sweep& sweep, const std::vector<std::vector<Error>>& errors, const std::string& file)
{
  std::vector<ReliefChart::Series> series;
  const std::vector<int>& methods = ReliefScene::SearchMethods();
  for (size_t m = 0; m < methods.size(); ++m)
  {
    ReliefChart::Series line{ vtkOpenGLReliefMapper::GetSearchMethodAsString(methods[m]) };
    line.Line = true;
    for (size_t c = 0; c < sweep.Cases.size(); ++c)
    {
      const Error& error = errors[c][m];
      line.X.push_back(sweep.Cases[c].Value);
      const double shown = sweep.Silhouettes ? error.Wrong : error.WrongDepth;
      line.Y.push_back(std::max(shown, ReliefChart::LogFloor));
    }
    auto same = std::find_if(series.begin(), series.end(),
      [&](const ReliefChart::Series& drawn) { return Indistinguishable(drawn.Y, line.Y); });
    if (same != series.end())
    {
      same->Name += ", " + line.Name;
    }
    else
    {
      series.push_back(line);
    }
  }
  ReliefChart::Axes axes;
  axes.Title = sweep.Name;
  axes.X = sweep.Parameter;
  axes.Y = sweep.Silhouettes ? "wrong pixels against the ground truth (share)"
                             : "pixels with a wrong depth (share of those both cover)";
  axes.LogY = true;
  axes.YRange[0] = ReliefChart::LogFloor;
  axes.YRange[1] = 10.0; // the top decade left to the legend
  ReliefChart::Write(series, axes, file);
}
}

namespace ReliefSweeps
{
std::string Run(const Options& options)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, options.Width, options.Height);
  if (!options.ImageDirectory.empty())
  {
    std::filesystem::create_directories(options.ImageDirectory);
  }
  std::ostringstream section;
  section << "Every search method at its default setting (Linear 10 steps, LinearBinary and "
             "Secant 10+5, SafetyRadius e = 0), self-shadowing off, against the ground truth "
             "of each scene (edges of 0.5 texel), in a "
          << options.Width << "x" << options.Height
          << " window. Each cell: the share of wrong pixels (as in the table above), then the "
             "share of the pixels both renders cover whose depth is more than 0.1 DepthScale "
             "off (the search's own failures, charted unless the sweep is about silhouettes). "
             "Methods within 1% of each other everywhere share a line; errors are charted at "
          << ReliefChart::LogFloor << " when below.\n\n";
  Truths truths;
  for (const Sweep& sweep : Sweeps(options.Quick))
  {
    std::vector<std::vector<Error>> errors;
    for (const Case& scene : sweep.Cases)
    {
      errors.push_back(Errors(scene, window, renderer, truths));
    }
    std::cout << "sweeps: " << sweep.Name << " done\n";
    section << "### " << sweep.Name << "\n\n" << sweep.Failure << "\n\n" << Table(sweep, errors)
            << "\n";
    if (!options.ImageDirectory.empty())
    {
      Chart(sweep, errors, options.ImageDirectory + "/" + sweep.File);
      section << "![" << sweep.Name << "](images/" << sweep.File << ")\n\n";
    }
  }
  return section.str();
}
}
