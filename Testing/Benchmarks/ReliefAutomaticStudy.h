// The Automatic search against every fixed setting (ReliefAccuracy::Settings) across the
// view angle: for each height map and angle, each setting's share of wrong pixels (eye
// depth more than 0.1 DepthScale from the ground truth's, among the pixels both cover:
// the search's own failures, not the flat frame's outline) and its height samples per
// pixel. Reported: the tables, whether any fixed setting beats Automatic in both at any
// angle (the Pareto check), and the cheapest fixed setting that keeps wrong pixels within
// the target at every angle, against Automatic's samples.
#ifndef ReliefAutomaticStudy_h
#define ReliefAutomaticStudy_h

#include <string>
#include <vector>

namespace ReliefAutomaticStudy
{
struct Options
{
  int Width = 480; ///< window size
  int Height = 360;
  int HeightMapSize = 256; ///< maps of Data/ resampled to this size; "steps" keeps its own
  double DepthScale = 0.08;
  std::vector<double> Angles = { 0.0, 30.0, 45.0, 60.0, 75.0, 80.0, 85.0 };
  std::vector<std::string> Maps = { "stones_height.png", "bricks_height.png", "steps" };
  double WrongTarget = 0.005; ///< the share of wrong pixels the issue asks for at most
  std::string ImageDirectory; ///< where the charts go (PNG); none when empty
};

/// One setting on one map at one angle.
struct Measurement
{
  std::string Map;
  double Angle = 0.0;
  std::string Family;
  std::string Parameters;
  bool Automatic = false;
  double WrongDepth = 0.0;  ///< share of the pixels both cover
  double MeanSamples = 0.0; ///< height samples per covered pixel
};

std::vector<Measurement> Measure(const Options& options);

/// The Markdown section: context, one table per map, the checks, the charts.
std::string Report(const std::vector<Measurement>& measurements, const Options& options);
}

#endif
