// The derivative frame (Tichenor 2012, vtkOpenGLDerivativeReliefMapper) against the tangent
// frame (vtkOpenGLReliefMapper): both against the ground truth on a plane and a torus
// (wrong pixels, depth and colour error, samples, ms/frame, and how far the two are from
// each other), and the seam each leaves at a crease: on a sheet folded into four flat
// panels, the largest jump of colour and depth across the fold lines, against the fold's
// crease angle and the view angle. The regression tests assert on the measurements; the
// bench reports them with charts.
#ifndef ReliefDerivativeStudy_h
#define ReliefDerivativeStudy_h

#include "vtkOpenGLReliefMapper.h"

#include <string>
#include <vector>

namespace ReliefDerivativeStudy
{
struct Options
{
  int Width = 320; ///< window size
  int Height = 240;
  int HeightMapSize = 64;     ///< the stones height map resampled to this square size
  double DepthScale = 0.05;
  int Frames = 0;             ///< timed frames per frame, view and round; 0: not timed
  int Rounds = 2;             ///< interleaved timing rounds
  std::vector<double> Creases = { 0.0, 5.0, 10.0, 15.0, 20.0, 30.0, 45.0 }; ///< degrees
  std::vector<double> ViewAngles = { 0.0, 20.0, 40.0, 60.0, 75.0 };         ///< degrees
  double SweepCrease = 20.0;  ///< the crease of the view-angle sweep
  double SweepView = 45.0;    ///< the view angle of the crease sweep
  std::string ImageDirectory; ///< where the charts go (PNG); none when empty
  int SearchMethod = vtkOpenGLReliefMapper::LINEAR_BINARY; ///< the accuracy study's
  bool TorusToo = true;       ///< the accuracy study on the torus besides the plane
};

/// One frame on one shape from one view, against the truth.
struct Accuracy
{
  std::string Shape;
  std::string View;
  std::string Frame;
  double WrongPixels = 0.0;   ///< as ReliefMetrics::WrongPixelFraction
  double Depth95 = 0.0;       ///< 95th percentile depth error, x DepthScale
  double ColourRmse = 0.0;    ///< against the truth
  double MeanSamples = 0.0;   ///< height samples per covered pixel
  double Milliseconds = 0.0;  ///< median frame time; 0 when not timed
  /// the derivative frame against the tangent frame's render of the same view (0 for
  /// the tangent frame's own rows): wrong pixels and colour RMSE
  double WrongAgainstTangent = 0.0;
  double RmseAgainstTangent = 0.0;
};

/// One frame on the folded sheet: the largest jumps across its three fold lines and
/// across the lines halfway between them (where the surface is flat: the relief's own
/// change over the same three pixels).
struct Seam
{
  double Crease = 0.0; ///< degrees between the normals of two neighbouring panels
  double View = 0.0;   ///< degrees between the view and the sheet's mean normal
  std::string Frame;
  double ColourJump = 0.0; ///< 8-bit levels of a (u, v) ramp: ~texels of a 256 map
  double DepthJump = 0.0;  ///< eye depth, x DepthScale
  double FlatColourJump = 0.0;
  double FlatDepthJump = 0.0;
};

/// The texture-space direction of a view ray as a derivative frame computes it, against
/// the exact one, for the fragment at the centre of a 320x240 view (30 degree view
/// angle) of a plane seen `View` degrees off its normal, the camera rolled `Roll`
/// degrees about its axis (the plane then tilts along a screen diagonal, and the
/// pixel's steps on the plane lose their right angle); computed on the CPU.
struct FrameError
{
  double View = 0.0;
  double Roll = 0.0;
  double StepAngle = 90.0; ///< degrees between dFdx and dFdy of the position
  double SeedError = 0.0;  ///< Tichenor's (2012) projection on normalized dFdx, dFdy (relative)
  double DualError = 0.0;  ///< reliefDerivativeAxes, the shader's (relative)
};
std::vector<FrameError> MeasureFrameError(const std::vector<double>& views);

/// The frames' names: the tangent frame, then the derivative frame.
const std::vector<std::string>& Frames();

/// The seam study's frames: the tangent frame with the sheet's smooth and split normals,
/// the derivative frame on the sheet without normals, computing smooth ones
/// (ComputeNormals) and not.
const std::vector<std::string>& SeamFrames();

std::vector<Accuracy> MeasureAccuracy(const Options& options);
std::vector<Seam> MeasureSeams(const Options& options);

/// The Markdown section of the bench: context, tables, summary and charts.
std::string Report(const std::vector<Accuracy>& accuracy, const std::vector<Seam>& seams,
  const std::vector<FrameError>& frameErrors, const Options& options);
}

#endif
