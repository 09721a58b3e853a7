#include "ReliefQuadricStudy.h"

#include "ReliefChart.h"
#include "ReliefMetrics.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <array>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>

namespace
{
using ReliefQuadricStudy::Measurement;

struct Shape
{
  const char* Name;
  std::function<vtkSmartPointer<vtkPolyData>(int)> Make; // the shape at a resolution
  double Frame[6]; // what the views frame
};

// The cylinder's views frame its middle, so its outline is the curved sides, not the open
// rims (Oliveira and Policarpo 2005 have no answer at a mesh's boundary, where the relief
// ends with the mesh).
const Shape Shapes[] = {
  { "sphere", ReliefScene::Sphere, { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 } },
  { "cylinder", [](int resolution) { return ReliefScene::Cylinder(resolution); },
    { -0.4, 0.4, -0.4, 0.4, -0.5, 0.5 } },
  { "torus", ReliefScene::Torus, { -0.5, 0.5, -0.15, 0.15, -0.5, 0.5 } },
};
using View = std::array<double, 2>; // azimuth, elevation
const View Views[] = { { 0.0, 10.0 }, { 35.0, 30.0 }, { 70.0, -20.0 } };

// The views of a shape: the three above, and for the torus also its inner side, seen from
// `sweep` degrees off its axis, where the hole's saddle-shaped wall is seen at grazing
// angles.
std::vector<View> ViewsOf(const Shape& shape, const std::vector<double>& sweep)
{
  std::vector<View> views(std::begin(Views), std::end(Views));
  if (std::string(shape.Name) == "torus")
  {
    for (double angle : sweep)
    {
      views.push_back({ angle, 0.0 });
    }
  }
  return views;
}

bool IsSweep(const Measurement& m)
{
  return m.Elevation == 0.0;
}

void Aim(vtkRenderer* renderer, const View& view, const double frame[6], vtkPolyData* truth)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, -3.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->Azimuth(view[0]);
  camera->Elevation(view[1]);
  camera->OrthogonalizeViewUp();
  // framed on the shape, not on the sunken truth
  renderer->ResetCamera(frame);
  renderer->ResetCameraClippingRange(truth->GetBounds());
}

// "24, 32 and 48"
template <typename Number>
std::string List(const std::vector<Number>& values)
{
  std::ostringstream list;
  for (size_t k = 0; k < values.size(); ++k)
  {
    list << (k == 0 ? "" : k + 1 == values.size() ? " and " : ", ") << values[k];
  }
  return list.str();
}

// The rows of the documentation's picture: truth, bare polygons, flat and quadric frames.
using Pictures = std::vector<std::vector<ReliefMetrics::Capture>>;

// What the picture shows, at the first facet count: every shape from the second view with
// the shallowest relief (where the hull decides the outline), and the torus's inner side at
// 80 degrees at every depth.
bool Pictured(const Shape& shape, int facets, double depthScale, const View& view,
  const ReliefQuadricStudy::Options& options)
{
  const bool first = facets == options.Facets.front();
  const double shallowest =
    *std::min_element(options.DepthScales.begin(), options.DepthScales.end());
  return first &&
    ((depthScale == shallowest && view == Views[1]) ||
      (std::string(shape.Name) == "torus" && view == View{ 80.0, 0.0 }));
}

void MeasureShape(const Shape& shape, int facets, double depthScale, vtkImageData* heights,
  vtkImageData* relief, vtkRenderWindow* window, vtkRenderer* renderer,
  const ReliefQuadricStudy::Options& options, std::vector<Measurement>& measurements,
  Pictures& pictures)
{
  auto coarse = shape.Make(facets);
  auto truthMesh = ReliefScene::DisplacedMesh(shape.Make(256), relief, depthScale, 0.5);
  vtkNew<vtkPolyDataMapper> truthMapper;
  truthMapper->SetInputData(truthMesh);
  vtkNew<vtkPolyDataMapper> polygonMapper;
  polygonMapper->SetInputData(coarse);
  vtkNew<vtkOpenGLReliefMapper> flat;
  vtkNew<vtkOpenGLQuadricReliefMapper> approximate;
  vtkNew<vtkOpenGLQuadricReliefMapper> exact;
  exact->SetDistanceModeToExact();
  vtkOpenGLReliefMapper* mappers[] = { flat, approximate, exact };
  for (vtkOpenGLReliefMapper* mapper : mappers)
  {
    mapper->SetInputData(coarse);
    mapper->SetHeightMapData(heights);
    mapper->SetDepthScale(depthScale);
    mapper->SetSelfShadowing(false);    // the stock mapper casts no shadows
    mapper->SetFootprintShading(false); // the frames' samples alone
    mapper->SetLinearSteps(32);
    mapper->SetBinarySteps(6);
  }
  // the actors' default properties: the mappers decide which faces carry relief
  const std::vector<vtkSmartPointer<vtkActor>> actors = {
    ReliefScene::ReliefActor(truthMapper, ""), ReliefScene::ReliefActor(polygonMapper, ""),
    ReliefScene::ReliefActor(flat, ""), ReliefScene::ReliefActor(approximate, ""),
    ReliefScene::ReliefActor(exact, "")
  };
  ReliefScene::Lineup lineup(window, renderer, actors);
  for (const View& view : ViewsOf(shape, options.InnerSweep))
  {
    Aim(renderer, view, shape.Frame, truthMesh);
    const ReliefMetrics::Capture truth = lineup.Capture(actors[0]);
    const ReliefMetrics::Capture polygons = lineup.Capture(actors[1]);
    std::vector<ReliefMetrics::Capture> picture = { truth,
      ReliefMetrics::CoverageComparison(polygons, truth) };
    for (size_t f = 0; f < 3; ++f)
    {
      const ReliefMetrics::Capture frame = lineup.Capture(actors[2 + f]);
      Measurement measurement;
      measurement.Shape = shape.Name;
      measurement.Facets = facets;
      measurement.DepthScale = depthScale;
      measurement.Azimuth = view[0];
      measurement.Elevation = view[1];
      measurement.Frame = ReliefQuadricStudy::Frames()[f];
      measurement.SilhouetteError = ReliefMetrics::SilhouetteError(frame, polygons, truth);
      measurement.WrongCoverage = ReliefMetrics::CoverageDifference(frame, truth);
      measurement.PolygonWrongCoverage = ReliefMetrics::CoverageDifference(polygons, truth);
      measurement.TruthOutline = ReliefMetrics::OutlinePixels(truth);
      measurement.WrongPixels = ReliefMetrics::WrongPixelFraction(frame, truth, depthScale);
      measurement.MeanSamples = ReliefScene::SampleCounts(window, renderer, mappers[f]).Mean;
      measurements.push_back(measurement);
      if (f < 2)
      {
        picture.push_back(ReliefMetrics::CoverageComparison(frame, truth));
      }
    }
    if (Pictured(shape, facets, depthScale, view, options))
    {
      pictures.push_back(picture);
    }
    if (options.Frames > 0)
    {
      const std::vector<double> medians = lineup.InterleavedMilliseconds(
        { actors[2], actors[3], actors[4] }, options.Rounds, options.Frames);
      for (size_t f = 0; f < 3; ++f)
      {
        measurements[measurements.size() - 3 + f].Milliseconds = medians[f];
      }
    }
  }
}

void WritePictures(const Pictures& pictures, const ReliefQuadricStudy::Options& options)
{
  std::vector<std::vector<const ReliefMetrics::Capture*>> rows;
  for (const auto& row : pictures)
  {
    rows.emplace_back();
    for (const ReliefMetrics::Capture& capture : row)
    {
      rows.back().push_back(&capture);
    }
  }
  std::filesystem::create_directories(options.ImageDirectory);
  ReliefMetrics::WriteMosaic(rows, options.ImageDirectory + "/quadric_outlines.png");
}
}

namespace ReliefQuadricStudy
{
const std::vector<std::string>& Frames()
{
  static const std::vector<std::string> frames = { "flat", "quadric, approximate distance",
    "quadric, exact distance" };
  return frames;
}

std::vector<Measurement> Measure(const Options& options)
{
  auto heights = ReliefScene::ResizedHeightMap("stones_height.png", options.HeightMapSize);
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputData(heights);
  relief->Update();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, options.Width, options.Height);
  std::vector<Measurement> measurements;
  Pictures pictures;
  for (int facets : options.Facets)
  {
    for (const Shape& shape : Shapes)
    {
      if (std::find(options.Shapes.begin(), options.Shapes.end(), shape.Name) ==
        options.Shapes.end())
      {
        continue;
      }
      for (double depthScale : options.DepthScales)
      {
        MeasureShape(shape, facets, depthScale, heights, relief->GetOutput(), window, renderer,
          options, measurements, pictures);
      }
    }
  }
  if (!options.ImageDirectory.empty())
  {
    WritePictures(pictures, options);
  }
  return measurements;
}

std::string Report(const std::vector<Measurement>& measurements, const Options& options)
{
  std::ostringstream section;
  section << "Stones (the height map resampled to " << options.HeightMapSize << "x"
          << options.HeightMapSize << ") at DepthScale " << List(options.DepthScales)
          << " on a sphere of radius 0.5, a cylinder of radius 0.4 (its middle) and a torus (ring "
             "0.36, tube 0.14), "
          << List(options.Facets)
          << " facets around each (a torus half as many around its tube), three views each and "
             "the torus's inner side seen from "
          << List(options.InnerSweep)
          << " degrees off its axis (elevation 0), in a " << options.Width << "x" << options.Height
          << " window; the actors' default properties. At the shallow depth even the stones' "
             "tops lie closer to the surface than coarse polygons sag below it: the outline is "
             "the curved surface's, which only fragments outside the polygons can draw (the "
             "quadric mapper's hull). Ground truth: the shape regenerated with 256 facets around "
             "and displaced (vtkReliefDisplacementFilter, edges of at most 0.5 texel). Silhouette "
             "error: pixels whose coverage differs from the truth's, over the same count for the "
             "bare polygons (1: no better than the polygons, 0: perfect). Every frame searches "
             "with LinearBinary 32+6, self-shadowing off; "
          << options.Frames << " timed frames x " << options.Rounds
          << " interleaved rounds per row (median).\n\n";
  section << "| shape | facets | DepthScale | azimuth, elevation | frame | silhouette error | "
             "wrong coverage (pixels: frame, polygons) | wrong pixels | samples/pixel (mean) | "
             "ms/frame |\n"
          << "| --- | ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: |\n"
          << std::setprecision(3);
  for (const Measurement& m : measurements)
  {
    section << "| " << m.Shape << " | " << m.Facets << " | " << m.DepthScale << " | "
            << m.Azimuth << ", " << m.Elevation << " | " << m.Frame << " | " << m.SilhouetteError
            << " | " << m.WrongCoverage << ", " << m.PolygonWrongCoverage << " | "
            << m.WrongPixels << " | " << m.MeanSamples << " | " << m.Milliseconds
            << " |\n";
  }
  // per number of facets and frame: the worst silhouette error over the three views of
  // each shape and over the torus's inner side up to 80 degrees, the mean samples and the
  // mean time against the flat frame's in the same views
  std::map<std::pair<int, std::string>, std::vector<const Measurement*>> byFrame;
  for (const Measurement& m : measurements)
  {
    byFrame[{ m.Facets, m.Frame }].push_back(&m);
  }
  for (int facets : options.Facets)
  {
    const auto& flat = byFrame[{ facets, Frames()[0] }];
    section << "\nAt " << facets << " facets:";
    for (const std::string& frame : Frames())
    {
      const auto& rows = byFrame[{ facets, frame }];
      double worst = 0.0;
      double worstSweep = 0.0;
      double samples = 0.0;
      double timeRatio = 0.0;
      for (size_t k = 0; k < rows.size(); ++k)
      {
        double& worstOfKind = IsSweep(*rows[k]) ? worstSweep : worst;
        if (rows[k]->Azimuth <= 80.0)
        {
          worstOfKind = std::max(worstOfKind, rows[k]->SilhouetteError);
        }
        samples += rows[k]->MeanSamples / rows.size();
        timeRatio += flat[k]->Milliseconds > 0.0
          ? rows[k]->Milliseconds / flat[k]->Milliseconds / rows.size()
          : 0.0;
      }
      section << " " << frame << ", silhouette error at most " << worst
              << " in the three views and " << worstSweep
              << " on the torus's inner side up to 80 degrees, " << samples
              << " samples a pixel, " << timeRatio << "x the flat frame's time;";
    }
  }
  section << " (target: a silhouette error of at most 0.25 for the quadric frame).\n\n";

  if (!options.ImageDirectory.empty())
  {
    std::filesystem::create_directories(options.ImageDirectory);
    std::vector<ReliefChart::Series> series;
    for (int facets : options.Facets)
    {
      for (const std::string& frame : Frames())
      {
        ReliefChart::Series line;
        line.Name = frame + ", " + std::to_string(facets) + " facets";
        for (const Measurement* m : byFrame[{ facets, frame }])
        {
          line.X.push_back(m->SilhouetteError);
          line.Y.push_back(m->Milliseconds);
        }
        series.push_back(line);
      }
    }
    ReliefChart::Axes axes;
    axes.Title = "Curved surfaces: silhouette error against cost";
    axes.X = "silhouette error against the ground truth (1: the polygons' outline)";
    axes.Y = "ms per frame (median)";
    ReliefChart::Write(series, axes, options.ImageDirectory + "/quadric_silhouette_error.png");
    section << "![silhouette error against ms/frame](images/quadric_silhouette_error.png)\n\n"
            << "Left to right: the truth, then where the bare polygons, the flat frame and the "
               "quadric frame (approximate distance) cover what the truth does (grey), more "
               "(red) and less (green), at "
            << options.Facets.front()
            << " facets; top to bottom: the sphere and the cylinder with shallow relief "
               "(azimuth 35, elevation 30), the torus's inner side at 80 degrees with deep "
               "relief, the torus with shallow relief and its inner side at 80 degrees.\n\n![the quadric frame's outlines](images/quadric_outlines.png)\n\n";
  }
  return section.str();
}
}
