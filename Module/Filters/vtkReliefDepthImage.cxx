#include "vtkReliefDepthImage.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>
#include <sstream>

bool vtkReliefDepthImage::Read(vtkImageData* image, std::string& error)
{
  std::ostringstream reason;
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  int dimensions[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dimensions);
  }
  if (!scalars || dimensions[0] < 1 || dimensions[1] < 1)
  {
    reason << "the input has no point scalars; connect vtkReliefTextureFilter's output or a "
              "one-component depth image";
  }
  else if (dimensions[2] != 1)
  {
    reason << "the input is 3D (" << dimensions[2] << " slices); extract one slice first";
  }
  else if (scalars->GetNumberOfComponents() != 1 && scalars->GetNumberOfComponents() != 4)
  {
    reason << "the input scalars have " << scalars->GetNumberOfComponents()
           << " components; expected vtkReliefTextureFilter's 4 (depth last) or 1 (depth)";
  }
  error = reason.str();
  if (!error.empty())
  {
    return false;
  }
  this->Width = dimensions[0];
  this->Height = dimensions[1];
  const int component = scalars->GetNumberOfComponents() - 1;
  const vtkIdType count = scalars->GetNumberOfTuples();
  this->Depths.resize(static_cast<size_t>(count));
  for (vtkIdType index = 0; index < count; ++index)
  {
    const double depth = scalars->GetComponent(index, component);
    this->Depths[static_cast<size_t>(index)] =
      std::isfinite(depth) ? static_cast<float>(std::min(std::max(depth, 0.0), 1.0)) : 1.0f;
  }
  return true;
}

double vtkReliefDepthImage::Interpolate(double u, double v) const
{
  const double x = u * this->Width - 0.5;
  const double y = v * this->Height - 0.5;
  const double i = std::floor(x);
  const double j = std::floor(y);
  const double fx = x - i;
  const double fy = y - j;
  const int i0 = static_cast<int>(i);
  const int j0 = static_cast<int>(j);
  const double bottom = (1.0 - fx) * this->At(i0, j0) + fx * this->At(i0 + 1, j0);
  const double top = (1.0 - fx) * this->At(i0, j0 + 1) + fx * this->At(i0 + 1, j0 + 1);
  return (1.0 - fy) * bottom + fy * top;
}
