#include "ReliefMetrics.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace
{
void RequireSameSize(const ReliefMetrics::Capture& a, const ReliefMetrics::Capture& b)
{
  if (a.Width != b.Width || a.Height != b.Height)
  {
    throw std::invalid_argument("captures of different sizes cannot be compared");
  }
}

// Rec. 601 luma of every pixel, as a one-channel float image.
OIIO::ImageBuf Luma(const ReliefMetrics::Capture& capture)
{
  OIIO::ImageBuf luma(OIIO::ImageSpec(capture.Width, capture.Height, 1, OIIO::TypeDesc::FLOAT));
  std::vector<float> values(static_cast<size_t>(capture.Width) * capture.Height);
  for (size_t pixel = 0; pixel < values.size(); ++pixel)
  {
    const float* rgb = &capture.Rgb[3 * pixel];
    values[pixel] = 0.299f * rgb[0] + 0.587f * rgb[1] + 0.114f * rgb[2];
  }
  luma.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, values.data());
  return luma;
}

OIIO::ImageBuf Rgb(const ReliefMetrics::Capture& capture)
{
  OIIO::ImageBuf rgb(OIIO::ImageSpec(capture.Width, capture.Height, 3, OIIO::TypeDesc::FLOAT));
  rgb.set_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, capture.Rgb.data());
  return rgb;
}

// SSIM's window, a normalised 11x11 Gaussian of sigma 1.5 centred on the origin, as its two
// one-dimensional factors: convolving with both in turn costs 22 taps a pixel instead of 121
// and gives the same values wherever the window lies inside the image, the only pixels SSIM
// averages.
constexpr int WindowRadius = 5;
OIIO::ImageBuf SsimWindowFactor(bool horizontal)
{
  const int length = 2 * WindowRadius + 1;
  OIIO::ImageSpec spec(horizontal ? length : 1, horizontal ? 1 : length, 1, OIIO::TypeDesc::FLOAT);
  (horizontal ? spec.x : spec.y) = -WindowRadius;
  spec.full_x = spec.x;
  spec.full_y = spec.y;
  OIIO::ImageBuf window(spec);
  for (int k = -WindowRadius; k <= WindowRadius; ++k)
  {
    const float weight = std::exp(-(k * k) / (2.0f * 1.5f * 1.5f));
    window.setpixel(horizontal ? k : 0, horizontal ? 0 : k, &weight);
  }
  return window;
}

std::vector<float> Values(const OIIO::ImageBuf& image)
{
  const OIIO::ImageSpec& spec = image.spec();
  std::vector<float> values(static_cast<size_t>(spec.width) * spec.height);
  image.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::FLOAT, values.data());
  return values;
}

// `image` less its mean over the whole view.
OIIO::ImageBuf Centred(const OIIO::ImageBuf& image)
{
  const auto statistics = OIIO::ImageBufAlgo::computePixelStats(image);
  return OIIO::ImageBufAlgo::sub(image, static_cast<float>(statistics.avg[0]));
}

// The local mean of `image` under the SSIM window.
std::vector<float> Mean(const OIIO::ImageBuf& image)
{
  static const OIIO::ImageBuf rows = SsimWindowFactor(true);
  static const OIIO::ImageBuf columns = SsimWindowFactor(false);
  return Values(
    OIIO::ImageBufAlgo::convolve(OIIO::ImageBufAlgo::convolve(image, rows), columns));
}
}

namespace ReliefMetrics
{
Capture Downsample(const Capture& fine, int factor)
{
  Capture coarse;
  coarse.Width = fine.Width / factor;
  coarse.Height = fine.Height / factor;
  coarse.Rgb.assign(3 * static_cast<size_t>(coarse.Width) * coarse.Height, 0.0f);
  coarse.EyeDepth.assign(static_cast<size_t>(coarse.Width) * coarse.Height, 0.0f);
  for (int y = 0; y < coarse.Height; ++y)
  {
    for (int x = 0; x < coarse.Width; ++x)
    {
      const size_t pixel = static_cast<size_t>(y) * coarse.Width + x;
      for (int j = 0; j < factor; ++j)
      {
        for (int i = 0; i < factor; ++i)
        {
          const size_t sample = static_cast<size_t>(y * factor + j) * fine.Width + x * factor + i;
          for (int c = 0; c < 3; ++c)
          {
            coarse.Rgb[3 * pixel + c] += fine.Rgb[3 * sample + c] / (factor * factor);
          }
          coarse.EyeDepth[pixel] = std::max(coarse.EyeDepth[pixel], fine.EyeDepth[sample]);
        }
      }
    }
  }
  return coarse;
}

long CoverageDifference(const Capture& a, const Capture& b)
{
  RequireSameSize(a, b);
  long count = 0;
  for (size_t pixel = 0; pixel < a.EyeDepth.size(); ++pixel)
  {
    count += a.Covers(pixel) != b.Covers(pixel) ? 1 : 0;
  }
  return count;
}

Capture CoverageComparison(const Capture& method, const Capture& truth)
{
  RequireSameSize(method, truth);
  Capture comparison = truth;
  for (size_t pixel = 0; pixel < truth.EyeDepth.size(); ++pixel)
  {
    const bool drawn = method.Covers(pixel);
    const bool true_ = truth.Covers(pixel);
    const float both = drawn && true_ ? 0.45f : 0.0f;
    comparison.Rgb[3 * pixel] = drawn && !true_ ? 1.0f : both;
    comparison.Rgb[3 * pixel + 1] = true_ && !drawn ? 1.0f : both;
    comparison.Rgb[3 * pixel + 2] = both;
  }
  return comparison;
}

bool WriteMosaic(const std::vector<std::vector<const Capture*>>& rows, const std::string& path)
{
  if (rows.empty() || rows[0].empty())
  {
    return false;
  }
  const Capture& first = *rows[0][0];
  size_t columns = 0;
  for (const auto& row : rows)
  {
    columns = std::max(columns, row.size());
  }
  OIIO::ImageBuf mosaic(OIIO::ImageSpec(first.Width * static_cast<int>(columns),
    first.Height * static_cast<int>(rows.size()), 3, OIIO::TypeDesc::FLOAT));
  for (size_t r = 0; r < rows.size(); ++r)
  {
    for (size_t c = 0; c < rows[r].size(); ++c)
    {
      RequireSameSize(first, *rows[r][c]);
      // captures run bottom to top, as OpenGL reads them
      OIIO::ImageBufAlgo::paste(mosaic, static_cast<int>(c) * first.Width,
        static_cast<int>(r) * first.Height, 0, 0, OIIO::ImageBufAlgo::flip(Rgb(*rows[r][c])));
    }
  }
  mosaic.set_write_format(OIIO::TypeDesc::UINT8);
  return mosaic.write(path);
}

long OutlinePixels(const Capture& capture)
{
  long outline = 0;
  for (int y = 0; y < capture.Height; ++y)
  {
    for (int x = 0; x < capture.Width; ++x)
    {
      auto covers = [&](int i, int j) {
        return i >= 0 && j >= 0 && i < capture.Width && j < capture.Height &&
          capture.Covers(static_cast<size_t>(j) * capture.Width + i);
      };
      outline += covers(x, y) &&
          !(covers(x - 1, y) && covers(x + 1, y) && covers(x, y - 1) && covers(x, y + 1))
        ? 1
        : 0;
    }
  }
  return outline;
}

double SilhouetteError(const Capture& method, const Capture& polygons, const Capture& truth)
{
  const long methodCount = CoverageDifference(method, truth);
  const long polygonCount = CoverageDifference(polygons, truth);
  return static_cast<double>(methodCount) / static_cast<double>(std::max(polygonCount, 1L));
}

double WrongPixelFraction(
  const Capture& method, const Capture& truth, double depthScale, double threshold)
{
  RequireSameSize(method, truth);
  long wrong = 0;
  long covered = 0;
  for (size_t pixel = 0; pixel < truth.EyeDepth.size(); ++pixel)
  {
    const bool both = method.Covers(pixel) && truth.Covers(pixel);
    covered += truth.Covers(pixel) ? 1 : 0;
    wrong += method.Covers(pixel) != truth.Covers(pixel) ||
        (both && std::abs(method.EyeDepth[pixel] - truth.EyeDepth[pixel]) > threshold * depthScale)
      ? 1
      : 0;
  }
  return static_cast<double>(wrong) / static_cast<double>(std::max(covered, 1L));
}

DepthError MeasureDepthError(
  const Capture& method, const Capture& truth, double depthScale, double threshold)
{
  RequireSameSize(method, truth);
  std::vector<double> errors;
  for (size_t pixel = 0; pixel < method.EyeDepth.size(); ++pixel)
  {
    if (method.Covers(pixel) && truth.Covers(pixel))
    {
      errors.push_back(std::abs(method.EyeDepth[pixel] - truth.EyeDepth[pixel]) / depthScale);
    }
  }
  DepthError result;
  result.Pixels = static_cast<long>(errors.size());
  if (errors.empty())
  {
    return result;
  }
  std::sort(errors.begin(), errors.end());
  const size_t count = errors.size();
  // nearest rank: the smallest value with at least p of the values at or below it
  auto percentile = [&](double p) {
    const size_t rank = static_cast<size_t>(std::ceil(p * count));
    return errors[std::min(std::max(rank, size_t(1)), count) - 1];
  };
  result.Median = percentile(0.5);
  result.Percentile95 = percentile(0.95);
  const auto above = std::upper_bound(errors.begin(), errors.end(), threshold);
  result.FractionAbove = static_cast<double>(errors.end() - above) / count;
  return result;
}

ColourError MeasureColourError(const Capture& method, const Capture& truth)
{
  RequireSameSize(method, truth);
  ColourError result;
  result.Rmse = OIIO::ImageBufAlgo::compare(Rgb(method), Rgb(truth), 1.0f, 1.0f).rms_error;

  // second moments from images shifted to zero mean: OpenImageIO convolves in float, and
  // E[x^2] - E[x]^2 of bright flat regions would cancel to noise as large as C2
  const OIIO::ImageBuf x = Luma(method);
  const OIIO::ImageBuf y = Luma(truth);
  const std::vector<float> meanX = Mean(x);
  const std::vector<float> meanY = Mean(y);
  const OIIO::ImageBuf shiftedX = Centred(x);
  const OIIO::ImageBuf shiftedY = Centred(y);
  const std::vector<float> shiftedMeanX = Mean(shiftedX);
  const std::vector<float> shiftedMeanY = Mean(shiftedY);
  const std::vector<float> meanXX = Mean(OIIO::ImageBufAlgo::mul(shiftedX, shiftedX));
  const std::vector<float> meanYY = Mean(OIIO::ImageBufAlgo::mul(shiftedY, shiftedY));
  const std::vector<float> meanXY = Mean(OIIO::ImageBufAlgo::mul(shiftedX, shiftedY));
  const double c1 = 0.01 * 0.01;
  const double c2 = 0.03 * 0.03;
  double sum = 0.0;
  long count = 0;
  for (int row = WindowRadius; row < method.Height - WindowRadius; ++row)
  {
    for (int column = WindowRadius; column < method.Width - WindowRadius; ++column)
    {
      const size_t pixel = static_cast<size_t>(row) * method.Width + column;
      const double mx = meanX[pixel];
      const double my = meanY[pixel];
      const double sx = shiftedMeanX[pixel];
      const double sy = shiftedMeanY[pixel];
      const double varianceX = meanXX[pixel] - sx * sx;
      const double varianceY = meanYY[pixel] - sy * sy;
      const double covariance = meanXY[pixel] - sx * sy;
      sum += (2.0 * mx * my + c1) * (2.0 * covariance + c2) /
        ((mx * mx + my * my + c1) * (varianceX + varianceY + c2));
      ++count;
    }
  }
  result.Ssim = count > 0 ? sum / count : 1.0;
  return result;
}
}
