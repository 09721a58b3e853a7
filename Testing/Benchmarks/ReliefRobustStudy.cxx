#include "ReliefRobustStudy.h"

#include "ReliefScene.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkReliefTextureFilter.h"

#include "ReliefMirrorMaps.h"
#include "ReliefReferenceHit.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <map>
#include <random>
#include <sstream>
#include <tuple>
#include <utility>

namespace
{
using namespace ReliefCpuMirror;

// The methods table's scene: four tiles across the square, DepthScale 0.02 of its side,
// so the relief's depth spans 0.08 of a tile.
constexpr double DepthInTiles = 0.08;
constexpr double Pi = 3.14159265358979323846;

struct Setting
{
  const char* Method;
  ReliefHit (*Search)(ReliefRay, int, int);
  double Tolerance;
  bool ScaledMaximum; // MaximumRadius grows with the map: a sixteenth of its side
};

const Setting Settings[] = {
  { "LinearBinary 10+5", &reliefSearchLinearBinary, 0.0, false },
  { "ExactDDA", &reliefSearchExactDDA, 0.0, false },
  { "SafetyRadius", &reliefSearchSafetyRadius, 0.0, false },
  { "SafetyRadius", &reliefSearchSafetyRadius, 0.05, false },
  { "RobustBinary", &reliefSearchRobustBinary, 0.0, false },
  { "RobustBinary", &reliefSearchRobustBinary, 0.01, false },
  { "RobustBinary", &reliefSearchRobustBinary, 0.05, false },
  { "RobustBinary", &reliefSearchRobustBinary, 0.1, false },
  { "RobustBinary", &reliefSearchRobustBinary, 0.05, true },
};

// The size the stones are resampled to before `size` (StonesAt): 0, none, for their own.
int SourceOf(int size, int source)
{
  return source == size ? 0 : source;
}

// The stones resampled to `size`, made once for every table; from the stones first
// resampled to `source` where it is given (0: from the image's own 512^2), so that every
// size holds the same relief.
const DepthField& StonesAt(int size, int source = 0)
{
  static std::map<std::pair<int, int>, DepthField> fields;
  const std::pair<int, int> key(size, SourceOf(size, source));
  auto found = fields.find(key);
  if (found == fields.end())
  {
    const char* name = "stones_height.png";
    vtkSmartPointer<vtkImageData> heights = key.second > 0
      ? ReliefScene::ResizedHeightMap(name, key.second)
      : ReliefScene::ReadImage(name);
    vtkNew<vtkReliefTextureFilter> relief;
    relief->SetInputData(ReliefScene::ResizedImage(heights, size));
    relief->Update();
    found = fields.emplace(key, FieldOf(relief->GetOutput())).first;
  }
  return found->second;
}

std::vector<ReliefRay> RaysAt(double angle, int count)
{
  std::mt19937 generator(1);
  std::uniform_real_distribution<float> entry(0.0f, 1.0f);
  std::uniform_real_distribution<double> azimuth(0.0, 2.0 * Pi);
  const double run = std::tan(angle * Pi / 180.0) * DepthInTiles;
  std::vector<ReliefRay> rays;
  for (int k = 0; k < count; ++k)
  {
    const double a = azimuth(generator);
    const float u = entry(generator);
    rays.push_back(reliefViewRay(
      vec2(u, entry(generator)), vec3(float(run * std::cos(a)), float(run * std::sin(a)), 1.0f)));
  }
  return rays;
}

// The brute-force first hit of each of `rays` (RaysAt(angle, ...)) over the stones at
// `size` (from `source`: StonesAt), computed once for every table.
const std::vector<double>& FirstHitsAt(
  int size, int source, double angle, const std::vector<ReliefRay>& rays)
{
  static std::map<std::tuple<int, int, double, size_t>, std::vector<double>> hits;
  const std::tuple<int, int, double, size_t> key(
    size, SourceOf(size, source), angle, rays.size());
  auto found = hits.find(key);
  if (found == hits.end())
  {
    std::vector<double> first;
    for (const ReliefRay& ray : rays)
    {
      first.push_back(ReferenceHit(StonesAt(size, source), ray));
    }
    found = hits.emplace(key, std::move(first)).first;
  }
  return found->second;
}

DepthField Lowered(const DepthField& field, double tolerance)
{
  DepthField deeper = field;
  for (float& depth : deeper.Depths)
  {
    depth += static_cast<float>(tolerance);
  }
  return deeper;
}

// The exact searches of the second table, each with what it reads.
struct ExactSearch
{
  const char* Method;
  ReliefHit (*Search)(ReliefRay, int, int);
};

const ExactSearch ExactSearches[] = {
  { "LinearBinary 10+5 (not exact)", &reliefSearchLinearBinary },
  { "ConeStep", &reliefSearchConeStep },
  { "MaximumMipmap", &reliefSearchMaximumMipmap },
  { "SlopeMipmap", &reliefSearchSlopeMipmap },
};

struct Row
{
  double Mean = 0.0;
  int Maximum = 0;
  int PastTheBound = 0; // after the first point more than e below the field
  int Wrong = 0;        // more than a texel from the first hit
};
}

namespace
{
// The exact searches' table over the stones at each size (from `source`: StonesAt).
std::string ExactTable(const ReliefRobustStudy::Options& options, int source)
{
  constexpr size_t Count = std::size(ExactSearches);
  const size_t sizes = options.Sizes.size();
  // per method and angle: the mean at each size, the largest count, rays off the hit
  std::vector<std::vector<std::vector<double>>> means(
    Count, std::vector<std::vector<double>>(options.ExactAngles.size()));
  std::vector<std::vector<int>> maxima(Count, std::vector<int>(options.ExactAngles.size(), 0));
  std::vector<std::vector<int>> wrong(Count, std::vector<int>(options.ExactAngles.size(), 0));
  for (int size : options.Sizes)
  {
    const DepthField& field = StonesAt(size, source);
    const DepthPyramid pyramid = PyramidOf(field);
    const SlopePyramid slopes = SlopesOf(field);
    const ConeStepMap cones = ConeMapOf(field);
    CurrentField = &field;
    CurrentPyramid = &pyramid;
    CurrentSlopes = &slopes;
    CurrentConeMap = &cones;
    for (size_t a = 0; a < options.ExactAngles.size(); ++a)
    {
      const std::vector<ReliefRay> rays = RaysAt(options.ExactAngles[a], options.Rays);
      const std::vector<double>& first =
        FirstHitsAt(size, source, options.ExactAngles[a], rays);
      for (size_t m = 0; m < Count; ++m)
      {
        double sum = 0.0;
        for (size_t k = 0; k < rays.size(); ++k)
        {
          const ReliefHit hit = ExactSearches[m].Search(rays[k], 10, 5);
          sum += hit.samples;
          maxima[m][a] = std::max(maxima[m][a], hit.samples);
          wrong[m][a] += HitError(field, rays[k], hit.t, first[k]) > 1e-3 ? 1 : 0;
        }
        means[m][a].push_back(sum / rays.size());
      }
    }
    std::cout << "exact searches: " << size << "x" << size << (source > 0 ? " (same relief)" : "")
              << " done" << std::endl;
  }
  std::ostringstream table;
  table << std::fixed << std::setprecision(2) << "| method | angle |";
  for (int size : options.Sizes)
  {
    table << " " << size << "^2 |";
  }
  table << " most x LinearBinary | growth " << options.Sizes.front() << "^2 to "
        << options.Sizes.back() << "^2 | samples/ray (max) | rays off the hit |\n| --- | ---: |";
  for (size_t k = 0; k < sizes + 4; ++k)
  {
    table << " ---: |";
  }
  table << "\n";
  for (size_t m = 0; m < Count; ++m)
  {
    for (size_t a = 0; a < options.ExactAngles.size(); ++a)
    {
      table << "| " << ExactSearches[m].Method << " | " << options.ExactAngles[a] << " |";
      double most = 0.0;
      for (size_t k = 0; k < sizes; ++k)
      {
        table << " " << means[m][a][k] << " |";
        most = std::max(most, means[m][a][k] / means[0][a][k]);
      }
      table << " " << most << " | " << std::setprecision(0)
            << 100.0 * (means[m][a].back() / means[m][a].front() - 1.0) << "% |"
            << std::setprecision(2) << " " << maxima[m][a] << " | " << wrong[m][a] << " |\n";
    }
  }
  return table.str();
}
}

std::string ReliefRobustStudy::ExactReport(const Options& options)
{
  const int smallest = *std::min_element(options.Sizes.begin(), options.Sizes.end());
  std::ostringstream report;
  report << "Mean samples per ray of the exact searches on the same rays (" << options.Rays
         << " per size and angle), uncapped, against LinearBinary's\n"
         << "at each size; the most that ratio reaches over the sizes; the growth of the mean "
            "from the\n"
         << "smallest map to the largest; the largest count of any ray; rays whose hit is "
            "more than\n"
         << "1e-3 (texel and depth) from the brute-force one. The issue's target for an exact "
            "search\n"
         << "whose cost does not grow: at most 1x LinearBinary, at most 64 samples for any "
            "ray, at most\n"
         << "20% growth, no ray off.\n\n"
         << ExactTable(options, 0) << "\n"
         << "The stones resampled from 512^2 hold less detail below it and the same above,\n"
         << "so the growth above mixes what a search pays for a finer grid with what it pays\n"
         << "for more relief. The same searches over the same relief at every size (the\n"
         << "stones resampled to " << smallest << "^2, then to each size) pay for the grid "
         << "alone:\n\n"
         << ExactTable(options, smallest);
  return report.str();
}

std::string ReliefRobustStudy::Report(const Options& options)
{
  std::ostringstream table;
  table << std::fixed << std::setprecision(2);
  table << "| height map | angle | method | e | MaximumRadius | samples/ray (mean) | "
           "x LinearBinary | samples/ray (max) | rays past the bound | rays off the hit |\n"
        << "| ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  for (int size : options.Sizes)
  {
    const DepthField& field = StonesAt(size);
    CurrentField = &field;
    const int scaledMaximum = std::min(255, std::max(32, size / 16));
    // the radii of each (e, MaximumRadius), made once for every angle and both searches
    std::map<std::pair<double, int>, SafetyRadiusMap> radiiOf;
    for (double angle : options.Angles)
    {
      const std::vector<ReliefRay> rays = RaysAt(angle, options.Rays);
      const std::vector<double>& first = FirstHitsAt(size, 0, angle, rays);
      double linearBinary = 0.0;
      for (const Setting& setting : Settings)
      {
        const int maximum = setting.ScaledMaximum ? scaledMaximum : 32;
        const bool searchesRadii = setting.Search == &reliefSearchSafetyRadius ||
          setting.Search == &reliefSearchRobustBinary;
        if (searchesRadii)
        {
          const std::pair<double, int> key(setting.Tolerance, maximum);
          if (radiiOf.find(key) == radiiOf.end())
          {
            radiiOf[key] = RadiiOf(field, setting.Tolerance, maximum);
          }
          CurrentRadii = &radiiOf[key];
        }
        const DepthField deeper = Lowered(field, setting.Tolerance);
        Row row;
        for (size_t k = 0; k < rays.size(); ++k)
        {
          const ReliefHit hit = setting.Search(rays[k], 10, 5);
          row.Mean += hit.samples;
          row.Maximum = std::max(row.Maximum, hit.samples);
          const double off = HitError(field, rays[k], hit.t, first[k]);
          row.Wrong += off > 1.0 ? 1 : 0;
          if (off > 1e-3 && searchesRadii)
          {
            const double deep =
              setting.Tolerance > 0.0 ? ReferenceHit(deeper, rays[k]) : first[k];
            row.PastTheBound +=
              hit.t > deep && HitError(field, rays[k], hit.t, deep) > 1e-3 ? 1 : 0;
          }
        }
        row.Mean /= rays.size();
        if (setting.Search == &reliefSearchLinearBinary)
        {
          linearBinary = row.Mean;
        }
        table << "| " << size << "x" << size << " | " << angle << " | " << setting.Method
              << " | " << (searchesRadii ? std::to_string(setting.Tolerance).substr(0, 4) : "-")
              << " | " << (searchesRadii ? std::to_string(maximum) : "-") << " | " << row.Mean
              << " | " << row.Mean / linearBinary << " | " << row.Maximum << " | "
              << (searchesRadii ? std::to_string(row.PastTheBound) : "-") << " | " << row.Wrong
              << " |\n";
      }
      std::cout << "robust: " << size << "x" << size << " at " << angle << " degrees done\n";
    }
  }
  std::ostringstream report;
  report << "The stones height map resampled to each size, in the methods table's scene (depth\n"
         << "0.08 of a tile), " << options.Rays
         << " rays per size and angle from random points of the tile in random\n"
         << "azimuths, searched by the CPU mirror of the shaders (the GLSL compiled as C++). "
            "Samples\n"
         << "per ray are what the GPU's SampleCount display counts, uncapped. Past the bound: "
            "rays\n"
         << "whose hit lies beyond the first point where the ray is more than e below the "
            "field (at\n"
         << "e = 0, beyond the first hit), the guarantee of Baboud and Decoret (2006, s3.5). "
            "Off the\n"
         << "hit: rays whose hit lies more than a texel from the first one (brute force in "
            "double,\n"
         << "ReliefReferenceHit.h); for LinearBinary these are the features it misses.\n\n"
         << table.str();
  return report.str();
}
