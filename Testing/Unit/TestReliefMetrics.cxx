// ReliefMetrics: coverage, depth and colour errors on captures whose answers are known.
#include "ReliefMetrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <vector>

namespace
{
using ReliefMetrics::Capture;
constexpr float Nothing = std::numeric_limits<float>::infinity();

// A width x height capture, colour and eye depth from functions of the pixel.
Capture Make(int width, int height, const std::function<float(int, int)>& depth,
  const std::function<float(int, int)>& grey = [](int, int) { return 0.5f; })
{
  Capture capture;
  capture.Width = width;
  capture.Height = height;
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      capture.EyeDepth.push_back(depth(column, row));
      const float value = grey(column, row);
      capture.Rgb.insert(capture.Rgb.end(), { value, value, value });
    }
  }
  return capture;
}

// A rectangle [0, w) x [0, h) at eye depth 2, nothing elsewhere.
Capture Rectangle(int w, int h)
{
  return Make(32, 32, [=](int x, int y) { return x < w && y < h ? 2.0f : Nothing; });
}
}

TEST(ReliefMetrics, CoverageDifferenceCountsPixelsOneCoversAndTheOtherDoesNot)
{
  EXPECT_EQ(ReliefMetrics::CoverageDifference(Rectangle(10, 10), Rectangle(10, 12)), 20);
  EXPECT_EQ(ReliefMetrics::CoverageDifference(Rectangle(10, 12), Rectangle(10, 10)), 20);
  EXPECT_EQ(ReliefMetrics::CoverageDifference(Rectangle(10, 10), Rectangle(10, 10)), 0);
  // depth does not matter, only whether something is drawn
  const Capture nearer =
    Make(32, 32, [](int x, int y) { return x < 10 && y < 10 ? 1.0f : Nothing; });
  EXPECT_EQ(ReliefMetrics::CoverageDifference(nearer, Rectangle(10, 10)), 0);
}

TEST(ReliefMetrics, SilhouetteErrorIsTheMethodsDifferenceOverThePolygons)
{
  const Capture truth = Rectangle(10, 10);
  const Capture polygons = Rectangle(10, 14); // 40 pixels off
  EXPECT_DOUBLE_EQ(ReliefMetrics::SilhouetteError(Rectangle(10, 11), polygons, truth), 0.25);
  EXPECT_DOUBLE_EQ(ReliefMetrics::SilhouetteError(polygons, polygons, truth), 1.0);
  EXPECT_DOUBLE_EQ(ReliefMetrics::SilhouetteError(truth, polygons, truth), 0.0);
  // polygons that already match: a perfect method scores 0, any other its count
  EXPECT_DOUBLE_EQ(ReliefMetrics::SilhouetteError(truth, truth, truth), 0.0);
  EXPECT_DOUBLE_EQ(ReliefMetrics::SilhouetteError(Rectangle(10, 11), truth, truth), 10.0);
}

TEST(ReliefMetrics, DepthErrorIsInUnitsOfDepthScaleOverPixelsBothCover)
{
  // 100 covered pixels in truth; the method is off by k / 1000 at pixel k (of the 10x10),
  // and covers a further column the truth does not, which does not count
  const Capture truth = Rectangle(10, 10);
  const Capture method = Make(32, 32, [](int x, int y) {
    return x < 10 && y < 10 ? 2.0f + (y * 10 + x) / 1000.0f : (x == 10 && y < 10 ? 5.0f : Nothing);
  });
  const auto error = ReliefMetrics::MeasureDepthError(method, truth, 0.01, 0.55);
  EXPECT_EQ(error.Pixels, 100);
  // errors k / 10 for k = 0..99: median (rank 50) 4.9, 95th percentile (rank 95) 9.4
  EXPECT_NEAR(error.Median, 4.9, 1e-4);
  EXPECT_NEAR(error.Percentile95, 9.4, 1e-4);
  // above 0.55: k = 6..99
  EXPECT_DOUBLE_EQ(error.FractionAbove, 0.94);
}

TEST(ReliefMetrics, WrongPixelsAreCoverageMismatchesAndDepthsTooFarApart)
{
  // truth: 10x10 at depth 2; method: 10x11 (10 extra pixels), and 5 pixels 0.02 deeper
  const Capture truth = Rectangle(10, 10);
  const Capture method = Make(32, 32, [](int x, int y) {
    return x < 10 && y < 11 ? (y == 0 && x < 5 ? 2.02f : 2.0f) : Nothing;
  });
  // DepthScale 0.1: 0.02 is 0.2 of it, above 0.1
  EXPECT_DOUBLE_EQ(ReliefMetrics::WrongPixelFraction(method, truth, 0.1), 15.0 / 100.0);
  // DepthScale 1: 0.02 is within 0.1 of it
  EXPECT_DOUBLE_EQ(ReliefMetrics::WrongPixelFraction(method, truth, 1.0), 10.0 / 100.0);
  EXPECT_DOUBLE_EQ(ReliefMetrics::WrongPixelFraction(truth, truth, 0.1), 0.0);
}

TEST(ReliefMetrics, DepthErrorOfIdenticalCapturesIsZero)
{
  const auto error = ReliefMetrics::MeasureDepthError(Rectangle(8, 8), Rectangle(8, 8), 0.05);
  EXPECT_EQ(error.Pixels, 64);
  EXPECT_EQ(error.Median, 0.0);
  EXPECT_EQ(error.Percentile95, 0.0);
  EXPECT_EQ(error.FractionAbove, 0.0);
}

TEST(ReliefMetrics, RmseOfAConstantOffsetIsTheOffset)
{
  const auto depth = [](int, int) { return 1.0f; };
  const Capture a = Make(16, 16, depth, [](int, int) { return 0.2f; });
  const Capture b = Make(16, 16, depth, [](int, int) { return 0.3f; });
  EXPECT_NEAR(ReliefMetrics::MeasureColourError(a, b).Rmse, 0.1, 1e-6);
  EXPECT_NEAR(ReliefMetrics::MeasureColourError(a, a).Rmse, 0.0, 1e-9);
}

TEST(ReliefMetrics, SsimOfFlatImagesIsTheLuminanceTerm)
{
  // no variance anywhere: SSIM = (2ab + C1) / (a^2 + b^2 + C1)
  const auto depth = [](int, int) { return 1.0f; };
  const Capture a = Make(24, 24, depth, [](int, int) { return 0.2f; });
  const Capture b = Make(24, 24, depth, [](int, int) { return 0.6f; });
  const double c1 = 1e-4;
  EXPECT_NEAR(ReliefMetrics::MeasureColourError(a, b).Ssim,
    (2 * 0.2 * 0.6 + c1) / (0.2 * 0.2 + 0.6 * 0.6 + c1), 1e-4);
}

TEST(ReliefMetrics, SsimIsOneForIdenticalImagesAndFallsForInvertedStructure)
{
  const auto depth = [](int, int) { return 1.0f; };
  const auto checker = [](int x, int y) { return ((x / 2 + y / 2) % 2) ? 0.8f : 0.2f; };
  const auto inverted = [&](int x, int y) { return 1.0f - checker(x, y); };
  const Capture a = Make(32, 32, depth, checker);
  EXPECT_NEAR(ReliefMetrics::MeasureColourError(a, a).Ssim, 1.0, 1e-5);
  // same means and variances, covariance negated: the structure term is about -1
  EXPECT_LT(ReliefMetrics::MeasureColourError(a, Make(32, 32, depth, inverted)).Ssim, -0.9);
}

TEST(ReliefMetrics, CapturesOfDifferentSizesAreRefused)
{
  EXPECT_THROW(ReliefMetrics::CoverageDifference(Rectangle(4, 4), Make(8, 8, [](int, int) {
    return 1.0f;
  })),
    std::invalid_argument);
}

TEST(ReliefMetrics, TheOutlineIsTheCoveredPixelsBesideUncoveredOnes)
{
  // a 10x6 rectangle in the corner: its ring of 2 (10 + 6) - 4 pixels, the border included
  EXPECT_EQ(ReliefMetrics::OutlinePixels(Rectangle(10, 6)), 28);
  EXPECT_EQ(ReliefMetrics::OutlinePixels(Rectangle(0, 0)), 0);
  EXPECT_EQ(ReliefMetrics::OutlinePixels(Rectangle(1, 1)), 1);
}

TEST(ReliefMetrics, TheCoverageComparisonColoursWhatEachCovers)
{
  const Capture comparison =
    ReliefMetrics::CoverageComparison(Rectangle(10, 10), Rectangle(10, 12));
  auto rgb = [&](int x, int y) {
    const size_t pixel = 3 * (static_cast<size_t>(y) * 32 + x);
    return std::vector<float>(comparison.Rgb.begin() + pixel, comparison.Rgb.begin() + pixel + 3);
  };
  EXPECT_EQ(rgb(5, 5), std::vector<float>({ 0.45f, 0.45f, 0.45f })); // both
  EXPECT_EQ(rgb(5, 11), std::vector<float>({ 0.0f, 1.0f, 0.0f }));   // the truth only
  EXPECT_EQ(rgb(20, 20), std::vector<float>({ 0.0f, 0.0f, 0.0f }));  // neither
  const Capture extra = ReliefMetrics::CoverageComparison(Rectangle(10, 12), Rectangle(10, 10));
  EXPECT_EQ(extra.Rgb[3 * (11 * 32 + 5)], 1.0f); // the method only: red
  EXPECT_EQ(extra.Rgb[3 * (11 * 32 + 5) + 1], 0.0f);
}
