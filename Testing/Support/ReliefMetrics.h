// How far a relief render is from its ground truth (the same height field as real
// geometry, vtkReliefDisplacementFilter), in coverage, depth and colour. Captures are
// plain arrays, so the metrics are tested on images whose answers are known; the
// benchmark fills them from render windows (ReliefScene::Capture).
#ifndef ReliefMetrics_h
#define ReliefMetrics_h

#include <cstddef>
#include <string>
#include <vector>

namespace ReliefMetrics
{
/// One rendered view: colour and eye depth per pixel, bottom row first.
struct Capture
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Rgb;      ///< 3 per pixel, in [0, 1]
  /// distance in front of the camera; +infinity where nothing is drawn
  std::vector<float> EyeDepth;

  bool Covers(std::size_t pixel) const { return this->EyeDepth[pixel] < 1e30f; }
};

/// A capture rendered `factor` times larger per axis, averaged down: each pixel's colour
/// the mean of its samples, its depth their farthest (covered only where all are).
Capture Downsample(const Capture& fine, int factor);

/// The coverage of `method` against `truth` as a picture: grey where both cover, red where
/// only the method does, green where only the truth does, black where neither.
Capture CoverageComparison(const Capture& method, const Capture& truth);

/// Writes captures of one size as a grid, each row left to right, rows top to bottom, as
/// an 8-bit image (any format OpenImageIO writes, by the extension); false when it cannot.
bool WriteMosaic(const std::vector<std::vector<const Capture*>>& rows, const std::string& path);

/// Pixels that one capture covers and the other does not.
long CoverageDifference(const Capture& a, const Capture& b);

/// The pixels a capture covers that have an uncovered pixel beside them (left, right, above
/// or below), or lie on the border: the length of its outline in pixels.
long OutlinePixels(const Capture& capture);

/// CoverageDifference(method, truth) / CoverageDifference(polygons, truth): 1 is no
/// better than the coarse polygons' silhouette, 0 is perfect. 0 when the polygons already
/// match the truth and the method does too, else the method's count over 1.
double SilhouetteError(const Capture& method, const Capture& polygons, const Capture& truth);

/// The share of the pixels the truth covers that are wrong: covered by one capture and
/// not the other, or covered by both with eye depths more than threshold x depthScale
/// apart. One number for coverage and depth together, the error axis of the charts.
double WrongPixelFraction(
  const Capture& method, const Capture& truth, double depthScale, double threshold = 0.1);

/// |eye depth - truth's eye depth| / depthScale over the pixels both cover.
struct DepthError
{
  long Pixels = 0;           ///< pixels both cover
  double Median = 0.0;
  double Percentile95 = 0.0; ///< nearest rank
  double FractionAbove = 0.0; ///< fraction of the pixels with an error above `threshold`
};
DepthError MeasureDepthError(
  const Capture& method, const Capture& truth, double depthScale, double threshold = 0.1);

/// Colour difference over the whole view: RMSE over all channels (OpenImageIO's
/// ImageBufAlgo::compare) and the mean SSIM of the luma (Wang et al. 2004: 11x11
/// Gaussian window of sigma 1.5, K1 = 0.01, K2 = 0.03, dynamic range 1), over the pixels
/// whose window lies inside the view.
struct ColourError
{
  double Rmse = 0.0;
  double Ssim = 1.0;
};
ColourError MeasureColourError(const Capture& method, const Capture& truth);
}

#endif
