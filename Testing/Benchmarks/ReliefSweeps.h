// Stability where methods fail: every search method's error against the ground truth
// (ReliefAccuracy.h) as one quantity of the scene sweeps through its range: the view
// angle, the width of thin features, the curvature of the surface under the relief
// (spheres, saddles), the crease angle between faces, and the depth scale. One chart per
// sweep.
#ifndef ReliefSweeps_h
#define ReliefSweeps_h

#include <string>

namespace ReliefSweeps
{
struct Options
{
  int Width = 480; ///< window size
  int Height = 360;
  bool Quick = false;         ///< three values per sweep
  std::string ImageDirectory; ///< where the charts go (PNG); none when empty
};

/// Runs every sweep; returns its Markdown section (tables and charts).
std::string Run(const Options& options);
}

#endif
