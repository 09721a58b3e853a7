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
#include <filesystem>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>

namespace
{
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
const double Views[][2] = { { 0.0, 10.0 }, { 35.0, 30.0 }, { 70.0, -20.0 } }; // azimuth, elevation

void Aim(vtkRenderer* renderer, const double view[2], const double frame[6], vtkPolyData* truth)
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
std::string FacetsList(const std::vector<int>& facets)
{
  std::string list;
  for (size_t k = 0; k < facets.size(); ++k)
  {
    list += (k == 0 ? "" : k + 1 == facets.size() ? " and " : ", ") + std::to_string(facets[k]);
  }
  return list;
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
  for (int facets : options.Facets)
  {
    for (const Shape& shape : Shapes)
    {
      auto coarse = shape.Make(facets);
      auto truthMesh =
        ReliefScene::DisplacedMesh(shape.Make(256), relief->GetOutput(), options.DepthScale, 0.5);
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
        mapper->SetDepthScale(options.DepthScale);
        mapper->SetSelfShadowing(false); // the stock mapper casts no shadows
        mapper->SetFootprintShading(false); // the frames' samples alone
        mapper->SetLinearSteps(32);
        mapper->SetBinarySteps(6);
      }
      // the actors' default properties: the mappers decide which faces carry relief
      const std::vector<vtkSmartPointer<vtkActor>> actors = {
        ReliefScene::ReliefActor(truthMapper, ""), ReliefScene::ReliefActor(polygonMapper, ""),
        ReliefScene::ReliefActor(flat, ""), ReliefScene::ReliefActor(approximate, ""),
        ReliefScene::ReliefActor(exact, "") };
      ReliefScene::Lineup lineup(window, renderer, actors);
      for (const auto& view : Views)
      {
        Aim(renderer, view, shape.Frame, truthMesh);
        const ReliefMetrics::Capture truth = lineup.Capture(actors[0]);
        const ReliefMetrics::Capture polygons = lineup.Capture(actors[1]);
        for (size_t f = 0; f < 3; ++f)
        {
          const ReliefMetrics::Capture frame = lineup.Capture(actors[2 + f]);
          Measurement measurement;
          measurement.Shape = shape.Name;
          measurement.Facets = facets;
          measurement.Azimuth = view[0];
          measurement.Elevation = view[1];
          measurement.Frame = Frames()[f];
          measurement.SilhouetteError = ReliefMetrics::SilhouetteError(frame, polygons, truth);
          measurement.WrongPixels =
            ReliefMetrics::WrongPixelFraction(frame, truth, options.DepthScale);
          measurement.MeanSamples = ReliefScene::SampleCounts(window, renderer, mappers[f]).Mean;
          measurements.push_back(measurement);
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
  }
  return measurements;
}

std::string Report(const std::vector<Measurement>& measurements, const Options& options)
{
  std::ostringstream section;
  section << "Stones (the height map resampled to " << options.HeightMapSize << "x"
          << options.HeightMapSize << ", DepthScale " << options.DepthScale
          << ") on a sphere of radius 0.5, a cylinder of radius 0.4 (its middle) and a torus, "
          << FacetsList(options.Facets)
          << " facets around each (a torus half as many around its tube), three views each, "
             "in a "
          << options.Width << "x" << options.Height
          << " window; the actors' default properties. Ground truth: the shape regenerated "
             "with 256 facets around and displaced (vtkReliefDisplacementFilter, edges of at most 0.5 "
             "texel). Silhouette error: pixels whose coverage differs from the truth's, over "
             "the same count for the bare polygons (1: no better than the polygons, 0: "
             "perfect). Every frame searches with LinearBinary 32+6, self-shadowing off; "
          << options.Frames << " timed frames x " << options.Rounds
          << " interleaved rounds per row (median).\n\n";
  section << "| shape | facets | azimuth, elevation | frame | silhouette error | wrong pixels | "
             "samples/pixel (mean) | ms/frame |\n"
          << "| --- | ---: | --- | --- | ---: | ---: | ---: | ---: |\n"
          << std::setprecision(3);
  for (const Measurement& m : measurements)
  {
    section << "| " << m.Shape << " | " << m.Facets << " | " << m.Azimuth << ", "
            << m.Elevation << " | " << m.Frame
            << " | " << m.SilhouetteError << " | " << m.WrongPixels << " | " << m.MeanSamples
            << " | " << m.Milliseconds << " |\n";
  }
  // per number of facets and frame over all views: the worst silhouette error, the mean
  // samples and the mean time against the flat frame's in the same views
  std::map<std::pair<int, std::string>, std::vector<const Measurement*>> byFrame;
  for (const Measurement& m : measurements)
  {
    byFrame[{ m.Facets, m.Frame }].push_back(&m);
  }
  for (int facets : options.Facets)
  {
    const auto& flat = byFrame[{ facets, Frames()[0] }];
    section << "\nOver the nine views at " << facets << " facets:";
    for (const std::string& frame : Frames())
    {
      const auto& rows = byFrame[{ facets, frame }];
      double worst = 0.0;
      double samples = 0.0;
      double timeRatio = 0.0;
      for (size_t k = 0; k < rows.size(); ++k)
      {
        worst = std::max(worst, rows[k]->SilhouetteError);
        samples += rows[k]->MeanSamples / rows.size();
        timeRatio += flat[k]->Milliseconds > 0.0
          ? rows[k]->Milliseconds / flat[k]->Milliseconds / rows.size()
          : 0.0;
      }
      section << " " << frame << ", silhouette error at most " << worst << ", " << samples
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
    section << "![silhouette error against ms/frame](images/quadric_silhouette_error.png)\n\n";
  }
  return section.str();
}
}
