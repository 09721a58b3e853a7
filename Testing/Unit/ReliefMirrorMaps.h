// What the CPU mirror reads (ReliefCpuMirror.h), made by the very filters whose output
// the mapper uploads: the depth field, the maximum mipmap, the cone map and the safety
// radii. Shared by the unit tests and the GPU-against-CPU regression test.
#ifndef ReliefMirrorMaps_h
#define ReliefMirrorMaps_h

#include "ReliefCpuMirror.h"
#include "vtkConeStepMapFilter.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkSafetyRadiusFilter.h"
#include "vtkSlopeMipmapFilter.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <vector>

namespace ReliefCpuMirror
{
/// The depths of a relief texture (depth in the last of four components) or of a
/// one-component depth image, as the mapper uploads them.
inline DepthField FieldOf(vtkImageData* image)
{
  DepthField field;
  field.Width = image->GetDimensions()[0];
  field.Height = image->GetDimensions()[1];
  vtkDataArray* texels = image->GetPointData()->GetScalars();
  const int depth = texels->GetNumberOfComponents() - 1;
  for (vtkIdType k = 0; k < texels->GetNumberOfTuples(); ++k)
  {
    field.Depths.push_back(static_cast<float>(texels->GetComponent(k, depth)));
  }
  return field;
}

/// A one-component depth image of the field, the input the acceleration filters take.
inline vtkSmartPointer<vtkImageData> DepthImage(const DepthField& field)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(field.Width, field.Height, 1);
  vtkNew<vtkFloatArray> depths;
  depths->SetNumberOfTuples(static_cast<vtkIdType>(field.Depths.size()));
  std::copy(field.Depths.begin(), field.Depths.end(), depths->GetPointer(0));
  image->GetPointData()->SetScalars(depths);
  return image;
}

/// The output of an acceleration filter run on the field.
inline vtkSmartPointer<vtkImageData> Accelerate(vtkReliefAccelerationFilter* filter, const DepthField& field)
{
  filter->SetInputData(DepthImage(field));
  filter->Update();
  return filter->GetOutput();
}

/// A pyramid filter's atlas, level by level; `Texel` makes a node's value from its
/// components.
template <typename Value, typename Texel>
NodePyramid<Value> PyramidFromAtlas(
  vtkReliefAccelerationFilter* filter, const DepthField& field, Texel texel)
{
  vtkImageData* atlas = Accelerate(filter, field);
  const int atlasWidth = atlas->GetDimensions()[0];
  const int components = filter->GetOutputComponents();
  const float* values =
    vtkFloatArray::SafeDownCast(atlas->GetPointData()->GetScalars())->GetPointer(0);
  NodePyramid<Value> pyramid;
  int origin[2];
  int size[2];
  for (int level = 0;
       vtkMaximumMipmapFilter::GetLevelPlacement(field.Width, field.Height, level, origin, size);
       ++level)
  {
    pyramid.Widths.push_back(size[0]);
    pyramid.Heights.push_back(size[1]);
    std::vector<Value> nodes;
    for (int j = 0; j < size[1]; ++j)
    {
      for (int i = 0; i < size[0]; ++i)
      {
        nodes.push_back(texel(values +
          (static_cast<size_t>(origin[1] + j) * atlasWidth + origin[0] + i) * components));
      }
    }
    pyramid.Levels.push_back(nodes);
  }
  return pyramid;
}

/// vtkMaximumMipmapFilter's pyramid of the field.
inline DepthPyramid PyramidOf(const DepthField& field)
{
  vtkNew<vtkMaximumMipmapFilter> filter;
  return PyramidFromAtlas<float>(filter, field, [](const float* texel) { return *texel; });
}

/// vtkSlopeMipmapFilter's pyramid of the field, its slope bounds packed as uploaded.
inline SlopePyramid SlopesOf(const DepthField& field)
{
  vtkNew<vtkSlopeMipmapFilter> filter;
  return PyramidFromAtlas<uvec4>(filter, field, [](const float* node) {
    const double values[8] = { node[0], node[1], node[2], node[3], node[4], node[5], node[6],
      node[7] };
    unsigned int texel[4];
    vtkSlopeMipmapFilter::PackNode(values, texel);
    return uvec4(texel[0], texel[1], texel[2], texel[3]);
  });
}

/// A per-cell map from an acceleration filter's output of the field's size.
template <typename Value>
CellMap<Value> CellMapOf(vtkImageData* image)
{
  static_assert(sizeof(Value) % sizeof(float) == 0, "a cell's value is whole floats");
  CellMap<Value> map;
  map.Width = image->GetDimensions()[0];
  map.Height = image->GetDimensions()[1];
  const float* values =
    vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars())->GetPointer(0);
  const size_t cells = static_cast<size_t>(map.Width) * map.Height;
  map.Values.resize(cells);
  std::copy(values, values + cells * sizeof(Value) / sizeof(float),
    reinterpret_cast<float*>(map.Values.data()));
  return map;
}

/// vtkConeStepMapFilter's (top, ratio) per cell of the field as the shader reads them:
/// uploaded in two bytes a cell (EncodeCone) and decoded by reliefConeDecode().
inline ConeStepMap ConeMapOf(const DepthField& field)
{
  vtkNew<vtkConeStepMapFilter> filter;
  ConeStepMap cones = CellMapOf<vec2>(Accelerate(filter, field));
  const double maximumRatio = vtkConeStepMapFilter::GetMaximumRatio(field.Width, field.Height);
  const vec2 range(static_cast<float>(maximumRatio),
    static_cast<float>(vtkConeStepMapFilter::RATIO_OCTAVES));
  for (vec2& cone : cones.Values)
  {
    unsigned char code[2];
    vtkConeStepMapFilter::EncodeCone(cone.x, cone.y, maximumRatio, code);
    cone = reliefConeDecode(vec2(code[0] / 255.0f, code[1] / 255.0f), range);
  }
  return cones;
}

/// vtkSafetyRadiusFilter's radius per cell of the field, at error tolerance e.
inline SafetyRadiusMap RadiiOf(const DepthField& field, double tolerance, int maximum = 32)
{
  vtkNew<vtkSafetyRadiusFilter> filter;
  filter->SetErrorTolerance(tolerance);
  filter->SetMaximumRadius(maximum);
  return CellMapOf<float>(Accelerate(filter, field));
}
}

#endif
