#include "ReliefPathStudy.h"

#include "ReliefChart.h"
#include "ReliefCpuMirror.h"
#include "ReliefMetrics.h"
#include "ReliefPathFixtures.h"
#include "ReliefPathScene.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFlyingEdges3D.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLPathFeatureMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProperty.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <limits>
#include <sstream>

namespace
{
namespace mirror = ReliefCpuMirror;

constexpr double DepthScale = 0.02;
const double ActorColour[3] = { 0.66, 0.33, 0.24 };
constexpr double Specular = 0.1;
constexpr double SpecularPower = 10.0;

// The study's mapper: the showcase with materials that differ in colour only (the stock
// mapper's geometry takes colours per point, one specular for all).
vtkSmartPointer<vtkOpenGLPathFeatureMapper> PathMapper(vtkPolyData* surface)
{
  auto mapper = vtkSmartPointer<vtkOpenGLPathFeatureMapper>::New();
  mapper->SetInputData(surface);
  vtkPathFeatureTextureFilter* filter = mapper->GetPathFeatureTextureFilter();
  const int first = filter->AddMaterial(0.62, 0.6, 0.56, Specular, SpecularPower);
  filter->AddMaterial(0.25, 0.22, 0.2, Specular, SpecularPower);
  filter->AddMaterial(0.75, 0.75, 0.78, Specular, SpecularPower);
  mapper->SetPathsData(ReliefPathScene::ShowcasePaths(first));
  mapper->SetProfilesData(ReliefPathScene::Profiles());
  mapper->SetDepthScale(DepthScale);
  filter->Update();
  return mapper;
}

void SetLook(vtkActor* actor)
{
  actor->GetProperty()->SetColor(ActorColour[0], ActorColour[1], ActorColour[2]);
  actor->GetProperty()->SetAmbient(0.2);
  actor->GetProperty()->SetSpecular(Specular);
  actor->GetProperty()->SetSpecularPower(SpecularPower);
}

// The diffuse colour of material texel `material` (the actor's for -1), in [0, 255].
std::array<double, 3> MaterialColour(const mirror::PathTextures& textures, float material)
{
  if (material < 0.0f)
  {
    return { 255.0 * ActorColour[0], 255.0 * ActorColour[1], 255.0 * ActorColour[2] };
  }
  const glm::vec4 colour = textures.Texel(int(material));
  return { 255.0 * colour.x, 255.0 * colour.y, 255.0 * colour.z };
}

// Where a vertical line through (u, v) enters and leaves the features' matter, by the
// CPU mirror's exact crossings (vtkReliefPathSearch.glsl, checked against a marched
// reference by the unit tests): depths, and the material of the surface at each.
struct Column
{
  std::vector<float> Depths;
  std::vector<float> Materials;
};

Column Crossings(const mirror::PathTextures& textures, double u, double v)
{
  mirror::CurrentPaths = &textures;
  const glm::vec4 header = textures.Texel(0);
  const float base = header.x;
  const float end = header.y + 0.01f;
  const glm::vec2 size(header.z, header.w);
  mirror::ReliefRay ray =
    mirror::reliefViewRay(glm::vec2(float(u), float(v)), glm::vec3(0.0f, 0.0f, 1.0f));
  const glm::vec2 cell = glm::floor(glm::vec2(ray.origin.x * size.x, ray.origin.y * size.y));
  const glm::vec4 listed = textures.Cell(cell);
  const int list = int(listed.x);
  const int count = std::min(int(listed.y), 32);
  const glm::vec2 centre((cell.x + 0.5f) / size.x, (cell.y + 0.5f) / size.y);
  Column column;
  bool solid = false;
  float t = 0.0f;
  for (int k = 0; k < 96; ++k)
  {
    const mirror::ReliefPathTransition change =
      mirror::reliefPathCellTransition(
        ray, list, count, centre, base, -1e30f, t, end, !solid, false);
    if (change.t < 0.0f)
    {
      break;
    }
    column.Depths.push_back(change.t);
    column.Materials.push_back(change.material);
    solid = !solid;
    t = change.t;
  }
  return column;
}

// A part of the square in (u, v): [U0, U1] x [V0, V1].
struct Window
{
  double U0 = 0.0;
  double V0 = 0.0;
  double U1 = 1.0;
  double V1 = 1.0;
};

// The features as geometry over a window of the square: a volume of signed distances
// along the depth to the nearest crossing of each column (positive in matter), contoured
// at 0, coloured by the material of the nearest crossing; `columnCount` columns along the
// window's longer side, `layers` through the depth; x = u - 0.5, y = v - 0.5, z = -depth x
// DepthScale.
vtkSmartPointer<vtkPolyData> TruthGeometry(
  const mirror::PathTextures& textures, int columnCount, int layers, const Window& window)
{
  const double spacing = std::max(window.U1 - window.U0, window.V1 - window.V0) / columnCount;
  const int nu = static_cast<int>(std::ceil((window.U1 - window.U0) / spacing - 1e-9));
  const int nv = static_cast<int>(std::ceil((window.V1 - window.V0) / spacing - 1e-9));
  const double deepest = textures.Texel(0).y;
  const double top = -0.05 * deepest; // air above the polygons, so protrusions close
  const double step = (deepest + 0.02 - top) / layers;
  std::vector<Column> columns(static_cast<size_t>(nu + 1) * (nv + 1));
  vtkSMPTools::For(0, static_cast<vtkIdType>(columns.size()), [&](vtkIdType begin, vtkIdType last) {
    for (vtkIdType c = begin; c < last; ++c)
    {
      columns[c] = Crossings(textures, window.U0 + spacing * double(c % (nu + 1)),
        window.V0 + spacing * double(c / (nu + 1)));
    }
  });
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(nu + 1, nv + 1, layers + 1);
  volume->SetSpacing(spacing, spacing, step * DepthScale);
  volume->SetOrigin(window.U0 - 0.5, window.V0 - 0.5, -(deepest + 0.02) * DepthScale);
  volume->AllocateScalars(VTK_FLOAT, 1);
  auto* field = static_cast<float*>(volume->GetScalarPointer());
  vtkSMPTools::For(0, static_cast<vtkIdType>(columns.size()), [&](vtkIdType begin, vtkIdType last) {
    for (vtkIdType c = begin; c < last; ++c)
    {
      const Column& column = columns[c];
      for (int k = 0; k <= layers; ++k)
      {
        const double depth = deepest + 0.02 - k * step;
        bool inside = false;
        double nearest = 3.0 * step;
        for (float crossing : column.Depths)
        {
          inside = depth >= crossing ? !inside : inside;
          nearest = std::min(nearest, std::abs(depth - crossing));
        }
        field[static_cast<size_t>(k) * columns.size() + c] =
          static_cast<float>((inside ? 1.0 : -1.0) * nearest / step);
      }
    }
  });
  vtkNew<vtkFlyingEdges3D> contour;
  contour->SetInputData(volume);
  contour->SetValue(0, 0.0);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(contour->GetOutputPort());
  normals->SetFeatureAngle(30.0);
  normals->Update();
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(normals->GetOutput());
  // each point's colour: the material of the nearest crossing of its column
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(surface->GetNumberOfPoints());
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    const double* point = surface->GetPoint(p);
    const int i = std::clamp(int(std::lround((point[0] + 0.5 - window.U0) / spacing)), 0, nu);
    const int j = std::clamp(int(std::lround((point[1] + 0.5 - window.V0) / spacing)), 0, nv);
    const Column& column = columns[static_cast<size_t>(j) * (nu + 1) + i];
    const double depth = -point[2] / DepthScale;
    float material = -1.0f;
    double nearest = 1e30;
    for (size_t k = 0; k < column.Depths.size(); ++k)
    {
      if (std::abs(depth - column.Depths[k]) < nearest)
      {
        nearest = std::abs(depth - column.Depths[k]);
        material = column.Materials[k];
      }
    }
    const std::array<double, 3> rgb = MaterialColour(textures, material);
    colours->SetTuple3(p, rgb[0], rgb[1], rgb[2]);
  }
  surface->GetPointData()->SetScalars(colours);
  return surface;
}

// The features rasterized as a height map `size` texels a side: each texel's first
// crossing straight down, as relief depth (0 to 1 over the deepest), and a colour texture
// of the material met there.
struct HeightMap
{
  vtkSmartPointer<vtkImageData> Depths;
  vtkSmartPointer<vtkImageData> Colours;
};

HeightMap Rasterize(const mirror::PathTextures& textures, int size)
{
  const double deepest = textures.Texel(0).y;
  HeightMap map;
  map.Depths = vtkSmartPointer<vtkImageData>::New();
  map.Depths->SetDimensions(size, size, 1);
  map.Depths->AllocateScalars(VTK_FLOAT, 1);
  map.Colours = vtkSmartPointer<vtkImageData>::New();
  map.Colours->SetDimensions(size, size, 1);
  map.Colours->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* depths = static_cast<float*>(map.Depths->GetScalarPointer());
  auto* colours = static_cast<unsigned char*>(map.Colours->GetScalarPointer());
  vtkSMPTools::For(0, static_cast<vtkIdType>(size) * size, [&](vtkIdType begin, vtkIdType last) {
    for (vtkIdType t = begin; t < last; ++t)
    {
      const Column column =
        Crossings(textures, (double(t % size) + 0.5) / size, (double(t / size) + 0.5) / size);
      const float first = column.Depths.empty() ? float(deepest) : column.Depths.front();
      const float material = column.Materials.empty() ? -1.0f : column.Materials.front();
      depths[t] = static_cast<float>(first / deepest);
      const std::array<double, 3> rgb = MaterialColour(textures, material);
      for (int c = 0; c < 3; ++c)
      {
        colours[3 * t + c] = static_cast<unsigned char>(std::lround(rgb[c]));
      }
    }
  });
  return map;
}

struct View
{
  const char* Name;
  double Angle;
  double Dolly;
};

const View Views[] = { { "close", 30.0, 3.5 }, { "middle", 45.0, 1.0 }, { "grazing 80", 80.0, 1.0 } };

void Aim(vtkRenderer* renderer, const View& view, const double bounds[6])
{
  ReliefScene::ViewSquare(renderer, view.Angle);
  vtkCamera* camera = renderer->GetActiveCamera();
  if (view.Dolly > 1.0)
  {
    // toward the crack across the bricks
    double focal[3];
    double position[3];
    camera->GetFocalPoint(focal);
    camera->GetPosition(position);
    const double target[3] = { -0.28, 0.12, 0.0 };
    for (int k = 0; k < 3; ++k)
    {
      position[k] += target[k] - focal[k];
    }
    camera->SetFocalPoint(target);
    camera->SetPosition(position);
    camera->Dolly(view.Dolly);
  }
  renderer->ResetCameraClippingRange(bounds);
}

// The part of the square the renderer's camera sees (through a 9 x 9 grid of its pixels,
// between the features' top and bottom planes), a little enlarged; all of it where a ray
// runs off above the features.
Window VisibleWindow(vtkRenderer* renderer, double deepest)
{
  const int* size = renderer->GetSize();
  const double planes[2] = { 0.05 * deepest * DepthScale, -(deepest + 0.02) * DepthScale };
  Window seen{ 1.0, 1.0, 0.0, 0.0 };
  for (int i = 0; i <= 8; ++i)
  {
    for (int j = 0; j <= 8; ++j)
    {
      double ends[2][4];
      for (int k = 0; k < 2; ++k)
      {
        renderer->SetDisplayPoint(size[0] * i / 8.0, size[1] * j / 8.0, k);
        renderer->DisplayToWorld();
        renderer->GetWorldPoint(ends[k]); // (divided through by w)
      }
      for (double z : planes)
      {
        const double run = ends[1][2] - ends[0][2];
        const double t = run != 0.0 ? (z - ends[0][2]) / run : -1.0;
        if (!(t >= 0.0 && t <= 1.0))
        {
          return Window();
        }
        const double u = ends[0][0] + t * (ends[1][0] - ends[0][0]) + 0.5;
        const double v = ends[0][1] + t * (ends[1][1] - ends[0][1]) + 0.5;
        seen = { std::min(seen.U0, u), std::min(seen.V0, v), std::max(seen.U1, u),
          std::max(seen.V1, v) };
      }
    }
  }
  const double margin = 0.01;
  return { std::max(seen.U0 - margin, 0.0), std::max(seen.V0 - margin, 0.0),
    std::min(seen.U1 + margin, 1.0), std::min(seen.V1 + margin, 1.0) };
}

// Truth pixels on the outline of a feature: in one (deeper or higher than the base plane
// by a tenth of DepthScale) with a neighbour that is not.
long EdgePixels(const ReliefMetrics::Capture& truth, const ReliefMetrics::Capture& base)
{
  auto feature = [&](int x, int y) {
    const size_t pixel = static_cast<size_t>(y) * truth.Width + x;
    return truth.Covers(pixel) && base.Covers(pixel) &&
      std::abs(truth.EyeDepth[pixel] - base.EyeDepth[pixel]) > 0.1 * DepthScale;
  };
  long edges = 0;
  for (int y = 1; y + 1 < truth.Height; ++y)
  {
    for (int x = 1; x + 1 < truth.Width; ++x)
    {
      if (feature(x, y) &&
        (!feature(x - 1, y) || !feature(x + 1, y) || !feature(x, y - 1) || !feature(x, y + 1)))
      {
        ++edges;
      }
    }
  }
  return std::max(edges, 1L);
}

// The square's interior as the view shows it: covered by the polygon and by the base
// plane below it, 3 pixels or more from where either ends. Past the polygon's outline
// texture-space detail shows the tiled base where the geometry has its edge: the same for
// every method compared, so left out.
std::vector<bool> Interior(const ReliefMetrics::Capture& top, const ReliefMetrics::Capture& base)
{
  constexpr int Margin = 3;
  std::vector<bool> inside(top.EyeDepth.size(), false);
  for (int y = Margin; y + Margin < top.Height; ++y)
  {
    for (int x = Margin; x + Margin < top.Width; ++x)
    {
      bool all = true;
      for (int j = -Margin; j <= Margin && all; ++j)
      {
        for (int i = -Margin; i <= Margin && all; ++i)
        {
          const size_t pixel = static_cast<size_t>(y + j) * top.Width + x + i;
          all = top.Covers(pixel) && base.Covers(pixel);
        }
      }
      inside[static_cast<size_t>(y) * top.Width + x] = all;
    }
  }
  return inside;
}

// `capture` with the pixels outside `inside` uncovered and black.
ReliefMetrics::Capture Within(ReliefMetrics::Capture capture, const std::vector<bool>& inside)
{
  for (size_t pixel = 0; pixel < inside.size(); ++pixel)
  {
    if (!inside[pixel])
    {
      capture.EyeDepth[pixel] = std::numeric_limits<float>::infinity();
      capture.Rgb[3 * pixel] = capture.Rgb[3 * pixel + 1] = capture.Rgb[3 * pixel + 2] = 0.0f;
    }
  }
  return capture;
}

struct Row
{
  std::string Method;
  vtkSmartPointer<vtkActor> Actor;
  vtkOpenGLReliefMapper* Relief = nullptr; // null for the geometry
  vtkIdType Bytes = 0;
};

struct Measurement
{
  double Wrong = 0.0;
  double EdgeError = 0.0;
  double Rmse = 0.0;
  double Milliseconds = 0.0;
  double Samples = 0.0;
};
}

namespace ReliefPathStudy
{
std::string Study(const Options& options)
{
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  vtkSmartPointer<vtkRenderer> renderer =
    ReliefScene::LitRenderer(window, options.Width, options.Height);
  vtkSmartPointer<vtkPolyData> square = ReliefScene::Square(1.0);

  std::vector<Row> rows;
  vtkSmartPointer<vtkOpenGLPathFeatureMapper> paths = PathMapper(square);
  const mirror::PathTextures textures =
    ReliefPathFixtures::Textures(paths->GetPathFeatureTextureFilter());
  const double deepest = textures.Texel(0).y;
  const double base = textures.Texel(0).x;

  vtkSmartPointer<vtkPolyData> truth =
    TruthGeometry(textures, options.TruthColumns, options.TruthLayers, Window());
  vtkNew<vtkPolyDataMapper> truthMapper;
  truthMapper->SetInputData(truth);
  truthMapper->SetColorModeToDirectScalars();
  auto addRow = [&](const std::string& name, vtkMapper* mapper, vtkOpenGLReliefMapper* relief,
                  vtkIdType bytes) {
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    SetLook(actor);
    if (relief)
    {
      // the stock mapper draws no shadows: compared without them (TestReliefSelfShadowing
      // and the shading study judge them)
      relief->SelfShadowingOff();
    }
    rows.push_back({ name, actor, relief, bytes });
    return actor;
  };
  // vertices (position, normal: floats; colour) and three indices a triangle
  addRow("geometry (truth)", truthMapper, nullptr,
    28 * truth->GetNumberOfPoints() + 12 * truth->GetNumberOfPolys());
  addRow("path features", paths, paths, 0);
  vtkSmartPointer<vtkOpenGLPathFeatureMapper> aliased = PathMapper(square);
  aliased->FootprintShadingOff();
  addRow("path features, antialiasing off", aliased, aliased, 0);
  std::vector<HeightMap> maps;
  for (int size : options.HeightMapSizes)
  {
    maps.push_back(Rasterize(textures, size));
    auto relief = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
    relief->SetInputData(square);
    relief->SetHeightMapData(maps.back().Depths);
    relief->GetReliefTextureFilter()->SetInputConventionToDepth();
    relief->SetDepthScale(DepthScale * deepest);
    relief->SetSearchMethodToConeStep();
    vtkActor* actor = addRow("height map " + std::to_string(size) + "^2, ConeStep", relief,
      relief, 0);
    vtkNew<vtkTexture> colour;
    colour->SetInputData(maps.back().Colours);
    colour->InterpolateOn();
    colour->MipmapOn();
    actor->SetTexture(colour);
    actor->GetProperty()->SetColor(1.0, 1.0, 1.0); // VTK multiplies the texture by it
  }
  // the plain square at the polygons and at the base surface, where the features are not
  vtkNew<vtkPolyDataMapper> plainMapper;
  plainMapper->SetInputData(square);
  vtkNew<vtkActor> topPlane;
  topPlane->SetMapper(plainMapper);
  vtkNew<vtkActor> basePlane;
  basePlane->SetMapper(plainMapper);
  basePlane->SetPosition(0.0, 0.0, -base * DepthScale);

  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (const Row& row : rows)
  {
    actors.push_back(row.Actor);
  }
  actors.push_back(topPlane);
  actors.push_back(basePlane);
  ReliefScene::Lineup lineup(window, renderer, actors);
  double bounds[6];
  truth->GetBounds(bounds);

  vtkNew<vtkRenderWindow> fineWindow;
  fineWindow->SetOffScreenRendering(1);
  vtkSmartPointer<vtkRenderer> fineRenderer = ReliefScene::LitRenderer(fineWindow,
    options.Width * options.Supersampling, options.Height * options.Supersampling);
  auto fineActor = vtkSmartPointer<vtkActor>::New();
  fineActor->SetMapper(truthMapper);
  SetLook(fineActor);
  fineRenderer->AddActor(fineActor);

  std::vector<std::vector<Measurement>> results(std::size(Views));
  std::vector<ReliefMetrics::Capture> middle;
  std::ostringstream partTruth;
  for (size_t v = 0; v < std::size(Views); ++v)
  {
    Aim(renderer, Views[v], bounds);
    // a view of part of the square (up close) gets a finer truth over that part: there a
    // column is a pixel, and the contour's bevel along each sharp edge shows
    const Window seen = VisibleWindow(renderer, deepest);
    const bool part = (seen.U1 - seen.U0) * (seen.V1 - seen.V0) < 0.5;
    if (part)
    {
      truthMapper->SetInputData(
        TruthGeometry(textures, options.TruthColumnsUpClose, options.TruthLayers, seen));
      partTruth << "; up close, over the part in view (u in [" << std::setprecision(2)
                << seen.U0 << ", " << seen.U1 << "], v in [" << seen.V0 << ", " << seen.V1
                << "]), from " << options.TruthColumnsUpClose
                << " columns along its longer side ("
                << truthMapper->GetInput()->GetNumberOfPolys() << " triangles)";
    }
    else
    {
      truthMapper->SetInputData(truth);
    }
    fineRenderer->GetActiveCamera()->DeepCopy(renderer->GetActiveCamera());
    fineRenderer->ResetCameraClippingRange(bounds);
    fineWindow->Render();
    const ReliefMetrics::Capture baseCapture = lineup.Capture(basePlane);
    const std::vector<bool> inside = Interior(lineup.Capture(topPlane), baseCapture);
    const ReliefMetrics::Capture colourTruth = Within(
      ReliefMetrics::Downsample(ReliefScene::Capture(fineWindow, fineRenderer), options.Supersampling),
      inside);
    const ReliefMetrics::Capture truthCapture = Within(lineup.Capture(rows[0].Actor), inside);
    const long edges = EdgePixels(truthCapture, baseCapture);
    std::vector<vtkActor*> timed;
    for (const Row& row : rows)
    {
      timed.push_back(row.Actor);
    }
    const std::vector<double> milliseconds =
      lineup.InterleavedMilliseconds(timed, options.Rounds, options.Frames);
    for (size_t r = 0; r < rows.size(); ++r)
    {
      const ReliefMetrics::Capture capture = Within(lineup.Capture(rows[r].Actor), inside);
      Measurement measured;
      const double wrong = ReliefMetrics::WrongPixelFraction(capture, truthCapture, DepthScale);
      measured.Wrong = wrong;
      long covered = 0;
      for (size_t pixel = 0; pixel < truthCapture.EyeDepth.size(); ++pixel)
      {
        covered += truthCapture.Covers(pixel) ? 1 : 0;
      }
      measured.EdgeError = wrong * covered / edges;
      measured.Rmse = ReliefMetrics::MeasureColourError(capture, colourTruth).Rmse;
      measured.Milliseconds = milliseconds[r];
      if (rows[r].Relief)
      {
        lineup.Show(rows[r].Actor);
        measured.Samples = ReliefScene::SampleCounts(window, renderer, rows[r].Relief).Mean;
      }
      results[v].push_back(measured);
      if (v == 1)
      {
        middle.push_back(capture);
      }
    }
    if (v == 1)
    {
      middle.push_back(colourTruth);
    }
  }
  for (Row& row : rows)
  {
    if (row.Relief)
    {
      row.Bytes = row.Relief->GetTextureBytes();
    }
  }
  for (size_t m = 0; m < maps.size(); ++m)
  {
    // the colour texture beside the depths: 4 bytes a texel (GL pads RGB8), mipmaps a third more
    const int size = options.HeightMapSizes[m];
    rows[3 + m].Bytes += 4 * static_cast<vtkIdType>(size) * size * 4 / 3;
  }

  std::ostringstream out;
  out << "The path-feature showcase (ReliefPathScene: bricks with a crack, a weld bead, a\n"
      << "dovetail slot, a ring of quadratic arcs; " << paths->GetPathFeatureTextureFilter()->GetNumberOfElements()
      << " elements, grid " << paths->GetPathFeatureTextureFilter()->GetResolutionUsed()[0]
      << "^2) on a unit square, DepthScale " << DepthScale << ", one scene light, "
      << options.Width << "x" << options.Height << ", self-shadowing off (the stock mapper\n"
      << "casts none). Truth: the solid the features define,\n"
      << "contoured from " << options.TruthColumns << "^2 x " << options.TruthLayers
      << " signed distances to the exact vertical crossings (" << truth->GetNumberOfPolys()
      << " triangles)" << partTruth.str()
      << ", drawn by VTK's stock\nmapper; colour judged against it rendered "
      << options.Supersampling << "x" << options.Supersampling
      << " larger and averaged. Height maps: each texel's first crossing straight\n"
      << "down (overhangs lost) and the material there as a colour texture, drawn by the\n"
      << "relief mapper with ConeStep. Measured over the square's interior, 3 pixels or more\n"
      << "from its outline (past it texture-space detail shows the tiled base where the\n"
      << "geometry ends, alike for every method). Wrong pixels: covered by one only or more than 0.1\n"
      << "DepthScale apart in depth; edge error: wrong pixels over the truth's feature\n"
      << "outline pixels. Samples: cells and element tests of the path walk, height reads\n"
      << "of the relief search; the footprint's rays included where antialiasing is on.\n"
      << "ms/frame: median of " << options.Frames << " frames x " << options.Rounds
      << " interleaved rounds.\n\n";
  out << "| view | method | wrong pixels | edge error (px) | colour RMSE | ms/frame | "
         "samples/pixel | texture bytes |\n"
      << "| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
  std::vector<ReliefChart::Series> series;
  for (const Row& row : rows)
  {
    series.push_back({ row.Method, {}, {} });
  }
  for (size_t v = 0; v < std::size(Views); ++v)
  {
    for (size_t r = 0; r < rows.size(); ++r)
    {
      const Measurement& m = results[v][r];
      out << "| " << Views[v].Name << " | " << rows[r].Method << " | " << std::fixed
          << std::setprecision(2) << 100.0 * m.Wrong << "% | " << m.EdgeError << " | "
          << std::setprecision(4) << m.Rmse << " | " << std::setprecision(1) << m.Milliseconds
          << " | ";
      if (rows[r].Relief)
      {
        out << m.Samples;
      }
      else
      {
        out << "-";
      }
      out << " | " << rows[r].Bytes << " |\n";
      series[r].X.push_back(m.Milliseconds);
      series[r].Y.push_back(std::max(m.Rmse, ReliefChart::LogFloor));
    }
  }
  if (!options.ImageDirectory.empty())
  {
    ReliefChart::Axes axes;
    axes.Title = "Path features: colour error against cost (close, middle, grazing)";
    axes.X = "ms/frame";
    axes.Y = "colour RMSE against the supersampled geometry";
    axes.LogX = true;
    // from 0, with room above the points for the legend
    double largest = 0.0;
    for (const ReliefChart::Series& one : series)
    {
      largest = std::max(largest, *std::max_element(one.Y.begin(), one.Y.end()));
    }
    axes.YRange[1] = 1.4 * largest;
    ReliefChart::Write(series, axes, options.ImageDirectory + "/path_features_error_cost.png");
    std::vector<const ReliefMetrics::Capture*> top;
    std::vector<const ReliefMetrics::Capture*> bottom;
    top.push_back(&middle.back()); // the supersampled truth
    for (size_t r = 1; r < middle.size() - 1; ++r)
    {
      (r < 3 ? top : bottom).push_back(&middle[r]);
    }
    bottom.push_back(&middle[0]);
    ReliefMetrics::WriteMosaic({ top, bottom }, options.ImageDirectory + "/path_features_middle.png");
    // where the colour error lies: |method - supersampled truth| x 4, path features and
    // the larger height map
    std::vector<ReliefMetrics::Capture> differences;
    for (size_t r : { size_t(1), size_t(2), middle.size() - 2 })
    {
      ReliefMetrics::Capture difference = middle[r];
      for (size_t k = 0; k < difference.Rgb.size(); ++k)
      {
        difference.Rgb[k] = std::min(1.0f, 4.0f * std::abs(middle[r].Rgb[k] - middle.back().Rgb[k]));
      }
      differences.push_back(difference);
    }
    ReliefMetrics::WriteMosaic({ { &differences[0], &differences[1], &differences[2] } },
      options.ImageDirectory + "/path_features_difference.png");
    out << "\n![error against cost](images/path_features_error_cost.png)\n\n"
        << "Middle view, top: the geometry supersampled, path features with and without\n"
        << "antialiasing; bottom: the height maps, the geometry at one sample a pixel.\n\n"
        << "![middle view](images/path_features_middle.png)\n";
  }
  return out.str();
}
}
