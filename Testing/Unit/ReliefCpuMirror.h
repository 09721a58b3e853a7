// The CPU mirror of the relief shaders: the very GLSL files the mapper compiles,
// compiled here as C++ with GLM, reading heights through an exact bilinear sampler.
#ifndef ReliefCpuMirror_h
#define ReliefCpuMirror_h

#include <glm/glm.hpp>

#include <cmath>
#include <functional>
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

  float At(int i, int j) const
  {
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

/// The field the shader code reads; set it before calling a search.
inline const DepthField* CurrentField = nullptr;

inline float SampleCurrentField(vec2 uv)
{
  return CurrentField->Sample(uv);
}

#define RELIEF_DEPTH(uv) ReliefCpuMirror::SampleCurrentField(uv)
#include "vtkReliefCommon.glsl"
#include "vtkReliefSearch.glsl"
#undef RELIEF_DEPTH
}

#endif
