// Speed against accuracy: every search method and setting of the relief mapper rendered
// beside the ground truth (the same height field as real geometry,
// vtkReliefDisplacementFilter, drawn by VTK's stock mapper with the same camera, clipping
// range, light and window), measured with ReliefMetrics, timed in the same run, and
// charted with the Pareto front. The dense displaced mesh a VTK user would render
// instead (one point per texel) is measured beside them.
#ifndef ReliefAccuracy_h
#define ReliefAccuracy_h

#include <string>
#include <vector>

class vtkOpenGLReliefMapper;

namespace ReliefAccuracy
{
/// One point of the chart: a search method at one setting of its parameters.
struct Setting
{
  std::string Family;
  std::string Parameters;
  int Method;
  int LinearSteps = 10;
  int BinarySteps = 5;
  double Tolerance = 0.0;       ///< SafetyRadius's error bound
  double ScreenTolerance = 0.5; ///< Automatic's, in pixels
  bool OverSlopes = false;      ///< Automatic over SlopeMipmap's pyramid, not cones
};

/// Every fixed setting of every search method, then Automatic at 0.5 and 2 pixels, and at
/// 0.5 pixels over the slope pyramid.
std::vector<Setting> Settings();

/// Gives `mapper` the setting's method and parameters.
void Apply(const Setting& setting, vtkOpenGLReliefMapper* mapper);

/// Whether the setting is Automatic's, not a fixed one.
bool IsAutomatic(const Setting& setting);

struct Options
{
  int HeightMapSize = 256; ///< the stones height map resampled to this square size
  int Width = 640;         ///< window size
  int Height = 480;
  double Angle = 45.0;     ///< view angle from the square's normal, degrees
  double DepthScale = 0.08;
  int Frames = 10;         ///< timed frames per row and round, after warm-up
  int Rounds = 2;          ///< interleaved timing rounds
  bool Convergence = true; ///< also render the truth at twice the resolution and compare
  std::string ImageDirectory; ///< where the charts go (PNG); none when empty
  std::string Method;         ///< one search method's settings only (its name), or all
};

/// Runs the study; returns its Markdown section (context, table, charts).
std::string Study(const Options& options);
}

#endif
