// The exact searches of vtkReliefGridSearch.glsl (and the fixed-step ones for
// comparison), run on the CPU through the very source the GPU compiles, against the
// brute-force reference of ReliefSearchReference.h.
#include "ReliefSearchReference.h"

#include <random>

namespace
{
using namespace ReliefCpuMirror;

class ReliefExactSearch : public ::testing::Test
{
protected:
  static void SetUpTestSuite() { AllScenes = new std::vector<Scene>(Scenes()); }
  static void TearDownTestSuite()
  {
    delete AllScenes;
    AllScenes = nullptr;
  }
  static void Use(const Scene& scene)
  {
    CurrentField = &scene.Field;
    CurrentPyramid = &scene.Pyramid;
  }
  static std::vector<Scene>* AllScenes;
};
std::vector<Scene>* ReliefExactSearch::AllScenes = nullptr;

}

TEST_F(ReliefExactSearch, ReferenceSolvesAPlaneAndASlope)
{
  DepthField slope = DepthField::FromFunction(16, 16, [](float u, float) { return 0.2f + 0.5f * u; });
  const ReliefRay ray = reliefViewRay(vec2(0.25f, 0.5f), vec3(0.3f, 0.1f, 1.0f));
  // t = 0.2 + 0.5 (0.25 + 0.3 t) away from the seam, where the bilinear field is the slope
  EXPECT_NEAR(ReferenceHit(slope, ray), (0.2 + 0.5 * 0.25) / (1.0 - 0.5 * 0.3), 1e-6);
  DepthField plane = DepthField::FromFunction(8, 8, [](float, float) { return 0.375f; });
  EXPECT_NEAR(ReferenceHit(plane, ray), 0.375, 1e-7);
}

TEST_F(ReliefExactSearch, ReferenceCatchesTheSaddleThatRasterizationMisses)
{
  // Baboud and Decoret 2006, Fig. 3: a ray crossing a saddle cell between two centrelines, above
  // the field at both, dips below the patch in between.
  DepthField saddle;
  saddle.Width = 2;
  saddle.Height = 2;
  saddle.Depths = { 0.0f, 1.0f, 1.0f, 0.0f }; // (0,0)=0, (1,0)=1, (0,1)=1, (1,1)=0
  // along the cell's anti-diagonal, from texel (0, 1) to (1, 0), the patch is 1 deep at
  // both ends and 0.5 at the middle: a ray at depth 0.6 is above at the ends only
  ReliefRay ray;
  ray.origin = vec3((0.02f + 0.5f) / 2.0f, (0.98f + 0.5f) / 2.0f, 0.6f);
  ray.direction = vec3(0.48f, -0.48f, 0.01f);
  ray.bend = 0.0f;
  ray.exact = vec4(0.0f, 0.0f, 0.0f, 0.0f);
  const double t = ReferenceHit(saddle, ray);
  EXPECT_GT(t, 0.2);
  EXPECT_LT(t, 0.5);
  CurrentField = &saddle;
  EXPECT_NEAR(reliefSearchExactDDA(ray, 0, 0).t, t, 1e-4);
}

TEST_F(ReliefExactSearch, ExactDDAMatchesTheReferenceEverywhere)
{
  ExpectExact(*AllScenes, "ExactDDA",
    [](const ReliefRay& ray) { return reliefSearchExactDDA(ray, 0, 0); });
}

TEST_F(ReliefExactSearch, MaximumMipmapMatchesTheReferenceEverywhere)
{
  ExpectExact(*AllScenes, "MaximumMipmap",
    [](const ReliefRay& ray) { return reliefSearchMaximumMipmap(ray, 0, 0); });
}

TEST_F(ReliefExactSearch, ExactSearchesKeepTheirHitsOnGrazingRaysThousandsOfCellsLong)
{
  ExpectGrazingHits(
    *AllScenes, "ExactDDA", [](const ReliefRay& ray) { return reliefSearchExactDDA(ray, 0, 0); });
  ExpectGrazingHits(*AllScenes, "MaximumMipmap",
    [](const ReliefRay& ray) { return reliefSearchMaximumMipmap(ray, 0, 0); });
}

TEST_F(ReliefExactSearch, MaximumMipmapTakesFewerSamplesThanExactDDAAtGrazingAngles)
{
  Use((*AllScenes)[5]); // the terrain
  long dda = 0;
  long mipmap = 0;
  std::mt19937 generator(21);
  std::uniform_real_distribution<float> entry(0.0f, 1.0f);
  for (int i = 0; i < 1000; ++i)
  {
    const ReliefRay ray =
      reliefViewRay(vec2(entry(generator), entry(generator)), vec3(2.0f, 0.7f, 1.0f));
    dda += reliefSearchExactDDA(ray, 0, 0).samples;
    mipmap += reliefSearchMaximumMipmap(ray, 0, 0).samples;
  }
  EXPECT_LT(mipmap, dda / 2) << "DDA " << dda << ", maximum mipmap " << mipmap;
}

TEST_F(ReliefExactSearch, AFloorAtTheDeepestLevelIsMetAtTheEndOfTheRay)
{
  // depth 1 is met at t = 1 exactly, where rounding may let the cell tests pass it: the
  // hit must still be a hit, with its clear point above it (else it shadows itself)
  Scene floor = MakeScene("floor", DepthField::FromFunction(64, 64, [](float, float) { return 1.0f; }));
  Use(floor);
  for (const ReliefRay& ray : ViewRays(300, 0.1f))
  {
    for (const ReliefHit& hit :
      { reliefSearchExactDDA(ray, 0, 0), reliefSearchMaximumMipmap(ray, 0, 0) })
    {
      ASSERT_TRUE(hit.hit);
      ASSERT_NEAR(hit.t, 1.0f, 1e-5f);
      ASSERT_LT(hit.clear.z, hit.position.z);
    }
  }
}

TEST_F(ReliefExactSearch, ExactSearchesFindWhereRisingRaysEnterTheField)
{
  // an impostor's views behind the object are searched along rays that rise toward their
  // face (vtkReliefImpostorFrame.glsl): from any depth, level or rising, the first point on
  // or below the field, or a miss
  std::mt19937 generator(41);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (const Scene& scene : *AllScenes)
  {
    Use(scene);
    int wrong = 0;
    for (int k = 0; k < 2000; ++k)
    {
      const float azimuth = 2.0f * float(Pi) * unit(generator);
      const float run = 0.02f + 0.5f * unit(generator);
      ReliefRay ray = reliefViewRay(vec2(unit(generator), unit(generator)), vec3(0.0f));
      ray.origin.z = unit(generator);
      ray.direction = vec3(run * std::cos(azimuth), run * std::sin(azimuth),
        k % 8 == 0 ? 0.0f : -ray.origin.z * unit(generator));
      const double reference = ReferenceHit(scene.Field, ray);
      const bool meets = reference < 1.0;
      for (const ReliefHit& hit :
        { reliefSearchExactDDA(ray, 0, 0), reliefSearchMaximumMipmap(ray, 0, 0) })
      {
        const bool right = hit.hit == meets &&
          (!meets || HitError(scene.Field, ray, hit.t, reference) <= Tolerance);
        if (!right && ++wrong <= 3)
        {
          ADD_FAILURE() << scene.Name << ": t " << hit.t << (hit.hit ? " (hit)" : " (miss)")
                        << " against " << reference << " for the ray from (" << ray.origin.x
                        << ", " << ray.origin.y << ", " << ray.origin.z << ") along ("
                        << ray.direction.x << ", " << ray.direction.y << ", "
                        << ray.direction.z << ")";
        }
      }
    }
    EXPECT_EQ(wrong, 0) << scene.Name << ", of 2000 rays";
  }
}

// The scenes with their cone maps and slope pyramids, made once (ReliefConeScenes).
class ReliefTiledSearch : public ReliefConeScenes
{
};

// Texture coordinates a thousand tiles out, as a mesh's may be: every exact grid search
// finds there the very hit it finds on the same ray moved back into the first tile, as
// it takes its texel coordinates from the first tile (reliefGridRay). Taken where the ray
// is, they are as much as 1/32 texel apart on these fields, and hits came out up to 180
// texels off the brute-force one.
TEST_F(ReliefTiledSearch, ExactSearchesFindTheSameHitsFarOutInTheTiling)
{
  const std::pair<const char*, Search> searches[] = { { "ExactDDA", &reliefSearchExactDDA },
    { "MaximumMipmap", &reliefSearchMaximumMipmap }, { "ConeStep", &reliefSearchConeStep },
    { "SafetyRadius", &reliefSearchSafetyRadius }, { "SlopeMipmap", &reliefSearchSlopeMipmap },
    { "Automatic", &reliefSearchAutomatic },
    { "Automatic over slopes", &reliefSearchAutomaticOverSlopes } };
  for (size_t k = 0; k < AllScenes->size(); ++k)
  {
    const Scene& scene = (*AllScenes)[k];
    Use(k);
    const SafetyRadiusMap radii = RadiiOf(scene.Field, 0.0);
    CurrentRadii = &radii;
    for (const auto& [method, search] : searches)
    {
      int different = 0;
      for (ReliefRay far : ViewRays(31, 0.1f))
      {
        far.origin.x += 1000.0f;
        far.origin.y -= 700.0f;
        ReliefRay near = far;
        near.origin.x -= std::floor(far.origin.x); // exact
        near.origin.y -= std::floor(far.origin.y);
        const ReliefHit farHit = search(far, 0, 0);
        const ReliefHit nearHit = search(near, 0, 0);
        different += farHit.t == nearHit.t && farHit.hit == nearHit.hit ? 0 : 1;
      }
      EXPECT_EQ(different, 0) << method << " on " << scene.Name << ", of " << RayCount
                              << " rays";
    }
  }
  CurrentRadii = nullptr;
}

// A field clamped at its edges (an impostor's views) is searched where the ray is: rays
// from a hair before its edge, where rounding puts an impostor's, are not moved into
// the tile, which would start them at the opposite edge. They stay over the field, as an
// impostor's do (its segments end at its box).
TEST_F(ReliefExactSearch, ExactSearchesReadAClampedFieldWhereTheRayIs)
{
  Scene clamped = (*AllScenes)[5]; // the terrain
  clamped.Field.ClampToEdge = true;
  Use(clamped);
  std::mt19937 generator(41);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  int wrong = 0;
  for (int k = 0; k < 1000; ++k)
  {
    const float along = 0.2f + 0.6f * unit(generator);
    const float across = 0.2f * (unit(generator) - 0.5f);
    const ReliefRay ray = k % 2 ? reliefViewRay(vec2(-1e-7f, along), vec3(0.3f, across, 1.0f))
                                : reliefViewRay(vec2(along, -1e-7f), vec3(across, 0.3f, 1.0f));
    const double reference = ReferenceHit(clamped.Field, ray);
    for (Search search : { &reliefSearchExactDDA, &reliefSearchMaximumMipmap })
    {
      wrong += HitError(clamped.Field, ray, search(ray, 0, 0).t, reference) <= Tolerance ? 0 : 1;
    }
  }
  EXPECT_EQ(wrong, 0) << "of 2000 hits";
}

TEST_F(ReliefExactSearch, FixedStepMethodsMissRatesAreMeasured)
{
  // Not exact by design: the share of rays whose hit is off by more than a texel is
  // printed for the record; the test only checks that every search reports a hit.
  unsigned seed = 200;
  for (const Scene& scene : *AllScenes)
  {
    Use(scene);
    int missed[3] = { 0, 0, 0 };
    for (const ReliefRay& ray : ViewRays(seed++, 0.1f))
    {
      const double reference = ReferenceHit(scene.Field, ray);
      const ReliefHit hits[3] = { reliefSearchLinear(ray, 10, 0), reliefSearchLinearBinary(ray, 10, 5),
        reliefSearchSecant(ray, 10, 5) };
      for (int k = 0; k < 3; ++k)
      {
        ASSERT_TRUE(std::isfinite(hits[k].t));
        missed[k] += HitError(scene.Field, ray, hits[k].t, reference) > 1.0 ? 1 : 0;
      }
    }
    std::cout << scene.Name << ": rays off by more than a texel: Linear(10) "
              << 100.0 * missed[0] / RayCount << "%, LinearBinary(10+5) "
              << 100.0 * missed[1] / RayCount << "%, Secant(10+5) "
              << 100.0 * missed[2] / RayCount << "%\n";
  }
}

TEST_F(ReliefExactSearch, SecantRecoversALinearSlopeInOneStep)
{
  // a slope is linear along the ray inside one cell row, so the secant is exact there
  DepthField slope = DepthField::FromFunction(256, 4, [](float u, float) { return 0.1f + 0.8f * u; });
  CurrentField = &slope;
  const ReliefRay ray = reliefViewRay(vec2(0.3f, 0.5f), vec3(0.05f, 0.0f, 1.0f));
  const float expected = (0.1f + 0.8f * 0.3f) / (1.0f - 0.8f * 0.05f);
  EXPECT_NEAR(reliefSearchSecant(ray, 10, 0).t, expected, 1e-5);
  EXPECT_GT(std::abs(reliefSearchLinearBinary(ray, 10, 0).t - expected), 1e-3);
}

TEST(ReliefMaximumMipmap, LevelsFollowOpenGLMipmapSizes)
{
  int origin[2];
  int size[2];
  EXPECT_EQ(vtkMaximumMipmapFilter::GetTopLevel(100, 37), 6);
  ASSERT_TRUE(vtkMaximumMipmapFilter::GetLevelPlacement(100, 37, 1, origin, size));
  EXPECT_EQ(size[0], 50);
  EXPECT_EQ(size[1], 18);
  EXPECT_EQ(origin[0], 100);
  ASSERT_TRUE(vtkMaximumMipmapFilter::GetLevelPlacement(100, 37, 6, origin, size));
  EXPECT_EQ(size[0], 1);
  EXPECT_EQ(size[1], 1);
  EXPECT_FALSE(vtkMaximumMipmapFilter::GetLevelPlacement(100, 37, 7, origin, size));
  int atlas[2];
  vtkMaximumMipmapFilter::GetAtlasSize(8, 1, atlas);
  EXPECT_EQ(atlas[0], 12);
  EXPECT_EQ(atlas[1], 3);
}

TEST(ReliefMaximumMipmap, EveryNodeHoldsTheHighestPointOfItsCells)
{
  const DepthField field = RandomField(23, 10, 31, 0.0f, 1.0f);
  const DepthPyramid pyramid = PyramidOf(field);
  for (int level = 0; level <= pyramid.Top(); ++level)
  {
    const int span = 1 << level;
    for (int j = 0; j < pyramid.Heights[level]; ++j)
    {
      for (int i = 0; i < pyramid.Widths[level]; ++i)
      {
        const int lastI = i == pyramid.Widths[level] - 1 ? field.Width : (i + 1) * span;
        const int lastJ = j == pyramid.Heights[level] - 1 ? field.Height : (j + 1) * span;
        float least = 1.0f;
        for (int y = j * span; y < lastJ; ++y)
        {
          for (int x = i * span; x < lastI; ++x)
          {
            least = std::min({ least, field.At(x, y), field.At(x + 1, y), field.At(x, y + 1),
              field.At(x + 1, y + 1) });
          }
        }
        ASSERT_EQ(pyramid.At(vec2(i, j), level), least) << "level " << level << " node " << i
                                                        << ", " << j;
      }
    }
  }
}
