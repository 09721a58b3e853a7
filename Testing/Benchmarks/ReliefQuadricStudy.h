// The quadric frame against the flat one (Oliveira and Policarpo 2005), and its two distance modes
// against each other: stones, deep and shallow, on a sphere, a cylinder and a torus, three views
// each and the torus's inner side from its axis to nearly edge-on, every frame rendered beside the
// ground truth (the same relief as real geometry on the finely regenerated shape) and measured:
// silhouette error, wrong pixels, height samples per pixel and ms/frame. The accuracy regression
// test asserts on the measurements; the bench reports them with a chart and a picture.
#ifndef ReliefQuadricStudy_h
#define ReliefQuadricStudy_h

#include <string>
#include <vector>

namespace ReliefQuadricStudy
{
struct Options
{
  int Width = 300; ///< window size
  int Height = 300;
  int HeightMapSize = 64;     ///< the stones height map resampled to this square size
  /// facets around each shape (a torus has half as many around its tube)
  std::vector<int> Facets = { 24, 32 };
  /// the shapes measured, of "sphere", "cylinder" and "torus"
  std::vector<std::string> Shapes = { "sphere", "cylinder", "torus" };
  /// deep relief, and shallow: at 0.005 even the stones' tops lie closer to the surface than
  /// the polygons sag below it at 24 facets, so that the hull decides the outline
  std::vector<double> DepthScales = { 0.05, 0.005 };
  /// the torus's inner side seen at these angles off its axis (degrees), besides
  std::vector<double> InnerSweep = { 0.0, 15.0, 30.0, 45.0, 60.0, 70.0, 75.0, 80.0, 85.0 };
  int Frames = 0;             ///< timed frames per frame, view and round; 0: not timed
  int Rounds = 2;             ///< interleaved timing rounds
  std::string ImageDirectory; ///< where the chart and picture go (PNG); none when empty
};

/// One frame (flat, quadric with either distance) on one shape seen from one view.
struct Measurement
{
  std::string Shape;
  int Facets = 0;
  double DepthScale = 0.0;
  double Azimuth = 0.0; ///< elevation 0: the torus's inner-side sweep
  double Elevation = 0.0;
  std::string Frame;
  double SilhouetteError = 0.0; ///< coverage mismatch over the bare polygons' (0 perfect)
  long WrongCoverage = 0;        ///< pixels covered by the frame or the truth, not both
  long PolygonWrongCoverage = 0; ///< the same for the bare polygons
  long TruthOutline = 0;         ///< the truth's outline, in pixels (ReliefMetrics::OutlinePixels)
  double WrongPixels = 0.0;     ///< as ReliefMetrics::WrongPixelFraction
  double MeanSamples = 0.0;     ///< height samples per covered pixel
  double Milliseconds = 0.0;    ///< median frame time; 0 when not timed
};

/// The frames' names, in the order each view lists them.
const std::vector<std::string>& Frames();

/// Renders and measures every shape, view and frame.
std::vector<Measurement> Measure(const Options& options);

/// The Markdown section of the bench: context, table, summary and chart.
std::string Report(const std::vector<Measurement>& measurements, const Options& options);
}

#endif
