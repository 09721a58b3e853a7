// vtkReliefDisplacementFilter: the relief as real geometry, on meshes and depth images
// whose displaced surfaces are known.
#include "ReliefEventRecorder.h"
#include "vtkReliefDisplacementFilter.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTexturedSphereSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace
{
// The unit square [0, 1]^2 in the xy plane, two triangles, texture coordinates = (x, y),
// normals +z.
vtkSmartPointer<vtkPolyData> UnitSquare()
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetPoint1(1.0, 0.0, 0.0);
  plane->SetPoint2(0.0, 1.0, 0.0);
  plane->Update();
  return plane->GetOutput();
}

// A depth image, depth(i, j) at texel (i, j) in every component (a component count of 4
// lays it out as vtkReliefTextureFilter does: a +z normal first, the depth last).
vtkSmartPointer<vtkImageData> DepthImage(
  int width, int height, const std::function<double(int, int)>& depth, int components = 1)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(components);
  values->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      for (int c = 0; c < components; ++c)
      {
        const bool normal = components == 4 && c < 3;
        values->SetComponent(static_cast<vtkIdType>(j) * width + i, c,
          normal ? (c == 2 ? 1.0 : 0.0) : depth(i, j));
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

vtkPolyData* Displace(vtkReliefDisplacementFilter* filter, vtkPolyData* mesh, vtkImageData* relief)
{
  filter->SetInputData(mesh);
  filter->SetReliefData(relief);
  filter->Update();
  return filter->GetOutput();
}

// Displaces `mesh` by `relief` with a new filter, expecting exactly one error that
// mentions `text`; the output (owned by `filter`).
vtkPolyData* DisplaceWithOneError(vtkReliefDisplacementFilter* filter, vtkPolyData* mesh,
  vtkImageData* relief, const std::string& text)
{
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::ErrorEvent, recorder);
  vtkPolyData* output = Displace(filter, mesh, relief);
  EXPECT_EQ(recorder->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(recorder->AnyMessageContains(text)) << "no error mentions " << text;
  return output;
}

double LongestEdgeInTexels(vtkPolyData* mesh, int width, int height)
{
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  double longest = 0.0;
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    mesh->GetCellPoints(cell, size, ids);
    for (vtkIdType corner = 0; corner < size; ++corner)
    {
      const vtkIdType a = ids[corner];
      const vtkIdType b = ids[(corner + 1) % size];
      longest = std::max(longest,
        std::hypot((tcoords->GetComponent(b, 0) - tcoords->GetComponent(a, 0)) * width,
          (tcoords->GetComponent(b, 1) - tcoords->GetComponent(a, 1)) * height));
    }
  }
  return longest;
}
}

TEST(ReliefDisplacementFilter, SubdividesUntilEveryEdgeSpansAtMostTheAskedTexels)
{
  vtkNew<vtkReliefDisplacementFilter> filter;
  filter->SetMaximumEdgeTexels(0.5);
  vtkPolyData* mesh =
    Displace(filter, UnitSquare(), DepthImage(8, 8, [](int, int) { return 0.0; }));
  // the diagonal spans 8 sqrt(2) texels: 5 halvings bring it under 0.5, 4 do not
  EXPECT_EQ(filter->GetSubdivisionLevels(), 5);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 2 << 10);
  EXPECT_LE(LongestEdgeInTexels(mesh, 8, 8), 0.5);
  EXPECT_DOUBLE_EQ(filter->GetLongestEdgeTexels(), LongestEdgeInTexels(mesh, 8, 8));
}

TEST(ReliefDisplacementFilter, PointsSinkByTheBilinearDepthBetweenTexelCentres)
{
  // depth rises linearly across the texel centres along x: the bilinear field is
  // depth = u between the first and last centres, and wraps between them
  const int width = 16;
  vtkNew<vtkReliefDisplacementFilter> filter;
  filter->SetDepthScale(0.1);
  filter->SetMaximumEdgeTexels(1.0);
  vtkPolyData* mesh = Displace(filter, UnitSquare(),
    DepthImage(width, 4, [&](int i, int) { return (i + 0.5) / width; }));
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  int inside = 0;
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    const double u = tcoords->GetComponent(id, 0);
    double point[3];
    mesh->GetPoint(id, point);
    if (u >= 0.5 / width && u <= 1.0 - 0.5 / width)
    {
      EXPECT_NEAR(point[2], -0.1 * u, 1e-6) << "at u = " << u;
      ++inside;
    }
    else
    {
      // between the last centre and the first, wrapped round: the two blend, so the edge
      // (u = 0 or 1, half-way between them) is at their mean depth 0.5
      const double edgeDistance = std::min(u, 1.0 - u) * width; // texels from the edge
      const double first = 0.5 / width;
      const double last = 1.0 - 0.5 / width;
      const double weightOfFirst = u < 0.5 ? 0.5 + edgeDistance : 0.5 - edgeDistance;
      EXPECT_NEAR(point[2], -0.1 * (weightOfFirst * first + (1.0 - weightOfFirst) * last), 1e-6)
        << "at u = " << u;
    }
    EXPECT_NEAR(point[0], u, 1e-6) << "points move along the normal only";
  }
  EXPECT_GT(inside, 100);
}

TEST(ReliefDisplacementFilter, TexelCentresAlongVOfANonSquareImage)
{
  // 4 x 16 texels, depth rising along v only: depth = v between the first and last rows'
  // centres, whatever u
  vtkNew<vtkReliefDisplacementFilter> filter;
  filter->SetDepthScale(0.1);
  filter->SetMaximumEdgeTexels(1.0);
  vtkPolyData* mesh =
    Displace(filter, UnitSquare(), DepthImage(4, 16, [](int, int j) { return (j + 0.5) / 16; }));
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  int inside = 0;
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    const double v = tcoords->GetComponent(id, 1);
    if (v >= 0.5 / 16 && v <= 1.0 - 0.5 / 16)
    {
      double point[3];
      mesh->GetPoint(id, point);
      EXPECT_NEAR(point[2], -0.1 * v, 1e-6) << "at v = " << v;
      ++inside;
    }
  }
  EXPECT_GT(inside, 100);
}

TEST(ReliefDisplacementFilter, LeavesItsInputUntouchedAndRepeatsItself)
{
  // fine enough already: no subdivision, the case where points could be shared
  auto square = UnitSquare();
  double before[3];
  square->GetPoint(0, before);
  vtkNew<vtkReliefDisplacementFilter> filter;
  filter->SetMaximumEdgeTexels(100.0);
  filter->SetDepthScale(0.1);
  auto relief = DepthImage(4, 4, [](int, int) { return 1.0; });
  Displace(filter, square, relief);
  ASSERT_EQ(filter->GetSubdivisionLevels(), 0);
  double after[3];
  square->GetPoint(0, after);
  EXPECT_EQ(after[2], before[2]);
  filter->SetDepthScale(0.2);
  vtkPolyData* mesh = Displace(filter, square, relief);
  double moved[3];
  mesh->GetPoint(0, moved);
  EXPECT_NEAR(moved[2], before[2] - 0.2, 1e-7);
  square->GetPoint(0, after);
  EXPECT_EQ(after[2], before[2]);
}

TEST(ReliefDisplacementFilter, MeshWithoutPolygonsIsAnErrorAndPassesThrough)
{
  auto square = UnitSquare();
  auto lines = vtkSmartPointer<vtkPolyData>::New();
  lines->SetPoints(square->GetPoints());
  lines->GetPointData()->ShallowCopy(square->GetPointData());
  vtkNew<vtkCellArray> line;
  const vtkIdType ids[2] = { 0, 1 };
  line->InsertNextCell(2, ids);
  lines->SetLines(line);
  vtkNew<vtkReliefDisplacementFilter> filter;
  vtkPolyData* mesh = DisplaceWithOneError(
    filter, lines, DepthImage(4, 4, [](int, int) { return 1.0; }), "no polygons");
  EXPECT_EQ(mesh->GetNumberOfLines(), 1);
}

TEST(ReliefDisplacementFilter, NormalsAreThoseOfTheDisplacedSurface)
{
  const int width = 16;
  vtkNew<vtkReliefDisplacementFilter> filter;
  filter->SetDepthScale(0.2);
  vtkPolyData* mesh = Displace(filter, UnitSquare(),
    DepthImage(width, 4, [&](int i, int) { return (i + 0.5) / width; }));
  // inside the ramp the surface is z = -0.2 x: unit normal (0.2, 0, 1) / |.|
  const double length = std::hypot(0.2, 1.0);
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  ASSERT_NE(normals, nullptr);
  int checked = 0;
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    const double u = tcoords->GetComponent(id, 0);
    const double v = tcoords->GetComponent(id, 1);
    if (u > 1.0 / width && u < 1.0 - 1.0 / width && v > 0.0 && v < 1.0)
    {
      EXPECT_NEAR(normals->GetComponent(id, 0), 0.2 / length, 1e-4);
      EXPECT_NEAR(normals->GetComponent(id, 1), 0.0, 1e-4);
      EXPECT_NEAR(normals->GetComponent(id, 2), 1.0 / length, 1e-4);
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(ReliefDisplacementFilter, ReadsTheReliefTexturesDepthComponent)
{
  // vtkReliefTextureFilter's layout: normal in the first three components, depth last
  vtkNew<vtkReliefDisplacementFilter> filter;
  filter->SetDepthScale(0.1);
  vtkPolyData* mesh = Displace(filter, UnitSquare(),
    DepthImage(4, 4, [](int, int) { return 0.25; }, 4));
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    double point[3];
    mesh->GetPoint(id, point);
    ASSERT_NEAR(point[2], -0.025, 1e-7);
  }
}

TEST(ReliefDisplacementFilter, CurvedMeshesSinkAlongTheirInterpolatedNormals)
{
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  sphere->Update();
  vtkNew<vtkReliefDisplacementFilter> filter;
  filter->SetDepthScale(0.25);
  filter->SetMaximumEdgeTexels(0.1);
  vtkPolyData* mesh =
    Displace(filter, sphere->GetOutput(), DepthImage(8, 8, [](int, int) { return 1.0; }));
  // subdivided points lie on the flat facets, at most the facets' sag inside the sphere,
  // and every one moves a full 0.25 inward
  const double sag = 1.0 - std::cos(vtkMath::Pi() / 8.0);
  ASSERT_GT(filter->GetSubdivisionLevels(), 0);
  for (vtkIdType id = 0; id < mesh->GetNumberOfPoints(); ++id)
  {
    double point[3];
    mesh->GetPoint(id, point);
    const double radius =
      std::sqrt(point[0] * point[0] + point[1] * point[1] + point[2] * point[2]);
    ASSERT_LE(radius, 0.75 + 1e-6);
    ASSERT_GE(radius, 0.75 - sag - 1e-6);
  }
}

TEST(ReliefDisplacementFilter, CapsTheTriangleCountWithAWarning)
{
  vtkNew<vtkReliefDisplacementFilter> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::WarningEvent, recorder);
  filter->SetMaximumNumberOfTriangles(2 << 6);
  vtkPolyData* mesh =
    Displace(filter, UnitSquare(), DepthImage(256, 256, [](int, int) { return 0.5; }));
  EXPECT_EQ(filter->GetSubdivisionLevels(), 3);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 2 << 6);
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 1);
  EXPECT_TRUE(recorder->AnyMessageContains("MaximumNumberOfTriangles"));
}

TEST(ReliefDisplacementFilter, MeshWithoutTextureCoordinatesIsAnErrorAndPassesThrough)
{
  auto square = UnitSquare();
  square->GetPointData()->SetTCoords(nullptr);
  vtkNew<vtkReliefDisplacementFilter> filter;
  vtkPolyData* mesh = DisplaceWithOneError(
    filter, square, DepthImage(4, 4, [](int, int) { return 1.0; }), "vtkTextureMapToPlane");
  EXPECT_EQ(mesh->GetNumberOfPoints(), square->GetNumberOfPoints());
  EXPECT_EQ(mesh->GetNumberOfPolys(), square->GetNumberOfPolys());
}

TEST(ReliefDisplacementFilter, ReliefWithoutDepthsIsAnErrorAndPassesTheMeshThrough)
{
  auto square = UnitSquare();
  vtkNew<vtkReliefDisplacementFilter> filter;
  vtkPolyData* mesh = DisplaceWithOneError(
    filter, square, DepthImage(4, 4, [](int, int) { return 1.0; }, 3), "vtkReliefTextureFilter");
  EXPECT_EQ(mesh->GetNumberOfPoints(), square->GetNumberOfPoints());
}

TEST(ReliefDisplacementFilter, SettersRefuseWhatIsNotALength)
{
  vtkNew<vtkReliefDisplacementFilter> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::WarningEvent, recorder);
  filter->SetDepthScale(0.2);
  for (double depthScale : { std::nan(""), std::numeric_limits<double>::infinity() })
  {
    filter->SetDepthScale(depthScale);
    EXPECT_EQ(filter->GetDepthScale(), 0.2) << depthScale;
  }
  filter->SetDepthScale(-1.0);
  EXPECT_EQ(filter->GetDepthScale(), 0.0);
  filter->SetMaximumEdgeTexels(2.0);
  filter->SetMaximumEdgeTexels(std::nan(""));
  EXPECT_EQ(filter->GetMaximumEdgeTexels(), 2.0);
  filter->SetMaximumEdgeTexels(0.0);
  EXPECT_EQ(filter->GetMaximumEdgeTexels(), 1e-3);
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 5);
  EXPECT_TRUE(recorder->AnyMessageContains("DepthScale") &&
    recorder->AnyMessageContains("MaximumEdgeTexels"));
  // no subdivision at all: accepted as it is
  filter->SetMaximumEdgeTexels(std::numeric_limits<double>::infinity());
  EXPECT_EQ(filter->GetMaximumEdgeTexels(), std::numeric_limits<double>::infinity());
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 5);
}

TEST(ReliefDisplacementFilter, ReportsProgressFromStartToEnd)
{
  vtkNew<vtkReliefDisplacementFilter> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::ProgressEvent, recorder);
  Displace(filter, UnitSquare(), DepthImage(16, 16, [](int, int) { return 0.5; }));
  ASSERT_GE(recorder->Progress.size(), 3u);
  EXPECT_EQ(recorder->Progress.front(), 0.0);
  EXPECT_EQ(recorder->Progress.back(), 1.0);
  for (size_t k = 1; k < recorder->Progress.size(); ++k)
  {
    EXPECT_GE(recorder->Progress[k], recorder->Progress[k - 1]);
  }
}
