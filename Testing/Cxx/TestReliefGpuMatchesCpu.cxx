// The GPU agrees with the CPU mirror: for each search method, a fixed oblique view of
// tiled relief is rendered, its depth buffer read back, and at sampled pixels the hit the
// shader wrote is compared with the hit of the same search run on the CPU, through
// ReliefCpuMirror.h: the very GLSL files of the mapper compiled as C++. The CPU builds
// each pixel's view ray with the tangent frame's own code (vtkReliefTangentBasis.glsl,
// vtkReliefTangentFrame.glsl), from the vertex stage's basis to the hit's distance, so
// what is compared is the whole chain on the GPU (interpolation, texture upload,
// acceleration image, search selection, depth correction) against code that is proven
// exact by the unit tests.
//
// Every method of vtkReliefSearchMethod is compared, Automatic over each acceleration it
// may read: the mirror's search of the method's GLSL function (ReliefCpuMirror::FindSearch),
// and the map PrepareMaps makes for it; and
// vtkOpenGLPathFeatureMapper's path walk, on its filter's textures, on a flat base and on
// a relief base. No baseline image:
// the depth buffer is checked against the mirror, not against a picture.
#include "ReliefMirrorMaps.h"
#include "ReliefPathFixtures.h"
#include "ReliefPathScene.h"
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkOpenGLPathFeatureMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefSearchMethod.h"
#include "vtkReliefTangentFrameFilter.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

namespace
{
namespace mirror = ReliefCpuMirror;


// The scenes: a height map tiled on the unit square, looked at 55 degrees off its normal
// around its centre, a corner where four tiles meet, so the texture's wrap is crossed.
struct Scene
{
  const char* Name;
  std::function<vtkSmartPointer<vtkImageData>()> HeightMap;
  double Tiles;      // repeats of the map along each side of the square
  double DepthScale; // world depth of relief depth 1
};

// Rivets: hemispheres on a plate and a scratch two texels wide, smooth and steep detail.
// Thin features: walls and spikes one texel wide, which fixed steps miss and exact
// searches do not, so the methods' hits differ most. Its floor is 8-bit level 59 (depth
// 0.769), clear of the depths that fixed steps and bisection sample exactly (k / 10,
// their midpoints), where the two sides' float filtering could round either way.
// A ray runs about 45 and 37 texels per unit of depth, 3.7 to 4.5 per linear step.
const Scene Scenes[] = {
  { "rivets", [] { return ReliefScene::ReadImage("rivets_height.png"); }, 4.0, 0.03 },
  { "thin features",
    [] {
      vtkSmartPointer<vtkImageData> heights = ReliefScene::ThinFeatures();
      auto levels = vtkSmartPointer<vtkImageData>::New();
      levels->SetDimensions(heights->GetDimensions());
      levels->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
      vtkDataArray* from = heights->GetPointData()->GetScalars();
      vtkDataArray* to = levels->GetPointData()->GetScalars();
      for (vtkIdType k = 0; k < from->GetNumberOfTuples(); ++k)
      {
        to->SetComponent(k, 0, from->GetComponent(k, 0) >= 1.0 ? 255.0 : 59.0);
      }
      return levels;
    },
    8.0, 0.05 },
};

constexpr int Width = 400;
constexpr int Height = 300;
constexpr double Tilt = 55.0; // degrees from the normal
constexpr double Distance = 0.45;
constexpr double ViewAngle = 20.0;
constexpr int Stride = 6; // every 6th pixel of every 6th row is a sample

// Agreement. Both sides run the same float code on rays that differ only by what the
// GPU's float interpolation of the entry point and view direction changes (a few 1e-5
// texel at texture coordinates up to 8), at the same pixel centre (no multisampling);
// the 24-bit depth buffer's step is about 1e-6 of the relief depth here (printed), 4e-5
// texel along these rays. Where the field is steep across the ray that grows to a few
// 1e-3 texel (the worst seen). So a hit agrees within 0.01 texel along the ray (and 0.01
// of depth, which binds only for steep rays): 3 times the worst seen on llvmpipe, and 7
// times less than what tells searches apart (LinearBinary's 10 + 5 steps stop up to
// 1/640 of the ray's depth run, 0.07 texel here, from the crossing).
constexpr double AgreeTexels = 0.01;
// Where a ray grazes an edge, or a step or bisection lands within rounding of the
// surface, the two float paths may branch apart (one LinearBinary pixel in 1601 on
// llvmpipe): allowed, rarely. Exchanging any two searches whose hits differ leaves at
// most 69% of one scene's pixels agreeing.
constexpr double RequiredShare = 0.97;
constexpr int MinimumCompared = 300;

// What the mirror reads, made from the relief texture the mapper uploaded by the filters
// the mapper runs (vtkOpenGLReliefTextures::UpdateAcceleration: a setting it gives its
// filter must be given here too).
struct Maps
{
  mirror::DepthField Field;
  mirror::DepthPyramid Pyramid;
  mirror::SlopePyramid Slopes;
  mirror::ConeStepMap Cones;
  mirror::SafetyRadiusMap Radii;
};

void PrepareMaps(const vtkReliefSearchMethod& method, vtkOpenGLReliefMapper* mapper, Maps& maps)
{
  const int kind = method.GetAccelerationKind();
  // the mapper's filter, fed at the render, makes what the GPU was given
  vtkReliefTextureFilter* relief = mapper->GetReliefTextureFilter();
  relief->Update();
  maps.Field = mirror::FieldOf(relief->GetOutput());
  mirror::CurrentField = &maps.Field;
  if (kind == vtkOpenGLReliefMapper::MAXIMUM_MIPMAP || kind == vtkOpenGLReliefMapper::SLOPE_MIPMAP)
  {
    maps.Pyramid = mirror::PyramidOf(maps.Field);
    mirror::CurrentPyramid = &maps.Pyramid;
    maps.Slopes = mirror::SlopesOf(maps.Field);
    mirror::CurrentSlopes = &maps.Slopes;
  }
  else if (kind == vtkOpenGLReliefMapper::CONE_STEP)
  {
    maps.Cones = mirror::ConeMapOf(maps.Field);
    mirror::CurrentConeMap = &maps.Cones;
  }
  else if (kind == vtkOpenGLReliefMapper::SAFETY_RADIUS)
  {
    maps.Radii = mirror::RadiiOf(maps.Field, mapper->GetSafetyRadiusTolerance());
    mirror::CurrentRadii = &maps.Radii;
  }
}

// The camera's transforms in double, as vtkOpenGLCamera gives them to the shaders.
struct View
{
  vtkNew<vtkMatrix4x4> WorldToView;
  vtkNew<vtkMatrix4x4> ViewToClip;
  vtkNew<vtkMatrix4x4> ClipToView;
  vtkNew<vtkMatrix4x4> ClipToWorld;

  explicit View(vtkCamera* camera)
  {
    const double aspect = double(Width) / Height;
    this->WorldToView->DeepCopy(camera->GetModelViewTransformMatrix());
    this->ViewToClip->DeepCopy(camera->GetProjectionTransformMatrix(aspect, -1.0, 1.0));
    vtkMatrix4x4::Invert(this->ViewToClip, this->ClipToView);
    vtkMatrix4x4::Invert(camera->GetCompositeProjectionTransformMatrix(aspect, -1.0, 1.0),
      this->ClipToWorld);
  }

  static void Apply(vtkMatrix4x4* matrix, const double in[4], double out[3])
  {
    double homogeneous[4];
    matrix->MultiplyPoint(in, homogeneous);
    for (int k = 0; k < 3; ++k)
    {
      out[k] = homogeneous[k] / homogeneous[3];
    }
  }

  // The point seen at window position (x, y), at normalized device depth z (-1 near, 1 far).
  void Unproject(vtkMatrix4x4* clipTo, double x, double y, double z, double out[3]) const
  {
    const double clip[4] = { 2.0 * x / Width - 1.0, 2.0 * y / Height - 1.0, z, 1.0 };
    Apply(clipTo, clip, out);
  }

  // Window depth (glDepthRange 0, 1) of a view-space point, as the shader writes it.
  double WindowDepth(const double viewPoint[3]) const
  {
    const double point[4] = { viewPoint[0], viewPoint[1], viewPoint[2], 1.0 };
    double clip[3];
    Apply(this->ViewToClip, point, clip);
    return std::min(std::max(0.5 * clip[2] + 0.5, 0.0), 1.0);
  }
};

// The vertex stage's basis of the square (vtkReliefTangentBasis.glsl), constant over a
// flat, unscaled square, so interpolation leaves it as it is.
mirror::ReliefTangentVertex SquareBasis(const View& view, vtkPolyData* surface)
{
  vtkPointData* points = surface->GetPointData();
  double normal[3];
  double tangent[3];
  points->GetNormals()->GetTuple(0, normal);
  points->GetTangents()->GetTuple(0, tangent);
  double scale[2];
  points->GetArray(vtkReliefTangentFrameFilter::TextureScaleArrayName())->GetTuple(0, scale);
  // the model is the world (an identity actor): model to view is the camera's turn, which
  // is its own normal matrix
  glm::mat3 directions;
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      directions[column][row] = float(view.WorldToView->GetElement(row, column));
    }
  }
  return mirror::reliefTangentVertex(
    glm::vec3(float(normal[0]), float(normal[1]), float(normal[2])),
    glm::vec3(float(tangent[0]), float(tangent[1]), float(tangent[2])),
    glm::vec2(float(scale[0]), float(scale[1])), glm::transpose(glm::inverse(directions)),
    directions);
}

// One sampled pixel as the fragment shader sees it.
struct Fragment
{
  double PositionVC[3]; // where the pixel's centre ray meets the square, view coordinates
  glm::vec2 TCoord;     // the square's texture coordinates there
};

// The square of ReliefScene::Square(tiles) spans [-0.5, 0.5]^2 in z = 0 with texture
// coordinates (x + 0.5, y + 0.5) * tiles. False where the pixel misses it.
bool SquareAt(
  const View& view, double tiles, double x, double y, double world[3], glm::dvec2& tcoord)
{
  double nearPoint[3];
  double farPoint[3];
  view.Unproject(view.ClipToWorld, x, y, -1.0, nearPoint);
  view.Unproject(view.ClipToWorld, x, y, 1.0, farPoint);
  const double s = nearPoint[2] / (nearPoint[2] - farPoint[2]);
  for (int k = 0; k < 3; ++k)
  {
    world[k] = nearPoint[k] + s * (farPoint[k] - nearPoint[k]);
  }
  tcoord = glm::dvec2((world[0] + 0.5) * tiles, (world[1] + 0.5) * tiles);
  return s > 0.0 && s < 1.0 && std::abs(world[0]) < 0.49 && std::abs(world[1]) < 0.49;
}

bool FragmentAt(const View& view, double tiles, int i, int j, Fragment& fragment)
{
  double world[3];
  glm::dvec2 tcoord;
  if (!SquareAt(view, tiles, i + 0.5, j + 0.5, world, tcoord))
  {
    return false;
  }
  const double point[4] = { world[0], world[1], world[2], 1.0 };
  View::Apply(view.WorldToView, point, fragment.PositionVC);
  fragment.TCoord = glm::vec2(float(tcoord.x), float(tcoord.y));
  return true;
}

struct Comparison
{
  int Compared = 0;
  int Agreeing = 0;
  double WorstTexels = 0.0;
  double WorstDepth = 0.0;
  double WorstWindowDepth = 0.0;
  double WorstQuantum = 0.0; // the depth one step of the 24-bit depth buffer spans
};

// The relief depth of the point at window depth `z` on the pixel's ray, measured as the
// shader measures its hit: along the view ray from the polygon, over the descent.
double ReliefDepthAt(const View& view, const Fragment& fragment, double x, double y, double z,
  const glm::dvec3& viewRay, double descent, double depthScale)
{
  double point[3];
  view.Unproject(view.ClipToView, x, y, 2.0 * z - 1.0, point);
  const glm::dvec3 offset(point[0] - fragment.PositionVC[0], point[1] - fragment.PositionVC[1],
    point[2] - fragment.PositionVC[2]);
  return glm::dot(offset, viewRay) * descent / depthScale;
}

// At sampled pixels, the GPU's depth against `search` on the CPU; `size`: the cells per
// tile that agreement is measured in (texels, or the path grid's cells).
Comparison Compare(double tiles, const std::string& method, mirror::Search search,
  glm::vec2 size, vtkOpenGLReliefMapper* mapper, const View& view,
  const mirror::ReliefTangentVertex& vertex, const std::vector<float>& zbuffer)
{
  const float depthScale = static_cast<float>(mapper->GetDepthScale()); // a float uniform
  Comparison result;
  for (int j = Stride / 2; j < Height; j += Stride)
  {
    for (int i = Stride / 2; i < Width; i += Stride)
    {
      Fragment fragment;
      const float z = zbuffer[static_cast<size_t>(j) * Width + i];
      if (!FragmentAt(view, tiles, i, j, fragment) || z >= 1.0f)
      {
        continue;
      }
      // vtkReliefFragmentImpl.glsl's calls of the frame, in float as there
      mirror::ReliefFragment pixel{};
      const glm::vec3 positionVC(float(fragment.PositionVC[0]), float(fragment.PositionVC[1]),
        float(fragment.PositionVC[2]));
      pixel.viewVC = glm::normalize(positionVC);
      pixel.tcoord = fragment.TCoord;
      pixel.frontFacing = true;
      pixel.depthScale = depthScale;
      pixel.eyeDistance = glm::length(positionVC);
      const mirror::ReliefFrame frame = mirror::reliefTangentFrame(
        mirror::reliefTangentBasis(vertex.normal, vertex.tangent, vertex.textureScale, true));
      mirror::ReliefRay ray = mirror::reliefFrameViewRay(frame, pixel);
      if (method.rfind("Automatic", 0) == 0)
      {
        // the entry's change to the next pixels: the Automatic search's budget
        Fragment alongX;
        Fragment alongY;
        if (!FragmentAt(view, tiles, i + 1, j, alongX) ||
          !FragmentAt(view, tiles, i, j + 1, alongY))
        {
          continue;
        }
        ray.screenRun = mirror::reliefScreenRun(glm::vec2(ray.direction.x, ray.direction.y),
          alongX.TCoord - fragment.TCoord, alongY.TCoord - fragment.TCoord,
          static_cast<float>(mapper->GetScreenTolerance()));
      }
      const mirror::ReliefHit hit = search(ray, mapper->GetLinearSteps(), mapper->GetBinarySteps());
      const double distance = mirror::reliefFrameHitDistance(frame, pixel, ray, hit);
      const glm::vec3 viewVC = pixel.viewVC;
      const float descent = std::max(-glm::dot(viewVC, frame.normal), 1e-6f);
      double hitVC[3];
      for (int k = 0; k < 3; ++k)
      {
        hitVC[k] = fragment.PositionVC[k] + viewVC[k] * distance;
      }

      // the GPU's hit, brought back from its window depth to the ray's relief depth
      const glm::dvec3 viewRay(viewVC);
      const double gpuDepth =
        ReliefDepthAt(view, fragment, i + 0.5, j + 0.5, z, viewRay, descent, depthScale);
      const double quantum = std::abs(ReliefDepthAt(view, fragment, i + 0.5, j + 0.5,
                                        z + 1.0 / 16777215.0, viewRay, descent, depthScale) -
        gpuDepth);
      const double depthDifference = std::abs(gpuDepth - hit.position.z);
      // the ray descends one unit of depth per unit of t: the hits lie this many texels apart
      const double texels = depthDifference *
        std::max(std::abs(double(ray.direction.x) * size.x),
          std::abs(double(ray.direction.y) * size.y));
      ++result.Compared;
      if (texels <= AgreeTexels && depthDifference <= AgreeTexels)
      {
        ++result.Agreeing;
      }
      result.WorstTexels = std::max(result.WorstTexels, texels);
      result.WorstDepth = std::max(result.WorstDepth, depthDifference);
      result.WorstWindowDepth =
        std::max(result.WorstWindowDepth, std::abs(double(z) - view.WindowDepth(hitVC)));
      result.WorstQuantum = std::max(result.WorstQuantum, quantum);
    }
  }
  return result;
}
}

// Prints a comparison; false, with an error, where too few pixels agree.
bool Report(const char* scene, const std::string& method, const Comparison& result)
{
  const double share = result.Compared ? double(result.Agreeing) / result.Compared : 0.0;
  std::cout << "  " << std::setw(14) << std::left << method << std::right
            << " pixels compared " << result.Compared << ", agreeing " << std::fixed
            << std::setprecision(1) << 100.0 * share << "%, worst " << std::scientific
            << std::setprecision(2) << result.WorstTexels << " cell, " << result.WorstDepth
            << " depth, " << result.WorstWindowDepth << " window depth (24-bit step "
            << result.WorstQuantum << " depth)\n"
            << std::defaultfloat;
  if (result.Compared < MinimumCompared || share < RequiredShare)
  {
    std::cerr << "ERROR: the GPU's " << method << " hits on " << scene
              << " do not match the CPU mirror's: " << result.Agreeing << " of "
              << result.Compared << " within " << AgreeTexels << " cell and depth\n";
    return false;
  }
  return true;
}

// The path-feature mapper's walk (vtkReliefPathSearch.glsl) on the showcase's paths, tiled
// twice, against the mirror's, on the filter's own textures, agreement measured in the
// grid's cells; with `onRelief`, the same paths cut into the rivet plate
// (vtkReliefPathOnRelief.glsl), its field searched by ExactDDA as the mirror's is, and
// agreement measured in its texels.
bool ComparePathFeatures(vtkRenderWindow* window, vtkRenderer* renderer, const View& view,
  std::vector<float>& zbuffer, Maps* onRelief)
{
  constexpr double Tiles = 2.0;
  vtkSmartPointer<vtkOpenGLPathFeatureMapper> mapper =
    ReliefPathScene::ShowcaseMapper(ReliefScene::Square(Tiles), 0.03);
  mapper->SetSelfShadowing(false);
  if (onRelief)
  {
    mapper->SetHeightMapData(Scenes[0].HeightMap());
    mapper->SetSearchMethodToExactDDA();
  }
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer->RemoveAllViewProps();
  renderer->AddActor(actor);
  window->Render();
  window->GetZbufferData(0, 0, Width - 1, Height - 1, zbuffer.data());
  renderer->RemoveAllViewProps();
  if (onRelief && !mapper->GetDrawingReliefBase())
  {
    std::cerr << "ERROR: the path-feature mapper drew no relief base for its height map\n";
    return false;
  }
  const mirror::PathTextures textures =
    ReliefPathFixtures::Textures(mapper->GetPathFeatureTextureFilter());
  mirror::CurrentPaths = &textures;
  const int* cells = mapper->GetPathFeatureTextureFilter()->GetResolutionUsed();
  glm::vec2 size{ float(cells[0]), float(cells[1]) };
  if (onRelief)
  {
    PrepareMaps(*vtkReliefSearchMethod::Get(vtkOpenGLReliefMapper::EXACT_DDA), mapper, *onRelief);
    size = glm::vec2(float(onRelief->Field.Width), float(onRelief->Field.Height));
  }
  const std::string method = onRelief ? "PathsOnRelief" : "PathFeatures";
  std::cout << (onRelief ? "path features on the rivet plate:\n" : "path features:\n");
  const Comparison result = Compare(Tiles, method,
    onRelief ? &mirror::reliefSearchPathFeaturesOnRelief : &mirror::reliefSearchPathFeatures,
    size, mapper, view, SquareBasis(view, mapper->GetReliefSurface()), zbuffer);
  return Report(
    onRelief ? "the path-feature showcase on the rivet plate" : "the path-feature showcase",
    method, result);
}

int TestReliefGpuMatchesCpu(int, char*[])
{
  vtkNew<vtkRenderWindow> window;
  window->SetSize(Width, Height);
  window->SetMultiSamples(0); // one depth per pixel, at its centre
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkCamera* camera = renderer->GetActiveCamera();
  const double tilt = vtkMath::RadiansFromDegrees(Tilt);
  camera->SetFocalPoint(0.0, 0.0, 0.0); // the corner of four tiles
  camera->SetPosition(0.0, -Distance * std::sin(tilt), Distance * std::cos(tilt));
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(ViewAngle);
  // a fixed range that holds the relief below the square (the mapper's bounds are the
  // square's), and no more, for the depth buffer's precision
  camera->SetClippingRange(0.5 * Distance, 3.0 * Distance);
  const View view(camera);

  int failures = 0;
  Maps maps;
  std::vector<float> zbuffer(static_cast<size_t>(Width) * Height);
  for (const Scene& scene : Scenes)
  {
    vtkNew<vtkOpenGLReliefMapper> mapper;
    mapper->SetInputData(ReliefScene::Square(scene.Tiles));
    mapper->SetHeightMapData(scene.HeightMap());
    mapper->SetDepthScale(scene.DepthScale);
    mapper->SetSelfShadowing(false); // the depth buffer is all that is read
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    renderer->RemoveAllViewProps();
    renderer->AddActor(actor);
    std::cout << scene.Name << ":\n";
    // every method, and Automatic over each acceleration it may read
    std::vector<std::pair<int, int>> searches; // method, AutomaticAcceleration
    for (int id : ReliefScene::SearchMethods())
    {
      searches.emplace_back(id, vtkOpenGLReliefMapper::CONE_STEP);
      if (id == vtkOpenGLReliefMapper::AUTOMATIC)
      {
        searches.emplace_back(id, vtkOpenGLReliefMapper::SLOPE_MIPMAP);
      }
    }
    for (const auto& [id, acceleration] : searches)
    {
      const bool automatic = id == vtkOpenGLReliefMapper::AUTOMATIC;
      const vtkReliefSearchMethod& description = automatic
        ? *vtkReliefSearchMethod::GetAutomatic(acceleration)
        : *vtkReliefSearchMethod::Get(id);
      std::string method = vtkOpenGLReliefMapper::GetSearchMethodAsString(id);
      if (automatic)
      {
        method += std::string(" over ") +
          vtkOpenGLReliefMapper::GetSearchMethodAsString(acceleration);
      }
      if (!mirror::FindSearch(description.Function))
      {
        std::cerr << "ERROR: " << method << " has no search in the CPU mirror\n";
        ++failures;
        continue;
      }
      mapper->SetSearchMethod(id);
      mapper->SetAutomaticAcceleration(acceleration);
      window->Render();
      if (mapper->GetActiveSearchMethod() != id)
      {
        std::cerr << "ERROR: the mapper searched with "
                  << vtkOpenGLReliefMapper::GetSearchMethodAsString(mapper->GetActiveSearchMethod())
                  << " instead of " << method << "\n";
        ++failures;
        continue;
      }
      window->GetZbufferData(0, 0, Width - 1, Height - 1, zbuffer.data());
      PrepareMaps(description, mapper, maps);
      const mirror::ReliefTangentVertex vertex = SquareBasis(view, mapper->GetReliefSurface());
      const Comparison result = Compare(scene.Tiles, method,
        mirror::FindSearch(description.Function),
        glm::vec2(float(maps.Field.Width), float(maps.Field.Height)), mapper, view, vertex,
        zbuffer);
      failures += Report(scene.Name, method, result) ? 0 : 1;
    }
  }
  failures += ComparePathFeatures(window, renderer, view, zbuffer, nullptr) ? 0 : 1;
  failures += ComparePathFeatures(window, renderer, view, zbuffer, &maps) ? 0 : 1;
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
