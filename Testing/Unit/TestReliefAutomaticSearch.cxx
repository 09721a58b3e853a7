// The Automatic search of vtkReliefAutomaticSearch.glsl, run on the CPU through the
// very source the GPU compiles, against the brute-force reference of
// ReliefSearchReference.h: exact where the screen run is unknown, within the screen
// tolerance at every run (the bound that keeps its regimes from popping), over either
// acceleration (AutomaticAcceleration), each regime where its costs say, and the curved
// variant within the tolerance on straight and curved rays.
#include "ReliefSearchReference.h"

#include <limits>
#include <set>

namespace
{
using namespace ReliefCpuMirror;

class ReliefAutomaticSearch : public ReliefConeScenes
{
};

// Automatic over each acceleration its long straight runs may step over.
struct Acceleration
{
  const char* Name;
  ReliefHit (*Search)(ReliefRay ray, int linearSteps, int refinementSteps);
};
const Acceleration Accelerations[] = { { "Automatic over cones", reliefSearchAutomatic },
  { "Automatic over slopes", reliefSearchAutomaticOverSlopes } };

// The ray with its run on screen: `tolerances` screen tolerances from t = 0 to 1.
ReliefRay WithScreenRun(ReliefRay ray, float tolerances)
{
  ray.screenRun = tolerances;
  return ray;
}

// Manhattan cells of the ray's whole run.
float Cells(const ReliefRay& ray)
{
  const vec2 run = reliefRunTexels(ray);
  return run.x + run.y;
}

// How far on screen, in tolerances, a hit at t lies from one at `reference`.
double ScreenError(const ReliefRay& ray, double t, double reference)
{
  return std::abs(t - reference) * ray.screenRun;
}

TEST(ReliefScreenRun, SolvesForThePixelOffsetOfTheRun)
{
  // one pixel along x moves (u, v) by (0.01, 0), along y by (0.005, 0.02): a skewed
  // footprint; the run (0.03, 0.04) is the offset (2, 2) pixels, 2 sqrt(2) of them
  const vec2 alongX(0.01f, 0.0f);
  const vec2 alongY(0.005f, 0.02f);
  const vec2 run(0.03f, 0.04f);
  EXPECT_NEAR(reliefScreenRun(run, alongX, alongY, 1.0f), 2.0 * std::sqrt(2.0), 1e-5);
  EXPECT_NEAR(reliefScreenRun(run, alongX, alongY, 0.5f), 4.0 * std::sqrt(2.0), 1e-5);
  // no tolerance, or derivatives that hold no mapping: not known, which asks for exactness
  EXPECT_EQ(reliefScreenRun(run, alongX, alongY, 0.0f), RELIEF_UNKNOWN_RUN);
  EXPECT_EQ(reliefScreenRun(run, alongX, 2.0f * alongX, 0.5f), RELIEF_UNKNOWN_RUN);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(reliefScreenRun(vec2(nan, 0.04f), alongX, alongY, 0.5f), RELIEF_UNKNOWN_RUN);
}

TEST_F(ReliefAutomaticSearch, IsExactWhereTheScreenRunIsNotKnown)
{
  for (const Acceleration& over : Accelerations)
  {
    size_t k = 0;
    ExpectExact(*AllScenes, over.Name,
      [&over](const ReliefRay& ray) { return over.Search(ray, 0, 0); }, Tolerance,
      [&k](const Scene&) { Use(k++); });
  }
}

TEST_F(ReliefAutomaticSearch, KeepsEveryHitWithinTheToleranceAtEveryScreenRun)
{
  // below one tolerance the search is skipped, above it ends within the tolerance: at
  // every run, every hit lies within one tolerance of the reference on screen, so
  // crossing from one regime to the other cannot shift the picture by more
  for (size_t k = 0; k < AllScenes->size(); ++k)
  {
    Use(k);
    for (const Acceleration& over : Accelerations)
    {
      for (float run : { 0.3f, 0.99f, 1.01f, 3.0f, 40.0f })
      {
        int wrong = 0;
        for (const ReliefRay& view : ViewRays(400 + unsigned(k), 0.1f))
        {
          if (Cells(view) > RELIEF_AUTOMATIC_CONE_CELLS)
          {
            continue; // stepped in bounded cost (BoundsTheCostOfRaysThousandsOfCellsLong)
          }
          const ReliefRay ray = WithScreenRun(view, run);
          const ReliefHit hit = over.Search(ray, 0, 0);
          const double reference = ReferenceHit(*CurrentField, ray);
          const double error = ScreenError(ray, hit.t, reference);
          // beyond one tolerance also within 1/20 of the depth, for the depth it writes
          const double depthError =
            run > 1.0f ? std::abs(hit.t - reference) * ray.direction.z : 0.0;
          wrong += hit.hit && error <= 1.0 + 1e-3 && depthError <= 0.05 + 1e-4 ? 0 : 1;
        }
        EXPECT_EQ(wrong, 0) << over.Name << " on " << (*AllScenes)[k].Name
                            << " at a screen run of " << run;
      }
    }
  }
}

TEST_F(ReliefAutomaticSearch, SpendsLeastWhereTheReliefIsBelowTheToleranceAndWalksShortRuns)
{
  Use(0);
  const ReliefRay steep = reliefViewRay(vec2(0.3f, 0.6f), vec3(0.01f, 0.005f, 1.0f));
  // (a ray on which ConeStep and SlopeMipmap take different samples, for the last check)
  const ReliefRay oblique = reliefViewRay(vec2(0.3f, 0.65f), vec3(0.3f, 0.2f, 1.0f));
  // within the tolerance: one secant step between the ray's ends
  EXPECT_EQ(reliefSearchAutomatic(WithScreenRun(oblique, 0.8f), 0, 0).samples, 3);
  // a run of a few cells: ExactDDA's walk, one sample a cell
  const ReliefRay walked = WithScreenRun(steep, 10.0f);
  EXPECT_EQ(
    reliefSearchAutomatic(walked, 0, 0).samples, reliefSearchExactDDA(walked, 0, 0).samples);
  // a long run: ConeStep, or SlopeMipmap, exact where the run is not known
  const ReliefRay stepped = WithScreenRun(oblique, RELIEF_UNKNOWN_RUN);
  const int coneSamples = reliefSearchConeStep(stepped, 0, 0).samples;
  const int slopeSamples = reliefSearchSlopeMipmap(stepped, 0, 0).samples;
  ASSERT_NE(coneSamples, slopeSamples); // so that each check below tells them apart
  EXPECT_EQ(reliefSearchAutomatic(stepped, 0, 0).samples, coneSamples);
  EXPECT_EQ(reliefSearchAutomaticOverSlopes(stepped, 0, 0).samples, slopeSamples);
}

TEST_F(ReliefAutomaticSearch, OverSlopesTakesFewerSamplesThanOverCones)
{
  // long runs (4 to 40 tolerances) of grazing rays: the regime the acceleration serves
  long cones = 0;
  long slopes = 0;
  for (size_t k = 0; k < AllScenes->size(); ++k)
  {
    Use(k);
    long fieldCones = 0;
    long fieldSlopes = 0;
    for (const ReliefRay& view : ViewRays(700 + unsigned(k), 0.1f))
    {
      const vec2 cells = reliefRunTexels(view);
      if (cells.x + cells.y <= RELIEF_AUTOMATIC_WALK_CELLS ||
        cells.x + cells.y > RELIEF_AUTOMATIC_CONE_CELLS)
      {
        continue; // the other regimes, the same for both
      }
      for (float run : { 4.0f, 40.0f })
      {
        fieldCones += reliefSearchAutomatic(WithScreenRun(view, run), 0, 0).samples;
        fieldSlopes += reliefSearchAutomaticOverSlopes(WithScreenRun(view, run), 0, 0).samples;
      }
    }
    std::cout << (*AllScenes)[k].Name << ": samples, Automatic over slopes " << fieldSlopes
              << ", over cones " << fieldCones << "\n";
    cones += fieldCones;
    slopes += fieldSlopes;
  }
  EXPECT_LT(slopes, cones);
}

TEST_F(ReliefAutomaticSearch, TakesNoMoreSamplesThanConeStepWhereBothAreExact)
{
  for (size_t k = 0; k < AllScenes->size(); ++k)
  {
    Use(k);
    long automatic = 0;
    long minified = 0; // a texel half a tolerance wide on screen
    long dda = 0;
    long cone = 0;
    // rays from straight down to grazing, on a relief a tenth of a tile deep and a
    // hundredth: many runs a few cells long
    for (float depth : { 0.1f, 0.01f })
    {
      for (const ReliefRay& view : ViewRays(500 + unsigned(k), depth))
      {
        if (Cells(view) > RELIEF_AUTOMATIC_CONE_CELLS)
        {
          continue; // stepped in bounded cost, not exactly
        }
        const ReliefRay ray = WithScreenRun(view, RELIEF_UNKNOWN_RUN);
        automatic += reliefSearchAutomatic(ray, 0, 0).samples;
        const vec2 cells = reliefRunTexels(view);
        minified +=
          reliefSearchAutomatic(WithScreenRun(view, 0.5f * (cells.x + cells.y)), 0, 0).samples;
        dda += reliefSearchExactDDA(ray, 0, 0).samples;
        cone += reliefSearchConeStep(ray, 0, 0).samples;
      }
    }
    const std::string& name = (*AllScenes)[k].Name;
    std::cout << name << ": samples per ray, Automatic " << automatic / (2.0 * RayCount)
              << " (texels of half a tolerance " << minified / (2.0 * RayCount)
              << "), ExactDDA " << dda / (2.0 * RayCount) << ", ConeStep "
              << cone / (2.0 * RayCount) << "\n";
    // walking short runs instead of stepping cones saves samples on every field; a
    // tolerance wider than a texel ends some searches before their last cells
    EXPECT_LT(automatic, cone) << name;
    EXPECT_LE(minified, automatic) << name;
    if (name == "16-bit terrain" || name == "smooth" || name == "rivets")
    {
      EXPECT_LT(minified, automatic) << name;
    }
  }
}

TEST_F(ReliefAutomaticSearch, BoundsTheCostOfRaysThousandsOfCellsLong)
{
  // rays beyond 89 degrees, 10^3 to 10^5 cells long: at most 256 steps and 16 halvings
  for (size_t k = 0; k < AllScenes->size(); ++k)
  {
    Use(k);
    int longRays = 0;
    for (float descent : { 2e-3f, 1e-2f, 5e-2f })
    {
      const ReliefRay ray =
        WithScreenRun(reliefViewRay(vec2(0.3f, 0.7f), vec3(0.8f, 0.6f, descent)), 1e4f);
      if (Cells(ray) > RELIEF_AUTOMATIC_CONE_CELLS)
      {
        ++longRays;
        const ReliefHit hit = reliefSearchAutomatic(ray, 0, 0);
        EXPECT_TRUE(hit.hit) << (*AllScenes)[k].Name;
        EXPECT_LE(hit.samples, 256 + 16 + 1) << (*AllScenes)[k].Name;
      }
    }
    EXPECT_GT(longRays, 0) << (*AllScenes)[k].Name;
  }
}

TEST_F(ReliefAutomaticSearch, CurvedVariantKeepsStraightRaysWithinTheTolerance)
{
  // a texel two tolerances wide on screen: steps of half a texel, which find every
  // feature wider than a texel; on white noise, spikes and saddles a texel wide they pass
  // some tips (printed, not checked)
  const std::set<std::string> wideFeatures = { "smooth", "cliffs", "16-bit terrain", "rivets" };
  for (size_t k = 0; k < AllScenes->size(); ++k)
  {
    Use(k);
    int wrong = 0;
    for (const ReliefRay& view : ViewRays(600 + unsigned(k), 0.1f))
    {
      const ReliefRay ray = WithScreenRun(view, 2.0f * length(reliefRunTexels(view)) + 1.0f);
      const ReliefHit hit = reliefSearchAutomaticCurved(ray, 0, 0);
      wrong += hit.hit && ScreenError(ray, hit.t, ReferenceHit(*CurrentField, ray)) <= 1.0 ? 0 : 1;
    }
    const std::string& name = (*AllScenes)[k].Name;
    std::cout << name << ": " << wrong << " of " << RayCount
              << " rays off by more than the tolerance\n";
    if (wideFeatures.count(name))
    {
      EXPECT_LE(wrong, RayCount / 100) << name;
    }
  }
}

TEST_F(ReliefAutomaticSearch, CurvedVariantFollowsTheBendOfTheRay)
{
  // a level floor at depth 0.6 under a ray whose depth is 0.3 t + 0.5 t^2: it meets the
  // floor where t solves 0.5 t^2 + 0.3 t - 0.6 = 0
  const DepthField floor = DepthField::FromFunction(64, 64, [](float, float) { return 0.6f; });
  CurrentField = &floor;
  ReliefRay ray = reliefViewRay(vec2(0.2f, 0.4f), vec3(0.05f, 0.02f, 1.0f));
  ray.direction.z = 0.3f;
  ray.bend = 0.5f;
  const double exact = (-0.3 + std::sqrt(0.09 + 4.0 * 0.5 * 0.6)) / (2.0 * 0.5);
  for (float run : { 2.0f, 30.0f, 500.0f })
  {
    const ReliefHit hit = reliefSearchAutomaticCurved(WithScreenRun(ray, run), 0, 0);
    EXPECT_TRUE(hit.hit);
    // a quarter of the tolerance on screen, and 1/256 of the depth
    EXPECT_LE(std::abs(hit.t - exact) * run, 0.25) << run;
    EXPECT_LE(std::abs(hit.position.z - 0.6f), 1.0 / 256.0) << run;
  }
}
}
