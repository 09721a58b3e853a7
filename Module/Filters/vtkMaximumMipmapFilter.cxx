#include "vtkMaximumMipmapFilter.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkReliefDepthImage.h"

#include <algorithm>

vtkStandardNewMacro(vtkMaximumMipmapFilter);

vtkMaximumMipmapFilter::vtkMaximumMipmapFilter() = default;

int vtkMaximumMipmapFilter::GetLevelSize(int size, int level)
{
  return std::max(1, size >> level);
}

void vtkMaximumMipmapFilter::GetChildRange(int node, int size, int level, int& first, int& last)
{
  first = 2 * node;
  last = node == GetLevelSize(size, level) - 1 ? GetLevelSize(size, level - 1) - 1 : first + 1;
}

int vtkMaximumMipmapFilter::GetTopLevel(int width, int height)
{
  int top = 0;
  while ((width >> (top + 1)) > 0 || (height >> (top + 1)) > 0)
  {
    ++top;
  }
  return top;
}

bool vtkMaximumMipmapFilter::GetLevelPlacement(
  int width, int height, int level, int origin[2], int size[2])
{
  if (width < 1 || height < 1 || level < 0 || level > GetTopLevel(width, height))
  {
    return false;
  }
  size[0] = GetLevelSize(width, level);
  size[1] = GetLevelSize(height, level);
  origin[0] = level == 0 ? 0 : width;
  origin[1] = 0;
  for (int below = 1; below < level; ++below)
  {
    origin[1] += GetLevelSize(height, below);
  }
  return true;
}

void vtkMaximumMipmapFilter::GetAtlasSize(int width, int height, int size[2])
{
  const int top = GetTopLevel(width, height);
  size[0] = width + (top > 0 ? GetLevelSize(width, 1) : 0);
  int column = 0;
  for (int level = 1; level <= top; ++level)
  {
    column += GetLevelSize(height, level);
  }
  // a map one texel high still has levels (1 texel each) stacked in its column
  size[1] = std::max(height, column);
}

void vtkMaximumMipmapFilter::GetOutputSize(int width, int height, int size[2])
{
  GetAtlasSize(width, height, size);
}

void vtkMaximumMipmapFilter::Compute(const vtkReliefDepthImage& field, vtkFloatArray* output)
{
  const int width = field.Width;
  const int height = field.Height;
  int atlas[2];
  GetAtlasSize(width, height, atlas);
  // texels of the atlas outside every level: the deepest, so they never stop a ray
  output->FillValue(1.0f);
  float* values = output->GetPointer(0);
  auto at = [&](int x, int y) -> float& { return values[static_cast<size_t>(y) * atlas[0] + x]; };

  // level 0: the highest point of each cell is its highest corner
  this->ForRows(height, 1, 0.0, 0.8, [&](int begin, int end) {
    for (int j = begin; j < end; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        at(i, j) = std::min(std::min(field.At(i, j), field.At(i + 1, j)),
          std::min(field.At(i, j + 1), field.At(i + 1, j + 1)));
      }
    }
  });

  ReduceLevels(width, height, 1, values,
    [](float* node, const float* child, int) { *node = std::min(*node, *child); });
}

void vtkMaximumMipmapFilter::ReduceLevels(int width, int height, int components, float* values,
  const std::function<void(float* node, const float* child, int slot)>& combine,
  const std::function<void(float* node)>& finish)
{
  int atlas[2];
  GetAtlasSize(width, height, atlas);
  auto at = [&](const int origin[2], int x, int y) {
    return values + (static_cast<size_t>(origin[1] + y) * atlas[0] + origin[0] + x) * components;
  };
  const int top = GetTopLevel(width, height);
  for (int level = 1; level <= top; ++level)
  {
    int origin[2], size[2], childOrigin[2], childSize[2];
    GetLevelPlacement(width, height, level, origin, size);
    GetLevelPlacement(width, height, level - 1, childOrigin, childSize);
    for (int j = 0; j < size[1]; ++j)
    {
      int firstRow, lastRow;
      GetChildRange(j, height, level, firstRow, lastRow);
      for (int i = 0; i < size[0]; ++i)
      {
        int firstColumn, lastColumn;
        GetChildRange(i, width, level, firstColumn, lastColumn);
        float* node = at(origin, i, j);
        const float* first = at(childOrigin, firstColumn, firstRow);
        std::copy(first, first + components, node);
        for (int y = firstRow; y <= lastRow; ++y)
        {
          for (int x = firstColumn; x <= lastColumn; ++x)
          {
            combine(node, at(childOrigin, x, y),
              std::min(x - firstColumn, 1) + 2 * std::min(y - firstRow, 1));
          }
        }
        if (finish)
        {
          finish(node);
        }
      }
    }
  }
}

void vtkMaximumMipmapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
