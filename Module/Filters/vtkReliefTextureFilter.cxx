#include "vtkReliefTextureFilter.h"

#include "vtkArrayDispatch.h"
#include "vtkDataArrayRange.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <limits>

vtkStandardNewMacro(vtkReliefTextureFilter);

namespace
{
constexpr double MinimumDepthToTexelRatio = 1e-6;
constexpr double MaximumDepthToTexelRatio = 1e6;

// Images at least this large run each pass in slices, reporting progress
// between them; smaller ones finish too fast for progress to matter.
constexpr vtkIdType SlicedProgressTexels = vtkIdType(1) << 20;
constexpr int ProgressSlices = 10;

bool IsFloatingType(int vtkType)
{
  return vtkType == VTK_FLOAT || vtkType == VTK_DOUBLE;
}

// Runs body(begin, end) over [0, count) with vtkSMPTools and moves the
// progress from `from` to `to`. Progress is reported between slices, never
// from inside the parallel loop, where observers would run on worker threads.
template <typename Body>
void ForWithProgress(
  vtkAlgorithm* self, vtkIdType count, vtkIdType texelsPerItem, double from, double to, Body& body)
{
  const int slices = count * texelsPerItem >= SlicedProgressTexels ? ProgressSlices : 1;
  for (int slice = 0; slice < slices; ++slice)
  {
    vtkSMPTools::For(count * slice / slices, count * (slice + 1) / slices, body);
    self->UpdateProgress(from + (to - from) * (slice + 1) / slices);
  }
}

// Writes the unit vector along (x, y, z) as the first three components of a
// texel; a vector without a direction becomes the flat normal (0, 0, 1).
void StoreNormal(float* texel, double x, double y, double z)
{
  const double length = std::hypot(x, y, z);
  if (!(length > 0.0) || !std::isfinite(length))
  {
    texel[0] = 0.0f;
    texel[1] = 0.0f;
    texel[2] = 1.0f;
    return;
  }
  texel[0] = static_cast<float>(x / length);
  texel[1] = static_cast<float>(y / length);
  texel[2] = static_cast<float>(z / length);
}

// Range of the finite values of one component, and how many are not finite.
template <typename ArrayT>
struct FiniteRange
{
  ArrayT* Array;
  int Component;
  vtkSMPThreadLocal<double> LocalMin;
  vtkSMPThreadLocal<double> LocalMax;
  vtkSMPThreadLocal<vtkIdType> LocalNonFinite;
  double Min = std::numeric_limits<double>::infinity();
  double Max = -std::numeric_limits<double>::infinity();
  vtkIdType NonFinite = 0;

  FiniteRange(ArrayT* array, int component)
    : Array(array)
    , Component(component)
  {
  }

  void Initialize()
  {
    this->LocalMin.Local() = std::numeric_limits<double>::infinity();
    this->LocalMax.Local() = -std::numeric_limits<double>::infinity();
    this->LocalNonFinite.Local() = 0;
  }

  void operator()(vtkIdType begin, vtkIdType end)
  {
    double& low = this->LocalMin.Local();
    double& high = this->LocalMax.Local();
    vtkIdType& nonFinite = this->LocalNonFinite.Local();
    for (const auto tuple : vtk::DataArrayTupleRange(this->Array, begin, end))
    {
      const double value = static_cast<double>(tuple[this->Component]);
      if (std::isfinite(value))
      {
        low = std::min(low, value);
        high = std::max(high, value);
      }
      else
      {
        ++nonFinite;
      }
    }
  }

  void Reduce()
  {
    for (double value : this->LocalMin)
    {
      this->Min = std::min(this->Min, value);
    }
    for (double value : this->LocalMax)
    {
      this->Max = std::max(this->Max, value);
    }
    for (vtkIdType count : this->LocalNonFinite)
    {
      this->NonFinite += count;
    }
  }
};

// Fills the depth (fourth component) of every texel from one input component.
struct DepthWorker
{
  template <typename ArrayT>
  void operator()(ArrayT* heights, int component, int convention, vtkFloatArray* relief,
    vtkAlgorithm* self, vtkIdType& nonFinite)
  {
    const vtkIdType count = heights->GetNumberOfTuples();
    const int type = heights->GetDataType();

    // Normalized level t = (value - low) * scale, in [0, 1]. Integer types
    // use their whole type range so that absolute levels are kept.
    double low = vtkDataArray::GetDataTypeMin(type);
    double high = vtkDataArray::GetDataTypeMax(type);
    nonFinite = 0;
    if (IsFloatingType(type))
    {
      FiniteRange<ArrayT> range(heights, component);
      vtkSMPTools::For(0, count, range);
      nonFinite = range.NonFinite;
      // With no finite value at all every texel is replaced by one level.
      low = range.NonFinite == count ? 0.0 : range.Min;
      high = range.NonFinite == count ? 0.0 : range.Max;
      self->UpdateProgress(0.2);
    }
    const bool flat = !(high > low);
    const double scale = flat ? 0.0 : 1.0 / (high - low);
    const bool heightConvention = convention == vtkReliefTextureFilter::HEIGHT;

    float* texels = relief->GetPointer(0);
    auto depths = [&](vtkIdType begin, vtkIdType end) {
      float* texel = texels + 4 * begin;
      for (const auto tuple : vtk::DataArrayTupleRange(heights, begin, end))
      {
        double value = static_cast<double>(tuple[component]);
        if (!std::isfinite(value))
        {
          value = value > 0.0 ? high : low;
        }
        // A flat image is all surface, whatever the convention.
        double depth = 0.0;
        if (!flat)
        {
          const double level = std::min(1.0, std::max(0.0, (value - low) * scale));
          depth = heightConvention ? 1.0 - level : level;
        }
        // on the grid of the mapper's 16-bit depth texture, which then holds it exactly
        texel[3] = static_cast<float>(
          std::round(depth * vtkReliefTextureFilter::DEPTH_LEVELS) /
          vtkReliefTextureFilter::DEPTH_LEVELS);
        texel += 4;
      }
    };
    ForWithProgress(self, count, 1, 0.2, 0.5, depths);
  }
};

// Fills the normal of every texel from the input's first three components.
struct InputNormalWorker
{
  template <typename ArrayT>
  void operator()(ArrayT* normals, vtkFloatArray* relief, vtkAlgorithm* self)
  {
    const int type = normals->GetDataType();
    const bool floating = IsFloatingType(type);
    const bool isSigned = vtkDataArray::GetDataTypeMin(type) < 0.0;
    const double typeMax = vtkDataArray::GetDataTypeMax(type);
    auto decode = [&](double value) {
      if (floating)
      {
        return value;
      }
      // Unsigned: [0, max] -> [-1, 1] as in 8-bit normal maps; signed: the
      // signed normalized convention of GL (SNORM).
      return isSigned ? std::max(-1.0, value / typeMax) : 2.0 * value / typeMax - 1.0;
    };

    float* texels = relief->GetPointer(0);
    auto store = [&](vtkIdType begin, vtkIdType end) {
      float* texel = texels + 4 * begin;
      for (const auto tuple : vtk::DataArrayTupleRange(normals, begin, end))
      {
        StoreNormal(texel, decode(static_cast<double>(tuple[0])),
          decode(static_cast<double>(tuple[1])), decode(static_cast<double>(tuple[2])));
        texel += 4;
      }
    };
    ForWithProgress(self, normals->GetNumberOfTuples(), 1, 0.5, 1.0, store);
  }
};

// Normals of the surface (i, j, -ratio * depth) by periodic central
// differences: the texture repeats, so the edges see the opposite edges.
void ComputeNormals(
  vtkFloatArray* relief, vtkIdType width, vtkIdType height, double ratio, vtkAlgorithm* self)
{
  float* texels = relief->GetPointer(0);
  auto depth = [&](vtkIdType i, vtkIdType j) {
    return static_cast<double>(texels[4 * (j * width + i) + 3]);
  };
  auto rows = [&](vtkIdType rowBegin, vtkIdType rowEnd) {
    for (vtkIdType j = rowBegin; j < rowEnd; ++j)
    {
      const vtkIdType below = j == 0 ? height - 1 : j - 1;
      const vtkIdType above = j == height - 1 ? 0 : j + 1;
      for (vtkIdType i = 0; i < width; ++i)
      {
        const vtkIdType left = i == 0 ? width - 1 : i - 1;
        const vtkIdType right = i == width - 1 ? 0 : i + 1;
        const double ddx = 0.5 * (depth(right, j) - depth(left, j));
        const double ddy = 0.5 * (depth(i, above) - depth(i, below));
        StoreNormal(texels + 4 * (j * width + i), ratio * ddx, ratio * ddy, 1.0);
      }
    }
  };
  ForWithProgress(self, height, width, 0.5, 1.0, rows);
}
}

//------------------------------------------------------------------------------
vtkReliefTextureFilter::vtkReliefTextureFilter() = default;

//------------------------------------------------------------------------------
const char* vtkReliefTextureFilter::GetInputConventionAsString()
{
  return this->InputConvention == DEPTH ? "Depth" : "Height";
}

//------------------------------------------------------------------------------
void vtkReliefTextureFilter::SetDepthToTexelRatio(double ratio)
{
  double accepted = ratio;
  if (!(ratio >= MinimumDepthToTexelRatio) || ratio > MaximumDepthToTexelRatio)
  {
    accepted = ratio > MaximumDepthToTexelRatio ? MaximumDepthToTexelRatio
                                                : MinimumDepthToTexelRatio;
    vtkWarningMacro("DepthToTexelRatio " << ratio << " is outside [" << MinimumDepthToTexelRatio
                                         << ", " << MaximumDepthToTexelRatio << "]; using "
                                         << accepted
                                         << ". Give the number of texels a depth of 1 spans.");
  }
  if (this->DepthToTexelRatio != accepted)
  {
    this->DepthToTexelRatio = accepted;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkReliefTextureFilter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkDataObject::SetPointDataActiveScalarInfo(
    outputVector->GetInformationObject(0), VTK_FLOAT, 4);
  return 1;
}

//------------------------------------------------------------------------------
int vtkReliefTextureFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Normalization and the periodic differences need the whole image.
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  return 1;
}

//------------------------------------------------------------------------------
int vtkReliefTextureFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  output->Initialize();
  this->UpdateProgress(0.0);

  if (!input || input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro("The input image is empty: connect a 2D height image (for example from "
                  "vtkOpenImageIOReader) and check that it updates without error.");
    return 1;
  }
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  if (!scalars || scalars->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkErrorMacro("The input image has no point scalars: make the height the active point "
                  "scalars (GetPointData()->SetScalars(), or vtkAssignAttribute).");
    return 1;
  }
  int dimensions[3];
  input->GetDimensions(dimensions);
  if (dimensions[2] > 1)
  {
    vtkErrorMacro("The input is not 2D (dimensions " << dimensions[0] << " x " << dimensions[1]
                                                     << " x " << dimensions[2]
                                                     << "): extract one slice first, for "
                                                        "example with vtkExtractVOI.");
    return 1;
  }
  const int components = scalars->GetNumberOfComponents();
  const int component = this->Component >= 0 ? this->Component : (components == 4 ? 3 : 0);
  if (component >= components)
  {
    vtkErrorMacro("Component " << component << " does not exist: the input scalars have "
                               << components << " component(s). Call SetComponent() with 0 to "
                               << components - 1 << ", or -1 to choose automatically.");
    return 1;
  }
  const bool inputNormals = this->UseInputNormals && components >= 3;
  if (this->UseInputNormals && !inputNormals)
  {
    vtkWarningMacro("UseInputNormals is on but the input has "
      << components
      << " component(s), not 3 or more: computing the normals from the depth instead. "
         "Turn UseInputNormals off, or give an RGB(A) normal map.");
  }

  const vtkIdType count = scalars->GetNumberOfTuples();
  vtkNew<vtkFloatArray> relief;
  relief->SetName("Relief");
  relief->SetNumberOfComponents(4);
  relief->SetNumberOfTuples(count);

  DepthWorker depthWorker;
  vtkIdType nonFinite = 0;
  if (!vtkArrayDispatch::Dispatch::Execute(
        scalars, depthWorker, component, this->InputConvention, relief.Get(), this, nonFinite))
  {
    depthWorker(scalars, component, this->InputConvention, relief.Get(), this, nonFinite);
  }
  if (nonFinite > 0)
  {
    vtkWarningMacro("Replaced " << nonFinite
                                << " non-finite height(s): +Inf by the highest level, -Inf "
                                   "and NaN by the lowest. Clean the height map to avoid this.");
  }

  if (inputNormals)
  {
    InputNormalWorker normalWorker;
    if (!vtkArrayDispatch::Dispatch::Execute(scalars, normalWorker, relief.Get(), this))
    {
      normalWorker(scalars, relief.Get(), this);
    }
  }
  else
  {
    ComputeNormals(relief, dimensions[0], dimensions[1], this->DepthToTexelRatio, this);
  }

  output->CopyStructure(input);
  output->GetPointData()->SetScalars(relief);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkReliefTextureFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InputConvention: " << this->GetInputConventionAsString() << "\n";
  os << indent << "Component: " << this->Component << "\n";
  os << indent << "DepthToTexelRatio: " << this->DepthToTexelRatio << "\n";
  os << indent << "UseInputNormals: " << (this->UseInputNormals ? "On" : "Off") << "\n";
}
