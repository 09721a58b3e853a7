// The derivative frame (vtkReliefDerivativeFrame.glsl, Tichenor 2012), run on the CPU through
// the source the GPU compiles: the texture axes it solves from screen-space derivatives
// must reproduce a triangle's exact affine texture mapping, skewed or not, against a
// face or a tilted interpolated normal, and say where the derivatives hold no mapping.
#include "ReliefCpuMirror.h"

#include <glm/glm.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace
{
// the frame's source as the GPU compiles it; its axes do not depend on the normals' define
namespace Shader = ReliefCpuMirror::DerivativeNormals;
using glm::dot;
using glm::vec2;
using glm::vec3;

// A triangle's plane and texture mapping: uv(p) = uv0 + (dot(p, gradU), dot(p, gradV))
// for p in the plane; two random pixel steps along it, as dFdx and dFdy see them.
struct Triangle
{
  vec3 Normal;
  vec3 GradU;
  vec3 GradV;
  vec3 AlongX;
  vec3 AlongY;
  vec2 UVAlongX() const { return this->UVAlong(this->AlongX); }
  vec2 UVAlongY() const { return this->UVAlong(this->AlongY); }
  vec2 UVAlong(vec3 step) const { return vec2(dot(this->GradU, step), dot(this->GradV, step)); }
};

vec3 RandomUnit(std::mt19937& random)
{
  std::normal_distribution<float> normal;
  return glm::normalize(vec3(normal(random), normal(random), normal(random)));
}

// A random plane, texture axes in it of random lengths and skew (at least 15 degrees
// apart), and pixel steps along it at least 10 degrees apart.
Triangle RandomTriangle(std::mt19937& random)
{
  std::uniform_real_distribution<float> angle(0.0f, 6.2831853f);
  std::uniform_real_distribution<float> skew(0.26f, 2.88f);
  std::uniform_real_distribution<float> logLength(-3.0f, 3.0f);
  std::uniform_real_distribution<float> stepAngle(0.18f, 2.96f);
  Triangle triangle;
  triangle.Normal = RandomUnit(random);
  const vec3 first = glm::normalize(glm::cross(triangle.Normal, RandomUnit(random)));
  const vec3 second = glm::cross(triangle.Normal, first);
  auto inPlane = [&](float radians, float length) {
    return (first * std::cos(radians) + second * std::sin(radians)) * length;
  };
  const float uAngle = angle(random);
  triangle.GradU = inPlane(uAngle, std::exp(logLength(random)));
  triangle.GradV = inPlane(uAngle + skew(random), std::exp(logLength(random)));
  const float xAngle = angle(random);
  triangle.AlongX = inPlane(xAngle, std::exp(logLength(random)));
  triangle.AlongY = inPlane(xAngle + stepAngle(random), std::exp(logLength(random)));
  return triangle;
}

// Relative agreement of a solved axis with the exact gradient.
float Mismatch(vec3 solved, vec3 exact)
{
  return glm::length(solved - exact) / glm::length(exact);
}

TEST(ReliefDerivativeFrame, ReproducesTheTrianglesMappingAgainstItsFaceNormal)
{
  std::mt19937 random(3);
  float worst = 0.0f;
  for (int k = 0; k < 10000; ++k)
  {
    const Triangle t = RandomTriangle(random);
    const Shader::ReliefAxes axes = Shader::reliefDerivativeAxes(
      t.AlongX, t.AlongY, t.UVAlongX(), t.UVAlongY(), t.Normal);
    ASSERT_TRUE(axes.usable) << "triangle " << k;
    worst = std::max({ worst, Mismatch(axes.u, t.GradU), Mismatch(axes.v, t.GradV) });
  }
  EXPECT_LT(worst, 1e-3f);
}

TEST(ReliefDerivativeFrame, SkewedTextureAxesAreNotProjectedOnTheSteps)
{
  // u along x, v at 45 degrees: Tichenor's (2012) projection on normalized dFdx, dFdy (here
  // x and y) would give v no change along x; the exact mapping has one
  Triangle t;
  t.Normal = vec3(0.0f, 0.0f, 1.0f);
  t.GradU = vec3(4.0f, 0.0f, 0.0f);
  t.GradV = vec3(-4.0f, 4.0f, 0.0f);
  t.AlongX = vec3(0.01f, 0.0f, 0.0f);
  t.AlongY = vec3(0.0f, 0.01f, 0.0f);
  const Shader::ReliefAxes axes =
    Shader::reliefDerivativeAxes(t.AlongX, t.AlongY, t.UVAlongX(), t.UVAlongY(), t.Normal);
  ASSERT_TRUE(axes.usable);
  EXPECT_LT(Mismatch(axes.v, t.GradV), 1e-5f);
  // a step along the true u axis moves v by nothing
  EXPECT_NEAR(dot(axes.v, vec3(1.0f, 1.0f, 0.0f)), 0.0f, 1e-4f);
}

TEST(ReliefDerivativeFrame, InterpolatedNormalGivesTheMappingProjectedAlongIt)
{
  // a smooth normal tilted off the face: moving along it leaves (u, v) unchanged, and
  // the steps on the face keep their texture changes
  std::mt19937 random(5);
  for (int k = 0; k < 1000; ++k)
  {
    const Triangle t = RandomTriangle(random);
    const vec3 tilted = glm::normalize(t.Normal + 0.5f * RandomUnit(random));
    if (dot(tilted, t.Normal) < 0.3f)
    {
      continue;
    }
    const Shader::ReliefAxes axes =
      Shader::reliefDerivativeAxes(t.AlongX, t.AlongY, t.UVAlongX(), t.UVAlongY(), tilted);
    ASSERT_TRUE(axes.usable);
    const float scale = glm::length(t.GradU) + glm::length(t.GradV);
    EXPECT_NEAR(dot(axes.u, tilted) / scale, 0.0f, 1e-4f);
    EXPECT_NEAR(dot(axes.v, tilted) / scale, 0.0f, 1e-4f);
    const vec2 uvX = t.UVAlongX();
    EXPECT_NEAR(dot(axes.u, t.AlongX), uvX.x, 1e-3f * std::abs(uvX.x) + 1e-4f);
    EXPECT_NEAR(dot(axes.v, t.AlongX), uvX.y, 1e-3f * std::abs(uvX.y) + 1e-4f);
  }
}

TEST(ReliefDerivativeFrame, ScaleFreeFromMicrometresToKilometres)
{
  std::mt19937 random(7);
  const Triangle t = RandomTriangle(random);
  for (float scale : { 1e-6f, 1.0f, 1e3f })
  {
    const Shader::ReliefAxes axes = Shader::reliefDerivativeAxes(
      t.AlongX * scale, t.AlongY * scale, t.UVAlongX(), t.UVAlongY(), t.Normal);
    ASSERT_TRUE(axes.usable) << "scale " << scale;
    EXPECT_LT(Mismatch(axes.u * scale, t.GradU), 1e-3f) << "scale " << scale;
  }
}

void ExpectUnusable(vec3 alongX, vec3 alongY, vec2 uvAlongX, vec2 uvAlongY, vec3 normal)
{
  const Shader::ReliefAxes axes =
    Shader::reliefDerivativeAxes(alongX, alongY, uvAlongX, uvAlongY, normal);
  EXPECT_FALSE(axes.usable);
  // the shader shades such fragments plainly; the axes stay finite and tilt nothing
  EXPECT_EQ(axes.u, vec3(0.0f));
  EXPECT_EQ(axes.v, vec3(0.0f));
}

TEST(ReliefDerivativeFrame, DegenerateDerivativesHoldNoMapping)
{
  const vec3 x(0.01f, 0.0f, 0.0f);
  const vec3 y(0.0f, 0.01f, 0.0f);
  const vec3 n(0.0f, 0.0f, 1.0f);
  // texture coordinates constant over the triangle
  ExpectUnusable(x, y, vec2(0.0f), vec2(0.0f), n);
  // texture coordinates along a line (u = v): no area in texture space
  ExpectUnusable(x, y, vec2(0.02f, 0.02f), vec2(0.01f, 0.01f), n);
  // steps along one line: no area on screen
  ExpectUnusable(x, x * 2.0f, vec2(0.02f, 0.0f), vec2(0.0f, 0.02f), n);
  // a normal in the face's plane
  ExpectUnusable(x, y, vec2(0.02f, 0.0f), vec2(0.0f, 0.02f), vec3(1.0f, 0.0f, 0.0f));
  // a zero normal
  ExpectUnusable(x, y, vec2(0.02f, 0.0f), vec2(0.0f, 0.02f), vec3(0.0f));
  // not finite
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float infinity = std::numeric_limits<float>::infinity();
  ExpectUnusable(vec3(nan), y, vec2(0.02f, 0.0f), vec2(0.0f, 0.02f), n);
  ExpectUnusable(x, y, vec2(infinity, 0.0f), vec2(0.0f, 0.02f), n);
}

TEST(ReliefDerivativeFrame, UnitOrFallsBackOnVectorsWithoutDirection)
{
  const vec3 fallback(0.0f, 0.0f, 1.0f);
  EXPECT_EQ(Shader::reliefUnitOr(vec3(3.0f, 0.0f, 4.0f), fallback), vec3(0.6f, 0.0f, 0.8f));
  EXPECT_EQ(Shader::reliefUnitOr(vec3(0.0f), fallback), fallback);
  EXPECT_EQ(
    Shader::reliefUnitOr(vec3(std::numeric_limits<float>::quiet_NaN()), fallback), fallback);
}

// A fragment of the face z = 0 seen along `view`, pixel steps along x and y, for
// either configuration's mirror.
template <typename Fragment>
Fragment FaceFragment(vec3 view)
{
  Fragment fragment{};
  fragment.viewVC = view;
  fragment.positionAlongX = vec3(0.01f, 0.0f, 0.0f);
  fragment.positionAlongY = vec3(0.0f, 0.01f, 0.0f);
  fragment.tcoordAlongX = vec2(0.02f, 0.0f);
  fragment.tcoordAlongY = vec2(0.0f, 0.02f);
  fragment.frontFacing = true;
  fragment.depthScale = 0.05f;
  fragment.deepest = 1.0f;
  return fragment;
}

TEST(ReliefDerivativeFrame, DepthFollowsTheVertexNormalOnlyWhereTheMeshHasThem)
{
  // the face's frame ignores a vertex normal; the smooth frame measures depth along it
  // while it faces the viewer, and along the face's normal where it turns away
  namespace face = ReliefCpuMirror::Derivative;
  namespace smooth = ReliefCpuMirror::DerivativeNormals;
  const vec3 view = glm::normalize(vec3(0.3f, 0.0f, -1.0f));
  const vec3 tilted = glm::normalize(vec3(0.2f, 0.0f, 1.0f));
  const face::ReliefFrame flat =
    face::reliefDerivativeFrame(FaceFragment<face::ReliefFragment>(view), tilted);
  EXPECT_TRUE(flat.usable);
  EXPECT_EQ(flat.normal, vec3(0.0f, 0.0f, 1.0f));
  const auto fragment = FaceFragment<smooth::ReliefFragment>(view);
  const smooth::ReliefFrame frame = smooth::reliefDerivativeFrame(fragment, tilted);
  EXPECT_TRUE(frame.usable);
  EXPECT_NEAR(glm::length(frame.normal - tilted), 0.0f, 1e-6f);
  // the axes stay perpendicular to the normal depth is measured along
  EXPECT_NEAR(dot(frame.axisU, frame.normal), 0.0f, 1e-5f);
  // a normal turned away from the viewer: the face's
  const vec3 away = glm::normalize(vec3(0.99f, 0.0f, 0.1f));
  EXPECT_EQ(smooth::reliefDerivativeFrame(fragment, away).normal, vec3(0.0f, 0.0f, 1.0f));
  // a flat frame's view ray descends one unit of depth per unit of t, and the hit's
  // distance is its depth over the ray's descent
  const smooth::ReliefRay ray = smooth::reliefFrameViewRay(frame, fragment);
  EXPECT_FLOAT_EQ(ray.direction.z, 1.0f);
  smooth::ReliefHit hit{};
  hit.position = smooth::reliefRayAt(ray, 0.5f);
  EXPECT_NEAR(smooth::reliefFrameHitDistance(frame, fragment, ray, hit),
    0.5f * fragment.depthScale / -dot(view, frame.normal), 1e-6f);
  EXPECT_FALSE(smooth::reliefFrameRayLeft(frame, ray, hit));
}
}
