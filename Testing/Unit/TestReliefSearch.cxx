// The searches of vtkReliefSearch.glsl, run on the CPU through the same source the
// GPU compiles, against intersections known exactly.
#include "ReliefCpuMirror.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
using namespace ReliefCpuMirror;

constexpr int RayCount = 10000;
constexpr float Pi = 3.14159265358979f;

// Random view rays entering the relief inside [uvMin, uvMax]^2 whose texture-space run
// per unit depth is at most maxRun.
std::vector<ReliefRay> RandomViewRays(float uvMin, float uvMax, float maxRun, unsigned seed)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<float> entry(uvMin, uvMax);
  std::uniform_real_distribution<float> run(0.0f, maxRun);
  std::uniform_real_distribution<float> azimuth(0.0f, 2.0f * Pi);
  std::vector<ReliefRay> rays;
  for (int i = 0; i < RayCount; ++i)
  {
    const float length = run(generator);
    const float angle = azimuth(generator);
    rays.push_back(reliefViewRay(vec2(entry(generator), entry(generator)),
      vec3(length * std::cos(angle), length * std::sin(angle), 1.0f)));
  }
  return rays;
}

// Ground truth on the bilinear field: the first sign change of (ray depth - field
// depth) found by dense marching, then bisected to float precision.
float ReferenceHit(const ReliefRay& ray)
{
  constexpr int Steps = 20000;
  float above = 0.0f;
  for (int i = 1; i <= Steps; ++i)
  {
    const float t = static_cast<float>(i) / Steps;
    if (reliefBelowField(reliefRayAt(ray, t)))
    {
      float below = t;
      for (int k = 0; k < 40; ++k)
      {
        const float middle = 0.5f * (above + below);
        (reliefBelowField(reliefRayAt(ray, middle)) ? below : above) = middle;
      }
      return 0.5f * (above + below);
    }
    above = t;
  }
  return 1.0f;
}

// Half the final bracket of LinearBinary: its worst error in t when the first
// crossing is the only one inside its linear step.
float LinearBinaryBound(int linearSteps, int binarySteps)
{
  return 0.5f / (linearSteps * std::ldexp(1.0f, binarySteps)) + 1e-5f;
}

class ReliefSearch : public ::testing::Test
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

TEST_F(ReliefSearch, ViewRayRunsFromTheSurfaceToDepthOne)
{
  const ReliefRay ray = reliefViewRay(vec2(0.25f, 0.75f), vec3(0.2f, -0.1f, 0.5f));
  EXPECT_FLOAT_EQ(ray.origin.z, 0.0f);
  EXPECT_FLOAT_EQ(reliefRayAt(ray, 1.0f).z, 1.0f);
  EXPECT_FLOAT_EQ(ray.direction.x, 0.4f);
  EXPECT_FLOAT_EQ(ray.direction.y, -0.2f);

  const ReliefRay grazing = reliefViewRay(vec2(0.0f), vec3(1.0f, 0.0f, 0.0f));
  EXPECT_TRUE(std::isfinite(grazing.direction.x));
  EXPECT_LE(grazing.direction.x, 1001.0f);
  const ReliefRay backward = reliefViewRay(vec2(0.0f), vec3(0.0f, 0.0f, -1.0f));
  EXPECT_TRUE(std::isfinite(backward.direction.z));
}

TEST_F(ReliefSearch, ConstantDepthPlaneIsFoundWithinTheStepBounds)
{
  for (float depth : { 0.0f, 0.137f, 0.5f, 0.731f, 1.0f })
  {
    this->Use(DepthField::FromFunction(16, 16, [depth](float, float) { return depth; }));
    for (const ReliefRay& ray : RandomViewRays(0.0f, 1.0f, 3.0f, 1))
    {
      const ReliefHit linearBinary = reliefSearchLinearBinary(ray, 10, 5);
      ASSERT_TRUE(linearBinary.hit);
      ASSERT_NEAR(linearBinary.position.z, depth, LinearBinaryBound(10, 5));
      const ReliefHit linear = reliefSearchLinear(ray, 10, 0);
      ASSERT_TRUE(linear.hit);
      ASSERT_GE(linear.position.z, depth - 1e-6f);
      ASSERT_LT(linear.position.z, depth + 0.1f + 1e-6f);
    }
  }
}

TEST_F(ReliefSearch, SamplesAreCountedAndTheLinearSearchStopsAtTheFirstHit)
{
  this->Use(DepthField::FromFunction(8, 8, [](float, float) { return 0.35f; }));
  const ReliefRay ray = reliefViewRay(vec2(0.5f), vec3(0.1f, 0.0f, 1.0f));
  EXPECT_EQ(reliefSearchLinear(ray, 10, 0).samples, 4);           // steps 0.1 .. 0.4
  EXPECT_EQ(reliefSearchLinearBinary(ray, 10, 5).samples, 9);  // then 5 bisections
  EXPECT_EQ(reliefSearchLinearBinary(ray, 20, 0).samples, 7);  // steps 0.05 .. 0.35
}

TEST_F(ReliefSearch, SlopeIsRecoveredAnalytically)
{
  // depth = a + b u is reproduced exactly by bilinear interpolation between texel
  // centres, so the hit solves t = a + b (u0 + t dx).
  const float a = 0.1f;
  const float b = 0.8f;
  this->Use(DepthField::FromFunction(64, 64, [a, b](float u, float) { return a + b * u; }));
  for (const ReliefRay& ray : RandomViewRays(0.3f, 0.6f, 0.25f, 2))
  {
    const float expected = (a + b * ray.origin.x) / (1.0f - b * ray.direction.x);
    ASSERT_NEAR(reliefSearchLinearBinary(ray, 10, 5).t, expected, LinearBinaryBound(10, 5));
    ASSERT_NEAR(reliefSearchLinearBinary(ray, 32, 8).t, expected, LinearBinaryBound(32, 8));
    const float linear = reliefSearchLinear(ray, 10, 0).t;
    ASSERT_GE(linear, expected - 1e-5f);
    ASSERT_LT(linear, expected + 0.1f + 1e-5f);
  }
}

TEST_F(ReliefSearch, SinusoidIsFoundWhereItsCrossingIsUnique)
{
  // With a run below 1 / (0.6 pi) per unit depth, ray depth minus field depth grows
  // monotonically, so the first crossing is the only one and bisection must find it.
  this->Use(DepthField::FromFunction(
    256, 256, [](float u, float v) { return 0.5f + 0.15f * std::sin(2.0f * Pi * u) +
                                          0.15f * std::sin(2.0f * Pi * v); }));
  for (const ReliefRay& ray : RandomViewRays(0.0f, 1.0f, 0.5f, 3))
  {
    const float expected = ReferenceHit(ray);
    ASSERT_NEAR(reliefSearchLinearBinary(ray, 10, 5).t, expected, LinearBinaryBound(10, 5));
  }
}

TEST_F(ReliefSearch, StepWallStopsTheRayAtItsFace)
{
  // A raised block (depth 0.2) between u = 0.25 and 0.75 over a floor at depth 0.8;
  // rays start on the floor side and run toward +u into the block's face.
  this->Use(DepthField::FromFunction(
    128, 8, [](float u, float) { return (u >= 0.25f && u < 0.75f) ? 0.2f : 0.8f; }));
  std::mt19937 generator(4);
  std::uniform_real_distribution<float> entry(0.02f, 0.2f);
  std::uniform_real_distribution<float> run(0.1f, 0.6f);
  int hitsOnTheFace = 0;
  for (int i = 0; i < RayCount; ++i)
  {
    const ReliefRay ray = reliefViewRay(vec2(entry(generator), 0.5f), vec3(run(generator), 0.0f, 1.0f));
    const float expected = ReferenceHit(ray);
    ASSERT_NEAR(reliefSearchLinearBinary(ray, 10, 5).t, expected, LinearBinaryBound(10, 5));
    const vec3 hit = reliefRayAt(ray, expected);
    hitsOnTheFace += (hit.z > 0.21f && hit.z < 0.79f) ? 1 : 0;
  }
  EXPECT_GT(hitsOnTheFace, RayCount / 4); // the rays do test the vertical face
}

TEST_F(ReliefSearch, FlatSurfaceNeverShadowsItself)
{
  // the floor's depth falls inside a linear step, so Linear's hit lies below it
  this->Use(DepthField::FromFunction(32, 32, [](float, float) { return 0.63f; }));
  std::mt19937 generator(5);
  std::uniform_real_distribution<float> slope(-3.0f, 3.0f);
  for (const ReliefRay& ray : RandomViewRays(0.0f, 1.0f, 2.0f, 7))
  {
    const vec3 toLight(slope(generator), slope(generator), -1.0f);
    const ReliefHit linear = reliefSearchLinear(ray, 10, 0);
    ASSERT_EQ(reliefLightVisibility(linear.clear, toLight, 10), 1.0f);
    const ReliefHit linearBinary = reliefSearchLinearBinary(ray, 10, 5);
    ASSERT_EQ(reliefLightVisibility(linearBinary.clear, toLight, 10), 1.0f);
  }
}

TEST_F(ReliefSearch, WallCastsAShadowOnlyAwayFromTheLight)
{
  // a full-height wall at u in [0.45, 0.55] over a floor at depth 0.5
  this->Use(DepthField::FromFunction(
    256, 4, [](float u, float) { return (u > 0.45f && u < 0.55f) ? 0.0f : 0.5f; }));
  const vec3 rightOfWall(0.62f, 0.5f, 0.49f); // a clear point just above the floor
  EXPECT_EQ(reliefLightVisibility(rightOfWall, vec3(-1.0f, 0.0f, -1.0f), 10), 0.0f);
  EXPECT_EQ(reliefLightVisibility(rightOfWall, vec3(1.0f, 0.0f, -1.0f), 10), 1.0f);
  EXPECT_EQ(reliefLightVisibility(rightOfWall, vec3(-0.01f, 0.0f, -1.0f), 10), 1.0f);
  EXPECT_EQ(reliefLightVisibility(rightOfWall, vec3(-1.0f, 0.0f, 0.2f), 10), 0.0f); // below horizon
}

TEST_F(ReliefSearch, DomesLitFromALowAngleHaveNoShadowAcne)
{
  // hemispherical domes (radius 0.2 tile, full depth) on a floor: wherever a dome
  // faces the light well, the hit found by LinearBinary must be lit
  const float radius = 0.2f;
  this->Use(DepthField::FromFunction(256, 256, [radius](float u, float v) {
    const float du = u - 0.5f;
    const float dv = v - 0.5f;
    const float r2 = (du * du + dv * dv) / (radius * radius);
    return r2 < 1.0f ? 1.0f - std::sqrt(1.0f - r2) : 1.0f;
  }));
  // steep enough that no light ray reaches the neighbouring tile's dome
  const vec3 toLight = normalize(vec3(-1.0f, 0.3f, -1.2f));
  int litChecked = 0;
  for (const ReliefRay& ray : RandomViewRays(0.25f, 0.75f, 0.6f, 6))
  {
    const ReliefHit hit = reliefSearchLinearBinary(ray, 32, 5);
    const ReliefHit coarse = reliefSearchLinear(ray, 32, 0);
    const vec2 offset = vec2(hit.position.x - 0.5f, hit.position.y - 0.5f) / radius;
    const float r2 = dot(offset, offset);
    if (r2 > 0.9f)
    {
      continue; // keep to the dome, away from its rim
    }
    // the dome's upward normal in (u, v, -depth): (-grad depth, 1) up to scale
    const vec3 normal =
      normalize(vec3(offset.x / radius, offset.y / radius, std::sqrt(1.0f - r2)));
    if (dot(normal, vec3(toLight.x, toLight.y, -toLight.z)) < 0.3f)
    {
      continue;
    }
    ++litChecked;
    ASSERT_EQ(reliefLightVisibility(hit.clear, toLight, 32), 1.0f)
      << "at (" << hit.position.x << ", " << hit.position.y << ", " << hit.position.z << ")";
    ASSERT_EQ(reliefLightVisibility(coarse.clear, toLight, 32), 1.0f)
      << "Linear at (" << coarse.position.x << ", " << coarse.position.y << ")";
  }
  EXPECT_GT(litChecked, 1000);
}
