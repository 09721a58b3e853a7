// The searches on the CPU mirror of the shaders (the GLSL compiled as C++), in height
// samples per ray, which is what the GPU's SampleCount display counts, uncapped, and no
// machine changes. The robust binary search as Baboud and Decoret (2006, s3.4-3.5, Table
// 1) measured it: SafetyRadius and RobustBinary against the height map's resolution, the
// view angle and the tolerance e, beside LinearBinary and ExactDDA on the same rays, and
// the paper's error bound checked on every ray against the brute-force intersection
// (ReliefReferenceHit.h). And the exact searches against resolution and angle.
#ifndef ReliefRobustStudy_h
#define ReliefRobustStudy_h

#include <string>
#include <vector>

namespace ReliefRobustStudy
{
struct Options
{
  std::vector<int> Sizes = { 128, 256, 512, 1024, 2048 }; ///< the stones map resampled
  std::vector<double> Angles = { 0.0, 45.0, 80.0 };        ///< from the normal, degrees
  std::vector<double> ExactAngles = { 0.0, 30.0, 45.0, 60.0, 70.0, 80.0 }; ///< the exact ones'
  int Rays = 4000;                                          ///< per size and angle
};

/// Runs the study of SafetyRadius and RobustBinary; returns its Markdown section.
std::string Report(const Options& options);

/// The exact searches' samples against resolution and angle, on the same rays, with the
/// targets of an exact search whose cost does not grow; returns its Markdown section.
std::string ExactReport(const Options& options);
}

#endif
