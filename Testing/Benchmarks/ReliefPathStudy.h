// Path features against the ground truth and against the peer a user would pick instead
// (the path-feature paper, seed 004, s6): the showcase's paths on a square drawn by
// vtkOpenGLPathFeatureMapper with antialiasing on and off; the same features as real
// geometry (the solid the features define, contoured from a fine volume of exact
// vertical crossings, overhangs included), drawn by VTK's stock mapper; and the same
// features rasterized into height maps (each texel's first crossing straight down, the
// material there as a colour texture) drawn by vtkOpenGLRelief mapper with ConeStep, its
// best exact search. Up close, at a middle distance and at 80 degrees: wrong pixels,
// edge position error, colour RMSE against the geometry supersampled 4x4, ms/frame,
// samples per pixel and texture bytes, one run, with a chart of error against cost.
#ifndef ReliefPathStudy_h
#define ReliefPathStudy_h

#include <string>
#include <vector>

namespace ReliefPathStudy
{
struct Options
{
  int Width = 480;
  int Height = 360;
  int TruthColumns = 1024;   ///< the truth's volume: columns along u and v
  int TruthLayers = 128;     ///< and layers through the depth
  int TruthColumnsUpClose = 2048; ///< along the longer side of the part a close view sees
  std::vector<int> HeightMapSizes = { 512, 2048 };
  int Supersampling = 4;     ///< of the truth, per axis, for the colour reference
  int Frames = 3;            ///< timed frames per row and round, after warm-up
  int Rounds = 2;
  std::string ImageDirectory; ///< where the chart and a mosaic go (PNG); none when empty
};

/// Runs the study; returns its Markdown section (context, table, chart).
std::string Study(const Options& options);
}

#endif
