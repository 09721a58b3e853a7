#include "ReliefDerivativeStudy.h"

#include "ReliefChart.h"
#include "ReliefMetrics.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLDerivativeReliefMapper.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkTexture.h"

#include "ReliefCpuMirror.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <map>
#include <sstream>

namespace
{
// the frame's source as the GPU compiles it; its axes do not depend on the normals' define
namespace Shader = ReliefCpuMirror::DerivativeNormals;

constexpr double Pi = 3.14159265358979323846;

void SetSearch(vtkOpenGLReliefMapper* mapper, vtkPolyData* surface, vtkImageData* heights,
  double depthScale, int method = vtkOpenGLReliefMapper::LINEAR_BINARY)
{
  mapper->SetInputData(surface);
  mapper->SetHeightMapData(heights);
  mapper->SetDepthScale(depthScale);
  mapper->SetSearchMethod(method);
  mapper->SetSelfShadowing(false); // the stock mapper casts no shadows
  mapper->SetFootprintShading(false); // the frames' samples alone
  mapper->SetLinearSteps(32);
  mapper->SetBinarySteps(6);
}

// A shape of the accuracy study: the coarse surface, the dense one the truth displaces,
// and its views, each aiming the camera.
struct Shape
{
  const char* Name;
  vtkSmartPointer<vtkPolyData> Coarse;
  vtkSmartPointer<vtkPolyData> Fine;
  std::vector<std::pair<std::string, std::function<void(vtkRenderer*)>>> Views;
};

std::function<void(vtkRenderer*)> SquareView(double angle)
{
  return [angle](vtkRenderer* renderer) { ReliefScene::ViewSquare(renderer, angle); };
}

std::function<void(vtkRenderer*)> TorusView(double azimuth, double elevation)
{
  return [=](vtkRenderer* renderer) {
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, -3.0, 0.0);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->Azimuth(azimuth);
    camera->Elevation(elevation);
    camera->OrthogonalizeViewUp();
    const double frame[6] = { -0.5, 0.5, -0.15, 0.15, -0.5, 0.5 };
    renderer->ResetCamera(frame);
  };
}

std::vector<Shape> Shapes()
{
  // the square: two tiles, so that the frame's texture scale matters; the torus: as the
  // quadric study's, 48 facets around, regenerated with 256 for the truth
  return {
    { "plane", ReliefScene::Square(2.0), ReliefScene::Square(2.0),
      { { "0 degrees", SquareView(0.0) }, { "45 degrees", SquareView(45.0) },
        { "70 degrees", SquareView(70.0) } } },
    { "torus", ReliefScene::Torus(48), ReliefScene::Torus(256),
      { { "azimuth 0, elevation 10", TorusView(0.0, 10.0) },
        { "azimuth 35, elevation 30", TorusView(35.0, 30.0) },
        { "azimuth 70, elevation -20", TorusView(70.0, -20.0) } } },
  };
}

//------------------------------------------------------------------------------
// The folded sheet: four flat panels of width 0.25 along the surface, tilted by +-c/2
// in turn about the y axis, so neighbouring panels' normals are c apart; texture
// coordinates unfolded (u by length along the surface, v = y + 0.5), so the texture
// runs on across every fold undistorted.
constexpr int Panels = 4;

vtkSmartPointer<vtkPolyData> FoldedSheet(double creaseDegrees)
{
  const double half = 0.5 * creaseDegrees * Pi / 180.0;
  std::vector<double> xs(1, 0.0);
  std::vector<double> zs(1, 0.0);
  for (int panel = 0; panel < Panels; ++panel)
  {
    const double tilt = panel % 2 == 0 ? half : -half;
    xs.push_back(xs.back() + std::cos(tilt) / Panels);
    zs.push_back(zs.back() + std::sin(tilt) / Panels);
  }
  const double meanX = 0.5 * xs.back();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  for (int column = 0; column <= Panels; ++column)
  {
    for (double y : { -0.5, 0.5 })
    {
      points->InsertNextPoint(xs[column] - meanX, y, zs[column] - 0.25 * zs[1]);
      tcoords->InsertNextTuple2(static_cast<double>(column) / Panels, y + 0.5);
    }
  }
  vtkNew<vtkCellArray> triangles;
  for (vtkIdType panel = 0; panel < Panels; ++panel)
  {
    const vtkIdType a = 2 * panel;
    const vtkIdType first[3] = { a, a + 2, a + 3 };
    const vtkIdType second[3] = { a, a + 3, a + 1 };
    triangles->InsertNextCell(3, first);
    triangles->InsertNextCell(3, second);
  }
  auto sheet = vtkSmartPointer<vtkPolyData>::New();
  sheet->SetPoints(points);
  sheet->SetPolys(triangles);
  sheet->GetPointData()->SetTCoords(tcoords);
  return sheet;
}

// The sheet with normals averaged at the folds (smooth), split there (each panel its
// own), or none.
enum class SheetNormals
{
  Smooth,
  Split,
  None
};

vtkSmartPointer<vtkPolyData> WithNormals(vtkPolyData* sheet, SheetNormals kind)
{
  if (kind == SheetNormals::None)
  {
    return sheet;
  }
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(sheet);
  normals->SetSplitting(kind == SheetNormals::Split);
  normals->SetFeatureAngle(0.5);
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOff();
  normals->Update();
  return normals->GetOutput();
}

// A ramp over the tile, red along u, green along v: the colour at a pixel is where the
// relief search hit, within one 8-bit level (a texel of a 256 map).
vtkSmartPointer<vtkTexture> Ramp()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(256, 256, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* texels = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int j = 0; j < 256; ++j)
  {
    for (int i = 0; i < 256; ++i)
    {
      unsigned char* texel = texels + 3 * (j * 256 + i);
      texel[0] = static_cast<unsigned char>(i);
      texel[1] = static_cast<unsigned char>(j);
      texel[2] = 0;
    }
  }
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(image);
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->RepeatOff();
  texture->EdgeClampOn();
  return texture;
}

// The largest jump of `value` across the line from a to b (world points) on screen,
// above the local trend: at each pixel along the line, value at 1.5 px on either side,
// less the change the values at 1.5 and 4.5 px predict over that gap.
double LargestJump(vtkRenderer* renderer, const ReliefMetrics::Capture& capture, const double a[3],
  const double b[3], const std::function<double(std::size_t)>& value)
{
  auto toDisplay = [&](const double world[3], double display[2]) {
    renderer->SetWorldPoint(world[0], world[1], world[2], 1.0);
    renderer->WorldToDisplay();
    const double* point = renderer->GetDisplayPoint();
    display[0] = point[0];
    display[1] = point[1];
  };
  double from[2];
  double to[2];
  toDisplay(a, from);
  toDisplay(b, to);
  const double length = std::hypot(to[0] - from[0], to[1] - from[1]);
  if (length < 1.0)
  {
    return 0.0;
  }
  const double across[2] = { -(to[1] - from[1]) / length, (to[0] - from[0]) / length };
  auto pixelAt = [&](double x, double y, std::size_t& pixel) {
    const int i = static_cast<int>(std::floor(x));
    const int j = static_cast<int>(std::floor(y));
    if (i < 0 || j < 0 || i >= capture.Width || j >= capture.Height)
    {
      return false;
    }
    pixel = static_cast<std::size_t>(j) * capture.Width + i;
    return capture.Covers(pixel);
  };
  double largest = 0.0;
  for (int step = 0; step <= static_cast<int>(length); ++step)
  {
    const double t = step / length;
    const double x = from[0] + t * (to[0] - from[0]);
    const double y = from[1] + t * (to[1] - from[1]);
    double samples[4];
    bool covered = true;
    const double offsets[4] = { -4.5, -1.5, 1.5, 4.5 };
    for (int k = 0; k < 4 && covered; ++k)
    {
      std::size_t pixel;
      covered = pixelAt(x + offsets[k] * across[0], y + offsets[k] * across[1], pixel);
      samples[k] = covered ? value(pixel) : 0.0;
    }
    if (covered)
    {
      const double trend = 0.5 * ((samples[1] - samples[0]) + (samples[3] - samples[2]));
      largest = std::max(largest, std::abs(samples[2] - samples[1] - trend));
    }
  }
  return largest;
}
}

namespace ReliefDerivativeStudy
{
std::vector<FrameError> MeasureFrameError(const std::vector<double>& views)
{
  using glm::dvec2;
  using glm::dvec3;
  // the plane z = 0, u along x and v along y rotated by 30 degrees (any rotation: the
  // error comes from the steps, not from the texture)
  const double turn = 30.0 * Pi / 180.0;
  const dvec3 gradU(std::cos(turn), std::sin(turn), 0.0);
  const dvec3 gradV(-std::sin(turn), std::cos(turn), 0.0);
  const dvec3 normal(0.0, 0.0, 1.0);
  auto uvOf = [&](dvec3 p) { return dvec2(glm::dot(gradU, p), glm::dot(gradV, p)); };
  std::vector<FrameError> errors;
  for (double roll : { 0.0, 45.0 })
  {
    for (double view : views)
    {
      const double tilt = view * Pi / 180.0;
      const double spin = roll * Pi / 180.0;
      // camera 3 away, tilted about x; its screen axes rolled about the view axis
      const dvec3 eye(0.0, -3.0 * std::sin(tilt), 3.0 * std::cos(tilt));
      const dvec3 forward = -glm::normalize(eye);
      const dvec3 up0(0.0, std::cos(tilt), std::sin(tilt));
      const dvec3 right0 = glm::cross(forward, up0);
      const dvec3 right = right0 * std::cos(spin) + up0 * std::sin(spin);
      const dvec3 up = up0 * std::cos(spin) - right0 * std::sin(spin);
      const double pixel = 2.0 * std::tan(15.0 * Pi / 180.0) / 240.0; // 30 degrees, 240 rows
      auto onPlane = [&](double x, double y) {
        const dvec3 ray = forward + (right * x + up * y) * pixel;
        return eye - ray * (eye.z / ray.z);
      };
      const dvec3 centre = onPlane(0.0, 0.0);
      const dvec3 alongX = onPlane(1.0, 0.0) - centre;
      const dvec3 alongY = onPlane(0.0, 1.0) - centre;
      const dvec2 uvAlongX = uvOf(alongX);
      const dvec2 uvAlongY = uvOf(alongY);
      // the surface ray of Tichenor (2012): the view ray's run along the plane per unit depth
      const dvec3 view3 = forward;
      const dvec3 run = (view3 - normal * glm::dot(view3, normal)) / std::abs(view3.z);
      const dvec2 exact = uvOf(run);
      // Tichenor (2012), Appendix: dUVdT * dot(SR, T) + dUVdB * dot(SR, B)
      const dvec3 t = glm::normalize(alongX);
      const dvec3 b = glm::normalize(alongY);
      const dvec2 seed = uvAlongX / glm::length(alongX) * glm::dot(run, t) +
        uvAlongY / glm::length(alongY) * glm::dot(run, b);
      const Shader::ReliefAxes axes = Shader::reliefDerivativeAxes(glm::vec3(alongX),
        glm::vec3(alongY), glm::vec2(uvAlongX), glm::vec2(uvAlongY), glm::vec3(normal));
      const dvec2 dual(glm::dot(dvec3(axes.u), run), glm::dot(dvec3(axes.v), run));
      FrameError error;
      error.View = view;
      error.Roll = roll;
      error.StepAngle =
        std::acos(glm::clamp(glm::dot(t, b), -1.0, 1.0)) * 180.0 / Pi;
      const double size = std::max(glm::length(exact), 1e-300);
      error.SeedError = glm::length(seed - exact) / size;
      error.DualError = glm::length(dual - exact) / size;
      errors.push_back(error);
    }
  }
  return errors;
}

const std::vector<std::string>& Frames()
{
  static const std::vector<std::string> frames = { "tangent", "derivative" };
  return frames;
}

const std::vector<std::string>& SeamFrames()
{
  static const std::vector<std::string> frames = { "tangent, smooth normals",
    "tangent, split normals", "derivative, ComputeNormals", "derivative, no normals" };
  return frames;
}

std::vector<Accuracy> MeasureAccuracy(const Options& options)
{
  auto heights = ReliefScene::ResizedHeightMap("stones_height.png", options.HeightMapSize);
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputData(heights);
  relief->Update();

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, options.Width, options.Height);
  std::vector<Accuracy> results;
  for (const Shape& shape : Shapes())
  {
    if (!options.TorusToo && std::string(shape.Name) == "torus")
    {
      continue;
    }
    auto truthMesh =
      ReliefScene::DisplacedMesh(shape.Fine, relief->GetOutput(), options.DepthScale, 0.5);
    vtkNew<vtkPolyDataMapper> truthMapper;
    truthMapper->SetInputData(truthMesh);
    vtkNew<vtkOpenGLReliefMapper> tangent;
    vtkNew<vtkOpenGLDerivativeReliefMapper> derivative;
    vtkOpenGLReliefMapper* mappers[] = { tangent, derivative };
    for (vtkOpenGLReliefMapper* mapper : mappers)
    {
      SetSearch(
        mapper, shape.Coarse, heights, options.DepthScale, options.SearchMethod);
    }
    const std::vector<vtkSmartPointer<vtkActor>> actors = { ReliefScene::ReliefActor(truthMapper, ""),
      ReliefScene::ReliefActor(tangent, ""), ReliefScene::ReliefActor(derivative, "") };
    ReliefScene::Lineup lineup(window, renderer, actors);
    for (const auto& [viewName, aim] : shape.Views)
    {
      aim(renderer);
      renderer->ResetCameraClippingRange(truthMesh->GetBounds());
      const ReliefMetrics::Capture truth = lineup.Capture(actors[0]);
      std::vector<ReliefMetrics::Capture> frames;
      for (size_t f = 0; f < 2; ++f)
      {
        frames.push_back(lineup.Capture(actors[1 + f]));
        Accuracy row;
        row.Shape = shape.Name;
        row.View = viewName;
        row.Frame = Frames()[f];
        row.WrongPixels = ReliefMetrics::WrongPixelFraction(frames[f], truth, options.DepthScale);
        row.Depth95 =
          ReliefMetrics::MeasureDepthError(frames[f], truth, options.DepthScale).Percentile95;
        row.ColourRmse = ReliefMetrics::MeasureColourError(frames[f], truth).Rmse;
        row.MeanSamples = ReliefScene::SampleCounts(window, renderer, mappers[f]).Mean;
        if (f == 1)
        {
          row.WrongAgainstTangent =
            ReliefMetrics::WrongPixelFraction(frames[1], frames[0], options.DepthScale);
          row.RmseAgainstTangent = ReliefMetrics::MeasureColourError(frames[1], frames[0]).Rmse;
        }
        results.push_back(row);
      }
      if (options.Frames > 0)
      {
        const std::vector<double> medians = lineup.InterleavedMilliseconds(
          { actors[1], actors[2] }, options.Rounds, options.Frames);
        for (size_t f = 0; f < 2; ++f)
        {
          results[results.size() - 2 + f].Milliseconds = medians[f];
        }
      }
    }
  }
  return results;
}

std::vector<Seam> MeasureSeams(const Options& options)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  auto renderer = ReliefScene::LitRenderer(window, options.Width, options.Height);
  auto heights = ReliefScene::ReadImage("waves_height.png");
  auto ramp = Ramp();

  // every (crease, view) pair of both sweeps, once
  std::vector<std::pair<double, double>> cases;
  for (double crease : options.Creases)
  {
    cases.emplace_back(crease, options.SweepView);
  }
  for (double view : options.ViewAngles)
  {
    if (std::find(cases.begin(), cases.end(), std::make_pair(options.SweepCrease, view)) ==
      cases.end())
    {
      cases.emplace_back(options.SweepCrease, view);
    }
  }

  std::vector<Seam> seams;
  for (const auto& [crease, view] : cases)
  {
    auto sheet = FoldedSheet(crease);
    const SheetNormals normals[] = { SheetNormals::Smooth, SheetNormals::Split,
      SheetNormals::None, SheetNormals::None };
    for (size_t f = 0; f < SeamFrames().size(); ++f)
    {
      vtkSmartPointer<vtkOpenGLReliefMapper> mapper;
      if (f < 2)
      {
        mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
      }
      else
      {
        auto derivative = vtkSmartPointer<vtkOpenGLDerivativeReliefMapper>::New();
        derivative->SetComputeNormals(f == 2);
        mapper = derivative;
      }
      SetSearch(mapper, WithNormals(sheet, normals[f]), heights, options.DepthScale);
      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->SetTexture(ramp);
      // unlit: the colour is the ramp at the hit, nothing else
      actor->GetProperty()->SetAmbient(1.0);
      actor->GetProperty()->SetDiffuse(0.0);
      actor->GetProperty()->SetSpecular(0.0);
      renderer->RemoveAllViewProps();
      renderer->AddActor(actor);
      vtkCamera* camera = renderer->GetActiveCamera();
      const double radians = view * Pi / 180.0;
      camera->SetFocalPoint(0.0, 0.0, 0.0);
      camera->SetPosition(3.0 * std::sin(radians), 0.0, 3.0 * std::cos(radians));
      camera->SetViewUp(0.0, 1.0, 0.0);
      renderer->ResetCamera();
      camera->Dolly(1.6);
      renderer->ResetCameraClippingRange();
      window->Render();
      const ReliefMetrics::Capture capture = ReliefScene::Capture(window, renderer);
      Seam seam;
      seam.Crease = crease;
      seam.View = view;
      seam.Frame = SeamFrames()[f];
      vtkPoints* points = sheet->GetPoints();
      // fold lines at the inner columns, flat lines halfway along the panels
      for (int line = 1; line < 2 * Panels; ++line)
      {
        const int column = line / 2;
        double a[3];
        double b[3];
        double nextA[3];
        points->GetPoint(2 * column, a);
        points->GetPoint(2 * column + 1, b);
        if (line % 2 == 1)
        {
          points->GetPoint(2 * column + 2, nextA);
          for (int c = 0; c < 3; c += 2)
          {
            a[c] = b[c] = 0.5 * (a[c] + nextA[c]);
          }
        }
        a[1] = -0.35; // away from the sheet's sides
        b[1] = 0.35;
        double colourJumpHere = 0.0;
        for (int channel = 0; channel < 2; ++channel)
        {
          colourJumpHere = std::max(colourJumpHere,
            LargestJump(renderer, capture, a, b, [&](std::size_t pixel) {
              return 255.0 * capture.Rgb[3 * pixel + channel];
            }));
        }
        const double depthJumpHere = LargestJump(renderer, capture, a, b,
          [&](std::size_t pixel) { return capture.EyeDepth[pixel] / options.DepthScale; });
        const bool fold = line % 2 == 0;
        double& colourMax = fold ? seam.ColourJump : seam.FlatColourJump;
        double& depthMax = fold ? seam.DepthJump : seam.FlatDepthJump;
        colourMax = std::max(colourMax, colourJumpHere);
        depthMax = std::max(depthMax, depthJumpHere);
      }
      seams.push_back(seam);
    }
  }
  // by crease, then view: each sweep's rows and lines in order, frames as listed
  std::stable_sort(seams.begin(), seams.end(), [](const Seam& a, const Seam& b) {
    return a.Crease < b.Crease || (a.Crease == b.Crease && a.View < b.View);
  });
  return seams;
}
}

namespace
{
// One line per seam frame, and the jumps halfway between folds (the relief's own change
// over the same pixels) of the frames with split or no normals and of those with smooth
// ones: the jump at the folds against the crease or the view angle, over one sweep; log
// scale, the jumps spanning two orders.
void DrawSeamChart(const std::vector<ReliefDerivativeStudy::Seam>& seams, bool byCrease,
  double fixed, bool colour, const std::string& title, const std::string& file)
{
  using ReliefDerivativeStudy::Seam;
  const std::vector<std::string>& frames = ReliefDerivativeStudy::SeamFrames();
  auto isFlat = [&](const std::string& frame) { return frame == frames[1] || frame == frames[3]; };
  std::vector<ReliefChart::Series> series;
  std::map<double, double> between[2]; // smooth frames, flat frames
  for (const std::string& frame : frames)
  {
    ReliefChart::Series line{ frame };
    line.Line = true;
    for (const Seam& seam : seams)
    {
      if (seam.Frame != frame || (byCrease ? seam.View : seam.Crease) != fixed)
      {
        continue;
      }
      const double x = byCrease ? seam.Crease : seam.View;
      line.X.push_back(x);
      // a log axis has no zero
      line.Y.push_back(std::max(colour ? seam.ColourJump : seam.DepthJump, 1e-3));
      double& largest = between[isFlat(frame) ? 1 : 0][x];
      largest = std::max(largest, colour ? seam.FlatColourJump : seam.FlatDepthJump);
    }
    series.push_back(line);
  }
  const char* names[2] = { "halfway between folds, smooth normals",
    "halfway between folds, split or no normals" };
  for (int kind = 0; kind < 2; ++kind)
  {
    ReliefChart::Series line{ names[kind] };
    line.Line = true;
    for (const auto& [x, y] : between[kind])
    {
      line.X.push_back(x);
      line.Y.push_back(std::max(y, 1e-3));
    }
    series.push_back(line);
  }
  ReliefChart::Axes axes;
  axes.Title = title;
  axes.X = byCrease ? "crease angle between neighbouring panels (degrees)"
                    : "view angle from the sheet's mean normal (degrees)";
  axes.Y = colour ? "largest colour jump (8-bit levels of a u, v ramp)"
                  : "largest depth jump (x DepthScale)";
  axes.LogY = true;
  ReliefChart::Write(series, axes, file);
}

void SeamTable(std::ostringstream& section, const std::vector<ReliefDerivativeStudy::Seam>& seams,
  bool byCrease, double fixed)
{
  section << "| " << (byCrease ? "crease" : "view angle")
          << " | frame | colour jump at folds | between folds | depth jump at folds | "
             "between folds |\n| ---: | --- | ---: | ---: | ---: | ---: |\n";
  for (const auto& seam : seams)
  {
    if ((byCrease ? seam.View : seam.Crease) != fixed)
    {
      continue;
    }
    section << "| " << (byCrease ? seam.Crease : seam.View) << " | " << seam.Frame << " | "
            << seam.ColourJump << " | " << seam.FlatColourJump << " | " << seam.DepthJump << " | "
            << seam.FlatDepthJump << " |\n";
  }
  section << "\n";
}
}

namespace ReliefDerivativeStudy
{
std::string Report(const std::vector<Accuracy>& accuracy, const std::vector<Seam>& seams,
  const std::vector<FrameError>& frameErrors, const Options& options)
{
  std::ostringstream section;
  section << std::setprecision(3);
  section << "Accuracy: stones (the height map resampled to " << options.HeightMapSize << "x"
          << options.HeightMapSize << ", DepthScale " << options.DepthScale
          << ") on a unit square tiled twice and on a torus of 48 facets around, three views "
             "each, in a "
          << options.Width << "x" << options.Height
          << " window, drawn by the tangent frame (vtkOpenGLReliefMapper) and the derivative "
             "frame (vtkOpenGLDerivativeReliefMapper, from the same mesh's positions, normals "
             "and texture coordinates only). Ground truth: vtkReliefDisplacementFilter on the "
             "square, and on the torus regenerated with 256 facets (edges of at most 0.5 "
             "texel). Both frames search with LinearBinary 32+6, self-shadowing off; "
          << options.Frames << " timed frames x " << options.Rounds
          << " interleaved rounds per row (median). \"Against tangent\": the derivative "
             "frame's render measured against the tangent frame's.\n\n";
  section << "| shape | view | frame | wrong pixels | depth error 95th percentile | colour "
             "RMSE | samples/pixel | ms/frame | wrong against tangent | RMSE against "
             "tangent |\n| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  double timeRatio = 0.0;
  double worstWrong = 0.0;
  double worstRmse = 0.0;
  int pairs = 0;
  for (size_t r = 0; r < accuracy.size(); ++r)
  {
    const Accuracy& a = accuracy[r];
    section << "| " << a.Shape << " | " << a.View << " | " << a.Frame << " | " << a.WrongPixels
            << " | " << a.Depth95 << " | " << a.ColourRmse << " | " << a.MeanSamples << " | "
            << a.Milliseconds << " | ";
    if (a.Frame == Frames()[1] && r > 0)
    {
      section << a.WrongAgainstTangent << " | " << a.RmseAgainstTangent << " |\n";
      timeRatio += accuracy[r - 1].Milliseconds > 0.0
        ? a.Milliseconds / accuracy[r - 1].Milliseconds
        : 0.0;
      worstWrong = std::max(worstWrong, a.WrongAgainstTangent);
      worstRmse = std::max(worstRmse, a.RmseAgainstTangent);
      ++pairs;
    }
    else
    {
      section << "- | - |\n";
    }
  }
  section << "\nOver the six views the derivative frame takes " << timeRatio / std::max(pairs, 1)
          << "x the tangent frame's time (mean of the ratios), and its render is at most "
          << worstWrong << " wrong pixels and " << worstRmse
          << " colour RMSE away from the tangent frame's.\n\n";

  section << "Seams: a sheet folded into four flat panels 0.25 wide, neighbouring panels' "
             "normals a crease angle apart, texture coordinates unfolded along it; the waves "
             "height map (one tile, DepthScale "
          << options.DepthScale
          << "), LinearBinary 32+6, seen across the folds. The colour texture is a ramp (red "
             "along u, green along v, one 8-bit level a 256th of the tile), unlit, so a "
             "colour jump is a jump of the hit's texture coordinates. At each pixel along "
             "the three fold lines the jump is the change between the pixels 1.5 px either "
             "side, less the change the pixels 3 px further out predict: the largest of "
             "them, for colour (the larger of u and v) and eye depth. The same measure "
             "halfway between folds, where the surface is flat, is the relief's own "
             "change. Normals: smooth (averaged at the folds), split (each panel its own: "
             "the tangent frame's faceted surface), none (the derivative frame then takes "
             "each face's), or none with ComputeNormals on (the derivative mapper computes "
             "smooth ones, the same as the tangent frame's here).\n\n";
  section << "Against the crease angle, seen " << options.SweepView << " degrees off the "
          << "sheet's normal:\n\n";
  SeamTable(section, seams, true, options.SweepView);
  section << "Against the view angle, crease " << options.SweepCrease << " degrees:\n\n";
  SeamTable(section, seams, false, options.SweepCrease);

  section << "The frame itself, on the CPU: the texture-space run of the view ray at the "
             "centre of a 320x240 view (30-degree view angle) of a plane, as Tichenor's (2012) "
             "Appendix computes it (projected on normalized dFdx and dFdy of the position) "
             "and as this mapper does (reliefDerivativeAxes, the shader's source), against "
             "the exact run; relative error. The camera tilts about a screen axis (roll 0: "
             "the pixel's steps on the plane stay at right angles) or a screen diagonal "
             "(roll 45: they close toward each other at grazing views).\n\n"
          << "| view angle | roll | angle between the steps | Tichenor's (2012) frame | this "
             "frame |\n| ---: | ---: | ---: | ---: | ---: |\n";
  for (const FrameError& e : frameErrors)
  {
    section << "| " << e.View << " | " << e.Roll << " | " << e.StepAngle << " | " << e.SeedError
            << " | " << e.DualError << " |\n";
  }
  section << "\n";

  if (!options.ImageDirectory.empty())
  {
    std::filesystem::create_directories(options.ImageDirectory);
    std::vector<ReliefChart::Series> series;
    for (const std::string& frame : Frames())
    {
      ReliefChart::Series points{ frame };
      for (const Accuracy& a : accuracy)
      {
        if (a.Frame == frame)
        {
          points.X.push_back(std::max(a.WrongPixels, ReliefChart::LogFloor));
          points.Y.push_back(a.Milliseconds);
        }
      }
      series.push_back(points);
    }
    ReliefChart::Axes axes;
    axes.Title = "Derivative against tangent frame: error and cost (plane and torus)";
    axes.X = "wrong pixels against the ground truth (share of the truth's pixels)";
    axes.Y = "ms per frame (median)";
    axes.LogX = true;
    ReliefChart::Write(series, axes, options.ImageDirectory + "/derivative_accuracy.png");
    section << "![wrong pixels against ms/frame](images/derivative_accuracy.png)\n\n";
    const std::string directory = options.ImageDirectory + "/";
    DrawSeamChart(seams, true, options.SweepView, true, "Seam colour jump against crease angle",
      directory + "derivative_seam_colour_crease.png");
    DrawSeamChart(seams, true, options.SweepView, false, "Seam depth jump against crease angle",
      directory + "derivative_seam_depth_crease.png");
    DrawSeamChart(seams, false, options.SweepCrease, true, "Seam colour jump against view angle",
      directory + "derivative_seam_colour_view.png");
    DrawSeamChart(seams, false, options.SweepCrease, false, "Seam depth jump against view angle",
      directory + "derivative_seam_depth_view.png");
    std::vector<ReliefChart::Series> frameSeries;
    for (double roll : { 0.0, 45.0 })
    {
      for (bool seedFrame : { true, false })
      {
        std::ostringstream name;
        name << (seedFrame ? "Tichenor's (2012) frame" : "this frame (dual basis)") << ", roll "
             << roll;
        ReliefChart::Series line{ name.str() };
        line.Line = true;
        for (const FrameError& e : frameErrors)
        {
          if (e.Roll == roll)
          {
            line.X.push_back(e.View);
            // a log axis has no zero: exact results are drawn at its floor
            line.Y.push_back(std::max(seedFrame ? e.SeedError : e.DualError, 1e-8));
          }
        }
        frameSeries.push_back(line);
      }
    }
    ReliefChart::Axes frameAxes;
    frameAxes.Title = "Derivative frames: error of the view ray's texture-space run";
    frameAxes.X = "view angle from the plane's normal (degrees)";
    frameAxes.Y = "relative error of the run (1e-8: exact)";
    frameAxes.LogY = true;
    ReliefChart::Write(frameSeries, frameAxes, directory + "derivative_frame_error.png");
    section << "![frame error against view angle](images/derivative_frame_error.png)\n\n"
            << "![colour jump against crease](images/derivative_seam_colour_crease.png)\n"
            << "![depth jump against crease](images/derivative_seam_depth_crease.png)\n\n"
            << "![colour jump against view angle](images/derivative_seam_colour_view.png)\n"
            << "![depth jump against view angle](images/derivative_seam_depth_view.png)\n\n";
  }
  return section.str();
}
}
