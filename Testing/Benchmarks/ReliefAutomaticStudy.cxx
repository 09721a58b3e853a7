#include "ReliefAutomaticStudy.h"

#include "ReliefAccuracy.h"
#include "ReliefChart.h"
#include "ReliefMetrics.h"
#include "ReliefScene.h"
#include "ReliefShadingStudy.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace
{
using ReliefAutomaticStudy::Measurement;

vtkSmartPointer<vtkImageData> HeightMap(const std::string& name, int size)
{
  if (name == "steps")
  {
    return ReliefShadingStudy::Steps();
  }
  return ReliefScene::ResizedHeightMap(name, size);
}

std::string Label(const std::string& family, const std::string& parameters)
{
  return parameters.empty() ? family : family + " " + parameters;
}

// The measurements of one map, by setting label, in the order measured, each by angle.
struct MapTable
{
  std::vector<std::string> Labels;
  std::map<std::string, bool> Automatic;
  std::map<std::string, std::map<double, Measurement>> Cells;
};

MapTable TableOf(const std::vector<Measurement>& measurements, const std::string& map)
{
  MapTable table;
  for (const Measurement& m : measurements)
  {
    if (m.Map != map)
    {
      continue;
    }
    const std::string label = Label(m.Family, m.Parameters);
    if (!table.Cells.count(label))
    {
      table.Labels.push_back(label);
      table.Automatic[label] = m.Automatic;
    }
    table.Cells[label][m.Angle] = m;
  }
  return table;
}

double MeanSamples(const std::map<double, Measurement>& byAngle)
{
  double sum = 0.0;
  for (const auto& [angle, m] : byAngle)
  {
    sum += m.MeanSamples;
  }
  return byAngle.empty() ? 0.0 : sum / byAngle.size();
}

double WorstWrong(const std::map<double, Measurement>& byAngle)
{
  double worst = 0.0;
  for (const auto& [angle, m] : byAngle)
  {
    worst = std::max(worst, m.WrongDepth);
  }
  return worst;
}

// Samples per pixel against the view angle, and wrong pixels against it (log), for
// Automatic and the fixed settings a user would weigh it against.
void Charts(const MapTable& table, const std::vector<std::string>& shown, const std::string& map,
  const std::string& directory)
{
  std::vector<ReliefChart::Series> samples;
  std::vector<ReliefChart::Series> wrong;
  for (const std::string& label : shown)
  {
    ReliefChart::Series s{ label };
    s.Line = true;
    ReliefChart::Series w{ label };
    w.Line = true;
    for (const auto& [angle, m] : table.Cells.at(label))
    {
      s.X.push_back(angle);
      s.Y.push_back(m.MeanSamples);
      w.X.push_back(angle);
      w.Y.push_back(std::max(m.WrongDepth, ReliefChart::LogFloor));
    }
    samples.push_back(s);
    wrong.push_back(w);
  }
  ReliefChart::Axes axes;
  axes.Title = "Height samples against view angle (" + map + ")";
  axes.X = "view angle from the normal (degrees)";
  axes.Y = "height samples per pixel (mean)";
  ReliefChart::Write(samples, axes, directory + "/automatic_samples.png");
  axes.Title = "Wrong pixels against view angle (" + map + ")";
  axes.Y = "pixels with a wrong depth (share of those both cover)";
  axes.LogY = true;
  axes.YRange[0] = ReliefChart::LogFloor;
  axes.YRange[1] = 10.0;
  ReliefChart::Write(wrong, axes, directory + "/automatic_wrong.png");
}
}

namespace ReliefAutomaticStudy
{
std::vector<Measurement> Measure(const Options& options)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, options.Width, options.Height);
  auto square = ReliefScene::Square(1.0);
  std::vector<Measurement> measurements;
  for (const std::string& map : options.Maps)
  {
    vtkSmartPointer<vtkImageData> heights = HeightMap(map, options.HeightMapSize);
    vtkNew<vtkReliefTextureFilter> reliefTexture;
    reliefTexture->SetInputData(heights);
    reliefTexture->Update();
    vtkNew<vtkPolyDataMapper> truthMapper;
    truthMapper->SetInputData(
      ReliefScene::DisplacedMesh(square, reliefTexture->GetOutput(), options.DepthScale, 0.5));
    auto truth = ReliefScene::ReliefActor(truthMapper, "");
    vtkNew<vtkOpenGLReliefMapper> mapper;
    mapper->SetInputData(square);
    mapper->SetHeightMapData(heights);
    mapper->SetDepthScale(options.DepthScale);
    mapper->SetSelfShadowing(false);    // the stock mapper casts no shadows
    mapper->SetFootprintShading(false); // the searches' own samples
    auto relief = ReliefScene::ReliefActor(mapper, "");
    for (double angle : options.Angles)
    {
      // framed on the coarse square alone, as the accuracy chart is
      renderer->RemoveAllViewProps();
      renderer->AddActor(relief);
      ReliefScene::ViewSquare(renderer, angle);
      renderer->GetActiveCamera()->Dolly(3.0);
      renderer->AddActor(truth);
      renderer->ResetCameraClippingRange();
      relief->VisibilityOff();
      truth->VisibilityOn();
      window->Render();
      const ReliefMetrics::Capture truthCapture = ReliefScene::Capture(window, renderer);
      truth->VisibilityOff();
      relief->VisibilityOn();
      for (const ReliefAccuracy::Setting& setting : ReliefAccuracy::Settings())
      {
        ReliefAccuracy::Apply(setting, mapper);
        window->Render();
        const ReliefMetrics::Capture capture = ReliefScene::Capture(window, renderer);
        Measurement m;
        m.Map = map;
        m.Angle = angle;
        m.Family = setting.Family;
        m.Parameters = setting.Parameters;
        m.Automatic = ReliefAccuracy::IsAutomatic(setting);
        m.WrongDepth =
          ReliefMetrics::MeasureDepthError(capture, truthCapture, options.DepthScale).FractionAbove;
        m.MeanSamples = ReliefScene::SampleCounts(window, renderer, mapper).Mean;
        measurements.push_back(m);
      }
      std::cout << "automatic: " << map << " at " << angle << " degrees done\n";
    }
  }
  return measurements;
}

std::string Report(const std::vector<Measurement>& measurements, const Options& options)
{
  std::ostringstream section;
  section << "Every setting of the accuracy chart and Automatic at ScreenTolerance 0.5 and 2 "
             "pixels (and 0.5 over the slope pyramid, AutomaticAcceleration SlopeMipmap), on "
             "one tile of each height map over the unit square filling a "
          << options.Width << "x" << options.Height << " window, DepthScale "
          << options.DepthScale << ", the maps of Data/ resampled to " << options.HeightMapSize
          << "x" << options.HeightMapSize
          << " and the sharp steps of the shading study (64x64), self-shadowing and footprint "
             "shading off. Each cell: the share of the pixels both the relief and the ground "
             "truth (edges of 0.5 texel) cover whose eye depth is more than 0.1 DepthScale "
             "off, in percent, then the height samples per pixel. (The flat frame's outline, "
             "which no search changes, is left out: the sweeps above count it.)\n\n";
  std::vector<std::string> maps;
  for (const Measurement& m : measurements)
  {
    if (std::find(maps.begin(), maps.end(), m.Map) == maps.end())
    {
      maps.push_back(m.Map);
    }
  }
  for (const std::string& map : maps)
  {
    const MapTable table = TableOf(measurements, map);
    section << "### " << map << "\n\n| setting |";
    for (double angle : options.Angles)
    {
      section << " " << angle << " deg |";
    }
    section << " mean samples |\n| --- |";
    for (size_t k = 0; k <= options.Angles.size(); ++k)
    {
      section << " ---: |";
    }
    section << "\n";
    for (const std::string& label : table.Labels)
    {
      const auto& byAngle = table.Cells.at(label);
      section << "| " << (table.Automatic.at(label) ? "**" + label + "**" : label) << " |";
      for (double angle : options.Angles)
      {
        const Measurement& m = byAngle.at(angle);
        section << std::setprecision(2) << " " << 100.0 * m.WrongDepth << " / "
                << std::setprecision(3) << m.MeanSamples << " |";
      }
      section << std::setprecision(3) << " " << MeanSamples(byAngle) << " |\n";
    }
    // the targets: the cheapest fixed setting within the target at every angle, and
    // whether any fixed setting beats Automatic in both error and samples at some angle
    std::string cheapest;
    for (const std::string& label : table.Labels)
    {
      const auto& byAngle = table.Cells.at(label);
      if (!table.Automatic.at(label) && WorstWrong(byAngle) <= options.WrongTarget &&
        (cheapest.empty() || MeanSamples(byAngle) < MeanSamples(table.Cells.at(cheapest))))
      {
        cheapest = label;
      }
    }
    const std::string automatic = Label("Automatic", "0.5 pixels");
    const auto& automaticCells = table.Cells.at(automatic);
    section << "\n" << std::setprecision(3) << automatic << ": wrong pixels at most "
            << 100.0 * WorstWrong(automaticCells) << "% (target " << 100.0 * options.WrongTarget
            << "%), " << MeanSamples(automaticCells) << " samples per pixel on average over the "
            << "angles. ";
    if (cheapest.empty())
    {
      section << "No fixed setting keeps within the target at every angle.";
    }
    else
    {
      const double fixedSamples = MeanSamples(table.Cells.at(cheapest));
      section << "The cheapest fixed setting within the target at every angle: " << cheapest
              << ", at most " << 100.0 * WorstWrong(table.Cells.at(cheapest)) << "%, "
              << fixedSamples << " samples (Automatic takes "
              << MeanSamples(automaticCells) / fixedSamples << " of them).";
    }
    std::ostringstream beaten;
    beaten << std::setprecision(4);
    for (double angle : options.Angles)
    {
      const Measurement& a = automaticCells.at(angle);
      for (const std::string& label : table.Labels)
      {
        const Measurement& f = table.Cells.at(label).at(angle);
        if (!f.Automatic && f.WrongDepth <= a.WrongDepth && f.MeanSamples < a.MeanSamples)
        {
          beaten << " " << label << " at " << angle << " degrees (" << 100.0 * f.WrongDepth
                 << "% / " << f.MeanSamples << " against " << 100.0 * a.WrongDepth << "% / "
                 << a.MeanSamples << ");";
        }
      }
    }
    section << " Pareto: "
            << (beaten.str().empty()
                   ? std::string("no fixed setting has both fewer wrong pixels (or as few) and "
                                 "fewer samples at any angle.")
                   : "beaten by" + beaten.str())
            << "\n\n";
    if (!options.ImageDirectory.empty() && map == maps.front())
    {
      std::filesystem::create_directories(options.ImageDirectory);
      // Automatic last, drawn over the fixed settings it matches
      std::vector<std::string> shown = { "ExactDDA", "MaximumMipmap", "LinearBinary 10+5 steps",
        "ConeStep" };
      if (!cheapest.empty() && std::find(shown.begin(), shown.end(), cheapest) == shown.end())
      {
        shown.push_back(cheapest);
      }
      shown.push_back(automatic);
      Charts(table, shown, map, options.ImageDirectory);
      section << "![samples against view angle](images/automatic_samples.png)\n\n"
              << "![wrong pixels against view angle](images/automatic_wrong.png)\n\n";
    }
  }
  return section.str();
}
}
