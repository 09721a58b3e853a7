// The quadric frame's view ray (vtkReliefQuadricFrame.glsl; Oliveira and Policarpo 2005,
// s3.1-3.3), run on the CPU through the same source the GPU compiles: its depth below the
// quadric, its search range, the silhouette test, the sampled searches following it, and
// the frame interface in both distance modes.
#include "ReliefCpuMirror.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
using namespace glm;
using ReliefCpuMirror::CurrentField;
using ReliefCpuMirror::DepthField;
// compiled with the exact distance, as the quadric mapper's exact mode is: rays without
// its terms read as without it
using namespace ReliefCpuMirror::QuadricExact;

constexpr float DepthScale = 0.05f;
const vec2 Scale(0.5f, 0.25f); // world length of one texture unit along x and y

// A unit view direction in the tangent frame, `tilt` radians from the inward normal.
vec3 View(float tilt, float azimuth)
{
  return vec3(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth),
    -std::cos(tilt));
}

// Depth below z = a x^2 + b y^2 (in DepthScale units) of the point at distance d along
// the view ray: Eq. 7, written out independently.
double DepthBelow(vec3 view, vec2 quadric, double d)
{
  const double x = view.x * d;
  const double y = view.y * d;
  const double z = view.z * d;
  return (quadric.x * x * x + quadric.y * y * y - z) / DepthScale;
}

// Eq. 5-6's depth of the point `d` along the view ray from a point `height` above the
// quadric's apex: s with P + U s on the quadric, U perpendicular to the ray in the plane
// of the ray and the normal, found by bisection (the point below the quadric).
double PerpendicularDepth(vec3 view, vec2 quadric, double d, double height)
{
  const double sine = std::sqrt(1.0 - double(view.z) * view.z);
  const double u[3] = { -view.x * view.z / sine, -view.y * view.z / sine, sine };
  const double p[3] = { view.x * d, view.y * d, height + view.z * d };
  // g(s) = quadric height minus height at P + U s: positive below the quadric
  auto below = [&](double s) {
    const double x = p[0] + u[0] * s;
    const double y = p[1] + u[1] * s;
    return quadric.x * x * x + quadric.y * y * y - (p[2] + u[2] * s);
  };
  double low = 0.0;
  double high = 1.0;
  while (below(high) > 0.0)
  {
    high *= 2.0;
  }
  for (int k = 0; k < 80; ++k)
  {
    const double middle = 0.5 * (low + high);
    (below(middle) > 0.0 ? low : high) = middle;
  }
  return low / DepthScale;
}

struct CurvedRay
{
  ReliefRay Ray;
  float Range;
};

CurvedRay MakeRay(vec3 view, vec2 quadric)
{
  const vec2 terms = reliefQuadricDepthTerms(view, quadric, DepthScale);
  const float range = reliefQuadricRange(terms, 1.0f);
  return { reliefQuadricViewRay(vec2(0.3f, 0.6f), view, Scale, terms, range), range };
}

class ReliefQuadricRay : public ::testing::Test
{
protected:
  void Use(const DepthField& field)
  {
    this->Field = field;
    CurrentField = &this->Field;
  }
  DepthField Field;
};
}

TEST_F(ReliefQuadricRay, DepthAndTextureCoordinatesFollowTheQuadric)
{
  // along the ray, the depth is the distance below the quadric and u, v advance by the
  // run over the texture scale (Eq. 9), for bowls, domes and saddles alike
  const vec2 quadrics[] = { { -0.8f, -0.8f }, { 0.5f, 0.3f }, { 0.6f, -0.4f }, { 0.0f, 0.0f } };
  for (vec2 quadric : quadrics)
  {
    for (float tilt : { 0.2f, 0.8f, 1.3f })
    {
      const vec3 view = View(tilt, 0.7f);
      const CurvedRay curved = MakeRay(view, quadric);
      for (float t : { 0.0f, 0.25f, 0.5f, 1.0f })
      {
        const vec3 point = reliefRayAt(curved.Ray, t);
        const double distance = double(t) * curved.Range;
        EXPECT_NEAR(point.z, DepthBelow(view, quadric, distance), 1e-4);
        EXPECT_NEAR(point.x, 0.3 + view.x * distance / Scale.x, 1e-5);
        EXPECT_NEAR(point.y, 0.6 + view.y * distance / Scale.y, 1e-5);
      }
    }
  }
}

TEST_F(ReliefQuadricRay, TheRangeEndsAtDepthOneOrBackOnTheQuadric)
{
  // flat: depth 1 at DepthScale / cos(tilt), as the straight ray of the flat frame
  const vec3 view = View(0.6f, 0.3f);
  const CurvedRay flat = MakeRay(view, vec2(0.0f, 0.0f));
  EXPECT_NEAR(flat.Range, DepthScale / std::cos(0.6f), 1e-6);
  EXPECT_NEAR(reliefRayAt(flat.Ray, 1.0f).z, 1.0f, 1e-5);
  EXPECT_FALSE(reliefQuadricLeaves(flat.Ray, 1.0f));
  const ReliefRay straight = reliefViewRay(vec2(0.3f, 0.6f),
    vec3(view.x / Scale.x / std::abs(view.z) * DepthScale,
      view.y / Scale.y / std::abs(view.z) * DepthScale, 1.0f));
  for (float t : { 0.3f, 1.0f })
  {
    EXPECT_NEAR(reliefRayAt(flat.Ray, t).x, reliefRayAt(straight, t).x, 1e-5);
    EXPECT_NEAR(reliefRayAt(flat.Ray, t).y, reliefRayAt(straight, t).y, 1e-5);
    EXPECT_NEAR(reliefRayAt(flat.Ray, t).z, reliefRayAt(straight, t).z, 1e-5);
  }

  // a dome (sphere of radius 0.5 seen from outside): a steep ray reaches depth 1, a
  // grazing one comes back to the quadric first, which is the silhouette
  const vec2 dome(-1.0f, -1.0f);
  const CurvedRay steep = MakeRay(View(0.3f, 0.0f), dome);
  EXPECT_NEAR(reliefRayAt(steep.Ray, 1.0f).z, 1.0f, 1e-4);
  EXPECT_FALSE(reliefQuadricLeaves(steep.Ray, 1.0f));
  const CurvedRay grazing = MakeRay(View(1.5f, 0.0f), dome);
  EXPECT_NEAR(reliefRayAt(grazing.Ray, 1.0f).z, 0.0f, 1e-4);
  EXPECT_TRUE(reliefQuadricLeaves(grazing.Ray, 1.0f));
  for (float t = 0.05f; t < 1.0f; t += 0.05f)
  {
    EXPECT_GT(reliefRayAt(grazing.Ray, t).z, 0.0f) << t; // inside the whole way
    EXPECT_LT(reliefRayAt(grazing.Ray, t).z, 1.0f) << t;
  }
  // a bowl (the inside of a sphere) never lets a ray out: depth 1 is always reached
  const CurvedRay bowl = MakeRay(View(1.5f, 0.0f), vec2(1.0f, 1.0f));
  EXPECT_NEAR(reliefRayAt(bowl.Ray, 1.0f).z, 1.0f, 1e-4);
  EXPECT_FALSE(reliefQuadricLeaves(bowl.Ray, 1.0f));
}

TEST_F(ReliefQuadricRay, BackFacesBehindACarvedOutlineAreTold)
{
  // A back face's view ray, followed back toward the viewer below the outward quadric,
  // is behind an outline exactly when it comes back out of the quadric before depth 1:
  // sampled here with the independent depth of Eq. 7. On a sphere of radius 0.5 that is
  // where the ray meets the back face at more than about 66 degrees from its normal.
  const vec2 quadrics[] = { { -1.0f, -1.0f }, { -1.0f, 0.0f }, { 0.6f, -0.4f }, { 1.0f, 1.0f },
    { 0.0f, 0.0f } };
  int behind = 0;
  for (vec2 quadric : quadrics)
  {
    for (float tilt = 0.05f; tilt < 1.56f; tilt += 0.05f)
    {
      for (float azimuth : { 0.0f, 0.7f, 1.5708f })
      {
        const vec3 view = View(tilt, azimuth);
        double deepest = 0.0;
        bool leaves = false;
        for (double d = 1e-4; d < 50.0 && !leaves && deepest < 1.0; d += 1e-4)
        {
          const double depth = DepthBelow(view, quadric, d);
          deepest = std::max(deepest, depth);
          leaves = depth < 0.0;
        }
        const bool expected = leaves && deepest < 1.0;
        if (std::abs(deepest - 1.0) < 1e-3)
        {
          continue; // grazes depth 1: either answer holds
        }
        const vec2 terms = reliefQuadricDepthTerms(view, quadric, DepthScale);
        EXPECT_EQ(reliefQuadricBehindOutline(terms, 1.0f, 1e30f), expected)
          << "quadric (" << quadric.x << ", " << quadric.y << "), tilt " << tilt << ", azimuth "
          << azimuth;
        behind += expected ? 1 : 0;
      }
    }
  }
  EXPECT_GT(behind, 10); // the cases include outlines
  const vec2 sphere(-1.0f, -1.0f);
  const vec2 steep = reliefQuadricDepthTerms(View(1.1f, 0.0f), sphere, DepthScale);
  const vec2 grazing = reliefQuadricDepthTerms(View(1.2f, 0.0f), sphere, DepthScale);
  EXPECT_FALSE(reliefQuadricBehindOutline(steep, 1.0f, 1e30f));
  EXPECT_TRUE(reliefQuadricBehindOutline(grazing, 1.0f, 1e30f));
  // the grazing ray comes back out of the quadric cos/sin^2 = 0.39 away: a viewer nearer
  // than that is inside the shape, and sees the back face
  const float leaves = std::cos(1.2f) / (std::sin(1.2f) * std::sin(1.2f));
  EXPECT_TRUE(reliefQuadricBehindOutline(grazing, 1.0f, 1.01f * leaves));
  EXPECT_FALSE(reliefQuadricBehindOutline(grazing, 1.0f, 0.99f * leaves));
}

TEST_F(ReliefQuadricRay, TheDeepestDepthSearchedSetsTheRangeAndTheOutline)
{
  // path features may cut deeper than 1 (ReliefFragment::deepest): a flat frame's range
  // runs to that depth, and a curved ray that turns back above it leaves the surface
  const vec3 view = View(0.6f, 0.3f);
  const vec2 flatTerms = reliefQuadricDepthTerms(view, vec2(0.0f), DepthScale);
  EXPECT_NEAR(reliefQuadricRange(flatTerms, 2.5f), 2.5f * reliefQuadricRange(flatTerms, 1.0f), 1e-6);
  const ReliefRay flat = reliefQuadricViewRay(
    vec2(0.3f, 0.6f), view, Scale, flatTerms, reliefQuadricRange(flatTerms, 2.5f));
  EXPECT_NEAR(reliefRayAt(flat, 1.0f).z, 2.5f, 1e-5);
  EXPECT_FALSE(reliefQuadricLeaves(flat, 2.5f));
  // on a sphere the grazing ray turns back at depth B^2 / -4A
  const vec2 sphere(-1.0f, -1.0f);
  const vec2 terms = reliefQuadricDepthTerms(View(1.2f, 0.0f), sphere, DepthScale);
  const float turn = terms.y * terms.y / (-4.0f * terms.x);
  for (float deepest : { 0.5f * turn, 2.0f * turn })
  {
    const bool leaves = deepest > turn;
    const ReliefRay ray = reliefQuadricViewRay(vec2(0.3f, 0.6f), View(1.2f, 0.0f), Scale, terms,
      reliefQuadricRange(terms, deepest));
    EXPECT_EQ(reliefQuadricLeaves(ray, deepest), leaves) << deepest;
    EXPECT_EQ(reliefQuadricBehindOutline(terms, deepest, 1e30f), leaves) << deepest;
  }
}

TEST_F(ReliefQuadricRay, SampledSearchesFollowTheCurvedRay)
{
  // a level field at depth 0.4 below a dome: a ray that reaches 0.4 is met where the
  // quadratic depth first equals it; one that turns back before is silhouette
  Use(DepthField::FromFunction(16, 16, [](float, float) { return 0.4f; }));
  const vec2 dome(-2.0f, -1.0f);
  int hits = 0;
  int silhouettes = 0;
  std::mt19937 generator(11);
  std::uniform_real_distribution<float> tilt(0.0f, 1.55f);
  std::uniform_real_distribution<float> azimuth(0.0f, 6.2831853f);
  for (int k = 0; k < 2000; ++k)
  {
    const vec3 view = View(tilt(generator), azimuth(generator));
    const CurvedRay curved = MakeRay(view, dome);
    // the analytic answer: A d^2 + B d = 0.4, or none when the maximum depth falls short
    const vec2 terms = reliefQuadricDepthTerms(view, dome, DepthScale);
    const double A = terms.x;
    const double B = terms.y;
    const double deepest = A < 0.0 ? -B * B / (4.0 * A) : 1e30;
    for (int method = 0; method < 3; ++method)
    {
      const ReliefHit hit = method == 0 ? reliefSearchLinearBinary(curved.Ray, 64, 16)
        : method == 1                   ? reliefSearchSecant(curved.Ray, 64, 8)
                                        : reliefSearchLinear(curved.Ray, 2048, 0);
      if (deepest < 0.4 - 1e-3)
      {
        ASSERT_FALSE(hit.hit) << "method " << method;
        ASSERT_TRUE(reliefQuadricLeaves(curved.Ray, 1.0f)) << "method " << method;
        silhouettes += method == 0 ? 1 : 0;
      }
      else if (deepest > 0.4 + 1e-3)
      {
        ASSERT_TRUE(hit.hit) << "method " << method;
        const double distance = 2.0 * 0.4 / (B + std::sqrt(B * B + 4.0 * A * 0.4));
        ASSERT_NEAR(hit.t * curved.Range, distance, 2e-3 * curved.Range) << "method " << method;
        hits += method == 0 ? 1 : 0;
      }
    }
  }
  std::cout << "dome over a level field: " << hits << " hits, " << silhouettes
            << " silhouette rays of 2000\n";
  EXPECT_GT(hits, 200);
  EXPECT_GT(silhouettes, 200);
}

TEST_F(ReliefQuadricRay, TheExactDistanceIsMeasuredPerpendicularToTheRay)
{
  // Eq. 5-6 where both curvatures bend away (a, b < 0): the point P + U s on the
  // quadric, U perpendicular to the ray in the plane of the ray and the normal, found
  // here by bisection; elsewhere, and head-on, the vertical distance (Eq. 7)
  // (a cylinder's zero term, here 1e-6, is zero: Eq. 7)
  const vec2 quadrics[] = { { -0.8f, -0.5f }, { -0.3f, -2.0f }, { 0.6f, -0.4f }, { 0.5f, 0.3f },
    { -0.7f, 0.0f }, { -0.7f, -1e-6f } };
  for (vec2 quadric : quadrics)
  {
    const bool convex = quadric.x < 0.0f && quadric.y < 0.0f && quadric.y != -1e-6f;
    for (float tilt : { 0.0f, 0.4f, 1.0f, 1.45f })
    {
      const vec3 view = View(tilt, 0.9f);
      const vec2 terms = reliefQuadricDepthTerms(view, quadric, DepthScale);
      const float range = reliefQuadricRange(terms, 1.0f);
      const ReliefRay ray = reliefQuadricExact(
        reliefQuadricViewRay(vec2(0.3f, 0.6f), view, Scale, terms, range), view, quadric,
        DepthScale, 0.0f, range);
      const double sine = std::sqrt(1.0 - double(view.z) * view.z);
      for (float t : { 0.1f, 0.4f, 0.8f })
      {
        const double d = double(t) * range;
        const double vertical = DepthBelow(view, quadric, d);
        double expected = vertical;
        if (convex && sine > 1e-4)
        {
          if (vertical <= 0.0)
          {
            continue; // above the quadric: the ray is outside, nothing to measure
          }
          expected = PerpendicularDepth(view, quadric, d, 0.0);
        }
        EXPECT_NEAR(reliefRayAt(ray, t).z, expected, 1e-3 * std::max(1.0, std::abs(expected)))
          << "a " << quadric.x << ", b " << quadric.y << ", tilt " << tilt << ", t " << t;
      }
    }
  }
}

// A front-facing fragment seen along `view` and its tangent basis, the axes of the
// frame, for either distance mode's mirror.
template <typename Fragment>
Fragment FragmentSeenAlong(vec3 view)
{
  Fragment fragment{};
  fragment.viewVC = view;
  fragment.tcoord = vec2(0.3f, 0.6f);
  fragment.frontFacing = true;
  fragment.depthScale = DepthScale;
  fragment.deepest = 1.0f;
  fragment.eyeDistance = 2.0f;
  return fragment;
}

template <typename Basis>
Basis AxisBasis()
{
  Basis basis;
  basis.normal = vec3(0.0f, 0.0f, 1.0f);
  basis.tangent = vec3(1.0f, 0.0f, 0.0f);
  basis.bitangent = vec3(0.0f, 1.0f, 0.0f);
  basis.textureScale = Scale;
  return basis;
}

TEST_F(ReliefQuadricRay, TheFrameMeasuresEachModesDistance)
{
  // the frame interface as the fragment body calls it: the approximate mode's view ray
  // is Eq. 7's everywhere; the exact mode's differs where both curvatures bend away
  namespace approximate = ReliefCpuMirror::Quadric;
  namespace exact = ReliefCpuMirror::QuadricExact;
  int differing = 0;
  for (vec2 quadric : { vec2(-0.8f, -0.5f), vec2(0.6f, -0.4f), vec2(0.5f, 0.3f) })
  {
    const bool convex = quadric.x < 0.0f && quadric.y < 0.0f;
    for (float tilt : { 0.4f, 1.0f })
    {
      const vec3 view = View(tilt, 0.9f);
      const auto fragment = FragmentSeenAlong<approximate::ReliefFragment>(view);
      const auto exactFragment = FragmentSeenAlong<exact::ReliefFragment>(view);
      const approximate::ReliefRay ray = approximate::reliefFrameViewRay(
        approximate::reliefQuadricFrame(
          AxisBasis<approximate::ReliefTangentBasis>(), quadric, 0.0f, fragment),
        fragment);
      const exact::ReliefRay exactRay = exact::reliefFrameViewRay(
        exact::reliefQuadricFrame(
          AxisBasis<exact::ReliefTangentBasis>(), quadric, 0.0f, exactFragment),
        exactFragment);
      const CurvedRay reference = MakeRay(view, quadric);
      for (float t : { 0.2f, 0.5f, 0.9f })
      {
        const float vertical = approximate::reliefRayAt(ray, t).z;
        const double expected = DepthBelow(view, quadric, double(t) * reference.Range);
        EXPECT_NEAR(vertical, expected, 1e-4 * std::max(1.0, std::abs(expected)))
          << "a " << quadric.x << ", b " << quadric.y << ", tilt " << tilt << ", t " << t;
        const float measured = exact::reliefRayAt(exactRay, t).z;
        if (convex)
        {
          differing += std::abs(measured - vertical) > 1e-4f;
        }
        else
        {
          EXPECT_EQ(measured, vertical);
        }
      }
    }
  }
  EXPECT_EQ(differing, 6); // every convex case: 2 tilts, 3 points
}

TEST_F(ReliefQuadricRay, AHullPointStartsItsRayWhereTheRayMeetsTheQuadric)
{
  // The quadric mapper's hull lies off the surface: a fragment `height` above the quadric
  // (below it, negative) starts its view ray where the ray first meets the quadric, and a
  // ray that passes above a dome meets nothing and is hidden. Both distance modes.
  namespace approximate = ReliefCpuMirror::Quadric;
  namespace exact = ReliefCpuMirror::QuadricExact;
  const vec2 quadrics[] = { { -1.0f, -1.0f }, { 0.5f, 0.3f }, { 0.6f, -0.4f }, { 0.0f, 0.0f } };
  int misses = 0;
  int meetings = 0;
  for (vec2 quadric : quadrics)
  {
    const bool dome = quadric.x < 0.0f && quadric.y < 0.0f;
    for (float tilt : { 0.3f, 1.0f, 1.45f })
    {
      for (float height : { 0.004f, -0.003f })
      {
        const vec3 view = View(tilt, 0.4f);
        const auto fragment = FragmentSeenAlong<approximate::ReliefFragment>(view);
        const auto frame = approximate::reliefQuadricFrame(
          AxisBasis<approximate::ReliefTangentBasis>(), quadric, height, fragment);
        // the ray's depth below the quadric, from the fragment, in depth units
        auto depthAt = [&](double d) { return DepthBelow(view, quadric, d) - height / DepthScale; };
        if (!frame.meets)
        {
          ++misses;
          EXPECT_TRUE(dome && height > 0.0f) << "only a ray above a dome misses it";
          for (double d = 0.0; d < 4.0; d += 0.001)
          {
            ASSERT_LT(depthAt(d), 0.0) << "the ray passes above the quadric";
          }
          EXPECT_TRUE(approximate::reliefFrameHides(frame, fragment));
          EXPECT_TRUE(
            approximate::reliefQuadricLeaves(approximate::reliefFrameViewRay(frame, fragment), 1.0f));
          continue;
        }
        ++meetings;
        EXPECT_FALSE(approximate::reliefFrameHides(frame, fragment));
        EXPECT_NEAR(depthAt(frame.entry), 0.0, 1e-4) << "the entry lies on the quadric";
        EXPECT_EQ(frame.entry > 0.0f, height > 0.0f);
        for (double d = 0.0; std::abs(d) < std::abs(frame.entry) * 0.999;
             d += frame.entry * 0.01)
        {
          EXPECT_EQ(depthAt(d) < 0.0, height > 0.0f) << "no nearer meeting";
        }
        const approximate::ReliefRay ray = approximate::reliefFrameViewRay(frame, fragment);
        const auto exactFragment = FragmentSeenAlong<exact::ReliefFragment>(view);
        const auto exactFrame = exact::reliefQuadricFrame(
          AxisBasis<exact::ReliefTangentBasis>(), quadric, height, exactFragment);
        const exact::ReliefRay exactRay = exact::reliefFrameViewRay(exactFrame, exactFragment);
        for (float t : { 0.0f, 0.3f, 0.9f })
        {
          const double d = frame.entry + double(t) * frame.range;
          const vec3 point = approximate::reliefRayAt(ray, t);
          EXPECT_NEAR(point.z, depthAt(d), 1e-3 * std::max(1.0, std::abs(depthAt(d))));
          EXPECT_NEAR(point.x, 0.3 + view.x * d / Scale.x, 1e-5);
          EXPECT_NEAR(point.y, 0.6 + view.y * d / Scale.y, 1e-5);
          approximate::ReliefHit hit{};
          hit.t = t;
          EXPECT_NEAR(approximate::reliefFrameHitDistance(frame, fragment, ray, hit), d, 1e-6);
          if (dome && depthAt(d) > 1e-3)
          {
            EXPECT_NEAR(exact::reliefRayAt(exactRay, t).z,
              PerpendicularDepth(view, quadric, d, height), 1e-3)
              << "tilt " << tilt << ", height " << height << ", t " << t;
          }
        }
      }
    }
  }
  EXPECT_GT(misses, 0);
  EXPECT_GT(meetings, 10);
}
