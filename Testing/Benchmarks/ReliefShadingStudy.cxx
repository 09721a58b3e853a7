#include "ReliefShadingStudy.h"

#include "ReliefMetrics.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkReliefDisplacementFilter.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace
{
// The map turned by 20 degrees on the patch
const double Cosine = std::cos(vtkMath::RadiansFromDegrees(20.0));
const double Sine = std::sin(vtkMath::RadiansFromDegrees(20.0));

// A patch of the plane z = 0 centred on the origin, one world unit a texel of a map
// `mapSize` texels wide, texture coordinates repeating it: `fine`, a quad a texel, for
// the displaced geometry, or one quad in all for the relief.
vtkSmartPointer<vtkPolyData> Patch(double halfWidth, double halfHeight, int mapSize, bool fine)
{
  const int columns = static_cast<int>(std::ceil(halfWidth));
  const int rows = static_cast<int>(std::ceil(halfHeight));
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-columns + 0.5, -rows + 0.5, 0.0);
  plane->SetPoint1(columns + 0.5, -rows + 0.5, 0.0);
  plane->SetPoint2(-columns + 0.5, rows + 0.5, 0.0);
  plane->SetResolution(fine ? 2 * columns : 1, fine ? 2 * rows : 1);
  plane->Update();
  auto patch = vtkSmartPointer<vtkPolyData>::New();
  patch->DeepCopy(plane->GetOutput());
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TextureCoordinates");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(patch->GetNumberOfPoints());
  for (vtkIdType point = 0; point < patch->GetNumberOfPoints(); ++point)
  {
    // turned, so that neither texels nor the map's features line up with the pixels
    const double* position = patch->GetPoint(point);
    const double x = Cosine * position[0] - Sine * position[1];
    const double y = Sine * position[0] + Cosine * position[1];
    tcoords->SetTypedComponent(point, 0, static_cast<float>(x / mapSize));
    tcoords->SetTypedComponent(point, 1, static_cast<float>(y / mapSize));
  }
  patch->GetPointData()->SetTCoords(tcoords);
  return patch;
}

// Parallel projection seen `angle` degrees from the patch's normal, `texelsPerPixel`
// texels a pixel along screen x.
void Aim(vtkRenderer* renderer, double angle, double texelsPerPixel, int height, double reach)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  const double radians = vtkMath::RadiansFromDegrees(angle);
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, -2.0 * reach * std::sin(radians), 2.0 * reach * std::cos(radians));
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->OrthogonalizeViewUp();
  camera->SetParallelScale(0.5 * texelsPerPixel * height);

  camera->SetClippingRange(0.5 * reach, 4.0 * reach);
}

double Luminance(const float* rgb)
{
  return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];
}

struct Comparison
{
  double LuminanceBias = 0.0;
  double Rmse = 0.0;
  double BlackShare = 0.0;
  double TruthBlackShare = 0.0;
};

// Over the pixels all three cover.
Comparison Compare(const ReliefMetrics::Capture& method, const ReliefMetrics::Capture& truth,
  const ReliefMetrics::Capture& other)
{
  double luminance = 0.0;
  double truthLuminance = 0.0;
  double squares = 0.0;
  long black = 0;
  long truthBlack = 0;
  long pixels = 0;
  for (size_t pixel = 0; pixel < truth.EyeDepth.size(); ++pixel)
  {
    if (!truth.Covers(pixel) || !method.Covers(pixel) || !other.Covers(pixel))
    {
      continue;
    }
    const float* rgb = &method.Rgb[3 * pixel];
    const float* truthRgb = &truth.Rgb[3 * pixel];
    luminance += Luminance(rgb);
    truthLuminance += Luminance(truthRgb);
    for (int c = 0; c < 3; ++c)
    {
      squares += (rgb[c] - truthRgb[c]) * (rgb[c] - truthRgb[c]);
    }
    black += std::max({ rgb[0], rgb[1], rgb[2] }) < 0.5f / 255.0f ? 1 : 0;
    truthBlack += std::max({ truthRgb[0], truthRgb[1], truthRgb[2] }) < 0.5f / 255.0f ? 1 : 0;
    ++pixels;
  }
  Comparison comparison;
  if (pixels > 0)
  {
    comparison.LuminanceBias = truthLuminance > 0.0 ? luminance / truthLuminance - 1.0 : 0.0;
    comparison.Rmse = std::sqrt(squares / (3.0 * pixels));
    comparison.BlackShare = static_cast<double>(black) / pixels;
    comparison.TruthBlackShare = static_cast<double>(truthBlack) / pixels;
  }
  return comparison;
}
}

namespace ReliefShadingStudy
{
vtkSmartPointer<vtkImageData> Steps()
{
  // blocks of 8x8 texels at heights hashed from the block, on 8 levels
  return ReliefScene::HeightImage(64, 64, [](int i, int j) {
    const unsigned hash = (static_cast<unsigned>(i / 8) * 73856093u) ^
      (static_cast<unsigned>(j / 8) * 19349663u);
    return static_cast<float>((hash >> 4) % 8) / 7.0f;
  });
}

std::vector<Measurement> Measure(const Options& options)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, options.Width, options.Height);
  vtkNew<vtkRenderWindow> fineWindow;
  fineWindow->SetOffScreenRendering(1);
  auto fineRenderer = ReliefScene::LitRenderer(fineWindow,
    options.Width * options.Supersampling, options.Height * options.Supersampling);

  struct View
  {
    double Angle;
    double TexelsPerPixel;
  };
  std::vector<View> views;
  for (double angle : options.Angles)
  {
    views.push_back({ angle, 1.0 });
  }
  for (double texelsPerPixel : options.TexelsPerPixel)
  {
    if (texelsPerPixel != 1.0)
    {
      views.push_back({ 60.0, texelsPerPixel });
    }
  }

  std::vector<Measurement> measurements;
  for (const std::string& map : options.Maps)
  {
    vtkSmartPointer<vtkImageData> heights =
      map == "steps" ? Steps() : ReliefScene::ReadImage(map);
    vtkNew<vtkReliefTextureFilter> relief;
    relief->SetInputData(heights);
    relief->Update();
    const int mapSize = heights->GetDimensions()[0];
    // one mapper for all views: its cone map is built once per height map
    vtkNew<vtkOpenGLReliefMapper> reliefMapper;
    reliefMapper->SetHeightMapData(heights);
    reliefMapper->SetDepthScale(options.DepthTexels);
    reliefMapper->SetSelfShadowing(false);
    reliefMapper->SetSearchMethodToConeStep();
    for (const View& view : views)
    {
      // beyond 2 texels a pixel, fewer pixels: as many texels in view as at 2
      const double shrink = std::min(1.0, 2.0 / view.TexelsPerPixel);
      const int width = std::max(32, static_cast<int>(std::lround(options.Width * shrink)));
      const int height = std::max(24, static_cast<int>(std::lround(options.Height * shrink)));
      window->SetSize(width, height);
      fineWindow->SetSize(width * options.Supersampling, height * options.Supersampling);
      const double radians = vtkMath::RadiansFromDegrees(view.Angle);
      const double halfHeight = 0.5 * view.TexelsPerPixel * height;
      const double halfWidth = halfHeight * width / height + 4.0;
      const double halfDepth =
        halfHeight / std::cos(radians) + options.DepthTexels * std::tan(radians) + 4.0;
      const double reach = std::max(halfWidth, halfDepth) + options.DepthTexels;

      reliefMapper->SetInputData(Patch(halfWidth, halfDepth, mapSize, false));
      vtkNew<vtkReliefDisplacementFilter> displaced;
      displaced->SetInputData(Patch(halfWidth, halfDepth, mapSize, true));
      displaced->SetReliefData(relief->GetOutput());
      displaced->SetDepthScale(options.DepthTexels);
      // edges of at most 3/8 of a texel and of a pixel: converged (halving them moves the
      // relief's RMSE against it by less than 0.005 on the steps)
      displaced->SetMaximumEdgeTexels(0.375 * std::min(1.0, view.TexelsPerPixel));
      displaced->SetMaximumNumberOfTriangles(VTK_ID_MAX);
      displaced->Update();
      vtkNew<vtkPolyDataMapper> geometryMapper;
      geometryMapper->SetInputConnection(displaced->GetOutputPort());

      auto reliefActor = ReliefScene::ReliefActor(reliefMapper, "");
      auto geometryActor = ReliefScene::ReliefActor(geometryMapper, "");
      Aim(renderer, view.Angle, view.TexelsPerPixel, height, reach);
      Aim(fineRenderer, view.Angle, view.TexelsPerPixel / options.Supersampling,
        height * options.Supersampling, reach);

      renderer->AddActor(reliefActor);
      reliefMapper->FootprintShadingOff();
      window->Render();
      const ReliefMetrics::Capture hitCapture = ReliefScene::Capture(window, renderer);
      const ReliefScene::SampleStatistics hitSamples =
        ReliefScene::SampleCounts(window, renderer, reliefMapper);
      reliefMapper->FootprintShadingOn();
      window->Render();
      const ReliefMetrics::Capture reliefCapture = ReliefScene::Capture(window, renderer);
      const ReliefScene::SampleStatistics samples =
        ReliefScene::SampleCounts(window, renderer, reliefMapper);
      renderer->RemoveActor(reliefActor);
      renderer->AddActor(geometryActor);
      window->Render();
      const ReliefMetrics::Capture pointCapture = ReliefScene::Capture(window, renderer);
      renderer->RemoveActor(geometryActor);
      fineRenderer->AddActor(geometryActor);
      fineWindow->Render();
      const ReliefMetrics::Capture truth = ReliefMetrics::Downsample(
        ReliefScene::Capture(fineWindow, fineRenderer), options.Supersampling);
      fineRenderer->RemoveActor(geometryActor);

      const Comparison reliefError = Compare(reliefCapture, truth, pointCapture);
      const Comparison pointError = Compare(pointCapture, truth, reliefCapture);
      const Comparison hitError = Compare(hitCapture, truth, pointCapture);
      Measurement measurement;
      measurement.Map = map;
      measurement.Angle = view.Angle;
      measurement.TexelsPerPixel = view.TexelsPerPixel;
      measurement.LuminanceBias = reliefError.LuminanceBias;
      measurement.Rmse = reliefError.Rmse;
      measurement.PointLuminanceBias = pointError.LuminanceBias;
      measurement.PointRmse = pointError.Rmse;
      measurement.HitLuminanceBias = hitError.LuminanceBias;
      measurement.HitRmse = hitError.Rmse;
      measurement.HitSamples = hitSamples.Mean;
      measurement.BlackShare = reliefError.BlackShare;
      measurement.TruthBlackShare = reliefError.TruthBlackShare;
      measurement.MeanSamples = samples.Mean;
      measurement.Triangles = displaced->GetOutput()->GetNumberOfCells();
      measurements.push_back(measurement);
    }
  }
  return measurements;
}

std::string Report(const std::vector<Measurement>& measurements, const Options& options)
{
  std::ostringstream report;
  report << "Each height map on a plane, one world unit a texel, DepthScale "
         << options.DepthTexels
         << " texels, the map turned 20 degrees to the pixels, seen in parallel projection "
            "in a "
         << options.Width << "x" << options.Height
         << " window (smaller beyond 2 texels a pixel, to hold as many texels), one "
            "directional light, no self-shadows, ConeStep (exact) searching. Truth: the same "
            "relief as displaced geometry (vtkReliefDisplacementFilter, edges of at most 3/8 "
            "texel and 3/8 pixel) drawn by vtkPolyDataMapper at "
         << options.Supersampling << "x" << options.Supersampling
         << " samples a pixel and averaged; point-sampled geometry: the same at one sample. "
            "Relief as the mapper draws it by default (FootprintShading on) and lit by the "
            "normal at its hit alone (off). Texels per pixel along screen x (along y 1 / "
            "cos(angle) times as many). Luminance bias: mean luminance over the truth's, "
            "minus 1; RMSE over the RGB channels in [0, 1]; black: shares of pixels without "
            "light (relief, truth); samples: height samples a pixel.\n\n";
  report << "| map | angle | texels/pixel | bias | RMSE | samples | bias, hit only | "
            "RMSE, hit only | samples, hit only | bias, point-sampled geometry | RMSE, "
            "point-sampled geometry | black | triangles |\n"
         << "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | "
            "---: | ---: |\n";
  double worstBias = 0.0;
  int aboveGeometry = 0;
  for (const Measurement& m : measurements)
  {
    report << std::fixed << "| " << m.Map << " | " << std::setprecision(0) << m.Angle << " | "
           << std::setprecision(1) << m.TexelsPerPixel << " | " << std::setprecision(3)
           << m.LuminanceBias << " | " << m.Rmse << " | " << std::setprecision(1)
           << m.MeanSamples << " | " << std::setprecision(3) << m.HitLuminanceBias << " | "
           << m.HitRmse << " | " << std::setprecision(1) << m.HitSamples << " | "
           << std::setprecision(3) << m.PointLuminanceBias << " | " << m.PointRmse << " | "
           << m.BlackShare << ", " << m.TruthBlackShare << " | " << m.Triangles << " |\n";
    if (m.Angle <= 80.0)
    {
      worstBias = std::max(worstBias, std::abs(m.LuminanceBias));
      // by more than half a level of 8-bit colour: magnified, what is left is the
      // difference of the bilinear field from the truth's triangles, which
      // point-sampled geometry shares with the truth
      aboveGeometry += m.Rmse > m.PointRmse + 0.002 ? 1 : 0;
    }
  }
  report << std::defaultfloat << "\nUp to 80 degrees, the largest luminance bias is "
         << std::setprecision(3) << 100.0 * worstBias
         << "% (target 3%), and the relief's RMSE exceeds point-sampled geometry's by more "
            "than half a level of 8-bit colour (0.002) in "
         << aboveGeometry << " of the rows (target none).\n";
  return report.str();
}
}
