// ./relief bench: frame time of relief mapping against plain texturing of the same
// coarse mesh, and the height samples per pixel, measured in one run.
//
// Scene: a two-triangle square filling an 800x600 view at 45 degrees, the 512x512
// bricks height map. Each configuration renders warm-up frames, then its frames are
// timed one by one (Render + WaitForCompletion); configurations are interleaved over
// several rounds so machine noise hits all alike. Reported: median and fastest ms/frame
// over all timed frames, their ratios to plain texturing, and the mean samples per
// covered pixel (SampleCount mode). Then every search method at three height-map sizes
// (Baboud and Decoret's (2006) Table 1), the acceleration filters' run times, and every method's
// speed against its accuracy (ReliefAccuracy.h).
#include "ReliefAccuracy.h"
#include "ReliefAutomaticStudy.h"
#include "ReliefImpostorStudy.h"
#include "ReliefPathStudy.h"
#include "ReliefDerivativeStudy.h"
#include "ReliefQuadricStudy.h"
#include "ReliefRobustStudy.h"
#include "ReliefScene.h"
#include "ReliefShadingStudy.h"
#include "ReliefSweeps.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkConeStepMapFilter.h"
#include "vtkImageData.h"
#include "vtkLocalQuadricFilter.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSafetyRadiusFilter.h"
#include "vtkSlopeMipmapFilter.h"
#include "vtkSuperquadricSource.h"
#include "vtkVersion.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iterator>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>

#include <unistd.h> // sysconf, for the resident memory

namespace
{
struct Configuration
{
  std::string Name;
  int SearchMethod; // -1: plain texturing
  int LinearSteps;
  int BinarySteps;
  bool SelfShadowing;
  bool FootprintShading; // the mapper's default; off elsewhere, to time the searches
  std::vector<double> Milliseconds;
  double MeanSamples = 0.0;
};

// The value after ':' or '=' on the first line holding `key`.
std::string FirstLineContaining(std::istream& in, const std::string& key)
{
  std::string line;
  while (std::getline(in, line))
  {
    if (line.find(key) != std::string::npos)
    {
      return line.substr(line.find_first_of(":=") + 1);
    }
  }
  return "unknown";
}

// True when `list` names only sections of the bench, comma-separated.
bool KnownSections(const std::string& list)
{
  std::istringstream sections(list);
  std::string section;
  int count = 0;
  while (std::getline(sections, section, ','))
  {
    if (section != "plain" && section != "methods" && section != "filters" &&
      section != "accuracy" && section != "sweeps" && section != "quadric" &&
      section != "derivative" && section != "sharing" && section != "shading" &&
      section != "automatic" && section != "paths" && section != "impostors" &&
      section != "robust" && section != "exact")
    {
      return false;
    }
    ++count;
  }
  return count > 0;
}

std::string Trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t");
  return first == std::string::npos ? "" : text.substr(first);
}

void ViewSquareFilling(vtkRenderer* renderer, double angle)
{
  ReliefScene::ViewSquare(renderer, angle);
  renderer->GetActiveCamera()->Dolly(2.2); // the square fills the view
  renderer->ResetCameraClippingRange();
}

// A height map of the methods table: its label and image.
struct TableMap
{
  std::string Label;
  vtkSmartPointer<vtkImageData> Image;
};

// The stones map resampled to each size (Baboud and Decoret's (2006) Table 1), then each
// map of `others` as it is.
std::vector<TableMap> TableMaps(
  const std::vector<int>& sizes, const std::vector<std::string>& others)
{
  std::vector<TableMap> maps;
  vtkSmartPointer<vtkImageData> heights = ReliefScene::ReadImage("stones_height.png");
  for (int size : sizes)
  {
    maps.push_back({ std::to_string(size) + "x" + std::to_string(size),
      ReliefScene::ResizedImage(heights, size) });
  }
  for (const std::string& name : others)
  {
    vtkSmartPointer<vtkImageData> image = ReliefScene::ReadImage(name);
    if (image->GetNumberOfPoints() == 0)
    {
      std::cerr << "relief bench: cannot read the height map " << name << "; left out\n";
    }
    else
    {
      const int* dimensions = image->GetDimensions();
      maps.push_back({ name.substr(name.find_last_of('/') + 1) + ", " +
          std::to_string(dimensions[0]) + "x" + std::to_string(dimensions[1]),
        image });
    }
  }
  return maps;
}

// Baboud and Decoret's (2006) Table 1 for every search method: each height map at three
// view angles; each method's cost relative to LinearBinary's, measured in the same run,
// interleaved.
std::string MethodsTable(vtkRenderWindow* window, vtkRenderer* renderer,
  vtkOpenGLReliefMapper* relief, const std::vector<TableMap>& maps, int frames, int rounds)
{
  // LinearBinary first: the others are measured against it; SafetyRadius and RobustBinary
  // at e = 0 and at the tolerance that trades a silhouette error of 0.05 depth for speed;
  // Automatic over cones and over the slope pyramid
  struct Method
  {
    int Id;
    double Tolerance;
    bool OverSlopes;
  };
  std::vector<Method> methods = { { vtkOpenGLReliefMapper::LINEAR_BINARY, 0.0, false } };
  for (int method : ReliefScene::SearchMethods())
  {
    if (method != vtkOpenGLReliefMapper::LINEAR_BINARY)
    {
      methods.push_back({ method, 0.0, false });
    }
    if (method == vtkOpenGLReliefMapper::SAFETY_RADIUS ||
      method == vtkOpenGLReliefMapper::ROBUST_BINARY)
    {
      methods.push_back({ method, 0.05, false });
    }
    if (method == vtkOpenGLReliefMapper::AUTOMATIC)
    {
      methods.push_back({ method, 0.0, true });
    }
  }
  std::ostringstream table;
  table << std::fixed << std::setprecision(2);
  table << "| height map | angle | method | ms/frame (median) | x LinearBinary | "
           "samples/pixel (mean) | x LinearBinary | samples/pixel (max) |\n"
        << "| ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: |\n";
  relief->SetLinearSteps(10);
  relief->SetBinarySteps(5);
  relief->SetSelfShadowing(true);
  relief->SetFootprintShading(false); // the searches' own cost
  for (const TableMap& map : maps)
  {
    relief->SetHeightMapData(map.Image);
    for (double angle : { 0.0, 45.0, 80.0 })
    {
      ViewSquareFilling(renderer, angle);
      std::vector<std::vector<double>> milliseconds(std::size(methods));
      std::vector<ReliefScene::SampleStatistics> samples(std::size(methods));
      for (int round = 0; round < rounds; ++round)
      {
        for (size_t m = 0; m < std::size(methods); ++m)
        {
          relief->SetSearchMethod(methods[m].Id);
          relief->SetSafetyRadiusTolerance(methods[m].Tolerance);
          relief->SetAutomaticAcceleration(methods[m].OverSlopes
              ? vtkOpenGLReliefMapper::SLOPE_MIPMAP
              : vtkOpenGLReliefMapper::CONE_STEP);
          if (round == 0)
          {
            samples[m] = ReliefScene::SampleCounts(window, renderer, relief);
          }
          const std::vector<double> timed = ReliefScene::FrameMilliseconds(window, 1, frames);
          milliseconds[m].insert(milliseconds[m].end(), timed.begin(), timed.end());
        }
      }
      const double baseMilliseconds = ReliefScene::Median(milliseconds[0]);
      for (size_t m = 0; m < std::size(methods); ++m)
      {
        const double median = ReliefScene::Median(milliseconds[m]);
        table << "| " << map.Label << " | " << angle << " | "
              << vtkOpenGLReliefMapper::GetSearchMethodAsString(methods[m].Id);
        if (methods[m].Tolerance > 0.0)
        {
          table << " (e = " << methods[m].Tolerance << ")";
        }
        if (methods[m].OverSlopes)
        {
          table << " (over SlopeMipmap)";
        }
        table << " | " << median
              << " | " << median / baseMilliseconds << " | " << samples[m].Mean << " | "
              << samples[m].Mean / samples[0].Mean << " | "
              << (samples[m].Maximum >= 255 ? ">= 255" : std::to_string(samples[m].Maximum))
              << " |\n";
      }
      std::cout << "methods: " << map.Label << " at " << angle << " degrees done" << std::endl;
    }
  }
  relief->SetHeightMapData(ReliefScene::ReadImage("bricks_height.png"));
  relief->SetSearchMethodToLinearBinary();
  relief->SetSafetyRadiusTolerance(0.0);
  relief->SetAutomaticAccelerationToConeStep();
  ViewSquareFilling(renderer, 45.0);
  return table.str();
}

// Resident memory of this process in bytes (Linux's /proc/self/statm).
double ResidentBytes()
{
  std::ifstream statm("/proc/self/statm");
  double pages = 0.0;
  double resident = 0.0;
  statm >> pages >> resident;
  return resident * static_cast<double>(sysconf(_SC_PAGESIZE));
}

// Many actors on one height map: each its own relief mapper of the same square and the
// same height image, as a multiblock dataset or many instances would be. What the
// window's relief textures take, what the process grows by, the first frame (filters,
// uploads and the shader's compilation) and the next, for one actor and for `many`.
std::string SharingTable(int size, int many)
{
  vtkSmartPointer<vtkImageData> heights =
    ReliefScene::ResizedHeightMap("stones_height.png", size);
  auto square = ReliefScene::Square(1.0);
  {
    // OpenGL's own first start (its libraries, a first context) counts for neither
    vtkNew<vtkRenderWindow> window;
    auto renderer = ReliefScene::LitRenderer(window, 400, 300);
    vtkNew<vtkPolyDataMapper> plain;
    plain->SetInputData(square);
    renderer->AddActor(ReliefScene::ReliefActor(plain, ""));
    window->Render();
  }
  std::ostringstream table;
  table << "| actors | texture bytes | process memory grown | first frame (s) | next frame (s) |\n"
        << "| ---: | ---: | ---: | ---: | ---: |\n";
  for (int count : { 1, many })
  {
    vtkNew<vtkRenderWindow> window;
    auto renderer = ReliefScene::LitRenderer(window, 400, 300);
    std::vector<vtkSmartPointer<vtkOpenGLReliefMapper>> mappers;
    for (int k = 0; k < count; ++k)
    {
      auto mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
      mapper->SetInputData(square);
      mapper->SetHeightMapData(heights);
      mapper->SetDepthScale(0.02);
      auto actor = ReliefScene::ReliefActor(mapper, "");
      actor->SetPosition(1.1 * (k % 10), 1.1 * (k / 10), 0.0);
      renderer->AddActor(actor);
      mappers.push_back(mapper);
    }
    renderer->ResetCamera();
    const double before = ResidentBytes();
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double grown = ResidentBytes() - before;
    const vtkIdType bytes = vtkOpenGLReliefMapper::GetTextureBytesInUse(window);
    const double next = ReliefScene::Median(ReliefScene::FrameMilliseconds(window, 1, 5)) / 1e3;
    table << "| " << count << " | " << bytes << " | " << std::fixed << std::setprecision(1)
          << grown / (1024.0 * 1024.0) << " MiB | " << std::setprecision(3) << seconds << " | "
          << next << " |\n";
    table.unsetf(std::ios::fixed);
  }
  return table.str();
}

// The acceleration filters' run times on the stones height map (targets: safety radii
// and cone map of 512x512 in 5 s, the maximum mipmap of 1024x1024 in 0.2 s; the slope
// pyramid of 1024x1024 beside it, without one) and the local quadrics' on a mesh of a
// million points, each the median of `rounds` runs.
std::string FiltersTable(int rounds)
{
  vtkSmartPointer<vtkImageData> heights = ReliefScene::ReadImage("stones_height.png");
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkReliefAccelerationFilter> Filter;
    int Size;
    const char* Target; // seconds, as the issues set them
  };
  vtkNew<vtkSafetyRadiusFilter> tolerant;
  tolerant->SetErrorTolerance(0.05);
  const Case cases[] = {
    { "vtkMaximumMipmapFilter", vtkSmartPointer<vtkMaximumMipmapFilter>::New(), 1024, "0.2" },
    { "vtkSlopeMipmapFilter", vtkSmartPointer<vtkSlopeMipmapFilter>::New(), 1024, "-" },
    { "vtkSafetyRadiusFilter (e = 0)", vtkSmartPointer<vtkSafetyRadiusFilter>::New(), 512, "5" },
    { "vtkSafetyRadiusFilter (e = 0.05)", tolerant.Get(), 512, "5" },
    { "vtkConeStepMapFilter", vtkSmartPointer<vtkConeStepMapFilter>::New(), 512, "5" } };
  std::ostringstream table;
  table << std::fixed << std::setprecision(3);
  table << "| filter | input | seconds (median) | target |\n| --- | ---: | ---: | ---: |\n";
  for (const Case& run : cases)
  {
    vtkNew<vtkReliefTextureFilter> texture;
    texture->SetInputData(ReliefScene::ResizedImage(heights, run.Size));
    texture->Update();
    run.Filter->SetInputConnection(texture->GetOutputPort());
    std::vector<double> seconds;
    for (int round = 0; round < rounds; ++round)
    {
      run.Filter->Modified();
      const auto start = std::chrono::steady_clock::now();
      run.Filter->Update();
      seconds.push_back(
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    table << "| " << run.Name << " | " << run.Size << "x" << run.Size << " | "
          << ReliefScene::Median(seconds) << " | " << run.Target << " |\n";
  }
  // the per-point quadrics of curved relief (target: a million points in 2 s), the
  // tangent frame included
  vtkNew<vtkSuperquadricSource> torus;
  torus->ToroidalOn();
  torus->SetThetaResolution(1000);
  torus->SetPhiResolution(1000);
  torus->Update();
  vtkNew<vtkLocalQuadricFilter> quadrics;
  quadrics->SetInputConnection(torus->GetOutputPort());
  std::vector<double> seconds;
  for (int round = 0; round < rounds; ++round)
  {
    quadrics->Modified();
    const auto start = std::chrono::steady_clock::now();
    quadrics->Update();
    seconds.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  table << "| vtkLocalQuadricFilter | torus of " << torus->GetOutput()->GetNumberOfPoints()
        << " points | " << ReliefScene::Median(seconds) << " | 2 |\n";
  return table.str();
}
}

int main(int argc, char* argv[])
{
  int frames = 20;
  int rounds = 3;
  bool quick = false;
  std::string only; // the sections to run, comma-separated, or all when empty
  std::string method; // the accuracy study's one search method, or all when empty
  std::vector<std::string> maps; // height maps of the methods table besides Data's
  std::string report;
  std::string results;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--data") && i + 1 < argc)
    {
      ReliefScene::SetDataDirectory(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--frames") && i + 1 < argc)
    {
      frames = std::max(1, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--rounds") && i + 1 < argc)
    {
      rounds = std::max(1, std::atoi(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--report") && i + 1 < argc)
    {
      report = argv[++i];
    }
    else if (!std::strcmp(argv[i], "--results") && i + 1 < argc)
    {
      results = argv[++i];
    }
    else if (!std::strcmp(argv[i], "--map") && i + 1 < argc)
    {
      maps.push_back(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--quick"))
    {
      quick = true;
    }
    else if (!std::strcmp(argv[i], "--method") && i + 1 < argc &&
      ReliefScene::SearchMethodNamed(argv[i + 1]) >= 0)
    {
      method = vtkOpenGLReliefMapper::GetSearchMethodAsString(
        ReliefScene::SearchMethodNamed(argv[++i]));
    }
    else if (!std::strcmp(argv[i], "--only") && i + 1 < argc && KnownSections(argv[i + 1]))
    {
      only = argv[++i];
    }
    else
    {
      if (std::strcmp(argv[i], "--help"))
      {
        std::cerr << "relief bench: cannot use '" << argv[i] << "'"
                  << (i + 1 < argc ? std::string(" '") + argv[i + 1] + "'" : std::string())
                  << "\n";
      }
      std::cout << "usage: ./relief bench [--quick] [--frames N (20)] [--rounds N (3)]\n"
                   "                     [--only SECTION[,SECTION...]]  (plain, methods,\n"
                   "                      filters, accuracy, sweeps, quadric, derivative,\n"
                   "                      sharing, shading, automatic, paths, impostors,\n"
                   "                      robust, exact)\n"
                   "                     [--method NAME (the accuracy study's one method)]\n"
                   "                     [--map FILE (a height map for the methods table,\n"
                   "                      besides Data's; relative to --data; repeatable)]\n"
                   "                     [--report FILE.md] [--results FILE.md]\n"
                   "Times relief mapping against plain texturing at 800x600, every search\n"
                   "method at three height-map sizes, every method's speed against its\n"
                   "accuracy, and its error as view angle, feature width, curvature and\n"
                   "depth scale sweep, the quadric frame's silhouettes on curved shapes, and\n"
                   "the derivative frame against the tangent frame, with its seams at creases,\n"
                   "shading against supersampled geometry, the Automatic search against every\n"
                   "fixed setting across the view angle, many actors on one height map,\n"
                   "path features against geometry, relief impostors against their mesh, and\n"
                   "the robust search's samples and error bound and the exact searches'\n"
                   "samples against resolution and angle, on the CPU mirror.\n"
                   "--report writes the timing tables, --results the accuracy study, the\n"
                   "sweeps, the quadric, derivative, shading and automatic studies with their\n"
                   "charts (PNG, in images/ beside FILE.md), each with machine and versions.\n"
                   "--quick: small sizes and few frames, a smoke run.\n";
      return std::strcmp(argv[i], "--help") ? 2 : 0;
    }
  }

  auto wanted = [&](const std::string& section) {
    return only.empty() || ("," + only + ",").find("," + section + ",") != std::string::npos;
  };
  if (!report.empty() &&
    !(wanted("plain") && wanted("methods") && wanted("filters") && wanted("sharing")))
  {
    std::cerr << "relief bench: --report writes every timing table; run it without --only, "
                 "or with --only plain,methods,filters,sharing (--results may go with any "
                 "--only).\n";
    return 2;
  }
  if (quick)
  {
    frames = std::min(frames, 3);
    rounds = 1;
  }
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, 800, 600);
  renderer->SetBackground(0.0, 0.0, 1.0);
  auto square = ReliefScene::Square(4.0);
  auto relief = ReliefScene::ReliefMapper(square, "bricks_height.png", 0.02);
  vtkNew<vtkPolyDataMapper> plain;
  plain->SetInputData(square);
  auto actor = ReliefScene::ReliefActor(relief, "bricks_color.png");
  renderer->AddActor(actor);
  ReliefScene::ViewSquare(renderer, 45.0);
  renderer->GetActiveCamera()->Dolly(2.2); // the square fills the view
  renderer->ResetCameraClippingRange();

  std::vector<Configuration> configurations = {
    { "plain texturing", -1, 0, 0, false, false },
    { "Linear 1, no self-shadowing (frame and shading)", vtkOpenGLReliefMapper::LINEAR, 1, 0,
      false, false },
    { "Linear 10", vtkOpenGLReliefMapper::LINEAR, 10, 0, true, false },
    { "LinearBinary 10+5", vtkOpenGLReliefMapper::LINEAR_BINARY, 10, 5, true, false },
    { "LinearBinary 10+5, no self-shadowing", vtkOpenGLReliefMapper::LINEAR_BINARY, 10, 5, false,
      false },
    { "LinearBinary 10+5, footprint shading", vtkOpenGLReliefMapper::LINEAR_BINARY, 10, 5, true,
      true },
    { "LinearBinary 32+8", vtkOpenGLReliefMapper::LINEAR_BINARY, 32, 8, true, false },
    { "Automatic", vtkOpenGLReliefMapper::AUTOMATIC, 10, 5, true, false },
    { "Automatic, footprint shading (the defaults)", vtkOpenGLReliefMapper::AUTOMATIC, 10, 5,
      true, true },
  };
  double coverage = 0.0;
  for (int round = 0; round < rounds && wanted("plain"); ++round)
  {
    for (Configuration& configuration : configurations)
    {
      if (configuration.SearchMethod < 0)
      {
        actor->SetMapper(plain);
      }
      else
      {
        actor->SetMapper(relief);
        relief->SetSearchMethod(configuration.SearchMethod);
        relief->SetLinearSteps(configuration.LinearSteps);
        relief->SetBinarySteps(configuration.BinarySteps);
        relief->SetSelfShadowing(configuration.SelfShadowing);
        relief->SetFootprintShading(configuration.FootprintShading);
        if (round == 0)
        {
          const ReliefScene::SampleStatistics statistics =
            ReliefScene::SampleCounts(window, renderer, relief);
          configuration.MeanSamples = statistics.Mean;
          coverage = statistics.Coverage;
        }
      }
      const std::vector<double> milliseconds = ReliefScene::FrameMilliseconds(window, 3, frames);
      configuration.Milliseconds.insert(
        configuration.Milliseconds.end(), milliseconds.begin(), milliseconds.end());
    }
  }

  std::vector<std::string> tableMaps = maps;
  if (!quick)
  {
    tableMaps.insert(
      tableMaps.begin(), { "bricks_height.png", "rivets_height.png", "waves_height.png" });
  }
  const std::string methodsTable = wanted("methods")
    ? MethodsTable(window, renderer, relief,
        TableMaps(quick ? std::vector<int>{ 64 } : std::vector<int>{ 128, 512, 2048 }, tableMaps),
        std::max(3, frames / 4), rounds)
    : "(not run)\n";
  const std::string filtersTable = wanted("filters") ? FiltersTable(rounds) : "(not run)\n";
  const int sharedSize = quick ? 64 : 1024;
  const int sharingActors = quick ? 4 : 100;
  const std::string sharingTable =
    wanted("sharing") ? SharingTable(sharedSize, sharingActors) : "(not run)\n";
  ReliefAccuracy::Options accuracy;
  accuracy.Method = method;
  accuracy.Frames = std::max(1, frames / 2); // per round, two rounds
  if (quick)
  {
    accuracy.HeightMapSize = 32;
    accuracy.Width = 200;
    accuracy.Height = 150;
    accuracy.Frames = 3;
    accuracy.Rounds = 1;
    accuracy.Convergence = false;
  }
  if (!results.empty())
  {
    const size_t slash = results.find_last_of('/');
    accuracy.ImageDirectory =
      (slash == std::string::npos ? std::string(".") : results.substr(0, slash)) + "/images";
  }
  std::string accuracySection = "(not run)\n";
  if (wanted("accuracy"))
  {
    accuracySection = ReliefAccuracy::Study(accuracy);
    if (!quick)
    {
      // the targets' detail: 512^2, without the charts and the convergence check (a
      // truth of edges 0.25 texel would take 34 million triangles)
      ReliefAccuracy::Options detail = accuracy;
      detail.HeightMapSize = 512;
      detail.Convergence = false;
      detail.ImageDirectory.clear();
      accuracySection += "\n### At 512x512 detail\n\n" + ReliefAccuracy::Study(detail);
    }
  }
  ReliefSweeps::Options sweeps;
  sweeps.Quick = quick;
  if (quick)
  {
    sweeps.Width = 200;
    sweeps.Height = 150;
  }
  sweeps.ImageDirectory = accuracy.ImageDirectory;
  const std::string sweepsSection =
    wanted("sweeps") ? ReliefSweeps::Run(sweeps) : "(not run)\n";
  ReliefQuadricStudy::Options quadric;
  quadric.Frames = std::max(1, frames / 2);
  quadric.Rounds = quick ? 1 : 2;
  if (quick)
  {
    quadric.Width = 150;
    quadric.Height = 150;
    quadric.HeightMapSize = 32;
    quadric.Facets = { 24 };
    quadric.InnerSweep = { 80.0 };
  }
  else
  {
    quadric.Facets = { 24, 32, 48 };
  }
  quadric.ImageDirectory = accuracy.ImageDirectory;
  const std::string quadricSection = wanted("quadric")
    ? ReliefQuadricStudy::Report(ReliefQuadricStudy::Measure(quadric), quadric)
    : "(not run)\n";
  ReliefDerivativeStudy::Options derivative;
  derivative.Frames = std::max(1, frames / 2);
  derivative.Rounds = quick ? 1 : 2;
  if (quick)
  {
    derivative.Width = 160;
    derivative.Height = 120;
    derivative.HeightMapSize = 32;
    derivative.Creases = { 0.0, 20.0, 45.0 };
    derivative.ViewAngles = { 0.0, 45.0 };
  }
  derivative.ImageDirectory = accuracy.ImageDirectory;
  const std::string derivativeSection = wanted("derivative")
    ? ReliefDerivativeStudy::Report(ReliefDerivativeStudy::MeasureAccuracy(derivative),
        ReliefDerivativeStudy::MeasureSeams(derivative),
        ReliefDerivativeStudy::MeasureFrameError({ 10.0, 30.0, 50.0, 60.0, 70.0, 80.0, 85.0 }),
        derivative)
    : "(not run)\n";
  ReliefShadingStudy::Options shading;
  if (quick)
  {
    shading.Width = 64;
    shading.Height = 48;
    shading.Angles = { 0.0, 75.0 };
    shading.TexelsPerPixel = { 4.0 };
    shading.Maps = { "steps" };
  }
  const std::string shadingSection = wanted("shading")
    ? ReliefShadingStudy::Report(ReliefShadingStudy::Measure(shading), shading)
    : "(not run)\n";
  ReliefAutomaticStudy::Options automatic;
  automatic.ImageDirectory = accuracy.ImageDirectory;
  if (quick)
  {
    automatic.Width = 160;
    automatic.Height = 120;
    automatic.HeightMapSize = 32;
    automatic.Angles = { 0.0, 75.0 };
    automatic.Maps = { "steps" };
  }
  const std::string automaticSection = wanted("automatic")
    ? ReliefAutomaticStudy::Report(ReliefAutomaticStudy::Measure(automatic), automatic)
    : "(not run)\n";

  ReliefPathStudy::Options pathOptions;
  pathOptions.ImageDirectory = accuracy.ImageDirectory;
  if (quick)
  {
    pathOptions.Width = 160;
    pathOptions.Height = 120;
    pathOptions.TruthColumns = 256;
    pathOptions.TruthColumnsUpClose = 256;
    pathOptions.TruthLayers = 48;
    pathOptions.HeightMapSizes = { 64, 256 };
    pathOptions.Supersampling = 2;
    pathOptions.Frames = 1;
    pathOptions.Rounds = 1;
  }
  const std::string pathSection =
    wanted("paths") ? ReliefPathStudy::Study(pathOptions) : "(not run)\n";

  ReliefImpostorStudy::Options impostorOptions;
  impostorOptions.ImageDirectory = accuracy.ImageDirectory;
  if (quick)
  {
    impostorOptions.Width = 160;
    impostorOptions.Height = 120;
    impostorOptions.MeshResolution = 48;
    impostorOptions.Instances = { 1, 4 };
    impostorOptions.ScreenShares = { 0.25 };
    impostorOptions.DepthResolutions = { 64 };
    impostorOptions.Frames = 1;
  }
  const std::string impostorSection =
    wanted("impostors") ? ReliefImpostorStudy::Study(impostorOptions) : "(not run)\n";
  ReliefRobustStudy::Options robustOptions;
  if (quick)
  {
    robustOptions.Sizes = { 32, 64 };
    robustOptions.Angles = { 45.0 };
    robustOptions.ExactAngles = { 80.0 };
    robustOptions.Rays = 200;
  }
  const std::string robustSection =
    wanted("robust") ? ReliefRobustStudy::Report(robustOptions) : "(not run)\n";
  const std::string exactSection =
    wanted("exact") ? ReliefRobustStudy::ExactReport(robustOptions) : "(not run)\n";

  std::ostringstream table;
  table << std::fixed << std::setprecision(2);
  if (!wanted("plain"))
  {
    table << "(not run)\n";
  }
  else
  {
    table << "| configuration | ms/frame (median) | x plain | ms/frame (fastest) | x plain | "
             "samples/pixel (mean) |\n"
          << "| --- | ---: | ---: | ---: | ---: | ---: |\n";
    const std::vector<double>& plainMilliseconds = configurations[0].Milliseconds;
    const double plainMedian = ReliefScene::Median(plainMilliseconds);
    const double plainFastest =
      *std::min_element(plainMilliseconds.begin(), plainMilliseconds.end());
    for (const Configuration& configuration : configurations)
    {
      const double median = ReliefScene::Median(configuration.Milliseconds);
      const double fastest =
        *std::min_element(configuration.Milliseconds.begin(), configuration.Milliseconds.end());
      table << "| " << configuration.Name << " | " << median << " | " << median / plainMedian
            << " | " << fastest << " | " << fastest / plainFastest << " | ";
      if (configuration.SearchMethod < 0)
      {
        table << "- |\n";
      }
      else
      {
        table << configuration.MeanSamples << " |\n";
      }
    }
  }

  std::ifstream cpuinfo("/proc/cpuinfo");
  const std::string cpu = Trim(FirstLineContaining(cpuinfo, "model name"));
  std::ifstream osRelease("/etc/os-release");
  std::string system = Trim(FirstLineContaining(osRelease, "PRETTY_NAME"));
  system.erase(std::remove(system.begin(), system.end(), '"'), system.end());
  window->Render(); // a context to ask, when no section above rendered in this window
  std::istringstream capabilities(
    vtkOpenGLRenderWindow::SafeDownCast(window)->ReportCapabilities());
  const std::string gl = Trim(FirstLineContaining(capabilities, "OpenGL renderer string"));
  const std::string glVersion = Trim(FirstLineContaining(capabilities, "OpenGL version string"));
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof(date), "%Y-%m-%d", std::gmtime(&now));

  std::ostringstream machine;
  machine << "Machine: " << cpu << ", " << std::thread::hardware_concurrency() << " threads; "
          << system << "; OpenGL: " << gl << ", " << glVersion << "; VTK "
          << vtkVersion::GetVTKVersion() << "; date " << date << ".\n";
  std::ostringstream context;
  context << "800x600, square filling " << std::setprecision(3) << 100.0 * coverage
          << "% of the view at 45 degrees, 512x512 16-bit height map, DepthScale 0.02,\n"
          << "one scene light, footprint shading off but where named (the mapper's default\n"
          << "is on); " << frames << " warm frames x " << rounds
          << " interleaved rounds per configuration. The median is the figure asked for;\n"
          << "the fastest frame is the one least disturbed by other work on a shared host.\n\n"
          << machine.str();
  const std::string methodsContext =
    "Search methods (Baboud and Decoret 2006, Table 1): the same square and light, the stones\n"
    "height map resampled to each size (4 tiles across the square), then Data's other maps\n"
    "and any given with --map as they are, DepthScale 0.02, self-shadowing on, footprint\n"
    "shading off (the searches' own cost), step counts 10 + 5; each method's figures\n"
    "relative to LinearBinary's in the same run.\n"
    "Samples are height reads per covered pixel (a cell test or pyramid node counts one);\n"
    "the display caps a pixel's count at 255.\n\n";
  const std::string methodsSection =
    methodsTable == "(not run)\n" ? methodsTable : methodsContext + methodsTable;
  const std::string filtersContext = "Acceleration filters, on the stones height map resampled, "
                                     "and the local quadrics of curved relief; "
                                     "vtkSMPTools backend " +
    std::string(vtkSMPTools::GetBackend()) + ", " +
    std::to_string(vtkSMPTools::GetEstimatedNumberOfThreads()) + " threads.\n\n";
  const std::string sharingContext = "Many actors on one " + std::to_string(sharedSize) + "x" +
    std::to_string(sharedSize) +
    " height map: each actor its own relief mapper of the same\n"
    "square and the same height image, in a window of its own after OpenGL's first start;\n"
    "the GPU bytes of the window's relief textures (GetTextureBytesInUse), what the\n"
    "process grows by in the first frame, that frame's time (filters, uploads, the\n"
    "shader's compilation) and the median of the next five.\n\n";
  std::cout << context.str() << "\n" << table.str() << "\n" << methodsContext << methodsTable
            << "\n" << filtersContext << filtersTable << "\n" << accuracySection << "\n"
            << sweepsSection << "\n" << quadricSection << "\n" << derivativeSection << "\n"
            << shadingSection << "\n" << automaticSection << "\n" << pathSection << "\n"
            << impostorSection << "\n" << robustSection << "\n" << exactSection << "\n"
            << sharingContext
            << sharingTable;

  if (!report.empty())
  {
    std::ofstream out(report);
    out << "# Benchmark: relief mapping against plain texturing\n\n"
        << "Produced by `./relief bench" << (only.empty() ? "" : " --only " + only);
    for (const std::string& map : maps)
    {
      out << " --map " << map;
    }
    out << " --report " << report << "`.\n\n"
        << context.str() << "\n" << table.str() << "\n## Search methods\n\n"
        << methodsContext << methodsTable << "\n## Acceleration filters\n\n" << filtersContext
        << filtersTable << "\n## Many actors on one height map\n\n" << sharingContext
        << sharingTable;
    std::cout << "written to " << report << "\n";
  }
  if (!results.empty())
  {
    std::ofstream out(results);
    out << "# Results: speed against accuracy\n\n"
        << "Produced by `./relief bench" << (only.empty() ? "" : " --only " + only);
    for (const std::string& map : maps)
    {
      out << " --map " << map;
    }
    out << " --results " << results << "`.\n\n"
        << machine.str();
    // the sections run, each under its heading (the accuracy study's is the page's)
    const std::pair<const char*, const std::string*> sections[] = {
      { nullptr, &accuracySection },
      { "Stability: where each method fails", &sweepsSection },
      { "Curved surfaces: the quadric frame's silhouettes", &quadricSection },
      { "Tangent-free relief: the derivative frame", &derivativeSection },
      { "Shading true to the pixel's footprint", &shadingSection },
      { "Automatic quality: the search each fragment needs", &automaticSection },
      { "Path features against geometry and height maps", &pathSection },
      { "Relief impostors against the mesh they replace", &impostorSection },
      { "Search methods (Baboud and Decoret 2006, Table 1)", &methodsSection },
      { "The robust search as the paper measured it", &robustSection },
      { "Exact searches against resolution and angle", &exactSection },
    };
    for (const auto& section : sections)
    {
      if (*section.second == "(not run)\n")
      {
        continue;
      }
      out << "\n";
      if (section.first)
      {
        out << "## " << section.first << "\n\n";
      }
      out << *section.second;
    }
    std::cout << "written to " << results << "\n";
  }
  return 0;
}
