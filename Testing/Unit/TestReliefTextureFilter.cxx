// vtkReliefTextureFilter against analytic depths and normals: ramps, wrap at
// the border, conventions, components, precision and bad inputs.

#include "ReliefEventRecorder.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkReliefTextureFilter.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <string>

namespace
{
using Value = std::function<double(int i, int j, int c)>;

// A width x height image of `vtkType` whose component c at column i, row j
// (row 0 at the bottom) is value(i, j, c).
vtkSmartPointer<vtkImageData> MakeImage(
  int width, int height, int components, int vtkType, const Value& value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  auto scalars = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(vtkType));
  scalars->SetNumberOfComponents(components);
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      for (int c = 0; c < components; ++c)
      {
        scalars->SetComponent(static_cast<vtkIdType>(j) * width + i, c, value(i, j, c));
      }
    }
  }
  image->GetPointData()->SetScalars(scalars);
  return image;
}

vtkImageData* RunFilter(vtkReliefTextureFilter* filter, vtkImageData* input)
{
  filter->SetInputData(input);
  filter->Update();
  return filter->GetOutput();
}

std::array<double, 4> Texel(vtkImageData* relief, int i, int j)
{
  std::array<double, 4> texel{};
  int extent[6];
  relief->GetExtent(extent);
  for (int c = 0; c < 4; ++c)
  {
    texel[c] = relief->GetScalarComponentAsDouble(extent[0] + i, extent[2] + j, extent[4], c);
  }
  return texel;
}

// A depth as the filter stores it: on the grid of the 16-bit depth texture.
double OnGrid(double depth)
{
  return std::round(depth * vtkReliefTextureFilter::DEPTH_LEVELS) /
    vtkReliefTextureFilter::DEPTH_LEVELS;
}

// The normal of the surface (i, j, -r * depth) for depth slopes ddx, ddy.
std::array<double, 3> ExpectedNormal(double r, double ddx, double ddy)
{
  const double length = std::sqrt(r * ddx * r * ddx + r * ddy * r * ddy + 1.0);
  return { r * ddx / length, r * ddy / length, 1.0 / length };
}

void ExpectNormal(const std::array<double, 4>& texel, const std::array<double, 3>& expected,
  double tolerance = 1e-6)
{
  EXPECT_NEAR(texel[0], expected[0], tolerance);
  EXPECT_NEAR(texel[1], expected[1], tolerance);
  EXPECT_NEAR(texel[2], expected[2], tolerance);
}

void ExpectEmpty(vtkImageData* output)
{
  EXPECT_EQ(output->GetNumberOfPoints(), 0);
  EXPECT_EQ(output->GetPointData()->GetScalars(), nullptr);
}
}

TEST(ReliefTextureFilter, OutputKeepsGeometryAndHasFourFloatComponentsNamedRelief)
{
  auto input = MakeImage(6, 4, 1, VTK_UNSIGNED_CHAR, [](int i, int j, int) { return i * j; });
  input->SetExtent(10, 15, 5, 8, 2, 2);
  input->SetSpacing(0.5, 2.0, 3.0);
  input->SetOrigin(1.0, -2.0, 3.5);
  vtkNew<vtkReliefTextureFilter> filter;
  filter->SetInputData(input);
  filter->UpdateInformation();
  vtkInformation* scalarInfo = vtkDataObject::GetActiveFieldInformation(
    filter->GetOutputInformation(0), vtkDataObject::FIELD_ASSOCIATION_POINTS,
    vtkDataSetAttributes::SCALARS);
  ASSERT_NE(scalarInfo, nullptr);
  EXPECT_EQ(scalarInfo->Get(vtkDataObject::FIELD_ARRAY_TYPE()), VTK_FLOAT);
  EXPECT_EQ(scalarInfo->Get(vtkDataObject::FIELD_NUMBER_OF_COMPONENTS()), 4);

  vtkImageData* output = RunFilter(filter, input);
  int inExtent[6], outExtent[6];
  input->GetExtent(inExtent);
  output->GetExtent(outExtent);
  for (int k = 0; k < 6; ++k)
  {
    EXPECT_EQ(outExtent[k], inExtent[k]);
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    EXPECT_EQ(output->GetSpacing()[axis], input->GetSpacing()[axis]);
    EXPECT_EQ(output->GetOrigin()[axis], input->GetOrigin()[axis]);
  }
  vtkDataArray* relief = output->GetPointData()->GetScalars();
  ASSERT_NE(relief, nullptr);
  EXPECT_STREQ(relief->GetName(), "Relief");
  EXPECT_EQ(relief->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(relief->GetNumberOfComponents(), 4);
  EXPECT_EQ(relief->GetNumberOfTuples(), 24);
  // Texel (5, 3) holds the largest value, 15: depth 1 - 15/255.
  EXPECT_NEAR(Texel(output, 5, 3)[3], 1.0 - 15.0 / 255.0, 1e-7);
}

TEST(ReliefTextureFilter, RampAlongXGivesAnalyticDepthAndPeriodicNormals)
{
  // Heights 0..7 along x: depth d(i) = 1 - i/7, slope -1/7 inside; at the
  // border the neighbour wraps to the other edge.
  const int width = 8;
  auto input =
    MakeImage(width, 3, 1, VTK_FLOAT, [](int i, int, int) { return static_cast<double>(i); });
  for (double r : { 1.0, 4.0 })
  {
    SCOPED_TRACE("DepthToTexelRatio " + std::to_string(r));
    vtkNew<vtkReliefTextureFilter> filter;
    filter->SetDepthToTexelRatio(r);
    vtkImageData* output = RunFilter(filter, input);
    ASSERT_EQ(output->GetNumberOfPoints(), 24);
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        const auto texel = Texel(output, i, j);
        auto depth = [&](int k) { return OnGrid(1.0 - ((k + width) % width) / 7.0); };
        EXPECT_NEAR(texel[3], depth(i), 1e-7) << "i " << i;
        // inside the ramp -1/7 (up to the grid), at the borders +3/7
        const double ddx = 0.5 * (depth(i + 1) - depth(i - 1));
        EXPECT_NEAR(ddx, (i == 0 || i == width - 1) ? 3.0 / 7.0 : -1.0 / 7.0, 1.0 / 65535.0);
        ExpectNormal(texel, ExpectedNormal(r, ddx, 0.0));
      }
    }
    // Depth grows toward -x inside the ramp, so the normal leans to -x.
    EXPECT_LT(Texel(output, 3, 1)[0], 0.0);
    EXPECT_GT(Texel(output, 0, 1)[0], 0.0);
  }
}

TEST(ReliefTextureFilter, RampAlongYStartsAtTheBottomRow)
{
  // 8-bit heights 0, 50, ..., 200 from the bottom row up.
  auto input = MakeImage(3, 5, 1, VTK_UNSIGNED_CHAR, [](int, int j, int) { return 50.0 * j; });
  vtkNew<vtkReliefTextureFilter> filter;
  vtkImageData* output = RunFilter(filter, input);
  const double step = 50.0 / 255.0;
  for (int j = 0; j < 5; ++j)
  {
    const auto texel = Texel(output, 1, j);
    EXPECT_NEAR(texel[3], 1.0 - j * step, 1e-7) << "row " << j;
    // Inside: slope -step per row. Rows 0 and 4 wrap: (d(1) - d(4)) / 2 and
    // (d(0) - d(3)) / 2, both +1.5 step.
    const double ddy = (j == 0 || j == 4) ? 1.5 * step : -step;
    ExpectNormal(texel, ExpectedNormal(1.0, 0.0, ddy));
  }
}

TEST(ReliefTextureFilter, DepthToTexelRatioRejectsNonPositiveValues)
{
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<ReliefEventRecorder> warnings;
  filter->AddObserver(vtkCommand::WarningEvent, warnings);
  EXPECT_EQ(filter->GetDepthToTexelRatio(), 1.0);
  filter->SetDepthToTexelRatio(2.5);
  EXPECT_EQ(filter->GetDepthToTexelRatio(), 2.5);
  EXPECT_EQ(warnings->Count(vtkCommand::WarningEvent), 0);
  for (double bad : { 0.0, -3.0, std::numeric_limits<double>::quiet_NaN() })
  {
    filter->SetDepthToTexelRatio(bad);
    EXPECT_GT(filter->GetDepthToTexelRatio(), 0.0);
    EXPECT_LT(filter->GetDepthToTexelRatio(), 1e-3);
  }
  EXPECT_EQ(warnings->Count(vtkCommand::WarningEvent), 3);
}

TEST(ReliefTextureFilter, InputConventions)
{
  auto input = MakeImage(4, 1, 1, VTK_UNSIGNED_CHAR, [](int i, int, int) { return 85.0 * i; });
  vtkNew<vtkReliefTextureFilter> filter;
  EXPECT_EQ(filter->GetInputConvention(), vtkReliefTextureFilter::HEIGHT);
  EXPECT_STREQ(filter->GetInputConventionAsString(), "Height");
  vtkImageData* output = RunFilter(filter, input);
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(Texel(output, i, 0)[3], 1.0 - i / 3.0, 1e-7);
  }

  filter->SetInputConventionToDepth();
  EXPECT_EQ(filter->GetInputConvention(), vtkReliefTextureFilter::DEPTH);
  EXPECT_STREQ(filter->GetInputConventionAsString(), "Depth");
  output = RunFilter(filter, input);
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_NEAR(Texel(output, i, 0)[3], i / 3.0, 1e-7);
  }

  filter->SetInputConventionToHeight();
  EXPECT_EQ(filter->GetInputConvention(), vtkReliefTextureFilter::HEIGHT);
}

TEST(ReliefTextureFilter, IntegerTypesAreNormalizedByTheirTypeRange)
{
  vtkNew<vtkReliefTextureFilter> filter;
  filter->SetInputConventionToDepth();

  // Only dark values: the depth stays small, it is not stretched to [0, 1].
  auto dark = MakeImage(3, 1, 1, VTK_UNSIGNED_CHAR, [](int i, int, int) { return 10.0 * i; });
  vtkImageData* output = RunFilter(filter, dark);
  EXPECT_NEAR(Texel(output, 0, 0)[3], 0.0, 1e-7);
  EXPECT_NEAR(Texel(output, 2, 0)[3], 20.0 / 255.0, 1e-7);

  auto signedBytes = MakeImage(
    3, 1, 1, VTK_SIGNED_CHAR, [](int i, int, int) { return i == 0 ? -128.0 : i == 1 ? 0.0 : 127.0; });
  output = RunFilter(filter, signedBytes);
  EXPECT_NEAR(Texel(output, 0, 0)[3], 0.0, 1e-7);
  EXPECT_NEAR(Texel(output, 1, 0)[3], 128.0 / 255.0, 1e-7);
  EXPECT_NEAR(Texel(output, 2, 0)[3], 1.0, 1e-7);

  auto shorts = MakeImage(
    2, 1, 1, VTK_SHORT, [](int i, int, int) { return i == 0 ? -32768.0 : 0.0; });
  output = RunFilter(filter, shorts);
  EXPECT_NEAR(Texel(output, 0, 0)[3], 0.0, 1e-7);
  EXPECT_NEAR(Texel(output, 1, 0)[3], 32768.0 / 65535.0, 1e-7);
}

TEST(ReliefTextureFilter, SixteenBitInputKeepsAdjacentLevelsApart)
{
  auto input = MakeImage(
    2, 1, 1, VTK_UNSIGNED_SHORT, [](int i, int, int) { return 30000.0 + i; });
  vtkNew<vtkReliefTextureFilter> filter;
  vtkImageData* output = RunFilter(filter, input);
  const double low = Texel(output, 0, 0)[3];
  const double high = Texel(output, 1, 0)[3];
  EXPECT_NEAR(low, 1.0 - 30000.0 / 65535.0, 1e-7);
  EXPECT_NE(low, high);
  // The higher level is less deep by one 16-bit step.
  EXPECT_NEAR(low - high, 1.0 / 65535.0, 1e-7);
}

TEST(ReliefTextureFilter, FloatInputIsNormalizedByItsRange)
{
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    SCOPED_TRACE(type == VTK_FLOAT ? "float" : "double");
    auto input = MakeImage(5, 1, 1, type, [](int i, int, int) { return -3.0 + 2.0 * i; });
    vtkNew<vtkReliefTextureFilter> filter;
    vtkImageData* output = RunFilter(filter, input);
    for (int i = 0; i < 5; ++i)
    {
      EXPECT_NEAR(Texel(output, i, 0)[3], OnGrid(1.0 - i / 4.0), 1e-7);
    }
  }
}

TEST(ReliefTextureFilter, FloatDepthsLieOnTheSixteenBitGrid)
{
  // what the mapper's 16-bit depth texture holds exactly: k / 65535, the nearest level
  auto input = MakeImage(
    16, 16, 1, VTK_DOUBLE, [](int i, int j, int) { return std::sin(0.7 * i) * std::cos(1.3 * j); });
  vtkNew<vtkReliefTextureFilter> filter;
  vtkImageData* output = RunFilter(filter, input);
  const double* range = input->GetPointData()->GetScalars()->GetRange();
  for (int j = 0; j < 16; ++j)
  {
    for (int i = 0; i < 16; ++i)
    {
      const double depth = Texel(output, i, j)[3];
      const double level = depth * vtkReliefTextureFilter::DEPTH_LEVELS;
      EXPECT_NEAR(level, std::round(level), 0.01) << i << ", " << j; // float: 4e-3 a level
      const double exact =
        1.0 - (input->GetScalarComponentAsDouble(i, j, 0, 0) - range[0]) / (range[1] - range[0]);
      EXPECT_NEAR(depth, exact, 0.5 / vtkReliefTextureFilter::DEPTH_LEVELS + 1e-7);
    }
  }
}

TEST(ReliefTextureFilter, ConstantImageIsFlatAtTheSurface)
{
  auto input = MakeImage(3, 3, 1, VTK_FLOAT, [](int, int, int) { return 42.0; });
  for (bool depthConvention : { false, true })
  {
    vtkNew<vtkReliefTextureFilter> filter;
    if (depthConvention)
    {
      filter->SetInputConventionToDepth();
    }
    vtkImageData* output = RunFilter(filter, input);
    ASSERT_EQ(output->GetNumberOfPoints(), 9);
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        const auto texel = Texel(output, i, j);
        EXPECT_EQ(texel[3], 0.0);
        ExpectNormal(texel, { 0.0, 0.0, 1.0 }, 0.0);
      }
    }
  }
}

TEST(ReliefTextureFilter, AutomaticComponentIsAlphaOfRgbaAndFirstOtherwise)
{
  // Component c of every texel holds 50 * (c + 1) + i.
  auto value = [](int i, int, int c) { return 50.0 * (c + 1) + i; };
  vtkNew<vtkReliefTextureFilter> filter;
  filter->SetInputConventionToDepth();
  EXPECT_EQ(filter->GetComponent(), -1);
  for (int components = 1; components <= 4; ++components)
  {
    SCOPED_TRACE("components " + std::to_string(components));
    auto input = MakeImage(2, 1, components, VTK_UNSIGNED_CHAR, value);
    const int expected = components == 4 ? 3 : 0;
    EXPECT_NEAR(Texel(RunFilter(filter, input), 1, 0)[3], value(1, 0, expected) / 255.0, 1e-7);
  }

  auto rgba = MakeImage(2, 1, 4, VTK_UNSIGNED_CHAR, value);
  filter->SetComponent(1);
  EXPECT_EQ(filter->GetComponent(), 1);
  EXPECT_NEAR(Texel(RunFilter(filter, rgba), 1, 0)[3], value(1, 0, 1) / 255.0, 1e-7);
}

TEST(ReliefTextureFilter, ComponentOutOfRangeGivesErrorAndEmptyOutputThenRecovers)
{
  auto input = MakeImage(2, 2, 2, VTK_UNSIGNED_CHAR, [](int i, int, int) { return i; });
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<ReliefEventRecorder> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  filter->SetComponent(2);
  ExpectEmpty(RunFilter(filter, input));
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(errors->AnyMessageContains("SetComponent"));

  errors->Clear();
  filter->SetComponent(1);
  EXPECT_EQ(RunFilter(filter, input)->GetNumberOfPoints(), 4);
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 0);
}

TEST(ReliefTextureFilter, UseInputNormalsDecodesIntegerNormals)
{
  // Texel 0: +x (255, 128, 128); texel 1: +z (128, 128, 255); texel 2:
  // (0, 0, 0), which decodes to (-1, -1, -1).
  const double rgb[3][3] = { { 255, 128, 128 }, { 128, 128, 255 }, { 0, 0, 0 } };
  auto input = MakeImage(3, 1, 4, VTK_UNSIGNED_CHAR,
    [&](int i, int, int c) { return c < 3 ? rgb[i][c] : 100.0 * i; });
  vtkNew<vtkReliefTextureFilter> filter;
  EXPECT_FALSE(filter->GetUseInputNormals());
  filter->UseInputNormalsOn();
  EXPECT_TRUE(filter->GetUseInputNormals());
  vtkImageData* output = RunFilter(filter, input);
  for (int i = 0; i < 3; ++i)
  {
    double n[3];
    for (int c = 0; c < 3; ++c)
    {
      n[c] = 2.0 * rgb[i][c] / 255.0 - 1.0;
    }
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const auto texel = Texel(output, i, 0);
    ExpectNormal(texel, { n[0] / length, n[1] / length, n[2] / length });
    // The height still comes from alpha.
    EXPECT_NEAR(texel[3], 1.0 - 100.0 * i / 255.0, 1e-7);
  }

  // Off again: normals computed from the alpha ramp, no longer +x.
  filter->UseInputNormalsOff();
  EXPECT_LT(Texel(RunFilter(filter, input), 1, 0)[2], 0.99);
}

TEST(ReliefTextureFilter, UseInputNormalsTakesFloatNormalsAsTheyAreAndFixesZero)
{
  const double rgb[3][3] = { { 0.6, 0.0, 0.8 }, { 3.0, 0.0, -4.0 }, { 0.0, 0.0, 0.0 } };
  auto input = MakeImage(3, 1, 3, VTK_FLOAT, [&](int i, int, int c) { return rgb[i][c]; });
  vtkNew<vtkReliefTextureFilter> filter;
  filter->UseInputNormalsOn();
  vtkImageData* output = RunFilter(filter, input);
  ExpectNormal(Texel(output, 0, 0), { 0.6, 0.0, 0.8 });
  ExpectNormal(Texel(output, 1, 0), { 0.6, 0.0, -0.8 });
  ExpectNormal(Texel(output, 2, 0), { 0.0, 0.0, 1.0 });
}

TEST(ReliefTextureFilter, UseInputNormalsWithoutRgbWarnsAndComputesNormals)
{
  auto input =
    MakeImage(4, 1, 2, VTK_FLOAT, [](int i, int, int c) { return c == 0 ? i : 7.0; });
  vtkNew<vtkReliefTextureFilter> reference;
  vtkImageData* expected = RunFilter(reference, input);

  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<ReliefEventRecorder> warnings;
  filter->AddObserver(vtkCommand::WarningEvent, warnings);
  filter->UseInputNormalsOn();
  vtkImageData* output = RunFilter(filter, input);
  EXPECT_EQ(warnings->Count(vtkCommand::WarningEvent), 1);
  EXPECT_TRUE(warnings->AnyMessageContains("UseInputNormals"));
  for (int i = 0; i < 4; ++i)
  {
    EXPECT_EQ(Texel(output, i, 0), Texel(expected, i, 0)) << "texel " << i;
  }
  EXPECT_GT(Texel(output, 0, 0)[0], 0.1) << "the ramp must tilt the computed normal";
}

TEST(ReliefTextureFilter, NonFiniteHeightsAreReplacedWithOneWarning)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  // Finite heights 2..4; +Inf, -Inf and NaN in the first row.
  const double heights[2][3] = { { inf, -inf, nan }, { 2.0, 3.0, 4.0 } };
  auto input = MakeImage(3, 2, 1, VTK_FLOAT, [&](int i, int j, int) { return heights[j][i]; });
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<ReliefEventRecorder> warnings;
  filter->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkImageData* output = RunFilter(filter, input);
  EXPECT_EQ(warnings->Count(vtkCommand::WarningEvent), 1);
  EXPECT_TRUE(warnings->AnyMessageContains("Replaced 3 "));

  ASSERT_EQ(output->GetNumberOfPoints(), 6);
  vtkFloatArray* relief = vtkFloatArray::SafeDownCast(output->GetPointData()->GetScalars());
  ASSERT_NE(relief, nullptr);
  for (vtkIdType k = 0; k < relief->GetNumberOfValues(); ++k)
  {
    EXPECT_TRUE(std::isfinite(relief->GetValue(k))) << "value " << k;
  }
  EXPECT_EQ(Texel(output, 0, 0)[3], 0.0) << "+Inf is the highest level";
  EXPECT_EQ(Texel(output, 1, 0)[3], 1.0) << "-Inf is the lowest level";
  EXPECT_EQ(Texel(output, 2, 0)[3], 1.0) << "NaN is the lowest level";
  EXPECT_NEAR(Texel(output, 1, 1)[3], OnGrid(0.5), 1e-7) << "finite heights keep their range";
}

TEST(ReliefTextureFilter, ThreeDimensionalInputGivesErrorAndEmptyOutputThenRecovers)
{
  auto volume = vtkSmartPointer<vtkImageData>::New();
  volume->SetDimensions(4, 4, 2);
  volume->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<ReliefEventRecorder> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);
  ExpectEmpty(RunFilter(filter, volume));
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(errors->AnyMessageContains("not 2D"));

  errors->Clear();
  auto slice = MakeImage(4, 4, 1, VTK_UNSIGNED_CHAR, [](int i, int, int) { return i; });
  EXPECT_EQ(RunFilter(filter, slice)->GetNumberOfPoints(), 16);
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 0);
}

TEST(ReliefTextureFilter, EmptyInputsGiveErrorAndEmptyOutput)
{
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<ReliefEventRecorder> errors;
  filter->AddObserver(vtkCommand::ErrorEvent, errors);

  vtkNew<vtkImageData> noPoints;
  ExpectEmpty(RunFilter(filter, noPoints));
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 1);

  vtkNew<vtkImageData> noScalars;
  noScalars->SetDimensions(3, 3, 1);
  ExpectEmpty(RunFilter(filter, noScalars));
  EXPECT_EQ(errors->Count(vtkCommand::ErrorEvent), 2);
  EXPECT_TRUE(errors->AnyMessageContains("no point scalars"));
}

TEST(ReliefTextureFilter, ReportsProgressFromStartToEndAndBetweenOnLargeImages)
{
  for (int size : { 8, 1024 })
  {
    SCOPED_TRACE("size " + std::to_string(size));
    auto input = MakeImage(size, size, 1, VTK_UNSIGNED_SHORT, [](int i, int j, int) {
      return (i * 31 + j * 17) % 65536;
    });
    vtkNew<vtkReliefTextureFilter> filter;
    vtkNew<ReliefEventRecorder> progress;
    filter->AddObserver(vtkCommand::ProgressEvent, progress);
    RunFilter(filter, input);
    ASSERT_GE(progress->Progress.size(), 2u);
    EXPECT_EQ(progress->Progress.front(), 0.0);
    EXPECT_EQ(progress->Progress.back(), 1.0);
    if (size >= 1024)
    {
      EXPECT_GE(progress->Progress.size(), 10u) << "a large image reports progress as it goes";
    }
  }
}

TEST(ReliefTextureFilter, PrintSelfListsEveryProperty)
{
  vtkNew<vtkReliefTextureFilter> filter;
  filter->SetInputConventionToDepth();
  filter->SetComponent(2);
  filter->SetDepthToTexelRatio(8.0);
  filter->UseInputNormalsOn();
  std::ostringstream printed;
  filter->Print(printed);
  const std::string text = printed.str();
  EXPECT_NE(text.find("InputConvention: Depth"), std::string::npos) << text;
  EXPECT_NE(text.find("Component: 2"), std::string::npos) << text;
  EXPECT_NE(text.find("DepthToTexelRatio: 8"), std::string::npos) << text;
  EXPECT_NE(text.find("UseInputNormals: On"), std::string::npos) << text;
}
