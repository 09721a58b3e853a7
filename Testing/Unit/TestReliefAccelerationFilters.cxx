// What every acceleration filter (vtkReliefAccelerationFilter) promises, checked once
// for each: it reads relief textures and depth images alike, refuses unusable input with
// one error naming the problem and an empty output, recovers on the next good input, and
// reports progress in order from the calling thread.
#include "ReliefEventRecorder.h"
#include "ReliefSearchReference.h"
#include "vtkConeStepMapFilter.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkSafetyRadiusFilter.h"
#include "vtkSlopeMipmapFilter.h"

#include "vtkCommand.h"
#include "vtkInformation.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <thread>

namespace
{
using namespace ReliefCpuMirror;

template <typename Filter>
class ReliefAccelerationFilter : public ::testing::Test
{
};
using Filters = ::testing::Types<vtkMaximumMipmapFilter, vtkSlopeMipmapFilter,
  vtkSafetyRadiusFilter, vtkConeStepMapFilter>;
TYPED_TEST_SUITE(ReliefAccelerationFilter, Filters);

vtkSmartPointer<vtkImageData> UniformImage(int x, int y, int z, int components)
{
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetDimensions(x, y, z);
  vtkNew<vtkFloatArray> scalars;
  scalars->SetNumberOfComponents(components);
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(x) * y * z);
  scalars->FillValue(0.5f);
  data->GetPointData()->SetScalars(scalars);
  return data;
}

// The same depths as vtkReliefTextureFilter lays them out: normal first, depth last.
vtkSmartPointer<vtkImageData> ReliefTexture(const DepthField& field)
{
  auto texture = vtkSmartPointer<vtkImageData>::New();
  texture->SetDimensions(field.Width, field.Height, 1);
  vtkNew<vtkFloatArray> texels;
  texels->SetNumberOfComponents(4);
  texels->SetNumberOfTuples(static_cast<vtkIdType>(field.Depths.size()));
  for (size_t k = 0; k < field.Depths.size(); ++k)
  {
    texels->SetTuple4(static_cast<vtkIdType>(k), 0.0, 0.0, 1.0, field.Depths[k]);
  }
  texture->GetPointData()->SetScalars(texels);
  return texture;
}

class ThreadRecorder : public vtkCommand
{
public:
  static ThreadRecorder* New() { return new ThreadRecorder; }
  void Execute(vtkObject*, unsigned long, void* callData) override
  {
    this->Threads.push_back(std::this_thread::get_id());
    this->Progress.push_back(*static_cast<double*>(callData));
  }
  std::vector<std::thread::id> Threads;
  std::vector<double> Progress;
};
}

TYPED_TEST(ReliefAccelerationFilter, ReliefTexturesGiveWhatTheirDepthsGive)
{
  const DepthField field = RandomField(19, 11, 7, 0.0f, 1.0f);
  vtkNew<TypeParam> fromDepths;
  fromDepths->SetInputData(DepthImage(field));
  fromDepths->Update();
  vtkNew<TypeParam> fromTexture;
  fromTexture->SetInputData(ReliefTexture(field));
  fromTexture->Update();
  vtkDataArray* expected = fromDepths->GetOutput()->GetPointData()->GetScalars();
  vtkDataArray* actual = fromTexture->GetOutput()->GetPointData()->GetScalars();
  ASSERT_NE(expected, nullptr);
  ASSERT_NE(actual, nullptr);
  EXPECT_EQ(actual->GetDataType(), VTK_FLOAT);
  ASSERT_EQ(actual->GetNumberOfValues(), expected->GetNumberOfValues());
  for (vtkIdType k = 0; k < actual->GetNumberOfValues(); ++k)
  {
    ASSERT_EQ(actual->GetVariantValue(k), expected->GetVariantValue(k)) << k;
  }
  // the pipeline knows the output's size and type before it runs
  vtkNew<TypeParam> informed;
  informed->SetInputData(DepthImage(field));
  informed->UpdateInformation();
  int extent[6];
  informed->GetOutputInformation(0)->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  int dimensions[3];
  fromDepths->GetOutput()->GetDimensions(dimensions);
  EXPECT_EQ(extent[1] + 1, dimensions[0]);
  EXPECT_EQ(extent[3] + 1, dimensions[1]);
}

TYPED_TEST(ReliefAccelerationFilter, BadInputGivesOneErrorAndAnEmptyOutputThenRecovers)
{
  const struct
  {
    vtkSmartPointer<vtkImageData> Input;
    const char* Reason;
  } cases[] = { { UniformImage(8, 8, 3, 1), "3D" }, { UniformImage(8, 8, 1, 2), "2 components" },
    { vtkSmartPointer<vtkImageData>::New(), "no point scalars" } };
  vtkNew<TypeParam> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::ErrorEvent, recorder);
  for (const auto& bad : cases)
  {
    recorder->Clear();
    filter->SetInputData(bad.Input);
    filter->Update();
    EXPECT_EQ(recorder->Count(vtkCommand::ErrorEvent), 1) << bad.Reason;
    EXPECT_TRUE(recorder->AnyMessageContains(bad.Reason)) << bad.Reason;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << bad.Reason;
  }
  recorder->Clear();
  filter->SetInputData(UniformImage(8, 8, 1, 1));
  filter->Update();
  EXPECT_EQ(recorder->Count(vtkCommand::ErrorEvent), 0);
  EXPECT_GE(filter->GetOutput()->GetNumberOfPoints(), 64);
}

TYPED_TEST(ReliefAccelerationFilter, ProgressComesFromTheCallingThreadInOrder)
{
  vtkNew<TypeParam> filter;
  vtkNew<ThreadRecorder> recorder;
  filter->AddObserver(vtkCommand::ProgressEvent, recorder);
  filter->SetInputData(DepthImage(RandomField(64, 64, 5, 0.0f, 1.0f)));
  filter->Update();
  ASSERT_GE(recorder->Progress.size(), 3u);
  EXPECT_EQ(recorder->Progress.front(), 0.0);
  EXPECT_EQ(recorder->Progress.back(), 1.0);
  for (size_t k = 0; k < recorder->Progress.size(); ++k)
  {
    EXPECT_EQ(recorder->Threads[k], std::this_thread::get_id());
    if (k > 0)
    {
      EXPECT_GE(recorder->Progress[k], recorder->Progress[k - 1]);
    }
  }
}
