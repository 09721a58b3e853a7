#include "ReliefAccuracy.h"

#include "ReliefChart.h"
#include "ReliefMetrics.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkReliefAccelerationFilter.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tuple>
#include <vector>

namespace
{
struct Row
{
  std::string Family;
  std::string Parameters;
  double Milliseconds = 0.0;
  double MeanSamples = -1.0; // -1: not a search (the meshes)
  int MaximumSamples = 0;
  double WrongPixels = 0.0;
  double Silhouette = 0.0;
  ReliefMetrics::DepthError Depth;
  ReliefMetrics::ColourError Colour;
  double Megabytes = 0.0;
};

// What the GPU holds for a mesh drawn by vtkPolyDataMapper: float positions, normals and
// texture coordinates per point, 32-bit indices per triangle.
double MeshMegabytes(vtkPolyData* mesh)
{
  return (32.0 * mesh->GetNumberOfPoints() + 12.0 * mesh->GetNumberOfPolys()) / 1e6;
}

// Indices of the rows no other row beats in both cost and error, cheapest first.
std::vector<size_t> ParetoFront(const std::vector<double>& cost, const std::vector<double>& error)
{
  std::vector<size_t> order(cost.size());
  for (size_t i = 0; i < order.size(); ++i)
  {
    order[i] = i;
  }
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return cost[a] < cost[b] || (cost[a] == cost[b] && error[a] < error[b]);
  });
  std::vector<size_t> front;
  for (size_t i : order)
  {
    if (front.empty() || error[i] < error[front.back()])
    {
      front.push_back(i);
    }
  }
  return front;
}

constexpr const char* TruthFamily = "ground truth";
constexpr const char* DenseFamily = "dense mesh";

// Error (x, log) against a cost (y) for every row with one, each family its colour, the
// Pareto front as a line; written as PNG.
void DrawChart(const std::vector<Row>& rows, bool bySamples, const std::string& title,
  const std::string& file)
{
  auto costOf = [&](const Row& row) { return bySamples ? row.MeanSamples : row.Milliseconds; };
  std::vector<double> costs;
  std::vector<double> errors;
  std::vector<ReliefChart::Series> series;
  for (const Row& row : rows)
  {
    // the truth is the reference, not a point to beat
    if (costOf(row) < 0.0 || row.Family == TruthFamily)
    {
      continue;
    }
    costs.push_back(costOf(row));
    errors.push_back(std::max(row.WrongPixels, ReliefChart::LogFloor));
    auto family = std::find_if(series.begin(), series.end(),
      [&](const ReliefChart::Series& s) { return s.Name == row.Family; });
    if (family == series.end())
    {
      series.push_back({ row.Family });
      family = series.end() - 1;
    }
    family->X.push_back(errors.back());
    family->Y.push_back(costs.back());
  }
  ReliefChart::Series front{ "Pareto front" };
  front.Line = true;
  front.Black = true;
  for (size_t i : ParetoFront(costs, errors))
  {
    front.X.push_back(errors[i]);
    front.Y.push_back(costs[i]);
  }
  series.push_back(front);
  ReliefChart::Axes axes;
  axes.Title = title;
  axes.X = "wrong pixels against the ground truth (share of the truth's pixels)";
  axes.Y = bySamples ? "height samples per pixel (mean)" : "ms per frame (median)";
  axes.LogX = true;
  ReliefChart::Write(series, axes, file);
}

// Renders the scene with one actor visible and measures it against the truth.
struct Bench
{
  vtkRenderWindow* Window;
  vtkRenderer* Renderer;
  std::vector<vtkActor*> Actors;
  ReliefMetrics::Capture Truth;
  ReliefMetrics::Capture Polygons;
  double DepthScale;

  ReliefMetrics::Capture Show(vtkActor* shown)
  {
    for (vtkActor* actor : this->Actors)
    {
      actor->SetVisibility(actor == shown);
    }
    this->Window->Render();
    return ReliefScene::Capture(this->Window, this->Renderer);
  }

  void Measure(vtkActor* shown, Row& row)
  {
    const ReliefMetrics::Capture capture = this->Show(shown);
    row.WrongPixels = ReliefMetrics::WrongPixelFraction(capture, this->Truth, this->DepthScale);
    row.Silhouette = ReliefMetrics::SilhouetteError(capture, this->Polygons, this->Truth);
    row.Depth = ReliefMetrics::MeasureDepthError(capture, this->Truth, this->DepthScale);
    row.Colour = ReliefMetrics::MeasureColourError(capture, this->Truth);
  }
};

// The targets against the dense mesh: the fastest relief row whose depth error (95th
// percentile) and wrong pixels are no worse than the dense mesh's, its speed-up and its
// share of the mesh's GPU bytes.
std::string TargetCheck(const std::vector<Row>& rows)
{
  const auto dense = std::find_if(
    rows.begin(), rows.end(), [](const Row& row) { return row.Family == DenseFamily; });
  const Row* best = nullptr;
  for (const Row& row : rows)
  {
    if (row.MeanSamples >= 0.0 && dense != rows.end() &&
      row.Depth.Percentile95 <= dense->Depth.Percentile95 &&
      row.WrongPixels <= dense->WrongPixels &&
      (!best || row.Milliseconds < best->Milliseconds))
    {
      best = &row;
    }
  }
  std::ostringstream check;
  if (!best)
  {
    check << "Against the dense mesh: no relief setting is as accurate.\n\n";
    return check.str();
  }
  check << std::setprecision(3) << "Against the dense mesh: the fastest relief setting whose "
        << "depth error (95th percentile) and wrong pixels are no worse than the mesh's is "
        << best->Family << " " << best->Parameters << ": " << best->Depth.Percentile95 << " and "
        << best->WrongPixels << " against " << dense->Depth.Percentile95 << " and "
        << dense->WrongPixels << ". It takes " << best->Milliseconds << " ms against "
        << dense->Milliseconds << " ms (" << dense->Milliseconds / best->Milliseconds
        << "x faster; target 5x) and " << best->Megabytes << " MB of GPU memory against "
        << dense->Megabytes << " MB (" << best->Megabytes / dense->Megabytes
        << " of it; target 0.1).";
  // how much of the frame the search itself leaves: the cheapest row, however wrong
  const Row* cheapest = nullptr;
  for (const Row& row : rows)
  {
    if (row.MeanSamples >= 0.0 && (!cheapest || row.Milliseconds < cheapest->Milliseconds))
    {
      cheapest = &row;
    }
  }
  check << " The cheapest relief setting of all, " << cheapest->Family << " "
        << cheapest->Parameters << " (" << cheapest->MeanSamples
        << " height samples a pixel, " << cheapest->WrongPixels << " wrong pixels), takes "
        << cheapest->Milliseconds << " ms: " << dense->Milliseconds / cheapest->Milliseconds
        << "x faster than the mesh.\n\n";
  return check.str();
}

std::string Table(const std::vector<Row>& rows)
{
  std::ostringstream table;
  table << "| method | setting | wrong pixels | silhouette error | depth error median | "
           "95th percentile | share above 0.1 | colour RMSE | SSIM | ms/frame | "
           "samples/pixel (mean) | (max) | GPU MB |\n"
        << "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: "
           "| ---: | ---: | ---: | ---: | ---: |\n";
  for (const Row& row : rows)
  {
    table << std::setprecision(3) << "| " << row.Family << " | " << row.Parameters << " | "
          << row.WrongPixels << " | " << row.Silhouette << " | " << row.Depth.Median << " | "
          << row.Depth.Percentile95 << " | " << row.Depth.FractionAbove << " | "
          << row.Colour.Rmse << " | " << row.Colour.Ssim << " | " << std::fixed
          << std::setprecision(1) << row.Milliseconds << std::defaultfloat << " | ";
    if (row.MeanSamples < 0.0)
    {
      table << "- | - | ";
    }
    else
    {
      table << std::setprecision(3) << row.MeanSamples << " | "
            << (row.MaximumSamples >= 255 ? std::string(">= 255")
                                          : std::to_string(row.MaximumSamples))
            << " | ";
    }
    table << std::setprecision(3) << row.Megabytes << " |\n";
  }
  return table.str();
}
}

namespace ReliefAccuracy
{
std::vector<Setting> Settings()
{
  using Mapper = vtkOpenGLReliefMapper;
  std::vector<Setting> settings;
  for (int steps : { 4, 8, 16, 32, 64 })
  {
    settings.push_back({ "Linear", std::to_string(steps) + " steps", Mapper::LINEAR, steps, 0 });
  }
  for (auto steps : { std::pair<int, int>{ 5, 3 }, { 10, 5 }, { 20, 6 }, { 40, 8 } })
  {
    settings.push_back({ "LinearBinary",
      std::to_string(steps.first) + "+" + std::to_string(steps.second) + " steps",
      Mapper::LINEAR_BINARY, steps.first, steps.second });
  }
  for (auto steps : { std::pair<int, int>{ 8, 3 }, { 16, 5 }, { 32, 5 } })
  {
    settings.push_back({ "Secant",
      std::to_string(steps.first) + "+" + std::to_string(steps.second) + " steps",
      Mapper::SECANT, steps.first, steps.second });
  }
  settings.push_back({ "ExactDDA", "", Mapper::EXACT_DDA });
  for (double tolerance : { 0.0, 0.05, 0.2 })
  {
    std::ostringstream label;
    label << "e = " << tolerance;
    settings.push_back({ "SafetyRadius", label.str(), Mapper::SAFETY_RADIUS, 10, 5, tolerance });
  }
  settings.push_back({ "RobustBinary", "e = 0.05", Mapper::ROBUST_BINARY, 10, 5, 0.05 });
  settings.push_back({ "ConeStep", "", Mapper::CONE_STEP });
  settings.push_back({ "MaximumMipmap", "", Mapper::MAXIMUM_MIPMAP });
  settings.push_back({ "SlopeMipmap", "", Mapper::SLOPE_MIPMAP });
  for (double pixels : { 0.5, 2.0 })
  {
    std::ostringstream label;
    label << pixels << " pixel" << (pixels == 1.0 ? "" : "s");
    settings.push_back({ "Automatic", label.str(), Mapper::AUTOMATIC, 10, 5, 0.0, pixels });
  }
  settings.push_back(
    { "Automatic over slopes", "0.5 pixels", Mapper::AUTOMATIC, 10, 5, 0.0, 0.5, true });
  return settings;
}

void Apply(const Setting& setting, vtkOpenGLReliefMapper* mapper)
{
  mapper->SetSearchMethod(setting.Method);
  mapper->SetLinearSteps(setting.LinearSteps);
  mapper->SetBinarySteps(std::max(setting.BinarySteps, 1));
  mapper->SetSafetyRadiusTolerance(setting.Tolerance);
  mapper->SetScreenTolerance(setting.ScreenTolerance);
  mapper->SetAutomaticAcceleration(setting.OverSlopes ? vtkOpenGLReliefMapper::SLOPE_MIPMAP
                                                      : vtkOpenGLReliefMapper::CONE_STEP);
}

bool IsAutomatic(const Setting& setting)
{
  return setting.Method == vtkOpenGLReliefMapper::AUTOMATIC;
}

std::string Study(const Options& requested)
{
  Options options = requested;
  options.Frames = std::max(options.Frames, 1);
  options.Rounds = std::max(options.Rounds, 1);
  const auto start = std::chrono::steady_clock::now();
  vtkSmartPointer<vtkImageData> heights =
    ReliefScene::ResizedHeightMap("stones_height.png", options.HeightMapSize);
  vtkNew<vtkReliefTextureFilter> reliefTexture;
  reliefTexture->SetInputData(heights);
  reliefTexture->Update();
  vtkImageData* relief = reliefTexture->GetOutput();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, options.Width, options.Height);
  auto square = ReliefScene::Square(1.0);

  vtkNew<vtkOpenGLReliefMapper> reliefMapper;
  reliefMapper->SetInputData(square);
  reliefMapper->SetHeightMapData(heights);
  reliefMapper->SetDepthScale(options.DepthScale);
  // the stock mapper casts no shadows: both are lit alike, without them
  reliefMapper->SetSelfShadowing(false);
  // the searches' accuracy and cost; footprint shading has its own study
  reliefMapper->SetFootprintShading(false);
  auto reliefActor = ReliefScene::ReliefActor(reliefMapper, "stones_color.png");

  auto meshActor = [&](vtkPolyData* mesh) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(mesh);
    return ReliefScene::ReliefActor(mapper, "stones_color.png");
  };
  auto truthMesh = ReliefScene::DisplacedMesh(square, relief, options.DepthScale, 0.5);
  auto truthActor = meshActor(truthMesh);
  auto polygonsActor = meshActor(square);
  // the dense mesh of equal detail: points one texel apart along u and v
  auto denseMesh = ReliefScene::DisplacedMesh(square, relief, options.DepthScale, 1.5);
  auto denseActor = meshActor(denseMesh);
  // framed on the coarse surface alone (the truth's sunken bounds would aim the camera
  // below it), filling the view: the flat frame cannot change a silhouette (the quadric
  // frame's scenes measure that), so every pixel compares depths
  renderer->AddActor(reliefActor);
  ReliefScene::ViewSquare(renderer, options.Angle);
  renderer->GetActiveCamera()->Dolly(3.0);
  std::vector<vtkActor*> actors = { reliefActor, truthActor, polygonsActor, denseActor };
  for (vtkActor* actor : actors)
  {
    renderer->AddActor(actor);
  }
  renderer->ResetCameraClippingRange();

  Bench bench{ window, renderer, actors, {}, {}, options.DepthScale };
  bench.Truth = bench.Show(truthActor);
  bench.Polygons = bench.Show(polygonsActor);

  // every row: how to show it, then its figures; timed last, in interleaved rounds, so
  // that machine noise hits all alike
  std::vector<Row> rows;
  std::vector<std::function<void()>> shows;
  for (const Setting& setting : Settings())
  {
    if (!options.Method.empty() && setting.Family != options.Method)
    {
      continue;
    }
    shows.push_back([&, setting]() {
      Apply(setting, reliefMapper);
      bench.Show(reliefActor);
    });
    shows.back()();
    Row row{ setting.Family, setting.Parameters };
    bench.Measure(reliefActor, row);
    const ReliefScene::SampleStatistics samples =
      ReliefScene::SampleCounts(window, renderer, reliefMapper);
    row.MeanSamples = samples.Mean;
    row.MaximumSamples = samples.Maximum;
    row.Megabytes = reliefMapper->GetTextureBytes() / 1e6; // as uploaded for this setting
    rows.push_back(row);
    std::cout << "accuracy: " << setting.Family << " " << setting.Parameters << " measured\n";
  }
  const std::tuple<const char*, const char*, vtkActor*, vtkPolyData*> meshes[] = {
    { DenseFamily, "1 point per texel", denseActor, denseMesh },
    { "coarse polygons", "no relief", polygonsActor, square },
    { TruthFamily, "edges of 0.5 texel", truthActor, truthMesh },
  };
  for (const auto& [family, parameters, actor, mesh] : meshes)
  {
    Row row{ family, parameters };
    bench.Measure(actor, row);
    row.Megabytes = MeshMegabytes(mesh);
    rows.push_back(row);
    shows.push_back([&bench, actor = actor]() { bench.Show(actor); });
  }
  std::vector<std::vector<double>> milliseconds(rows.size());
  for (int round = 0; round < options.Rounds; ++round)
  {
    for (size_t r = 0; r < rows.size(); ++r)
    {
      shows[r]();
      const std::vector<double> timed = ReliefScene::FrameMilliseconds(window, 2, options.Frames);
      milliseconds[r].insert(milliseconds[r].end(), timed.begin(), timed.end());
    }
    std::cout << "accuracy: timing round " << round + 1 << " of " << options.Rounds << " done\n";
  }
  for (size_t r = 0; r < rows.size(); ++r)
  {
    rows[r].Milliseconds = ReliefScene::Median(milliseconds[r]);
  }

  std::ostringstream convergence;
  if (options.Convergence)
  {
    auto finerMesh = ReliefScene::DisplacedMesh(square, relief, options.DepthScale, 0.25);
    auto finerActor = meshActor(finerMesh);
    renderer->AddActor(finerActor);
    bench.Actors.push_back(finerActor);
    const ReliefMetrics::Capture finer = bench.Show(finerActor);
    const auto depth = ReliefMetrics::MeasureDepthError(bench.Truth, finer, options.DepthScale);
    convergence << "Convergence of the ground truth: against the truth with edges of 0.25 texel ("
                << finerMesh->GetNumberOfPolys() << " triangles), the truth used ("
                << truthMesh->GetNumberOfPolys() << " triangles) has "
                << ReliefMetrics::WrongPixelFraction(bench.Truth, finer, options.DepthScale)
                << " wrong pixels, depth error median " << depth.Median << " and 95th percentile "
                << depth.Percentile95 << " (x DepthScale), colour RMSE "
                << ReliefMetrics::MeasureColourError(bench.Truth, finer).Rmse << ".\n\n";
  }

  std::ostringstream section;
  section << "Scene: the stones height map resampled to " << options.HeightMapSize << "x"
          << options.HeightMapSize << ", one tile on the unit square filling the view, DepthScale "
          << options.DepthScale << ", seen " << options.Angle << " degrees from its normal in a "
          << options.Width << "x" << options.Height
          << " window; one scene light, self-shadowing off (the stock mapper casts none), "
             "footprint shading off (its own study measures it). "
             "Ground truth: vtkReliefDisplacementFilter with edges of at most 0.5 texel ("
          << truthMesh->GetNumberOfPolys()
          << " triangles) drawn by vtkPolyDataMapper with the same camera, clipping range, "
             "light and colour texture. Dense mesh: the same filter with points one texel "
             "apart ("
          << denseMesh->GetNumberOfPolys()
          << " triangles). Wrong pixels: covered by one render and not the other, or more "
             "than 0.1 DepthScale apart in eye depth, as a share of the truth's pixels "
             "(charted at "
          << ReliefChart::LogFloor << " when below). Depth errors are in units of DepthScale; "
          << options.Frames << " timed frames x " << options.Rounds
          << " interleaved rounds per row (median). GPU MB: for relief, the textures the mapper "
             "reports (GetTextureBytes: the 16-bit depth, the method's "
             "acceleration image); for meshes, vertex and index buffers.\n\n"
          << convergence.str() << Table(rows) << "\n" << TargetCheck(rows);
  if (!options.ImageDirectory.empty())
  {
    std::filesystem::create_directories(options.ImageDirectory);
    DrawChart(rows, false, "Speed against accuracy",
      options.ImageDirectory + "/accuracy_time.png");
    DrawChart(rows, true, "Height samples against accuracy",
      options.ImageDirectory + "/accuracy_samples.png");
    section << "![error against ms/frame](images/accuracy_time.png)\n\n"
            << "![error against samples per pixel](images/accuracy_samples.png)\n\n";
  }
  section << "Study time: " << std::fixed << std::setprecision(0)
          << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
          << " s.\n";
  return section.str();
}
}
