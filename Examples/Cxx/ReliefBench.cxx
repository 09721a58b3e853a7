// ./relief bench: frame time of relief mapping against plain texturing of the same
// coarse mesh, and the height samples per pixel, measured in one run.
//
// Scene: a two-triangle square filling an 800x600 view at 45 degrees, the 512x512
// bricks height map. Each configuration renders warm-up frames, then its frames are
// timed one by one (Render + WaitForCompletion); configurations are interleaved over
// several rounds so machine noise hits all alike. Reported: median and fastest ms/frame
// over all timed frames, their ratios to plain texturing, and the mean samples per
// covered pixel (SampleCount mode).
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkVersion.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>

namespace
{
struct Configuration
{
  std::string Name;
  int SearchMethod; // -1: plain texturing
  int LinearSteps;
  int BinarySteps;
  bool SelfShadowing;
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

std::string Trim(const std::string& text)
{
  const auto first = text.find_first_not_of(" \t");
  return first == std::string::npos ? "" : text.substr(first);
}

// The mean red (samples) over covered pixels, and the covered fraction of the view.
std::pair<double, double> MeanSamples(vtkRenderWindow* window, vtkOpenGLReliefMapper* mapper)
{
  mapper->SetDisplayModeToSampleCount();
  window->Render();
  const std::vector<unsigned char> pixels = ReliefScene::Pixels(window);
  mapper->SetDisplayModeToShaded();
  double sum = 0.0;
  size_t covered = 0;
  for (size_t i = 0; i + 2 < pixels.size(); i += 3)
  {
    if (pixels[i + 1] == 0 && pixels[i + 2] == 0) // background is blue
    {
      sum += pixels[i];
      ++covered;
    }
  }
  return { covered ? sum / covered : 0.0, static_cast<double>(covered) / (pixels.size() / 3) };
}
}

int main(int argc, char* argv[])
{
  int frames = 20;
  int rounds = 3;
  std::string report;
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
    else
    {
      std::cout << "usage: ./relief bench [--frames N (20)] [--rounds N (3)] [--report FILE.md]\n"
                   "Times relief mapping against plain texturing at 800x600; --report\n"
                   "writes the table, machine and versions as Markdown.\n";
      return std::strcmp(argv[i], "--help") ? 2 : 0;
    }
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
    { "plain texturing", -1, 0, 0, false },
    { "Linear 1, no self-shadowing (frame and shading)", vtkOpenGLReliefMapper::LINEAR, 1, 0,
      false },
    { "Linear 10", vtkOpenGLReliefMapper::LINEAR, 10, 0, true },
    { "LinearBinary 10+5", vtkOpenGLReliefMapper::LINEAR_BINARY, 10, 5, true },
    { "LinearBinary 10+5, no self-shadowing", vtkOpenGLReliefMapper::LINEAR_BINARY, 10, 5, false },
    { "LinearBinary 32+8", vtkOpenGLReliefMapper::LINEAR_BINARY, 32, 8, true },
  };
  double coverage = 0.0;
  for (int round = 0; round < rounds; ++round)
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
        if (round == 0)
        {
          std::tie(configuration.MeanSamples, coverage) = MeanSamples(window, relief);
        }
      }
      const std::vector<double> milliseconds = ReliefScene::FrameMilliseconds(window, 3, frames);
      configuration.Milliseconds.insert(
        configuration.Milliseconds.end(), milliseconds.begin(), milliseconds.end());
    }
  }

  std::ostringstream table;
  table << std::fixed << std::setprecision(2);
  table << "| configuration | ms/frame (median) | x plain | ms/frame (fastest) | x plain | "
           "samples/pixel (mean) |\n"
        << "| --- | ---: | ---: | ---: | ---: | ---: |\n";
  const double plainMedian = ReliefScene::Median(configurations[0].Milliseconds);
  const double plainFastest =
    *std::min_element(configurations[0].Milliseconds.begin(), configurations[0].Milliseconds.end());
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

  std::ifstream cpuinfo("/proc/cpuinfo");
  const std::string cpu = Trim(FirstLineContaining(cpuinfo, "model name"));
  std::ifstream osRelease("/etc/os-release");
  std::string system = Trim(FirstLineContaining(osRelease, "PRETTY_NAME"));
  system.erase(std::remove(system.begin(), system.end(), '"'), system.end());
  std::istringstream capabilities(
    vtkOpenGLRenderWindow::SafeDownCast(window)->ReportCapabilities());
  const std::string gl = Trim(FirstLineContaining(capabilities, "OpenGL renderer string"));
  const std::time_t now = std::time(nullptr);
  char date[32];
  std::strftime(date, sizeof(date), "%Y-%m-%d", std::gmtime(&now));

  std::ostringstream context;
  context << "800x600, square filling " << std::setprecision(3) << 100.0 * coverage
          << "% of the view at 45 degrees, 512x512 16-bit height map, DepthScale 0.02,\n"
          << "one scene light; " << frames << " warm frames x " << rounds
          << " interleaved rounds per configuration. The median is the figure asked for;\n"
          << "the fastest frame is the one least disturbed by other work on a shared host.\n\n"
          << "Machine: " << cpu << ", " << std::thread::hardware_concurrency()
          << " threads; " << system << "; OpenGL: " << gl << "; VTK "
          << vtkVersion::GetVTKVersion() << "; date "
          << date << ".\n";
  std::cout << context.str() << "\n" << table.str();

  if (!report.empty())
  {
    std::ofstream out(report);
    out << "# Benchmark: relief mapping against plain texturing\n\n"
        << "Produced by `./relief bench --report " << report << "`.\n\n"
        << context.str() << "\n" << table.str();
    std::cout << "written to " << report << "\n";
  }
  return 0;
}
