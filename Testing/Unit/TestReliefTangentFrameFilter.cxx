// vtkReliefTangentFrameFilter: the per-point frame and texture scale of the relief
// mappers, on meshes whose answers are known.
#include "ReliefEventRecorder.h"
#include "vtkReliefTangentFrameFilter.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
// A width x height rectangle in the xy plane, one quad, texture coordinates [0, 1]^2
// (u mirrored when asked).
vtkSmartPointer<vtkPolyData> Rectangle(double width, double height, bool mirrorU = false)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetPoint1(width, 0.0, 0.0);
  plane->SetPoint2(0.0, height, 0.0);
  plane->Update();
  auto rectangle = vtkSmartPointer<vtkPolyData>::New();
  rectangle->DeepCopy(plane->GetOutput());
  if (mirrorU)
  {
    vtkDataArray* tcoords = rectangle->GetPointData()->GetTCoords();
    for (vtkIdType i = 0; i < tcoords->GetNumberOfTuples(); ++i)
    {
      tcoords->SetComponent(i, 0, 1.0 - tcoords->GetComponent(i, 0));
    }
  }
  return rectangle;
}

vtkPolyData* Frame(vtkReliefTangentFrameFilter* filter, vtkPolyData* input)
{
  filter->SetInputData(input);
  filter->Update();
  return filter->GetOutput();
}

vtkDataArray* Scale(vtkPolyData* frame)
{
  return frame->GetPointData()->GetArray(vtkReliefTangentFrameFilter::TextureScaleArrayName());
}
}

TEST(ReliefTangentFrameFilter, TextureScaleIsTheModelLengthOfOneTextureUnit)
{
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkPolyData* frame = Frame(filter, Rectangle(2.0, 0.5));
  ASSERT_TRUE(filter->GetHasSurface());
  EXPECT_EQ(frame->GetNumberOfPolys(), 2); // the quad became two triangles
  ASSERT_NE(Scale(frame), nullptr);
  ASSERT_NE(frame->GetPointData()->GetTangents(), nullptr);
  for (vtkIdType i = 0; i < frame->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(Scale(frame)->GetComponent(i, 0), 2.0, 1e-6);
    EXPECT_NEAR(Scale(frame)->GetComponent(i, 1), 0.5, 1e-6);
    double tangent[3];
    frame->GetPointData()->GetTangents()->GetTuple(i, tangent);
    EXPECT_NEAR(tangent[0], 1.0, 1e-6); // along increasing u
  }
}

TEST(ReliefTangentFrameFilter, MirroredTextureGivesNegativeBitangentScale)
{
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkPolyData* frame = Frame(filter, Rectangle(1.0, 1.0, true));
  for (vtkIdType i = 0; i < frame->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(Scale(frame)->GetComponent(i, 0), 1.0, 1e-6);
    EXPECT_NEAR(Scale(frame)->GetComponent(i, 1), -1.0, 1e-6);
  }
}

TEST(ReliefTangentFrameFilter, MissingNormalsAreComputedAndGivenArraysKept)
{
  auto rectangle = Rectangle(1.0, 1.0);
  rectangle->GetPointData()->SetNormals(nullptr);
  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("MyTangents");
  tangents->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < rectangle->GetNumberOfPoints(); ++i)
  {
    tangents->InsertNextTuple3(1.0, 0.0, 0.0);
  }
  rectangle->GetPointData()->SetTangents(tangents);
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkPolyData* frame = Frame(filter, rectangle);
  ASSERT_NE(frame->GetPointData()->GetNormals(), nullptr);
  EXPECT_NEAR(std::abs(frame->GetPointData()->GetNormals()->GetComponent(0, 2)), 1.0, 1e-6);
  EXPECT_STREQ(frame->GetPointData()->GetTangents()->GetName(), "MyTangents");
  EXPECT_EQ(rectangle->GetPointData()->GetNormals(), nullptr); // the input is untouched
}

TEST(ReliefTangentFrameFilter, CurvedMeshScaleFollowsTheSurface)
{
  // a sphere of radius 1 with u around the equator: one texture unit spans 2 pi there
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(1.0);
  sphere->SetThetaResolution(64);
  sphere->SetPhiResolution(32);
  sphere->Update();
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  vtkPolyData* surface = sphere->GetOutput();
  for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    tcoords->InsertNextTuple2(std::atan2(p[1], p[0]) / (2.0 * vtkMath::Pi()), p[2]);
  }
  surface->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkPolyData* frame = Frame(filter, surface);
  int checked = 0;
  for (vtkIdType i = 0; i < frame->GetNumberOfPoints(); ++i)
  {
    double p[3];
    frame->GetPoint(i, p);
    const double ringRadius = std::sqrt(p[0] * p[0] + p[1] * p[1]);
    if (std::abs(p[2]) < 0.3 && std::abs(std::atan2(p[1], p[0])) < 2.5) // off the u seam
    {
      EXPECT_NEAR(Scale(frame)->GetComponent(i, 0), 2.0 * vtkMath::Pi() * ringRadius, 0.05);
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
}

TEST(ReliefTangentFrameFilter, MeshWithoutTextureCoordinatesIsAnErrorAndPassesThrough)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::ErrorEvent, recorder);
  vtkPolyData* frame = Frame(filter, sphere->GetOutput());
  EXPECT_EQ(recorder->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(recorder->AnyMessageContains("vtkTextureMapToCylinder"));
  EXPECT_FALSE(filter->GetHasSurface());
  EXPECT_EQ(frame->GetNumberOfPoints(), sphere->GetOutput()->GetNumberOfPoints());
  EXPECT_EQ(Scale(frame), nullptr);
}

TEST(ReliefTangentFrameFilter, LinesAndVerticesAreLeftOutAndLinesAloneAreAnError)
{
  // the rectangle plus a line and a vertex: the frame is built on the triangles alone
  auto mixed = Rectangle(1.0, 1.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType line[2] = { 0, 3 };
  lines->InsertNextCell(2, line);
  mixed->SetLines(lines);
  vtkNew<vtkCellArray> verts;
  const vtkIdType vertex[1] = { 1 };
  verts->InsertNextCell(1, vertex);
  mixed->SetVerts(verts);
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkPolyData* frame = Frame(filter, mixed);
  ASSERT_TRUE(filter->GetHasSurface());
  EXPECT_EQ(frame->GetNumberOfPolys(), 2);
  EXPECT_EQ(frame->GetNumberOfLines() + frame->GetNumberOfVerts(), 0);

  auto linesOnly = vtkSmartPointer<vtkPolyData>::New();
  linesOnly->SetPoints(mixed->GetPoints());
  linesOnly->GetPointData()->SetTCoords(mixed->GetPointData()->GetTCoords());
  linesOnly->SetLines(lines);
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::ErrorEvent, recorder);
  Frame(filter, linesOnly);
  EXPECT_FALSE(filter->GetHasSurface());
  EXPECT_EQ(recorder->Count(vtkCommand::ErrorEvent), 1);
  EXPECT_TRUE(recorder->AnyMessageContains("no polygons"));
}

TEST(ReliefTangentFrameFilter, TrianglesWithoutTextureAreaGiveAFiniteFrame)
{
  // a 3 x 3 grid whose centre point takes the texture coordinates of its neighbour:
  // the triangles around it lose texture area on one side
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(3, 3);
  plane->Update();
  auto grid = vtkSmartPointer<vtkPolyData>::New();
  grid->DeepCopy(plane->GetOutput());
  vtkDataArray* tcoords = grid->GetPointData()->GetTCoords();
  tcoords->SetTuple(5, tcoords->GetTuple(6));
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkPolyData* frame = Frame(filter, grid);
  ASSERT_TRUE(filter->GetHasSurface());
  vtkDataArray* tangents = frame->GetPointData()->GetTangents();
  for (vtkIdType i = 0; i < frame->GetNumberOfPoints(); ++i)
  {
    double length = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_TRUE(std::isfinite(tangents->GetComponent(i, c)));
      length += tangents->GetComponent(i, c) * tangents->GetComponent(i, c);
    }
    EXPECT_NEAR(length, 1.0, 1e-5);
    EXPECT_NEAR(tangents->GetComponent(i, 2), 0.0, 1e-6); // in the plane of the grid
    ASSERT_TRUE(std::isfinite(Scale(frame)->GetComponent(i, 0)));
    ASSERT_TRUE(std::isfinite(Scale(frame)->GetComponent(i, 1)));
  }
}

TEST(ReliefTangentFrameFilter, FeatureAnglesOutOfRangeAreClampedAndNaNRefused)
{
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::WarningEvent, recorder);
  filter->SetFeatureAngle(45.0);
  filter->SetFeatureAngle(std::nan(""));
  EXPECT_EQ(filter->GetFeatureAngle(), 45.0);
  filter->SetFeatureAngle(200.0);
  EXPECT_EQ(filter->GetFeatureAngle(), 180.0);
  filter->SetFeatureAngle(-5.0);
  EXPECT_EQ(filter->GetFeatureAngle(), 0.0);
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 3);
  EXPECT_TRUE(recorder->AnyMessageContains("FeatureAngle"));
}

TEST(ReliefTangentFrameFilter, NormalsWithoutDirectionAreTheSurfacesWithOneWarning)
{
  // the rectangle's normals: one zero, one NaN; the frame holds the plane's +z there
  auto rectangle = Rectangle(2.0, 1.0);
  vtkDataArray* normals = rectangle->GetPointData()->GetNormals();
  normals->SetTuple3(0, 0.0, 0.0, 0.0);
  normals->SetTuple3(1, std::nan(""), 0.0, 0.0);
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::WarningEvent, recorder);
  vtkPolyData* frame = Frame(filter, rectangle);
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 1);
  EXPECT_TRUE(recorder->AnyMessageContains("without a direction"));
  vtkDataArray* framed = frame->GetPointData()->GetNormals();
  for (vtkIdType point = 0; point < framed->GetNumberOfTuples(); ++point)
  {
    EXPECT_NEAR(std::abs(framed->GetComponent(point, 2)), 1.0, 1e-6) << point;
  }
  EXPECT_TRUE(std::isnan(normals->GetComponent(1, 0))); // the input keeps its own
}

TEST(ReliefTangentFrameFilter, TextureCoordinatesNotFiniteSpoilOnlyTheirOwnTriangles)
{
  // a 4x4-quad plane; one corner point's coordinates NaN: every point keeps a finite,
  // unit frame, and the points of the triangles away from it the plane's exact scale
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(4, 4);
  plane->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(plane->GetOutput());
  mesh->GetPointData()->GetTCoords()->SetTuple2(0, std::nan(""), 0.0);
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::WarningEvent, recorder);
  vtkPolyData* frame = Frame(filter, mesh);
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 1);
  EXPECT_TRUE(recorder->AnyMessageContains("not finite"));
  vtkDataArray* tangents = frame->GetPointData()->GetTangents();
  vtkDataArray* scale = Scale(frame);
  for (vtkIdType point = 0; point < frame->GetNumberOfPoints(); ++point)
  {
    double tangent[3];
    tangents->GetTuple(point, tangent);
    EXPECT_NEAR(vtkMath::Norm(tangent), 1.0, 1e-6) << point;
    EXPECT_TRUE(std::isfinite(scale->GetComponent(point, 0)) &&
      std::isfinite(scale->GetComponent(point, 1)))
      << point;
    double position[3];
    frame->GetPoint(point, position);
    if (position[0] > -0.2 || position[1] > -0.2) // no triangle of point 0's
    {
      EXPECT_NEAR(tangent[0], 1.0, 1e-6) << point;
      EXPECT_NEAR(scale->GetComponent(point, 0), 1.0, 1e-6) << point;
      EXPECT_NEAR(scale->GetComponent(point, 1), 1.0, 1e-6) << point;
    }
  }
}

TEST(ReliefTangentFrameFilter, GivenTangentsAreMadeUnitAndPerpendicular)
{
  // long tangents tilted out of the plane
  auto rectangle = Rectangle(1.0, 1.0);
  vtkNew<vtkFloatArray> tangents;
  tangents->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < rectangle->GetNumberOfPoints(); ++i)
  {
    tangents->InsertNextTuple3(3.0, 0.0, 2.0);
  }
  rectangle->GetPointData()->SetTangents(tangents);
  vtkNew<vtkReliefTangentFrameFilter> filter;
  vtkPolyData* frame = Frame(filter, rectangle);
  vtkDataArray* unit = frame->GetPointData()->GetTangents();
  for (vtkIdType i = 0; i < frame->GetNumberOfPoints(); ++i)
  {
    EXPECT_NEAR(unit->GetComponent(i, 0), 1.0, 1e-6);
    EXPECT_NEAR(unit->GetComponent(i, 2), 0.0, 1e-6);
    EXPECT_NEAR(Scale(frame)->GetComponent(i, 0), 1.0, 1e-6);
  }
}
