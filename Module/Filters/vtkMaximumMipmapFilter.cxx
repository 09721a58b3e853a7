#include "vtkMaximumMipmapFilter.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkReliefDepthImage.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>

vtkStandardNewMacro(vtkMaximumMipmapFilter);

namespace
{
int LevelSize(int size, int level)
{
  return std::max(1, size >> level);
}

// Children of node `node` at the level below, in one axis: [first, last].
void ChildRange(int node, int size, int level, int& first, int& last)
{
  first = 2 * node;
  last = node == LevelSize(size, level) - 1 ? LevelSize(size, level - 1) - 1 : first + 1;
}
}

vtkMaximumMipmapFilter::vtkMaximumMipmapFilter() = default;

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
  size[0] = LevelSize(width, level);
  size[1] = LevelSize(height, level);
  origin[0] = level == 0 ? 0 : width;
  origin[1] = 0;
  for (int below = 1; below < level; ++below)
  {
    origin[1] += LevelSize(height, below);
  }
  return true;
}

void vtkMaximumMipmapFilter::GetAtlasSize(int width, int height, int size[2])
{
  const int top = GetTopLevel(width, height);
  size[0] = width + (top > 0 ? LevelSize(width, 1) : 0);
  int column = 0;
  for (int level = 1; level <= top; ++level)
  {
    column += LevelSize(height, level);
  }
  // a map one texel high still has levels (1 texel each) stacked in its column
  size[1] = std::max(height, column);
}

int vtkMaximumMipmapFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  int atlas[2];
  GetAtlasSize(extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, atlas);
  const int outExtent[6] = { 0, atlas[0] - 1, 0, atlas[1] - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), outExtent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 1);
  return 1;
}

int vtkMaximumMipmapFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // every level depends on the whole map, whatever part of the atlas is asked for
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  return 1;
}

int vtkMaximumMipmapFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  this->UpdateProgress(0.0);
  vtkReliefDepthImage field;
  std::string error;
  if (!field.Read(input, error))
  {
    vtkErrorMacro("Cannot build a maximum mipmap: " << error << ".");
    output->Initialize();
    return 1;
  }
  const int width = field.Width;
  const int height = field.Height;
  int atlas[2];
  GetAtlasSize(width, height, atlas);
  output->SetDimensions(atlas[0], atlas[1], 1);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->SetSpacing(input->GetSpacing());
  vtkNew<vtkFloatArray> minimumDepth;
  minimumDepth->SetName("MinimumDepth");
  minimumDepth->SetNumberOfTuples(static_cast<vtkIdType>(atlas[0]) * atlas[1]);
  // texels of the atlas outside every level: the deepest, so they never stop a ray
  minimumDepth->FillValue(1.0f);
  float* values = minimumDepth->GetPointer(0);
  auto at = [&](int x, int y) -> float& { return values[static_cast<size_t>(y) * atlas[0] + x]; };

  // level 0: the highest point of each cell is its highest corner
  vtkSMPTools::For(0, height, [&](vtkIdType begin, vtkIdType end) {
    for (int j = static_cast<int>(begin); j < end; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        at(i, j) = std::min(std::min(field.At(i, j), field.At(i + 1, j)),
          std::min(field.At(i, j + 1), field.At(i + 1, j + 1)));
      }
    }
  });
  this->UpdateProgress(0.8);

  const int top = GetTopLevel(width, height);
  for (int level = 1; level <= top; ++level)
  {
    int origin[2], size[2], childOrigin[2], childSize[2];
    GetLevelPlacement(width, height, level, origin, size);
    GetLevelPlacement(width, height, level - 1, childOrigin, childSize);
    for (int j = 0; j < size[1]; ++j)
    {
      int firstRow, lastRow;
      ChildRange(j, height, level, firstRow, lastRow);
      for (int i = 0; i < size[0]; ++i)
      {
        int firstColumn, lastColumn;
        ChildRange(i, width, level, firstColumn, lastColumn);
        float least = 1.0f;
        for (int y = firstRow; y <= lastRow; ++y)
        {
          for (int x = firstColumn; x <= lastColumn; ++x)
          {
            least = std::min(least, at(childOrigin[0] + x, childOrigin[1] + y));
          }
        }
        at(origin[0] + i, origin[1] + j) = least;
      }
    }
  }
  output->GetPointData()->SetScalars(minimumDepth);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkMaximumMipmapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
