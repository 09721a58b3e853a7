#include "vtkReliefAccelerationFilter.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkReliefDepthImage.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <string>

void vtkReliefAccelerationFilter::GetOutputSize(int width, int height, int size[2])
{
  size[0] = width;
  size[1] = height;
}

void vtkReliefAccelerationFilter::ForRows(int rows, int slices, double fromProgress,
  double toProgress, const std::function<void(int begin, int end)>& work)
{
  slices = std::max(1, std::min(slices, rows));
  for (int slice = 0; slice < slices && !this->GetAbortExecute(); ++slice)
  {
    vtkSMPTools::For(rows * slice / slices, rows * (slice + 1) / slices,
      [&](vtkIdType begin, vtkIdType end) { work(static_cast<int>(begin), static_cast<int>(end)); });
    this->UpdateProgress(fromProgress + (toProgress - fromProgress) * (slice + 1) / slices);
  }
}

int vtkReliefAccelerationFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int extent[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  int size[2];
  this->GetOutputSize(extent[1] - extent[0] + 1, extent[3] - extent[2] + 1, size);
  const int outExtent[6] = { 0, size[0] - 1, 0, size[1] - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), outExtent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, this->GetOutputComponents());
  return 1;
}

int vtkReliefAccelerationFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
    inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
  return 1;
}

int vtkReliefAccelerationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  this->UpdateProgress(0.0);
  vtkReliefDepthImage field;
  std::string error;
  if (!field.Read(input, error))
  {
    vtkErrorMacro("Cannot build " << this->GetProductName() << ": " << error << ".");
    output->Initialize();
    return 1;
  }
  int size[2];
  this->GetOutputSize(field.Width, field.Height, size);
  output->SetDimensions(size[0], size[1], 1);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->SetSpacing(input->GetSpacing());
  vtkNew<vtkFloatArray> values;
  values->SetName(this->GetOutputName());
  values->SetNumberOfComponents(this->GetOutputComponents());
  values->SetNumberOfTuples(static_cast<vtkIdType>(size[0]) * size[1]);
  this->Compute(field, values);
  output->GetPointData()->SetScalars(values);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkReliefAccelerationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
