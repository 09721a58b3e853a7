#include "vtkReliefSearchMethod.h"

#include "vtkConeStepMapFilter.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkSafetyRadiusFilter.h"
#include "vtkShaderProgram.h"
#include "vtkSlopeMipmapFilter.h"

#include <cctype>
#include <iterator>

namespace
{
template <typename Filter>
vtkReliefAccelerationFilter* NewFilter()
{
  return Filter::New();
}

// SafetyRadiusTolerance, the error bound e of vtkSafetyRadiusFilter's radii.
void SetErrorTolerance(vtkReliefAccelerationFilter* filter, double tolerance)
{
  vtkSafetyRadiusFilter::SafeDownCast(filter)->SetErrorTolerance(tolerance);
}

// vtkConeStepMapFilter's ratio range, which EncodeCone's bytes are relative to.
void SetConeUniforms(vtkShaderProgram* program, const int reliefSize[2])
{
  const float range[2] = {
    static_cast<float>(vtkConeStepMapFilter::GetMaximumRatio(reliefSize[0], reliefSize[1])),
    static_cast<float>(vtkConeStepMapFilter::RATIO_OCTAVES) };
  program->SetUniform2f("reliefConeRange", range);
}

// Where each level of vtkMaximumMipmapFilter's atlas (vtkSlopeMipmapFilter's too) starts, and
// the top level.
void SetPyramidUniforms(vtkShaderProgram* program, const int reliefSize[2])
{
  constexpr int MaximumLevels = 32; // reliefPyramidRows' size in vtkReliefGridSearch.glsl
  float rows[MaximumLevels] = {};
  int origin[2];
  int size[2];
  int top = 0;
  while (top + 1 < MaximumLevels &&
    vtkMaximumMipmapFilter::GetLevelPlacement(reliefSize[0], reliefSize[1], top + 1, origin, size))
  {
    rows[++top] = static_cast<float>(origin[1]);
  }
  program->SetUniformi("reliefPyramidTop", top);
  program->SetUniform1fv("reliefPyramidRows", MaximumLevels, rows);
}

using Method = vtkReliefSearchMethod;
// One entry per method, in order of Id.
const vtkReliefSearchMethod Methods[] = {
  { vtkOpenGLReliefMapper::LINEAR, "Linear", "reliefSearchLinear", true, Method::NO_ACCELERATION,
    nullptr, nullptr, nullptr },
  { vtkOpenGLReliefMapper::LINEAR_BINARY, "LinearBinary", "reliefSearchLinearBinary", true,
    Method::NO_ACCELERATION, nullptr, nullptr, nullptr },
  { vtkOpenGLReliefMapper::SECANT, "Secant", "reliefSearchSecant", true, Method::NO_ACCELERATION,
    nullptr, nullptr, nullptr },
  { vtkOpenGLReliefMapper::EXACT_DDA, "ExactDDA", "reliefSearchExactDDA", false,
    Method::NO_ACCELERATION, nullptr, nullptr, nullptr },
  { vtkOpenGLReliefMapper::SAFETY_RADIUS, "SafetyRadius", "reliefSearchSafetyRadius", false,
    Method::FLOAT_TEXELS, &NewFilter<vtkSafetyRadiusFilter>, &SetErrorTolerance, nullptr },
  { vtkOpenGLReliefMapper::CONE_STEP, "ConeStep", "reliefSearchConeStep", false,
    Method::CONE_BYTES, &NewFilter<vtkConeStepMapFilter>, nullptr, &SetConeUniforms },
  { vtkOpenGLReliefMapper::MAXIMUM_MIPMAP, "MaximumMipmap", "reliefSearchMaximumMipmap", false,
    Method::FLOAT_TEXELS, &NewFilter<vtkMaximumMipmapFilter>, nullptr, &SetPyramidUniforms },
  { vtkOpenGLReliefMapper::AUTOMATIC, "Automatic", "reliefSearchAutomatic", false,
    Method::CONE_BYTES, &NewFilter<vtkConeStepMapFilter>, nullptr, &SetConeUniforms },
  { vtkOpenGLReliefMapper::ROBUST_BINARY, "RobustBinary", "reliefSearchRobustBinary", false,
    Method::FLOAT_TEXELS, &NewFilter<vtkSafetyRadiusFilter>, &SetErrorTolerance, nullptr },
  { vtkOpenGLReliefMapper::SLOPE_MIPMAP, "SlopeMipmap", "reliefSearchSlopeMipmap", false,
    Method::SLOPE_CODES, &NewFilter<vtkSlopeMipmapFilter>, nullptr, &SetPyramidUniforms },
};

// Automatic where rays curve: fixed steps sized to the screen tolerance, no cone map.
const vtkReliefSearchMethod AutomaticOnCurvedRays = { vtkOpenGLReliefMapper::AUTOMATIC,
  "Automatic", "reliefSearchAutomaticCurved", true, Method::NO_ACCELERATION, nullptr, nullptr,
  nullptr };

// Automatic whose long straight runs step over the slope pyramid: SlopeMipmap's image.
const vtkReliefSearchMethod AutomaticOverSlopes = { vtkOpenGLReliefMapper::AUTOMATIC,
  "Automatic", "reliefSearchAutomaticOverSlopes", false, Method::SLOPE_CODES,
  &NewFilter<vtkSlopeMipmapFilter>, nullptr, &SetPyramidUniforms };

std::string Squeezed(const std::string& name)
{
  std::string squeezed;
  for (char c : name)
  {
    if (c != '-')
    {
      squeezed += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
  }
  return squeezed;
}
}

const vtkReliefSearchMethod* vtkReliefSearchMethod::Get(int id)
{
  return id >= 0 && id < GetNumberOfMethods() ? &Methods[id] : nullptr;
}

const vtkReliefSearchMethod* vtkReliefSearchMethod::GetForCurvedRays(int id)
{
  if (id == vtkOpenGLReliefMapper::AUTOMATIC)
  {
    return &AutomaticOnCurvedRays;
  }
  const vtkReliefSearchMethod* method = Get(id);
  return method && method->FollowsCurvedRays ? method : nullptr;
}

const vtkReliefSearchMethod* vtkReliefSearchMethod::GetAutomatic(int acceleration)
{
  switch (acceleration)
  {
    case vtkOpenGLReliefMapper::CONE_STEP:
      return Get(vtkOpenGLReliefMapper::AUTOMATIC);
    case vtkOpenGLReliefMapper::SLOPE_MIPMAP:
      return &AutomaticOverSlopes;
    default:
      return nullptr;
  }
}

int vtkReliefSearchMethod::GetNumberOfMethods()
{
  return static_cast<int>(std::size(Methods));
}

const vtkReliefSearchMethod* vtkReliefSearchMethod::Find(const std::string& name)
{
  for (const vtkReliefSearchMethod& method : Methods)
  {
    if (Squeezed(method.Name) == Squeezed(name))
    {
      return &method;
    }
  }
  return nullptr;
}

int vtkReliefSearchMethod::GetAccelerationKind() const
{
  for (const vtkReliefSearchMethod& method : Methods)
  {
    if (method.NewAccelerationFilter == this->NewAccelerationFilter &&
      method.Encoding == this->Encoding)
    {
      return method.Id;
    }
  }
  return this->Id;
}

std::string vtkReliefSearchMethod::GetShaderDefine() const
{
  // the slope pyramid is read as integers (vtkReliefFragmentDec.glsl's sampler)
  return std::string("#define RELIEF_SEARCH ") + this->Function + "\n" +
    (this->Encoding == SLOPE_CODES ? "#define RELIEF_ACCELERATION_CODES\n" : "");
}
