// vtkReliefImpostorFilter: its views' projections (the box's faces on the unit cube, lines
// kept straight), a sphere and a box on a ground captured and read back, reverse
// perspective seeing the walls an orthogonal view loses (Baboud and Decoret 2006, s4,
// Fig. 9), what no view saw, colours, and bad input.

#include "ReliefEventRecorder.h"
#include "ReliefImpostorMeshes.h"

#include "vtkDataArray.h"
#include "vtkElevationFilter.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefImpostorFilter.h"
#include "vtkSmartPointer.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace
{
glm::dmat4 Projection(vtkReliefImpostorFilter* filter, int view)
{
  double rows[16];
  EXPECT_TRUE(filter->GetViewProjection(view, rows));
  glm::dmat4 matrix;
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      matrix[column][row] = rows[4 * row + column];
    }
  }
  return matrix;
}

glm::dvec3 ToView(const glm::dmat4& projection, const glm::dvec3& point)
{
  const glm::dvec4 h = projection * glm::dvec4(point, 1.0);
  return glm::dvec3(h) / h.w;
}

glm::dvec3 ToWorld(const glm::dmat4& projection, const glm::dvec3& view)
{
  const glm::dvec4 h = glm::inverse(projection) * glm::dvec4(view, 1.0);
  return glm::dvec3(h) / h.w;
}

using ReliefImpostorMeshes::CubeOnGround;
using ReliefImpostorMeshes::Sphere;

// The world point of each texel of slice `view` that met the mesh.
std::vector<glm::dvec3> Hits(vtkReliefImpostorFilter* filter, int view)
{
  vtkImageData* depths = filter->GetDepthOutput();
  int dimensions[3];
  depths->GetDimensions(dimensions);
  vtkDataArray* depth = depths->GetPointData()->GetScalars();
  const glm::dmat4 projection = Projection(filter, view);
  std::vector<glm::dvec3> hits;
  for (int j = 0; j < dimensions[1]; ++j)
  {
    for (int i = 0; i < dimensions[0]; ++i)
    {
      const double d =
        depth->GetTuple1((static_cast<vtkIdType>(view) * dimensions[1] + j) * dimensions[0] + i);
      if (d < 1.0)
      {
        hits.push_back(ToWorld(projection,
          glm::dvec3((i + 0.5) / dimensions[0], (j + 0.5) / dimensions[1], d)));
      }
    }
  }
  return hits;
}

// Colour texels of view 0 whose normal is horizontal (a wall's).
int WallTexels(vtkReliefImpostorFilter* filter)
{
  vtkImageData* colours = filter->GetColourOutput();
  vtkDataArray* normals = colours->GetPointData()->GetNormals();
  int dimensions[3];
  colours->GetDimensions(dimensions);
  int walls = 0;
  for (vtkIdType texel = 0; texel < static_cast<vtkIdType>(dimensions[0]) * dimensions[1];
       ++texel)
  {
    double n[3];
    normals->GetTuple(texel, n);
    walls += std::abs(n[2]) < 0.1 && (n[0] != 0.0 || n[1] != 0.0) ? 1 : 0;
  }
  return walls;
}
} // namespace

TEST(ReliefImpostorFilter, ViewsMapTheBoxFacesToTheUnitCube)
{
  for (int projection : { vtkReliefImpostorFilter::ORTHOGRAPHIC,
         vtkReliefImpostorFilter::REVERSE_PERSPECTIVE })
  {
    vtkNew<vtkReliefImpostorFilter> filter;
    vtkNew<ReliefEventRecorder> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings); // no colour: white
    vtkNew<vtkCubeSource> box;
    box->SetXLength(2.0);
    box->SetYLength(3.0);
    box->SetZLength(4.0);
    filter->SetInputConnection(box->GetOutputPort());
    filter->SetPadding(0.0);
    filter->SetProjection(projection);
    filter->SetDepthResolution(16);
    filter->SetColourResolution(16);
    filter->Update();
    const glm::dvec3 half(1.0, 1.5, 2.0);
    for (int view = 0; view < 6; ++view)
    {
      SCOPED_TRACE("view " + std::to_string(view) + ", projection " + std::to_string(projection));
      const int axis = view / 2;
      const double side = view % 2 == 0 ? 1.0 : -1.0;
      const glm::dmat4 matrix = Projection(filter.GetPointer(), view);
      // the face's corners at depth 0 on the unit square's corners, the far face at depth 1
      for (int corner = 0; corner < 4; ++corner)
      {
        glm::dvec3 near(0.0);
        near[axis] = side * half[axis];
        near[(axis + 1) % 3] = (corner & 1 ? 1.0 : -1.0) * half[(axis + 1) % 3];
        near[(axis + 2) % 3] = (corner & 2 ? 1.0 : -1.0) * half[(axis + 2) % 3];
        // the face's corners at depth 0, the far face's at depth 1, on the unit square's
        // corners; in reverse perspective (apex two depths away) the frustum's far end is
        // the far face, its near end twice the face: the face's corners at 1/4 and 3/4
        const double inner = projection == vtkReliefImpostorFilter::ORTHOGRAPHIC ? 0.0 : 0.25;
        const glm::dvec3 onFace = ToView(matrix, near);
        EXPECT_NEAR(onFace.z, 0.0, 1e-12);
        EXPECT_NEAR(std::min(std::abs(onFace.x - inner), std::abs(onFace.x - 1.0 + inner)), 0.0,
          1e-12);
        EXPECT_NEAR(std::min(std::abs(onFace.y - inner), std::abs(onFace.y - 1.0 + inner)), 0.0,
          1e-12);
        glm::dvec3 far = near;
        far[axis] = -far[axis];
        const glm::dvec3 onFar = ToView(matrix, far);
        EXPECT_NEAR(onFar.z, 1.0, 1e-12);
        EXPECT_NEAR(onFar.x, onFace.x < 0.5 ? 0.0 : 1.0, 1e-12);
        EXPECT_NEAR(onFar.y, onFace.y < 0.5 ? 0.0 : 1.0, 1e-12);
      }
      // u x v along the outward normal: the face as seen from outside
      const glm::dvec3 origin = ToWorld(matrix, glm::dvec3(0.0, 0.0, 0.0));
      const glm::dvec3 u = ToWorld(matrix, glm::dvec3(1.0, 0.0, 0.0)) - origin;
      const glm::dvec3 v = ToWorld(matrix, glm::dvec3(0.0, 1.0, 0.0)) - origin;
      EXPECT_GT(side * glm::cross(u, v)[axis], 0.0);
      // a straight world line stays straight in the view's cube (s4: rays stay lines)
      const glm::dvec3 a = ToView(matrix, glm::dvec3(0.3, -0.7, 1.1));
      const glm::dvec3 b = ToView(matrix, glm::dvec3(-0.4, 0.9, -1.5));
      const glm::dvec3 c = ToView(matrix, glm::dvec3(0.3 + 0.25 * -0.7, -0.7 + 0.25 * 1.6,
        1.1 + 0.25 * -2.6));
      EXPECT_NEAR(glm::length(glm::cross(b - a, c - a)), 0.0, 1e-12);
    }
  }
}

TEST(ReliefImpostorFilter, SphereReadsBackOnItsSurface)
{
  const double radius = 1.0;
  vtkSmartPointer<vtkPolyData> sphere = Sphere(radius, 96);
  for (int projection : { vtkReliefImpostorFilter::ORTHOGRAPHIC,
         vtkReliefImpostorFilter::REVERSE_PERSPECTIVE })
  {
    SCOPED_TRACE("projection " + std::to_string(projection));
    vtkNew<vtkReliefImpostorFilter> filter;
    filter->SetInputData(sphere);
    filter->SetProjection(projection);
    filter->SetDepthResolution(96);
    filter->SetColourResolution(32);
    vtkNew<ReliefEventRecorder> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings); // no colour: white
    filter->Update();
    int dimensions[3];
    filter->GetDepthOutput()->GetDimensions(dimensions);
    EXPECT_EQ(dimensions[0], 96);
    EXPECT_EQ(dimensions[2], 6);
    // the polygonal sphere lies between its inscribed and circumscribed radii; texels the
    // sphere only reaches into, along its outline, hold its least depth within them: a
    // point of their ray at most half a texel's diagonal from the surface
    const double inscribed = radius * std::cos(M_PI / 96) * std::cos(M_PI / 96);
    double box[6];
    filter->GetBox(box);
    const double side = box[1] - box[0];
    // reverse perspective's texels are up to twice as large, on the near face
    const double reach = 0.71 * side / 96.0 *
      (projection == vtkReliefImpostorFilter::ORTHOGRAPHIC ? 1.0 : 2.0);
    for (int view = 0; view < 6; ++view)
    {
      const std::vector<glm::dvec3> hits = Hits(filter.GetPointer(), view);
      int onSurface = 0;
      for (const glm::dvec3& hit : hits)
      {
        ASSERT_GE(glm::length(hit), inscribed - 1e-6);
        ASSERT_LE(glm::length(hit), radius + reach);
        onSurface += glm::length(hit) <= radius + 1e-6 ? 1 : 0;
      }
      if (projection == vtkReliefImpostorFilter::ORTHOGRAPHIC)
      {
        // the disc's share of the face, at the texel centres and along the outline
        const double exact = static_cast<double>(onSurface) / (96.0 * 96.0);
        EXPECT_NEAR(exact, M_PI * radius * radius / (side * side), 0.01);
        const double covered = static_cast<double>(hits.size()) / (96.0 * 96.0);
        EXPECT_GT(covered, exact);
        EXPECT_LT(covered, M_PI * (radius + reach) * (radius + reach) / (side * side) + 0.01);
      }
    }
    EXPECT_LT(filter->GetUnseenSurfaceFraction(), 0.005);
    vtkDataArray* unseen =
      filter->GetDepthOutput()->GetFieldData()->GetArray("UnseenSurfaceFraction");
    ASSERT_NE(unseen, nullptr);
    EXPECT_EQ(unseen->GetTuple1(0), filter->GetUnseenSurfaceFraction());
    EXPECT_NE(filter->GetColourOutput()->GetFieldData()->GetArray("ViewProjections"), nullptr);
  }
}

TEST(ReliefImpostorFilter, ReversePerspectiveSeesTheWallsAnOrthogonalViewLoses)
{
  vtkSmartPointer<vtkPolyData> scene = CubeOnGround();
  auto capture = [&](int views, int projection) {
    auto filter = vtkSmartPointer<vtkReliefImpostorFilter>::New();
    filter->SetInputData(scene);
    filter->SetNumberOfViews(views);
    filter->SetProjection(projection);
    filter->SetPadding(0.0);
    filter->SetDepthResolution(128);
    filter->SetColourResolution(128);
    vtkNew<ReliefEventRecorder> warnings;
    filter->AddObserver(vtkCommand::WarningEvent, warnings);
    filter->Update();
    return filter;
  };
  auto orthographic = capture(1, vtkReliefImpostorFilter::ORTHOGRAPHIC);
  auto perspective = capture(1, vtkReliefImpostorFilter::REVERSE_PERSPECTIVE);
  auto all = capture(6, vtkReliefImpostorFilter::ORTHOGRAPHIC);
  // from above, straight down: the top and the ground; the walls (4 of 22 units of area),
  // the cube's bottom and the ground under it (1 each) unseen
  EXPECT_EQ(WallTexels(orthographic), 0);
  EXPECT_NEAR(orthographic->GetUnseenSurfaceFraction(), 6.0 / 22.0, 0.02);
  // leaning rays see the walls from above: each wall's image is a trapezoid a sixteenth of
  // the near end wide (rays from 0.5 to 1 out of the 8 units it spans), 1/8 to 2/8 of it
  // long, about 192 texels
  EXPECT_GT(WallTexels(perspective), 4 * 150);
  EXPECT_NEAR(perspective->GetUnseenSurfaceFraction(), 2.0 / 22.0, 0.02);
  // six views see everything (the cube's bottom lies on the ground, seen from below)
  EXPECT_LT(all->GetUnseenSurfaceFraction(), 0.01);
  // each wall hit lies on a wall
  for (const glm::dvec3& hit : Hits(perspective, 0))
  {
    const double inside = std::max(std::abs(hit.x), std::abs(hit.y));
    ASSERT_TRUE(std::abs(hit.z) < 1e-6 || std::abs(hit.z - 1.0) < 1e-6 ||
      (std::abs(inside - 0.5) < 1e-6 && hit.z <= 1.0));
  }
}

TEST(ReliefImpostorFilter, ColoursComeFromPointScalars)
{
  vtkNew<vtkElevationFilter> elevation; // VTK's default table: red (low) to blue (high)
  elevation->SetInputData(Sphere(1.0, 48));
  elevation->SetLowPoint(0.0, 0.0, -1.0);
  elevation->SetHighPoint(0.0, 0.0, 1.0);
  vtkNew<vtkReliefImpostorFilter> filter;
  filter->SetInputConnection(elevation->GetOutputPort());
  filter->SetColourResolution(33);
  vtkNew<ReliefEventRecorder> warnings;
  filter->AddObserver(vtkCommand::WarningEvent, warnings);
  filter->Update();
  EXPECT_EQ(warnings->Count(vtkCommand::WarningEvent), 0);
  vtkDataArray* colours = filter->GetColourOutput()->GetPointData()->GetScalars();
  const vtkIdType slice = 33 * 33;
  const vtkIdType middle = 16 * 33 + 16;
  double top[4];
  double bottom[4];
  double corner[4];
  colours->GetTuple(4 * slice + middle, top);    // +z view, the sphere's top
  colours->GetTuple(5 * slice + middle, bottom); // -z view, its bottom
  colours->GetTuple(4 * slice, corner);          // beside the sphere: nothing
  EXPECT_GT(top[2], 200.0);
  EXPECT_LT(top[0], 50.0);
  EXPECT_GT(bottom[0], 200.0);
  EXPECT_LT(bottom[2], 50.0);
  EXPECT_EQ(top[3], 255.0);
  EXPECT_EQ(corner[3], 0.0);
  vtkDataArray* normals = filter->GetColourOutput()->GetPointData()->GetNormals();
  double n[3];
  normals->GetTuple(4 * slice + middle, n);
  EXPECT_GT(n[2], 0.99);
}

TEST(ReliefImpostorFilter, BadInputIsReportedAndTheCaptureGoesOn)
{
  vtkNew<ReliefEventRecorder> messages;
  vtkNew<vtkReliefImpostorFilter> filter;
  filter->AddObserver(vtkCommand::ErrorEvent, messages);
  filter->AddObserver(vtkCommand::WarningEvent, messages);
  filter->AddObserver(vtkCommand::ProgressEvent, messages);

  // an empty mesh: an error, empty outputs
  vtkNew<vtkPolyData> empty;
  filter->SetInputData(empty);
  filter->Update();
  EXPECT_TRUE(messages->AnyMessageContains("no polygons"));
  EXPECT_EQ(filter->GetDepthOutput()->GetNumberOfPoints(), 0);

  // a flat mesh: thickened, with a warning; the capture sees it
  messages->Clear();
  vtkNew<vtkPlaneSource> plane;
  filter->SetInputConnection(plane->GetOutputPort());
  filter->SetPadding(0.0);
  filter->SetDepthResolution(8);
  filter->SetColourResolution(8);
  filter->Update();
  EXPECT_TRUE(messages->AnyMessageContains("flat along z"));
  EXPECT_TRUE(messages->AnyMessageContains("no colour"));
  EXPECT_EQ(messages->Count(vtkCommand::ErrorEvent), 0);
  double box[6];
  filter->GetBox(box);
  EXPECT_NEAR(box[5] - box[4], 0.01, 1e-12);
  EXPECT_EQ(Hits(filter.GetPointer(), 4).size(), 64u); // from +z
  EXPECT_GT(messages->Progress.size(), 2u);
  EXPECT_EQ(messages->Progress.back(), 1.0);

  // resolutions of 0 or beyond the limit, an apex inside the box: errors, empty outputs
  messages->Clear();
  filter->SetDepthResolution(0);
  filter->Update();
  EXPECT_TRUE(messages->AnyMessageContains("must lie in [1, 16384]"));
  EXPECT_EQ(filter->GetDepthOutput()->GetNumberOfPoints(), 0);
  messages->Clear();
  filter->SetDepthResolution(8);
  filter->SetColourResolution(vtkReliefImpostorFilter::MaximumResolution + 1);
  filter->Update();
  EXPECT_TRUE(messages->AnyMessageContains("must lie in [1, 16384]"));
  messages->Clear();
  filter->SetColourResolution(8);
  filter->SetProjectionToReversePerspective();
  filter->SetApexDistance(1.0);
  filter->Update();
  EXPECT_TRUE(messages->AnyMessageContains("must be over 1"));
  EXPECT_EQ(filter->GetColourOutput()->GetNumberOfPoints(), 0);
  messages->Clear();
  filter->SetApexDistance(3.0);
  filter->Update();
  EXPECT_EQ(messages->Count(vtkCommand::ErrorEvent), 0);
  EXPECT_EQ(filter->GetDepthOutput()->GetNumberOfPoints(), 8 * 8 * 6);
}
