// The CPU mirror of the relief shaders: the very GLSL files the mapper compiles,
// compiled here as C++ with GLM, reading heights through an exact bilinear sampler.
#ifndef ReliefCpuMirror_h
#define ReliefCpuMirror_h

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ReliefCpuMirror
{
using namespace glm;

/// A tiling height field sampled like GL_LINEAR with GL_REPEAT on level 0: bilinear
/// interpolation of depths stored at texel centres ((i + 0.5) / width, ...).
struct DepthField
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Depths; // row j = 0 is v's bottom row
  bool ClampToEdge = false;  // GL_CLAMP_TO_EDGE (an impostor's views), not GL_REPEAT

  float At(int i, int j) const
  {
    if (this->ClampToEdge)
    {
      i = std::min(std::max(i, 0), this->Width - 1);
      j = std::min(std::max(j, 0), this->Height - 1);
    }
    i = ((i % this->Width) + this->Width) % this->Width;
    j = ((j % this->Height) + this->Height) % this->Height;
    return this->Depths[static_cast<size_t>(j) * this->Width + i];
  }

  float Sample(vec2 uv) const
  {
    const float x = uv.x * this->Width - 0.5f;
    const float y = uv.y * this->Height - 0.5f;
    const float i = std::floor(x);
    const float j = std::floor(y);
    const float fx = x - i;
    const float fy = y - j;
    const int ii = static_cast<int>(i);
    const int jj = static_cast<int>(j);
    const float bottom = mix(this->At(ii, jj), this->At(ii + 1, jj), fx);
    const float top = mix(this->At(ii, jj + 1), this->At(ii + 1, jj + 1), fx);
    return mix(bottom, top, fy);
  }

  /// A field whose texel (i, j) holds depth(u, v) at its centre.
  static DepthField FromFunction(
    int width, int height, const std::function<float(float, float)>& depth)
  {
    DepthField field;
    field.Width = width;
    field.Height = height;
    field.Depths.resize(static_cast<size_t>(width) * height);
    for (int j = 0; j < height; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        field.Depths[static_cast<size_t>(j) * width + i] =
          depth((i + 0.5f) / width, (j + 0.5f) / height);
      }
    }
    return field;
  }
};

/// A pyramid as the GPU holds it: level L of max(1, size >> L) nodes per axis, unpacked
/// from the atlas of vtkMaximumMipmapFilter (least depths) or vtkSlopeMipmapFilter (the
/// texels of RELIEF_SLOPE_NODE: vtkSlopeMipmapFilter::PackNode's four integers).
template <typename Value>
struct NodePyramid
{
  std::vector<int> Widths;
  std::vector<int> Heights;
  std::vector<std::vector<Value>> Levels;

  int Top() const { return static_cast<int>(this->Levels.size()) - 1; }
  Value At(vec2 node, int level) const
  {
    return this->Levels[level][static_cast<size_t>(node.y) * this->Widths[level] +
      static_cast<size_t>(node.x)];
  }
};
using DepthPyramid = NodePyramid<float>;
using SlopePyramid = NodePyramid<uvec4>;

/// A value per cell as the acceleration filters write them, repeating like the texture:
/// vtkConeStepMapFilter's (top depth, cone ratio), vtkSafetyRadiusFilter's radius.
template <typename Value>
struct CellMap
{
  int Width = 0;
  int Height = 0;
  std::vector<Value> Values; // row j = 0 first

  Value At(vec2 cell) const
  {
    const int i = ((static_cast<int>(cell.x) % this->Width) + this->Width) % this->Width;
    const int j = ((static_cast<int>(cell.y) % this->Height) + this->Height) % this->Height;
    return this->Values[static_cast<size_t>(j) * this->Width + i];
  }
};
using ConeStepMap = CellMap<vec2>;
using SafetyRadiusMap = CellMap<float>;

/// vtkPathFeatureTextureFilter's two textures, texel by texel, the grid repeating.
struct PathTextures
{
  int GridWidth = 1;
  int GridHeight = 1;
  std::vector<vec4> Grid;
  std::vector<vec4> Data;

  vec4 Cell(vec2 cell) const
  {
    const int i = ((static_cast<int>(cell.x) % this->GridWidth) + this->GridWidth) % this->GridWidth;
    const int j =
      ((static_cast<int>(cell.y) % this->GridHeight) + this->GridHeight) % this->GridHeight;
    return this->Grid[static_cast<size_t>(j) * this->GridWidth + i];
  }
  vec4 Texel(int index) const { return this->Data[static_cast<size_t>(index)]; }
};

/// An impostor's views (vtkReliefImpostorFilter's), as vtkOpenGLReliefImpostorMapper
/// uploads them: each view's field (clamped at its edges), its pyramid for MaximumMipmap,
/// and its projection from model coordinates.
struct ImpostorViews
{
  std::vector<DepthField> Fields;
  std::vector<DepthPyramid> Pyramids; // one per view, or none
  std::vector<mat4> Projections;
  std::vector<float> DepthRatios; // the box's depth along each view over its face's size
};

/// The field and the acceleration maps the shader code reads; set them before a search.
inline const DepthField* CurrentField = nullptr;
inline const DepthPyramid* CurrentPyramid = nullptr;
inline const SlopePyramid* CurrentSlopes = nullptr;
inline const ConeStepMap* CurrentConeMap = nullptr;
inline const SafetyRadiusMap* CurrentRadii = nullptr;
inline const PathTextures* CurrentPaths = nullptr;
inline const ImpostorViews* CurrentImpostor = nullptr;

/// RELIEF_IMPOSTOR_SELECT: the shader code reads view `view` of CurrentImpostor.
inline void SelectImpostorView(int view)
{
  CurrentField = &CurrentImpostor->Fields[static_cast<size_t>(view)];
  CurrentPyramid = CurrentImpostor->Pyramids.empty()
    ? nullptr
    : &CurrentImpostor->Pyramids[static_cast<size_t>(view)];
}

inline float SampleCurrentField(vec2 uv)
{
  return CurrentField->Sample(uv);
}

inline vec4 CellDepths(vec2 cell)
{
  const int i = static_cast<int>(cell.x);
  const int j = static_cast<int>(cell.y);
  return vec4(CurrentField->At(i, j), CurrentField->At(i + 1, j), CurrentField->At(i, j + 1),
    CurrentField->At(i + 1, j + 1));
}

#define RELIEF_DEPTH(uv) ReliefCpuMirror::SampleCurrentField(uv)
#define RELIEF_DEPTH_SIZE vec2(CurrentField->Width, CurrentField->Height)
#define RELIEF_DEPTH_REPEATS (!CurrentField->ClampToEdge)
#define RELIEF_CELL_DEPTHS(cell) ReliefCpuMirror::CellDepths(cell)
#define RELIEF_PYRAMID_DEPTH(node, level) CurrentPyramid->At(node, level)
#define RELIEF_PYRAMID_TOP CurrentPyramid->Top()
#define RELIEF_SLOPE_NODE(node, level) CurrentSlopes->At(node, level)
#define RELIEF_CONE_STEP(cell) CurrentConeMap->At(cell)
#define RELIEF_SAFETY_RADIUS(cell) CurrentRadii->At(cell)
#define RELIEF_PATH_TEXEL(index) CurrentPaths->Texel(index)
#define RELIEF_PATH_CELL(cell) CurrentPaths->Cell(cell)
// The shader sources, compiled once for each frame in each configuration its defines
// allow (shader functions are not inline: one copy per test source). The searches come
// with every frame, as in the shader: a ray's reads depend on RELIEF_EXACT_DISTANCE.
// Tangent, the flat tangent frame, is also the namespace's own: searches on straight rays.
inline namespace Tangent
{
namespace
{
#define RELIEF_MIRROR_FLAT_FRAME
#define RELIEF_MIRROR_FRAME "vtkReliefTangentFrame.glsl"
#include "ReliefCpuMirrorSources.h"
/// The impostor frame (straight rays), each view searched by ImpostorSearch.
ReliefHit (*ImpostorSearch)(ReliefRay ray, int linearSteps, int refinementSteps) = nullptr;
#define RELIEF_SEARCH ImpostorSearch
#define RELIEF_IMPOSTOR_VIEWS static_cast<int>(CurrentImpostor->Fields.size())
#define RELIEF_IMPOSTOR_PROJECTION(view) CurrentImpostor->Projections[static_cast<size_t>(view)]
#define RELIEF_IMPOSTOR_SELECT(view) SelectImpostorView(view)
#define RELIEF_IMPOSTOR_DEPTH_RATIO(view) CurrentImpostor->DepthRatios[static_cast<size_t>(view)]
#include "vtkReliefImpostorFrame.glsl"
#undef RELIEF_SEARCH
#undef RELIEF_IMPOSTOR_VIEWS
#undef RELIEF_IMPOSTOR_PROJECTION
#undef RELIEF_IMPOSTOR_SELECT
#undef RELIEF_IMPOSTOR_DEPTH_RATIO
}
}
/// The quadric frame, measuring depth along the normal (Eq. 7)
namespace Quadric
{
namespace
{
#define RELIEF_CURVED_FRAME
#define RELIEF_MIRROR_FRAME "vtkReliefQuadricFrame.glsl"
#include "ReliefCpuMirrorSources.h"
}
}
/// The quadric frame with its exact distance (Eq. 6), where it applies
namespace QuadricExact
{
namespace
{
#define RELIEF_EXACT_DISTANCE
#define RELIEF_MIRROR_FRAME "vtkReliefQuadricFrame.glsl"
#include "ReliefCpuMirrorSources.h"
#undef RELIEF_EXACT_DISTANCE
#undef RELIEF_CURVED_FRAME
}
}
/// The derivative frame on the face's own normal
namespace Derivative
{
namespace
{
#define RELIEF_MIRROR_FLAT_FRAME
#define RELIEF_MIRROR_FRAME "vtkReliefDerivativeFrame.glsl"
#include "ReliefCpuMirrorSources.h"
}
}
/// The derivative frame along interpolated vertex normals
namespace DerivativeNormals
{
namespace
{
#define RELIEF_VERTEX_NORMALS
#define RELIEF_MIRROR_FLAT_FRAME
#define RELIEF_MIRROR_FRAME "vtkReliefDerivativeFrame.glsl"
#include "ReliefCpuMirrorSources.h"
#undef RELIEF_VERTEX_NORMALS
}
}

/// A search as the shader calls it (RELIEF_SEARCH), on the flat frame's rays.
using Search = ReliefHit (*)(ReliefRay ray, int linearSteps, int refinementSteps);

/// The mirror's search of the GLSL function `function` (vtkReliefSearchMethod's
/// Function), or null when the mirror lacks it.
inline Search FindSearch(const std::string& function)
{
#define RELIEF_MIRROR_SEARCH(name) { #name, &name }
  static const std::map<std::string, Search> searches = {
    RELIEF_MIRROR_SEARCH(reliefSearchLinear),
    RELIEF_MIRROR_SEARCH(reliefSearchLinearBinary),
    RELIEF_MIRROR_SEARCH(reliefSearchSecant),
    RELIEF_MIRROR_SEARCH(reliefSearchExactDDA),
    RELIEF_MIRROR_SEARCH(reliefSearchSafetyRadius),
    RELIEF_MIRROR_SEARCH(reliefSearchConeStep),
    RELIEF_MIRROR_SEARCH(reliefSearchMaximumMipmap),
    RELIEF_MIRROR_SEARCH(reliefSearchAutomatic),
    RELIEF_MIRROR_SEARCH(reliefSearchAutomaticOverSlopes),
    RELIEF_MIRROR_SEARCH(reliefSearchAutomaticCurved),
    RELIEF_MIRROR_SEARCH(reliefSearchRobustBinary),
    RELIEF_MIRROR_SEARCH(reliefSearchSlopeMipmap),
  };
#undef RELIEF_MIRROR_SEARCH
  const auto found = searches.find(function);
  return found == searches.end() ? nullptr : found->second;
}
#undef RELIEF_DEPTH
#undef RELIEF_DEPTH_SIZE
#undef RELIEF_DEPTH_REPEATS
#undef RELIEF_CELL_DEPTHS
#undef RELIEF_PYRAMID_DEPTH
#undef RELIEF_PYRAMID_TOP
#undef RELIEF_SLOPE_NODE
#undef RELIEF_CONE_STEP
#undef RELIEF_SAFETY_RADIUS
#undef RELIEF_PATH_TEXEL
#undef RELIEF_PATH_CELL
}

#endif
