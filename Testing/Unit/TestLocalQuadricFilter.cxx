// vtkLocalQuadricFilter: the per-point quadrics z = a x^2 + b y^2 of curved relief
// (Oliveira and Policarpo 2005, Eq. 1-2), on surfaces whose answers are known.
#include "ReliefEventRecorder.h"
#include "vtkLocalQuadricFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkCubeSource.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReliefTangentFrameFilter.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <vector>

namespace
{
constexpr double Pi = 3.14159265358979323846;

// What a surface gives at parameters (s, t) in [0, 1]^2: its point, normal and tangent
// (the direction of increasing s, which is the texture's u).
struct SurfacePoint
{
  double Position[3];
  double Normal[3];
  double Tangent[3];
};
using Surface = std::function<SurfacePoint(double s, double t)>;

// An n x m grid of points over the surface, quads split into triangles, texture
// coordinates (s, t), the surface's exact normals and tangents (or cell normals only).
vtkSmartPointer<vtkPolyData> Grid(
  int n, int m, const Surface& surface, bool cellNormalsOnly = false)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  tcoords->SetName("TCoords");
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetName("Normals");
  vtkNew<vtkFloatArray> tangents;
  tangents->SetNumberOfComponents(3);
  tangents->SetName("Tangents");
  for (int j = 0; j < m; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double s = double(i) / (n - 1);
      const double t = double(j) / (m - 1);
      const SurfacePoint point = surface(s, t);
      points->InsertNextPoint(point.Position);
      tcoords->InsertNextTuple2(s, t);
      normals->InsertNextTuple(point.Normal);
      tangents->InsertNextTuple(point.Tangent);
    }
  }
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j + 1 < m; ++j)
  {
    for (int i = 0; i + 1 < n; ++i)
    {
      const vtkIdType corner = j * n + i;
      const vtkIdType a[3] = { corner, corner + 1, corner + n + 1 };
      const vtkIdType b[3] = { corner, corner + n + 1, corner + n };
      triangles->InsertNextCell(3, a);
      triangles->InsertNextCell(3, b);
    }
  }
  auto grid = vtkSmartPointer<vtkPolyData>::New();
  grid->SetPoints(points);
  grid->SetPolys(triangles);
  grid->GetPointData()->SetTCoords(tcoords);
  if (cellNormalsOnly)
  {
    vtkNew<vtkFloatArray> cellNormals;
    cellNormals->SetNumberOfComponents(3);
    cellNormals->SetName("Normals");
    for (vtkIdType k = 0; k < triangles->GetNumberOfCells(); ++k)
    {
      cellNormals->InsertNextTuple3(0.0, 0.0, 1.0);
    }
    grid->GetCellData()->SetNormals(cellNormals);
  }
  else
  {
    grid->GetPointData()->SetNormals(normals);
    grid->GetPointData()->SetTangents(tangents);
  }
  return grid;
}

// z = A x^2 + B y^2 over [-1, 1]^2, x along s.
Surface Quadric(double A, double B)
{
  return [=](double s, double t) {
    const double x = 2.0 * s - 1.0;
    const double y = 2.0 * t - 1.0;
    const double nx = -2.0 * A * x;
    const double ny = -2.0 * B * y;
    const double nl = std::sqrt(nx * nx + ny * ny + 1.0);
    const double tl = std::sqrt(1.0 + 4.0 * A * A * x * x);
    return SurfacePoint{ { x, y, A * x * x + B * y * y }, { nx / nl, ny / nl, 1.0 / nl },
      { 1.0 / tl, 0.0, 2.0 * A * x / tl } };
  };
}

// A sphere of radius r, s around the equator (theta), t from pole to pole, kept away
// from the poles; normals outward, or inward (the inside seen from within).
Surface Sphere(double r, bool inward = false)
{
  return [=](double s, double t) {
    const double theta = 2.0 * Pi * s;
    const double phi = 0.2 * Pi + 0.6 * Pi * t;
    const double out[3] = { std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
      std::cos(phi) };
    const double sign = inward ? -1.0 : 1.0;
    return SurfacePoint{ { r * out[0], r * out[1], r * out[2] },
      { sign * out[0], sign * out[1], sign * out[2] },
      { -std::sin(theta), std::cos(theta), 0.0 } };
  };
}

// A cylinder of radius r around the z axis, s around it, t along it (height 2).
Surface Cylinder(double r)
{
  return [=](double s, double t) {
    const double theta = 2.0 * Pi * s;
    return SurfacePoint{ { r * std::cos(theta), r * std::sin(theta), 2.0 * t },
      { std::cos(theta), std::sin(theta), 0.0 }, { -std::sin(theta), std::cos(theta), 0.0 } };
  };
}

// Triangles over the given points, with texture coordinates (x, y), normals +z and
// tangents +x, so that every frame is known exactly.
vtkSmartPointer<vtkPolyData> FlatFramed(const std::vector<std::array<double, 3>>& positions,
  const std::vector<std::array<vtkIdType, 3>>& cells)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tangents;
  tangents->SetNumberOfComponents(3);
  for (const auto& position : positions)
  {
    points->InsertNextPoint(position.data());
    tcoords->InsertNextTuple2(position[0], position[1]);
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
    tangents->InsertNextTuple3(1.0, 0.0, 0.0);
  }
  vtkNew<vtkCellArray> triangles;
  for (const auto& cell : cells)
  {
    triangles->InsertNextCell(3, cell.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  mesh->GetPointData()->SetTCoords(tcoords);
  mesh->GetPointData()->SetNormals(normals);
  mesh->GetPointData()->SetTangents(tangents);
  return mesh;
}

vtkPolyData* Fit(vtkLocalQuadricFilter* filter, vtkPolyData* input)
{
  filter->SetInputData(input);
  filter->Update();
  return filter->GetOutput();
}

vtkDataArray* Quadrics(vtkPolyData* output)
{
  return output->GetPointData()->GetArray(vtkLocalQuadricFilter::QuadricArrayName());
}

vtkIdType FallbackCount(vtkPolyData* output)
{
  vtkDataArray* count =
    output->GetFieldData()->GetArray(vtkLocalQuadricFilter::FallbackCountArrayName());
  return count ? static_cast<vtkIdType>(count->GetTuple1(0)) : -1;
}

// The output point at the input's grid point (i, j) of an n-wide grid: the filter keeps
// the points of a triangulated mesh with normals and tangents in their order.
vtkIdType GridPoint(int n, int i, int j)
{
  return static_cast<vtkIdType>(j) * n + i;
}
}

TEST(LocalQuadricFilter, RecoversParaboloidsSaddlesAndParabolicCylindersExactly)
{
  // at the apex the grid's neighbours lie exactly on z = A x^2 + B y^2 in the exact frame
  const double cases[][2] = { { 0.3, 0.7 }, { 0.5, -0.4 }, { 0.6, 0.0 }, { 0.0, -0.8 },
    { 0.0, 0.0 } };
  for (const auto& coefficients : cases)
  {
    SCOPED_TRACE("A " + std::to_string(coefficients[0]) + ", B " + std::to_string(coefficients[1]));
    vtkNew<vtkLocalQuadricFilter> filter;
    vtkPolyData* output = Fit(filter, Grid(21, 21, Quadric(coefficients[0], coefficients[1])));
    vtkDataArray* quadrics = Quadrics(output);
    ASSERT_NE(quadrics, nullptr);
    const vtkIdType apex = GridPoint(21, 10, 10);
    ASSERT_NEAR(output->GetPoint(apex)[0], 0.0, 1e-12);
    EXPECT_NEAR(quadrics->GetComponent(apex, 0), coefficients[0], 1e-6);
    EXPECT_NEAR(quadrics->GetComponent(apex, 1), coefficients[1], 1e-6);
    EXPECT_EQ(FallbackCount(output), 0);
  }
}

TEST(LocalQuadricFilter, SpheresGiveMinusOneOverTwoRadiusOutsideAndPlusInside)
{
  for (double r : { 0.5, 2.0 })
  {
    for (bool inward : { false, true })
    {
      SCOPED_TRACE("r " + std::to_string(r) + (inward ? " inward" : " outward"));
      vtkNew<vtkLocalQuadricFilter> filter;
      const int n = 65;
      const int m = 25;
      vtkPolyData* output = Fit(filter, Grid(n, m, Sphere(r, inward)));
      vtkDataArray* quadrics = Quadrics(output);
      const double expected = (inward ? 1.0 : -1.0) / (2.0 * r);
      // interior points: 1-ring steps of about a tenth of the radius, so the x^4 terms
      // of the sphere move the fit by well under 1%
      for (int j = 1; j + 1 < m; ++j)
      {
        for (int i = 1; i + 1 < n; ++i)
        {
          const vtkIdType p = GridPoint(n, i, j);
          ASSERT_NEAR(quadrics->GetComponent(p, 0), expected, 0.01 * std::abs(expected));
          ASSERT_NEAR(quadrics->GetComponent(p, 1), expected, 0.01 * std::abs(expected));
        }
      }
      EXPECT_EQ(FallbackCount(output), 0);
    }
  }
}

TEST(LocalQuadricFilter, CylindersCurveAcrossTheAxisOnlyEvenOnTheirBoundary)
{
  const double r = 0.75;
  const int n = 49;
  const int m = 5;
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkPolyData* output = Fit(filter, Grid(n, m, Cylinder(r)));
  vtkDataArray* quadrics = Quadrics(output);
  for (int j = 0; j < m; ++j) // rows 0 and m - 1 are the boundary
  {
    for (int i = 1; i + 1 < n; ++i)
    {
      const vtkIdType p = GridPoint(n, i, j);
      ASSERT_NEAR(quadrics->GetComponent(p, 0), -1.0 / (2.0 * r), 0.005 / r) << i << ", " << j;
      ASSERT_NEAR(quadrics->GetComponent(p, 1), 0.0, 1e-4) << i << ", " << j;
    }
  }
}

TEST(LocalQuadricFilter, TextureSeamsShareOneNeighbourhood)
{
  // the cylinder's seam: columns 0 and n - 1 are two copies of the same points, as a
  // texture seam makes them. Computed normals there lean to their one side; fitted over
  // the triangles of both sides, the lean cancels (fitted over one side's, a is lost)
  const double r = 0.75;
  const int n = 49;
  const int m = 5;
  auto cylinder = Grid(n, m, Cylinder(r));
  cylinder->GetPointData()->SetNormals(nullptr);
  cylinder->GetPointData()->SetTangents(nullptr);
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkPolyData* output = Fit(filter, cylinder);
  ASSERT_EQ(output->GetNumberOfPoints(), n * m); // no normals were split
  vtkDataArray* quadrics = Quadrics(output);
  for (int j = 1; j + 1 < m; ++j)
  {
    for (int i : { 0, n - 1 })
    {
      const vtkIdType p = GridPoint(n, i, j);
      EXPECT_NEAR(quadrics->GetComponent(p, 0), -1.0 / (2.0 * r), 0.01 / r) << i << ", " << j;
      EXPECT_NEAR(quadrics->GetComponent(p, 1), 0.0, 1e-3) << i << ", " << j;
    }
  }
}

TEST(LocalQuadricFilter, CreasesSplitForTheirNormalsKeepTheirSides)
{
  // a cube's corners are copies, one a face, each with its face's normal: the copies of a
  // crease stay apart, and every flat face fits flat (fitted over all three faces at a
  // corner, in one face's frame, a and b would bend strongly)
  vtkNew<vtkCubeSource> cube;
  cube->Update();
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkPolyData* output = Fit(filter, cube->GetOutput());
  vtkDataArray* quadrics = Quadrics(output);
  ASSERT_NE(quadrics, nullptr);
  for (vtkIdType p = 0; p < quadrics->GetNumberOfTuples(); ++p)
  {
    EXPECT_NEAR(quadrics->GetComponent(p, 0), 0.0, 1e-9) << p;
    EXPECT_NEAR(quadrics->GetComponent(p, 1), 0.0, 1e-9) << p;
  }
}

TEST(LocalQuadricFilter, UndeterminedPointsFallBackToFlatAndAreCounted)
{
  // one good triangle; a zero-area triangle whose points lie on one line (each sees
  // its neighbours along x only: Eq. 2 is singular); a point no triangle uses; a point
  // at NaN in a triangle of its own
  const double nan = std::nan("");
  auto mesh = FlatFramed({ { 0, 0, 0 }, { 1, 0, 0.1 }, { 0, 1, 0.2 }, { 2, 0, 0 }, { 3, 0, 0 },
                           { 4, 0, 0 }, { 9, 9, 9 }, { nan, 0, 0 }, { 6, 0, 0 }, { 5, 1, 0 } },
    { { 0, 1, 2 }, { 3, 4, 5 }, { 7, 8, 9 } });
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkPolyData* output = Fit(filter, mesh);
  vtkDataArray* quadrics = Quadrics(output);
  ASSERT_NE(quadrics, nullptr);
  ASSERT_EQ(quadrics->GetNumberOfTuples(), 10);
  // point 0 of the good triangle sees (1, 0, 0.1) and (0, 1, 0.2): a = 0.1, b = 0.2
  EXPECT_NEAR(quadrics->GetComponent(0, 0), 0.1, 1e-6);
  EXPECT_NEAR(quadrics->GetComponent(0, 1), 0.2, 1e-6);
  // the flat triangle (3), the unused point (1) and the NaN triangle (3: the NaN point
  // itself, and its two neighbours, which see one finite neighbour each, along x or y)
  for (vtkIdType p : { 3, 4, 5, 6, 7, 8, 9 })
  {
    EXPECT_EQ(quadrics->GetComponent(p, 0), 0.0) << p;
    EXPECT_EQ(quadrics->GetComponent(p, 1), 0.0) << p;
  }
  EXPECT_EQ(filter->GetNumberOfFallbacks(), 7);
  EXPECT_EQ(FallbackCount(output), 7);
  for (vtkIdType p = 0; p < 10; ++p)
  {
    EXPECT_TRUE(std::isfinite(quadrics->GetComponent(p, 0)) &&
      std::isfinite(quadrics->GetComponent(p, 1)))
      << p;
  }
}

TEST(LocalQuadricFilter, CellNormalsOnlyAreTurnedIntoPointNormals)
{
  // a paraboloid with cell normals only: the tangent frame filter computes point normals
  // (averaged, so nearly exact at the apex) and tangents
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkPolyData* output = Fit(filter, Grid(21, 21, Quadric(0.3, -0.2), true));
  vtkDataArray* quadrics = Quadrics(output);
  ASSERT_NE(quadrics, nullptr);
  ASSERT_NE(output->GetPointData()->GetNormals(), nullptr);
  vtkIdType apex = -1;
  for (vtkIdType p = 0; p < output->GetNumberOfPoints(); ++p)
  {
    if (std::abs(output->GetPoint(p)[0]) < 1e-9 && std::abs(output->GetPoint(p)[1]) < 1e-9)
    {
      apex = p;
    }
  }
  ASSERT_GE(apex, 0);
  EXPECT_NEAR(quadrics->GetComponent(apex, 0), 0.3, 0.01);
  EXPECT_NEAR(quadrics->GetComponent(apex, 1), -0.2, 0.01);
}

TEST(LocalQuadricFilter, NonManifoldEdgesAreFitted)
{
  // three triangles on one edge (a fin): every point is fitted, nothing is lost
  vtkNew<vtkPoints> points;
  const double positions[][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1, 0 }, { 0.5, -1, 0 },
    { 0.5, 0, 1 } };
  for (const auto& position : positions)
  {
    points->InsertNextPoint(position);
  }
  vtkNew<vtkCellArray> triangles;
  const vtkIdType cells[3][3] = { { 0, 1, 2 }, { 1, 0, 3 }, { 0, 1, 4 } };
  for (const auto& cell : cells)
  {
    triangles->InsertNextCell(3, cell);
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  for (vtkIdType p = 0; p < 5; ++p)
  {
    tcoords->InsertNextTuple2(points->GetPoint(p)[0], points->GetPoint(p)[1]);
  }
  mesh->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkPolyData* output = Fit(filter, mesh);
  vtkDataArray* quadrics = Quadrics(output);
  ASSERT_NE(quadrics, nullptr);
  EXPECT_EQ(quadrics->GetNumberOfTuples(), output->GetNumberOfPoints());
  EXPECT_GE(output->GetNumberOfPoints(), 5);
  for (vtkIdType p = 0; p < quadrics->GetNumberOfTuples(); ++p)
  {
    EXPECT_TRUE(std::isfinite(quadrics->GetComponent(p, 0)) &&
      std::isfinite(quadrics->GetComponent(p, 1)))
      << p;
  }
}

TEST(LocalQuadricFilter, TwoRingsSteadyANoisySphere)
{
  // radial noise of 0.5% of the radius: the 1-ring fit swings with it, the 2-ring fit
  // less (both centred on -1 / (2 r))
  const double r = 1.0;
  const int n = 97;
  const int m = 37;
  auto sphere = Grid(n, m, Sphere(r));
  std::mt19937 generator(3);
  std::uniform_real_distribution<double> noise(-0.005, 0.005);
  vtkPoints* points = sphere->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    double position[3];
    points->GetPoint(p, position);
    const double scale = 1.0 + noise(generator);
    points->SetPoint(p, position[0] * scale, position[1] * scale, position[2] * scale);
  }
  auto spread = [&](int rings) {
    vtkNew<vtkLocalQuadricFilter> filter;
    filter->SetNeighbourhoodRings(rings);
    EXPECT_EQ(filter->GetNeighbourhoodRings(), rings);
    vtkDataArray* quadrics = Quadrics(Fit(filter, sphere));
    double squares = 0.0;
    int count = 0;
    for (int j = 2; j + 2 < m; ++j)
    {
      for (int i = 2; i + 2 < n; ++i)
      {
        const double error = quadrics->GetComponent(GridPoint(n, i, j), 0) + 0.5 / r;
        squares += error * error;
        ++count;
      }
    }
    return std::sqrt(squares / count);
  };
  const double oneRing = spread(1);
  const double twoRings = spread(2);
  std::cout << "a's RMS error on the noisy sphere: 1 ring " << oneRing << ", 2 rings " << twoRings
            << "\n";
  EXPECT_LT(twoRings, 0.5 * oneRing);
}

TEST(LocalQuadricFilter, TwoRingsReachPastACollinearFirstRing)
{
  // points 0, 1, 2 on the x axis (a zero-area triangle); 2 also belongs to a triangle
  // reaching off the axis: 0 and 1 see only the axis in one ring, two rings see past 2
  auto mesh = FlatFramed({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0.05 }, { 3, 1, 0.1 } },
    { { 0, 1, 2 }, { 2, 4, 3 } });
  vtkNew<vtkLocalQuadricFilter> filter;
  Fit(filter, mesh);
  EXPECT_EQ(filter->GetNumberOfFallbacks(), 2);
  filter->SetNeighbourhoodRings(2);
  vtkDataArray* quadrics = Quadrics(Fit(filter, mesh));
  EXPECT_EQ(filter->GetNumberOfFallbacks(), 0);
  EXPECT_NE(quadrics->GetComponent(0, 1), 0.0);
}

TEST(LocalQuadricFilter, AMeshWithoutTextureCoordinatesIsOneErrorAndPassesThrough)
{
  auto mesh = Grid(5, 5, Quadric(0.1, 0.1));
  mesh->GetPointData()->SetTCoords(nullptr);
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkNew<ReliefEventRecorder> messages;
  filter->AddObserver(vtkCommand::ErrorEvent, messages);
  filter->AddObserver(vtkCommand::WarningEvent, messages);
  vtkPolyData* output = Fit(filter, mesh);
  EXPECT_EQ(messages->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(messages->AnyMessageContains("texture coordinates"));
  EXPECT_EQ(output->GetNumberOfPoints(), mesh->GetNumberOfPoints());
  EXPECT_EQ(output->GetNumberOfPolys(), mesh->GetNumberOfPolys());
  EXPECT_EQ(Quadrics(output), nullptr);
}

TEST(LocalQuadricFilter, OutputKeepsTheFrameAndReportsProgress)
{
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkNew<ReliefEventRecorder> events;
  filter->AddObserver(vtkCommand::ProgressEvent, events);
  vtkPolyData* output = Fit(filter, Grid(33, 33, Quadric(0.2, 0.1)));
  vtkDataArray* quadrics = Quadrics(output);
  ASSERT_NE(quadrics, nullptr);
  EXPECT_EQ(quadrics->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(quadrics->GetNumberOfComponents(), 2);
  EXPECT_EQ(quadrics->GetNumberOfTuples(), output->GetNumberOfPoints());
  EXPECT_NE(output->GetPointData()->GetNormals(), nullptr);
  EXPECT_NE(output->GetPointData()->GetTangents(), nullptr);
  EXPECT_NE(
    output->GetPointData()->GetArray(vtkReliefTangentFrameFilter::TextureScaleArrayName()),
    nullptr);
  ASSERT_GE(events->Progress.size(), 3u);
  EXPECT_TRUE(std::is_sorted(events->Progress.begin(), events->Progress.end()));
  EXPECT_EQ(events->Progress.back(), 1.0);
}

TEST(LocalQuadricFilter, TheLiftedHullEnclosesACoarseSphere)
{
  // a coarse sphere's triangles sag inside it: each point lifted along its normal by its
  // lift, every triangle of the hull lies outside the sphere (up to the normals' tilt
  // across a triangle, 2% of the sag), and no point is lifted more than the deepest sag of
  // its triangles, a third of the surface's rise over their longest edge
  const double r = 0.5;
  vtkNew<vtkLocalQuadricFilter> filter;
  const int n = 13;
  const int m = 7;
  vtkPolyData* output = Fit(filter, Grid(n, m, Sphere(r, false)));
  vtkDataArray* lifts =
    output->GetPointData()->GetArray(vtkLocalQuadricFilter::HullLiftArrayName());
  ASSERT_NE(lifts, nullptr);
  ASSERT_EQ(lifts->GetNumberOfTuples(), output->GetNumberOfPoints());
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  double deepestSag = 0.0;
  double mostLift = 0.0;
  auto polys = vtk::TakeSmartPointer(output->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    polys->GetCurrentCell(size, ids);
    double lifted[3][3];
    double flat[3] = { 0.0, 0.0, 0.0 };
    for (int k = 0; k < 3; ++k)
    {
      double point[3];
      double normal[3];
      output->GetPoint(ids[k], point);
      normals->GetTuple(ids[k], normal);
      const double length =
        std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
      for (int c = 0; c < 3; ++c)
      {
        lifted[k][c] = point[c] + lifts->GetComponent(ids[k], 0) * normal[c] / length;
        flat[c] += point[c] / 3.0;
      }
      mostLift = std::max(mostLift, lifts->GetComponent(ids[k], 0));
    }
    deepestSag = std::max(
      deepestSag, r - std::sqrt(flat[0] * flat[0] + flat[1] * flat[1] + flat[2] * flat[2]));
    // the hull's triangle, sampled: its points at least the sphere's radius from the centre
    for (double u = 0.0; u <= 1.0; u += 0.125)
    {
      for (double v = 0.0; u + v <= 1.0; v += 0.125)
      {
        double distance = 0.0;
        for (int c = 0; c < 3; ++c)
        {
          const double x = (1.0 - u - v) * lifted[0][c] + u * lifted[1][c] + v * lifted[2][c];
          distance += x * x;
        }
        ASSERT_GT(std::sqrt(distance), r - 0.02 * deepestSag - 1e-9) << u << " " << v;
      }
    }
  }
  EXPECT_GT(deepestSag, 0.005); // the test's mesh is coarse
  EXPECT_LT(mostLift, 2.0 * deepestSag);
}

TEST(LocalQuadricFilter, CreasesAndFlatFacesAreNotLifted)
{
  // a cube: flat faces rise nowhere above their triangles, and its corners are creases
  vtkNew<vtkCubeSource> cube;
  cube->Update();
  vtkNew<vtkLocalQuadricFilter> filter;
  vtkPolyData* output = Fit(filter, cube->GetOutput());
  vtkDataArray* lifts =
    output->GetPointData()->GetArray(vtkLocalQuadricFilter::HullLiftArrayName());
  ASSERT_NE(lifts, nullptr);
  for (vtkIdType p = 0; p < lifts->GetNumberOfTuples(); ++p)
  {
    EXPECT_EQ(lifts->GetComponent(p, 0), 0.0) << p;
  }
  // quadrics computed elsewhere get their lifts too
  auto lifted = vtk::TakeSmartPointer(vtkLocalQuadricFilter::NewHullLifts(output));
  ASSERT_NE(lifted, nullptr);
  EXPECT_EQ(lifted->GetNumberOfTuples(), output->GetNumberOfPoints());
  vtkNew<vtkPolyData> bare;
  EXPECT_EQ(vtkLocalQuadricFilter::NewHullLifts(bare), nullptr);
}
