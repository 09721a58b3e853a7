// The impostor frame (vtkReliefImpostorFrame.glsl) on the CPU: rays through the box of a
// mesh captured by vtkReliefImpostorFilter, searched through the very source the GPU
// compiles, against the mesh's own surface. Six views carve a sphere that one view
// extrudes; reverse perspective puts the hits on the walls of a box on a ground; every
// exact search finds the same hits.
#include "ReliefImpostorMeshes.h"
#include "ReliefMirrorMaps.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefImpostorFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

namespace
{
using namespace ReliefCpuMirror;

// The views of a capture as vtkOpenGLReliefImpostorMapper uploads them: 16-bit depths
// (vtkReliefImpostorFilter::EncodeDepth), clamped at the edges, with their pyramids.
ImpostorViews ViewsOf(vtkReliefImpostorFilter* filter)
{
  vtkImageData* depths = filter->GetDepthOutput();
  const int* dimensions = depths->GetDimensions();
  vtkDataArray* values = depths->GetPointData()->GetScalars();
  ImpostorViews views;
  for (int view = 0; view < dimensions[2]; ++view)
  {
    DepthField field;
    field.Width = dimensions[0];
    field.Height = dimensions[1];
    field.ClampToEdge = true;
    const vtkIdType first = static_cast<vtkIdType>(view) * dimensions[0] * dimensions[1];
    for (vtkIdType k = 0; k < static_cast<vtkIdType>(dimensions[0]) * dimensions[1]; ++k)
    {
      field.Depths.push_back(vtkReliefImpostorFilter::DecodeDepth(
        vtkReliefImpostorFilter::EncodeDepth(static_cast<float>(values->GetTuple1(first + k)))));
    }
    views.Pyramids.push_back(PyramidOf(field));
    views.Fields.push_back(field);
    double rows[16];
    filter->GetViewProjection(view, rows);
    mat4 projection;
    for (int row = 0; row < 4; ++row)
    {
      for (int column = 0; column < 4; ++column)
      {
        projection[column][row] = static_cast<float>(rows[4 * row + column]);
      }
    }
    views.Projections.push_back(projection);
    const double* box = filter->GetBox();
    const int axis = dimensions[2] == 1 ? 2 : view / 2;
    const double side[3] = { box[1] - box[0], box[3] - box[2], box[5] - box[4] };
    views.DepthRatios.push_back(
      static_cast<float>(side[axis] / std::sqrt(side[(axis + 1) % 3] * side[(axis + 2) % 3])));
  }
  return views;
}

vtkNew<vtkReliefImpostorFilter> Capture(vtkPolyData* mesh, int views, bool reversePerspective)
{
  vtkNew<vtkReliefImpostorFilter> filter;
  filter->SetInputData(mesh);
  filter->SetNumberOfViews(views);
  filter->SetProjection(reversePerspective ? vtkReliefImpostorFilter::REVERSE_PERSPECTIVE
                                           : vtkReliefImpostorFilter::ORTHOGRAPHIC);
  filter->SetDepthResolution(128);
  filter->SetColourResolution(8);
  filter->Update();
  return filter;
}

struct Traced
{
  bool Hit = false;
  vec3 Point = vec3(0.0f);
  int Samples = 0;
};

// The first point of the impostor on the ray from `origin` along `direction`.
Traced Trace(vtkReliefImpostorFilter* filter, vec3 origin, vec3 direction)
{
  const double* box = filter->GetBox();
  const ReliefImpostorSegment segment = reliefImpostorClip(origin, direction,
    vec3(box[0], box[2], box[4]), vec3(box[1], box[3], box[5]), 0.0f);
  Traced traced;
  if (segment.crosses)
  {
    const ReliefImpostorHit hit = reliefImpostorSearch(segment, 16, 8);
    traced.Hit = hit.hit;
    traced.Point = mix(segment.entry, segment.exit, hit.share);
    traced.Samples = hit.samples;
  }
  return traced;
}

// Whether the ray from `origin` along unit `direction` meets the sphere of `radius` about
// the origin.
bool SphereMet(vec3 origin, vec3 direction, float radius)
{
  const float b = dot(origin, direction);
  return b < 0.0f && b * b - dot(origin, origin) + radius * radius >= 0.0f;
}

// The sphere the frame's tests capture: radius 1, 96 facets around.
vtkSmartPointer<vtkPolyData> Sphere()
{
  return ReliefImpostorMeshes::Sphere(1.0, 96);
}

struct SearchMethod
{
  const char* Name;
  ReliefHit (*Function)(ReliefRay, int, int);
};
const SearchMethod ExactSearches[] = { { "ExactDDA", &reliefSearchExactDDA },
  { "MaximumMipmap", &reliefSearchMaximumMipmap } };
}

TEST(ReliefImpostorFrame, SixViewsPutEveryHitOnTheSphere)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  for (bool reversePerspective : { false, true })
  {
    vtkNew<vtkReliefImpostorFilter> filter = Capture(sphere, 6, reversePerspective);
    const ImpostorViews views = ViewsOf(filter);
    CurrentImpostor = &views;
    const float texel = 2.04f / 128.0f; // of the box's side
    for (const SearchMethod& method : ExactSearches)
    {
      ImpostorSearch = method.Function;
      std::mt19937 generator(5);
      std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
      int wrong = 0;
      int hits = 0;
      for (int k = 0; k < 2000; ++k)
      {
        vec3 origin(unit(generator), unit(generator), unit(generator));
        origin = 4.0f * normalize(origin + vec3(0.0f, 0.0f, 1e-3f));
        const vec3 target(1.2f * unit(generator), 1.2f * unit(generator), 1.2f * unit(generator));
        const vec3 direction = normalize(target - origin);
        const bool onSphere = SphereMet(origin, direction, 1.0f);
        // how close the ray passes to the outline: within a texel or two either answer is fair
        const float passing = std::sqrt(std::max(dot(origin, origin) -
          dot(origin, direction) * dot(origin, direction), 0.0f));
        const Traced traced = Trace(filter, origin, direction);
        hits += traced.Hit ? 1 : 0;
        // a hit lies on the surface within two texels, wherever along it
        const bool fair = std::abs(passing - 1.0f) < 2.0f * texel ||
          (traced.Hit == onSphere &&
            (!onSphere || std::abs(length(traced.Point) - 1.0f) < 2.0f * texel));
        if (!fair && ++wrong <= 3)
        {
          ADD_FAILURE() << method.Name << (reversePerspective ? ", reverse perspective" : "")
                        << ": the ray passing " << passing << " from the centre "
                        << (traced.Hit ? "hit at radius " : "missed")
                        << (traced.Hit ? length(traced.Point) : 0.0f);
        }
      }
      EXPECT_EQ(wrong, 0) << method.Name << " of 2000 rays";
      EXPECT_GT(hits, 600) << method.Name;
    }
  }
  CurrentImpostor = nullptr;
}

TEST(ReliefImpostorFrame, AnOutlineIsShadedFromTheViewOfItsFace)
{
  // the top of a cube on a ground, hit from a tenth of a texel to two texels from its
  // edges (nearer, either face is fair): a side view sees its wall there, as flat as the
  // lid is from above, and the lid's point lies within its tolerance, a texel or two
  // behind the wall; the lid's colour and normal are the view from above's (+z, view 4)
  vtkNew<vtkReliefImpostorFilter> filter = Capture(ReliefImpostorMeshes::CubeOnGround(), 6, false);
  const ImpostorViews views = ViewsOf(filter);
  CurrentImpostor = &views;
  ImpostorSearch = &reliefSearchMaximumMipmap;
  const double* box = filter->GetBox();
  const float texel = static_cast<float>(box[1] - box[0]) / 128.0f;
  int hits = 0;
  int wrong = 0;
  for (int k = 0; k < 40; ++k)
  {
    const float inward = (0.1f + 0.05f * k) * texel;
    for (const vec3 target : { vec3(0.5f - inward, 0.1f, 1.0f), vec3(-0.1f, 0.5f - inward, 1.0f),
           vec3(-0.5f + inward, -0.2f, 1.0f) })
    {
      const vec3 origin = target + vec3(0.3f, 0.2f, 3.0f);
      const ReliefImpostorSegment segment = reliefImpostorClip(origin,
        normalize(target - origin), vec3(box[0], box[2], box[4]), vec3(box[1], box[3], box[5]),
        0.0f);
      const ReliefImpostorHit hit = reliefImpostorSearch(segment, 16, 8);
      const vec3 point = mix(segment.entry, segment.exit, hit.share);
      if (!hit.hit || std::abs(point.z - 1.0f) > 0.01f)
      {
        continue; // on the wall, within the field's skirt
      }
      ++hits;
      const int view = reliefImpostorShadingView(segment, hit);
      if (view != 4 && ++wrong <= 3)
      {
        ADD_FAILURE() << "the lid's point " << inward / texel << " texels from its edge is "
                      << "shaded from view " << view;
      }
    }
  }
  EXPECT_GT(hits, 60);
  EXPECT_EQ(wrong, 0) << "of " << hits << " hits on the lid";
  CurrentImpostor = nullptr;
}

TEST(ReliefImpostorFrame, OneViewExtrudesWhatSixViewsCarve)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  ImpostorSearch = &reliefSearchMaximumMipmap;
  // a level ray below the equator: one view (+z) holds everything under the sphere's top,
  // a column of radius 1; six views hold the sphere
  const vec3 origin(-4.0f, 0.0f, -0.5f);
  const vec3 direction(1.0f, 0.0f, 0.0f);
  const float texel = 2.04f / 128.0f;
  vtkNew<vtkReliefImpostorFilter> one = Capture(sphere, 1, false);
  ImpostorViews views = ViewsOf(one);
  CurrentImpostor = &views;
  Traced traced = Trace(one, origin, direction);
  ASSERT_TRUE(traced.Hit);
  EXPECT_NEAR(traced.Point.x, -1.0f, 2.0f * texel);
  vtkNew<vtkReliefImpostorFilter> six = Capture(sphere, 6, false);
  views = ViewsOf(six);
  traced = Trace(six, origin, direction);
  ASSERT_TRUE(traced.Hit);
  EXPECT_NEAR(traced.Point.x, -std::sqrt(0.75f), 2.0f * texel);
  CurrentImpostor = nullptr;
}

TEST(ReliefImpostorFrame, ReversePerspectiveHitsTheWallsOfABoxOnAGround)
{
  // a unit cube standing on a 4 x 4 ground, seen from above at 60 degrees from vertical
  vtkNew<vtkReliefImpostorFilter> filter = Capture(ReliefImpostorMeshes::CubeOnGround(), 6, true);
  const ImpostorViews views = ViewsOf(filter);
  CurrentImpostor = &views;
  const float texel = 4.1f / 128.0f;
  for (const SearchMethod& method : ExactSearches)
  {
    ImpostorSearch = method.Function;
    int wrong = 0;
    for (int k = 0; k < 21; ++k)
    {
      // rays toward the wall x = -0.5, across its height and width, and the ground
      // before it
      const float height = 0.05f + 0.9f * (k % 7) / 6.0f;
      const float across = -0.4f + 0.4f * (k / 7);
      const vec3 target(-0.5f, across, height);
      const vec3 direction = normalize(vec3(std::sin(1.047f), 0.0f, -std::cos(1.047f)));
      const Traced traced = Trace(filter, target - 6.0f * direction, direction);
      if (!traced.Hit || length(traced.Point - target) > 2.0f * texel)
      {
        ++wrong;
        ADD_FAILURE() << method.Name << ": the ray to the wall at (" << target.x << ", "
                      << target.y << ", " << target.z << ") "
                      << (traced.Hit ? "hit at " : "missed") << traced.Point.x << ", "
                      << traced.Point.y << ", " << traced.Point.z;
      }
      // beside the cube, the ray meets the ground
      const vec3 beside(0.3f, 0.8f + 0.5f * across, 0.0f);
      const Traced ground = Trace(filter, beside - 6.0f * direction, direction);
      EXPECT_TRUE(ground.Hit && length(ground.Point - beside) < 2.0f * texel)
        << method.Name << ": the ground at y = " << beside.y;
    }
    EXPECT_EQ(wrong, 0) << method.Name;
  }
  CurrentImpostor = nullptr;
}

TEST(ReliefImpostorFrame, ExactSearchesAgreeOnEveryRay)
{
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkNew<vtkReliefImpostorFilter> filter = Capture(sphere, 6, true);
  const ImpostorViews views = ViewsOf(filter);
  CurrentImpostor = &views;
  std::mt19937 generator(9);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  int disagreements = 0;
  long samples[2] = { 0, 0 };
  for (int k = 0; k < 1000; ++k)
  {
    const vec3 origin = 4.0f * normalize(vec3(unit(generator), unit(generator), unit(generator)));
    const vec3 direction =
      normalize(vec3(unit(generator), unit(generator), unit(generator)) - origin);
    Traced traced[2];
    for (int m = 0; m < 2; ++m)
    {
      ImpostorSearch = ExactSearches[m].Function;
      traced[m] = Trace(filter, origin, direction);
      samples[m] += traced[m].Samples;
    }
    if (traced[0].Hit != traced[1].Hit ||
      (traced[0].Hit && length(traced[0].Point - traced[1].Point) > 1e-3f))
    {
      ++disagreements;
    }
  }
  EXPECT_EQ(disagreements, 0);
  // the pyramid skips what the cell walk visits one by one
  EXPECT_LT(samples[1], samples[0]);
  CurrentImpostor = nullptr;
}

TEST(ReliefImpostorFrame, ASheetSeenEdgeOnIsKept)
{
  // a square with no thickness, in a box of a hundredth of its side: the side views see
  // it edge on, between their texel rows, and must still hold it (TouchTriangle)
  vtkNew<vtkPlaneSource> sheet;
  sheet->SetResolution(4, 4);
  sheet->Update();
  vtkNew<vtkReliefImpostorFilter> filter;
  filter->SetInputData(sheet->GetOutput());
  filter->SetPadding(0.0);
  filter->SetDepthResolution(128);
  filter->SetColourResolution(8);
  filter->Update();
  const ImpostorViews views = ViewsOf(filter);
  CurrentImpostor = &views;
  for (const SearchMethod& method : ExactSearches)
  {
    ImpostorSearch = method.Function;
    int missed = 0;
    for (int k = 0; k < 100; ++k)
    {
      const vec3 target(-0.4f + 0.8f * (k % 10) / 9.0f, -0.4f + 0.8f * (k / 10) / 9.0f, 0.0f);
      const vec3 direction = normalize(vec3(0.3f, 0.2f, -1.0f));
      const Traced traced = Trace(filter, target - 3.0f * direction, direction);
      missed += traced.Hit && length(traced.Point - target) < 0.02f ? 0 : 1;
    }
    EXPECT_EQ(missed, 0) << method.Name << ", of 100 rays";
  }
  CurrentImpostor = nullptr;
}

TEST(ReliefImpostorFrame, ANearPlaneInsideTheObjectShowsItsCut)
{
  // a ray whose first point (the near plane's) lies inside the sphere: every view holds
  // it, and it is the hit
  vtkSmartPointer<vtkPolyData> sphere = Sphere();
  vtkNew<vtkReliefImpostorFilter> filter = Capture(sphere, 6, false);
  const ImpostorViews views = ViewsOf(filter);
  CurrentImpostor = &views;
  ImpostorSearch = &reliefSearchMaximumMipmap;
  const Traced traced = Trace(filter, vec3(0.2f, -0.1f, 0.3f), normalize(vec3(1.0f, 0.5f, 0.2f)));
  EXPECT_TRUE(traced.Hit);
  EXPECT_LT(length(traced.Point - vec3(0.2f, -0.1f, 0.3f)), 1e-4f);
  CurrentImpostor = nullptr;
}
