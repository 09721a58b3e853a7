// Shading against the pixel's footprint: a relief seen at view angles from 0 to 85 degrees
// and minified from 0.5 to 8 texels a pixel, its colour measured against the same relief
// as displaced geometry supersampled 3x3 over each pixel (what an antialiased camera
// sees), beside that geometry point-sampled (what a dense mesh drawn plainly gives).
// Parallel projection, so that every pixel of a view has the same footprint; the relief
// lit by one directional light and not self-shadowed (the geometry casts no shadows).
#ifndef ReliefShadingStudy_h
#define ReliefShadingStudy_h

#include "vtkImageData.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace ReliefShadingStudy
{
struct Options
{
  int Width = 128; ///< window size, at up to 2 texels a pixel; smaller beyond, so that
  int Height = 96; ///< the truth's triangles stay few
  int Supersampling = 3;     ///< truth samples per pixel along each axis
  double DepthTexels = 8.0;  ///< DepthScale, in texels of the height map
  std::vector<double> Angles = { 0.0, 30.0, 60.0, 75.0, 80.0, 85.0 }; ///< at 1 texel a pixel
  std::vector<double> TexelsPerPixel = { 0.5, 2.0, 4.0, 8.0 };       ///< at 60 degrees
  std::vector<std::string> Maps = { "steps", "bricks_height.png", "stones_height.png",
    "rivets_height.png", "waves_height.png" };
};

/// One height map at one view angle and minification.
struct Measurement
{
  std::string Map;
  double Angle = 0.0;
  double TexelsPerPixel = 0.0;   ///< along screen x; 1 / cos(angle) times that along y
  double LuminanceBias = 0.0;    ///< relief's mean luminance over the truth's, minus 1
  double Rmse = 0.0;             ///< relief's colour RMSE against the truth
  double PointLuminanceBias = 0.0; ///< the same of point-sampled geometry
  double PointRmse = 0.0;
  double HitLuminanceBias = 0.0; ///< the relief's with FootprintShading off
  double HitRmse = 0.0;
  double HitSamples = 0.0;
  double BlackShare = 0.0;       ///< relief pixels that are black
  double TruthBlackShare = 0.0;  ///< truth pixels that are black
  double MeanSamples = 0.0;      ///< the relief's height samples per pixel
  long Triangles = 0;            ///< of the displaced geometry
};

/// A 64x64 height map of sharp steps: blocks of 8x8 texels, each at its own height.
vtkSmartPointer<vtkImageData> Steps();

/// Renders and measures every map, angle and minification.
std::vector<Measurement> Measure(const Options& options);

/// The Markdown section of the bench: context, table and summary.
std::string Report(const std::vector<Measurement>& measurements, const Options& options);
}

#endif
