// The path-feature search of vtkReliefPathSearch.glsl, run on the CPU through the very
// source the GPU compiles, on vtkPathFeatureTextureFilter's textures: analytic cases
// (a groove's floor, a V's wall, a revolved end, crossings, priorities, a crack, an
// overhang) and random rays against the marched reference of ReliefPathFixtures.h.
#include "ReliefMirrorMaps.h"
#include "ReliefPathFixtures.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

namespace
{
using namespace ReliefCpuMirror;
using namespace ReliefPathFixtures;

// A scene's textures, kept while its searches run.
struct Built
{
  vtkNew<vtkPathFeatureTextureFilter> Filter;
  PathTextures Textures;
  double Base = 0.0;
  double Deepest = 0.0;

  explicit Built(const Scene& scene, int resolution = 0)
  {
    this->Filter->SetPathsData(PathsData(scene.Paths));
    if (!scene.Profiles.empty())
    {
      this->Filter->SetProfilesData(ProfilesData(scene.Profiles));
    }
    this->Filter->SetGridResolution(resolution, resolution);
    this->Filter->Update();
    this->Textures = ReliefPathFixtures::Textures(this->Filter);
    this->Base = this->Filter->GetBaseDepth();
    this->Deepest = this->Filter->GetMaximumDepth();
    CurrentPaths = &this->Textures;
  }
};

ReliefRay Ray(vec2 uv, vec3 direction)
{
  return reliefViewRay(uv, direction);
}

// The depth a vertical ray at uv meets.
float DepthAt(vec2 uv)
{
  return reliefSearchPathFeatures(Ray(uv, vec3(0.0f, 0.0f, 1.0f)), 0, 0).position.z;
}

const std::vector<dvec2> VGroove = { { -1.0, 0.0 }, { 0.0, 1.0 }, { 1.0, 0.0 } };
const std::vector<dvec2> Ridge = { { -1.0, 0.0 }, { -0.5, -0.4 }, { 0.5, -0.4 }, { 1.0, 0.0 } };
// wider below than at its opening: a dovetail (Fig. 8's non-height-field profiles)
const std::vector<dvec2> Dovetail = { { -0.5, 0.0 }, { -1.0, 0.6 }, { 1.0, 0.6 }, { 0.5, 0.0 } };
}

namespace
{
// What AgreeWithTheReference found.
struct Agreement
{
  int Rays = 0;
  int Agreeing = 0; // within 1e-4 of the reference's t
  int Slivers = 0;  // stopped on matter thinner than the march's step, which it stepped over
  int OnField = 0;  // met no material deeper than 1e-4 below `base`: a relief base's field
};

// `count` random rays up to 80 degrees from the normal (`seed`) through `search`, against
// the marched reference down to tEnd; a ray that neither agrees nor stops on a sliver
// fails the test, `what` naming the case. The rays enter anywhere on the tile, or within
// `spread` of the points `around`, in turn.
Agreement AgreeWithTheReference(Search search, const Reference& reference, double tEnd,
  double base, int count, unsigned seed, const std::string& what,
  const std::vector<vec2>& around = {}, float spread = 0.0f)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Agreement agreement;
  for (int k = 0; k < count; ++k)
  {
    const float angle = 6.2831853f * unit(random);
    const float run = 0.3f * unit(random);
    vec2 uv(unit(random), unit(random));
    if (!around.empty())
    {
      uv = around[k % around.size()] + spread * (2.0f * uv - vec2(1.0f, 1.0f));
    }
    const ReliefRay ray = Ray(uv, vec3(run * std::cos(angle), run * std::sin(angle), 1.0f));
    const ReliefHit hit = search(ray, 0, 0);
    const glm::dvec3 origin(ray.origin);
    const glm::dvec3 direction(ray.direction);
    const double expected = reference.Hit(origin, direction, tEnd, 5e-4);
    if (!(expected >= 0.0) || !hit.hit)
    {
      ADD_FAILURE() << what << ": a ray that meets nothing (the reference at " << expected
                    << ", the search " << (hit.hit ? "hits" : "misses") << ")";
      continue;
    }
    agreement.Rays += 1;
    agreement.OnField +=
      reliefPathHitMaterial < 0.0f && hit.position.z > base + 1e-4 ? 1 : 0;
    if (std::abs(hit.t - expected) < 1e-4)
    {
      agreement.Agreeing += 1;
    }
    else if (hit.t < expected && reference.Solid(origin + (hit.t + 1e-5) * direction))
    {
      agreement.Slivers += 1;
    }
    else
    {
      ADD_FAILURE() << what << ": ray from " << ray.origin.x << " " << ray.origin.y
                    << " along " << ray.direction.x << " " << ray.direction.y << " hits at "
                    << hit.t << ", the reference at " << expected;
    }
  }
  return agreement;
}
}

TEST(ReliefPathSearch, GrooveFloorAndPlainSurface)
{
  Scene scene;
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1 });
  Built built(scene);
  EXPECT_EQ(built.Base, 0.0);
  EXPECT_NEAR(built.Deepest, 1.0, 1e-9);
  // the default groove is a half circle of 8 facets: 1 deep on its centre line
  EXPECT_NEAR(DepthAt(vec2(0.5f, 0.5f)), 1.0f, 1e-5f);
  // a vertex of the profile at x = -cos(pi/4)
  const float x = static_cast<float>(std::cos(M_PI / 4));
  EXPECT_NEAR(DepthAt(vec2(0.5f, 0.5f + 0.05f * x)), std::sin(M_PI / 4), 1e-5f);
  // beside the groove: the plain surface, lit as the plain surface
  const ReliefHit plain = reliefSearchPathFeatures(Ray(vec2(0.5f, 0.7f), vec3(0, 0, 1)), 0, 0);
  EXPECT_TRUE(plain.hit);
  EXPECT_NEAR(plain.position.z, 0.0f, 1e-6f);
  EXPECT_NEAR(reliefPathHitNormal.z, -1.0f, 1e-6f);
  EXPECT_EQ(reliefPathHitMaterial, -1.0f);
}

TEST(ReliefPathSearch, OverAVWallAndItsNormal)
{
  Scene scene;
  scene.Profiles = { VGroove };
  scene.Paths.push_back({ { { 0.2, 0.5 }, { 0.8, 0.5 } }, 0.2, 0 });
  Built built(scene);
  // the wall on the path's left (v > 0.5): depth = 1 - (v - 0.5) / 0.1
  EXPECT_NEAR(DepthAt(vec2(0.5f, 0.53f)), 0.7f, 1e-5f);
  // an oblique ray toward -v: v = 0.58 - 0.05 t at depth t meets the wall's
  // 1 - (v - 0.5) / 0.1 = 0.2 + 0.5 t at t = 0.4
  const ReliefHit hit = reliefSearchPathFeatures(Ray(vec2(0.5f, 0.58f), vec3(0, -0.05f, 1)), 0, 0);
  EXPECT_NEAR(hit.t, 0.4f, 1e-4f);
  EXPECT_NEAR(hit.position.z, 1.0f - (hit.position.y - 0.5f) / 0.1f, 1e-4f);
  // the wall's outward normal in (u, v, depth) points up the slope: -v and -depth
  // in proportion to the wall's gradient, depth falling 10 per unit of v
  const vec3 normal = normalize(reliefPathHitNormal);
  EXPECT_NEAR(normal.x, 0.0f, 1e-5f);
  EXPECT_NEAR(normal.y / normal.z, 10.0f, 1e-3f);
  EXPECT_LT(normal.z, 0.0f);
}

TEST(ReliefPathSearch, RevolvedEndsAndJoints)
{
  Scene scene;
  scene.Profiles = { VGroove };
  // an L: the corner's outside is round, its inside sharp
  scene.Paths.push_back({ { { 0.2, 0.3 }, { 0.6, 0.3 }, { 0.6, 0.7 } }, 0.2, 0 });
  Built built(scene);
  // beyond the start, 0.04 from the end point: the revolved V, 0.6 deep
  EXPECT_NEAR(DepthAt(vec2(0.16f, 0.3f)), 0.6f, 1e-5f);
  EXPECT_NEAR(DepthAt(vec2(0.2f - 0.03f, 0.3f + 0.04f)), 0.5f, 1e-5f);
  // past the corner's outside, 0.05 from the corner point diagonally
  const float d = 0.05f / std::sqrt(2.0f);
  EXPECT_NEAR(DepthAt(vec2(0.6f + d, 0.3f - d)), 0.5f, 1e-5f);
  // inside the corner, the deeper of the two pieces
  EXPECT_NEAR(DepthAt(vec2(0.58f, 0.33f)), 0.8f, 1e-5f);
  EXPECT_NEAR(DepthAt(vec2(0.1f, 0.3f)), 0.0f, 1e-6f);
}

// Where a straight path is split into pieces (MaximumElementLength: at u = 0.3, 0.5 and
// 0.7), each piece ends at the plane across the joint, its neighbour going on: the sweep.
// Revolved there, two notches beside the centre line (a profile whose inside does not
// reach its middle) would cut the centre line round the joint.
TEST(ReliefPathSearch, StraightJointsAreNotRevolved)
{
  Scene scene;
  scene.Profiles = { { { -1.0, 0.0 }, { -0.6, 0.5 }, { -0.2, 0.0 }, { 0.2, 0.0 }, { 0.6, 0.5 },
    { 1.0, 0.0 } } };
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1, 0 });
  Built built(scene);
  for (const float u : { 0.3f, 0.48f, 0.5f, 0.52f, 0.69f, 0.71f })
  {
    EXPECT_NEAR(DepthAt(vec2(u, 0.5f)), 0.0f, 1e-6f) << u;
    // the notch 0.6 half widths across: 0.5 deep, at and beside the joints alike
    EXPECT_NEAR(DepthAt(vec2(u, 0.5f + 0.03f)), 0.5f, 1e-5f) << u;
  }
  // rays that run along the centre line across the joints, and down into the notch
  const ReliefHit along =
    reliefSearchPathFeatures(Ray(vec2(0.35f, 0.5f), vec3(1.0f, 0.0f, 4.0f)), 0, 0);
  EXPECT_NEAR(along.position.z, 0.0f, 1e-6f);
  const ReliefHit notch =
    reliefSearchPathFeatures(Ray(vec2(0.45f, 0.53f), vec3(0.2f, 0.0f, 1.0f)), 0, 0);
  EXPECT_NEAR(notch.position.z, 0.5f, 1e-5f);
  EXPECT_NEAR(notch.position.x, 0.55f, 1e-5f);
  // the revolved end where the path ends: the notch comes round the end point
  EXPECT_NEAR(DepthAt(vec2(0.9f + 0.03f, 0.5f)), 0.5f, 1e-5f);
}

// A ray that grazes down from a ridge's top toward the base (0.4 below it, 400 tiles
// on) over a repeating grid of 256^2 runs out of steps (RELIEF_MAX_ITERATIONS cells, the
// cells it passes over included) and misses: no walk runs on without end.
TEST(ReliefPathSearch, GrazingRayRunsOutOfStepsAndMisses)
{
  Scene scene;
  scene.Profiles = { Ridge };
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1, 0 });
  Built built(scene, 256);
  const ReliefHit hit =
    reliefSearchPathFeatures(Ray(vec2(0.3f, 0.2f), vec3(1.0f, 0.0f, 1e-9f)), 0, 0);
  EXPECT_FALSE(hit.hit) << hit.t;
  EXPECT_LE(hit.samples, RELIEF_MAX_ITERATIONS + 1);
  EXPECT_GE(hit.samples, RELIEF_MAX_ITERATIONS / 2);
}

TEST(ReliefPathSearch, CrossingCutsUniteAndPrioritiesBridge)
{
  Scene scene;
  scene.Profiles = { VGroove, Ridge };
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.2, 0 });    // groove along u
  scene.Paths.push_back({ { { 0.3, 0.1 }, { 0.3, 0.9 } }, 0.2, 1 });    // ridge along v
  scene.Paths.push_back({ { { 0.7, 0.1 }, { 0.7, 0.9 } }, 0.2, 1, 1 }); // a ridge above it
  Built built(scene);
  EXPECT_NEAR(built.Base, 0.4, 1e-6); // the profile went through float points
  // the ridge's top reaches the polygon
  EXPECT_NEAR(DepthAt(vec2(0.3f, 0.8f)), 0.0f, 1e-5f);
  EXPECT_NEAR(DepthAt(vec2(0.2f, 0.8f)), 0.4f, 1e-5f);
  // equal priorities: the groove's cut goes on through the ridge
  EXPECT_NEAR(DepthAt(vec2(0.3f, 0.52f)), 0.4f + 0.8f, 1e-5f);
  // the higher ridge bridges the groove: its top stays, the groove runs under it
  EXPECT_NEAR(DepthAt(vec2(0.7f, 0.52f)), 0.0f, 1e-5f);
  // on its flank, 0.16 above the base; under the flank the groove stays open
  EXPECT_NEAR(DepthAt(vec2(0.62f, 0.5f)), 0.24f, 1e-5f);
}

TEST(ReliefPathSearch, CrackNarrowsToNothing)
{
  Scene scene;
  scene.Profiles = { VGroove };
  PathSpec crack{ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1, 0 };
  crack.ScaleEnd = 0.0;
  scene.Paths.push_back(crack);
  Built built(scene);
  // half way: half as wide and half as deep
  EXPECT_NEAR(DepthAt(vec2(0.5f, 0.5f)), 0.5f, 1e-5f);
  EXPECT_NEAR(DepthAt(vec2(0.5f, 0.5125f)), 0.25f, 1e-5f);
  EXPECT_NEAR(DepthAt(vec2(0.3f, 0.5f)), 0.75f, 1e-5f);
  EXPECT_NEAR(DepthAt(vec2(0.9f, 0.5f)), 0.0f, 1e-5f);
}

TEST(ReliefPathSearch, OverhangHidesWhatIsUnderIt)
{
  Scene scene;
  scene.Profiles = { Dovetail };
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.2, 0 });
  Built built(scene);
  // straight down through the opening: the floor
  EXPECT_NEAR(DepthAt(vec2(0.5f, 0.5f)), 0.6f, 1e-5f);
  // straight down over the undercut: the lip's top, the plain surface
  EXPECT_NEAR(DepthAt(vec2(0.5f, 0.58f)), 0.0f, 1e-5f);
  // slanting in through the opening toward +v (x = -0.2 - t at depth t), under the lip
  // (|x| > 0.5), inside the undercut wall (x > -0.5 - t / 1.2) down to the floor
  const ReliefHit hit = reliefSearchPathFeatures(Ray(vec2(0.5f, 0.52f), vec3(0, 0.1f, 1)), 0, 0);
  EXPECT_NEAR(hit.t, 0.6f, 1e-4f);
  EXPECT_NEAR(hit.position.y, 0.58f, 1e-5f); // beneath the lip
}

TEST(ReliefPathSearch, AgreesWithTheMarchedReference)
{
  Scene scene;
  scene.Profiles = { VGroove, Ridge, Dovetail, DefaultGroove() };
  scene.Paths.push_back({ { { 0.05, 0.25 }, { 0.95, 0.3 } }, 0.08, 0 });
  scene.Paths.push_back({ { { 0.2, 0.05 }, { 0.25, 0.6 }, { 0.7, 0.8 } }, 0.06, 1 });
  scene.Paths.push_back({ { { 0.5, 0.1 }, { 0.55, 0.9 } }, 0.1, 2, 1 });
  scene.Paths.push_back({ { { 0.9, 0.6 }, { 1.15, 0.95 } }, 0.05, 3 }); // across the tile's edge
  PathSpec crack{ { { 0.1, 0.9 }, { 0.45, 0.7 } }, 0.06, 0 };
  crack.ScaleEnd = 0.0;
  scene.Paths.push_back(crack);
  for (int resolution : { 0, 7 })
  {
    Built built(scene, resolution);
    Reference reference(scene, built.Base);
    // up to 80 degrees from the normal, features 0.05 to 0.1 wide, 0.4 to 1.6 deep
    const Agreement agreement = AgreeWithTheReference(&reliefSearchPathFeatures, reference,
      built.Deepest, built.Base, 600, 18, "grid " + std::to_string(resolution));
    EXPECT_GE(agreement.Agreeing, agreement.Rays * 99 / 100)
      << agreement.Slivers << " slivers, grid " << resolution;
  }
}

// Where a path turns, one element's revolved end is left out where the other's holds all
// of it (vtkPathFeatureTextureFilter: a centred profile that cuts or adds, one scale):
// the walk still meets the surfaces the reference defines with both ends revolved, at
// corners of 20 to 160 degrees, for centred profiles (a vee, a dovetail that overhangs, a
// ridge) and for those that keep both ends (two notches, an off-centre vee; a vee and an
// off-centre vee that narrow), and after an element shorter than the profile's reach.
// (Beyond an end, an off-centre profile's two halves meet on the plane through the
// element's axis: the walk's state changes there; without that crossing a narrowing
// off-centre vee's ray went through.)
TEST(ReliefPathSearch, CornersRevolveOnce)
{
  Scene scene;
  scene.Profiles = { VGroove, Dovetail, Ridge,
    { { -1.0, 0.0 }, { -0.6, 0.5 }, { -0.2, 0.0 }, { 0.2, 0.0 }, { 0.6, 0.5 }, { 1.0, 0.0 } },
    { { -1.0, 0.0 }, { 0.5, 1.0 }, { 1.0, 0.0 } } };
  std::vector<vec2> corners;
  const int profiles[7] = { 0, 1, 2, 3, 4, 0, 4 };
  for (int row = 0; row < 7; ++row)
  {
    // a zigzag along u, its corners turning by 20 to 160 degrees
    PathSpec path{ {}, 0.06, profiles[row] };
    const double v = 0.07 + 0.14 * row;
    path.Points.push_back({ 0.05, v });
    double u = 0.05;
    for (int k = 0; k < 4; ++k)
    {
      const double half = (20.0 + 40.0 * k) * M_PI / 360.0; // half the turn
      u += 0.05 + 0.04 * std::sin(half);
      path.Points.push_back({ u, v + (k % 2 == 0 ? 0.04 : -0.04) * std::cos(half) });
      corners.emplace_back(static_cast<float>(u), static_cast<float>(path.Points.back().y));
    }
    path.Points.push_back({ u + 0.001, path.Points.back().y + 0.001 }); // shorter than its reach
    path.Points.push_back({ u + 0.1, path.Points.back().y });
    corners.emplace_back(static_cast<float>(u + 0.001), static_cast<float>(path.Points.back().y));
    path.ScaleEnd = row >= 5 ? 0.5 : 1.0; // the last two narrow
    scene.Paths.push_back(path);
  }
  Built built(scene);
  Reference reference(scene, built.Base);
  const Agreement agreement = AgreeWithTheReference(&reliefSearchPathFeatures, reference,
    built.Deepest, built.Base, 1200, 23, "corners", corners, 0.05f);
  EXPECT_GE(agreement.Agreeing, agreement.Rays * 99 / 100) << agreement.Slivers << " slivers";
}

// The filter puts the base as far below the polygons as the tallest addition rises, so a
// ridge's flat top lies at depth 0, where the view ray starts: inside it. The ray meets
// the top there, lit as the top and with the ridge's material (region sampling's rays,
// reliefPathRegionSurfaces, meet the same), not the actor's.
TEST(ReliefPathSearch, ATopAtThePolygonShowsItsMaterial)
{
  Scene scene;
  scene.Profiles = { Ridge };
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1, 0 });
  vtkNew<vtkPathFeatureTextureFilter> filter;
  filter->AddMaterial(0.8, 0.2, 0.1, 0.5, 20.0);
  filter->SetPathsData(PathsData(scene.Paths, { 0 }));
  filter->SetProfilesData(ProfilesData(scene.Profiles));
  filter->Update();
  const PathTextures textures = Textures(filter);
  CurrentPaths = &textures;
  for (const vec3& direction : { vec3(0.0f, 0.0f, 1.0f), vec3(0.3f, 0.2f, 1.0f) })
  {
    const ReliefHit hit = reliefSearchPathFeatures(Ray(vec2(0.5f, 0.5f), direction), 0, 0);
    EXPECT_TRUE(hit.hit);
    EXPECT_NEAR(hit.position.z, 0.0f, 1e-6f);
    EXPECT_GE(reliefPathHitMaterial, 0.0f) << direction.x;
    EXPECT_NEAR(normalize(reliefPathHitNormal).z, -1.0f, 1e-6f) << direction.x;
  }
  // beside the ridge, the plain base with the actor's material
  reliefSearchPathFeatures(Ray(vec2(0.5f, 0.8f), vec3(0.0f, 0.0f, 1.0f)), 0, 0);
  EXPECT_EQ(reliefPathHitMaterial, -1.0f);
}

// Below a curved surface's quadric (the quadric frame, vtkOpenGLQuadricPathFeatureMapper)
// the view ray's depth is quadratic along it, its range [0, 1] running to the deepest cut
// or back out of the quadric (then it passes the outline: a miss). The walk follows it in
// straight pieces within 1/256 of depth: its hit lies between the marched reference's
// along the curve sunk and lifted by that much, its clear point (where shadow rays start)
// in air, and it misses where the curve does.
TEST(ReliefPathSearch, FollowsCurvedRaysBelowAQuadric)
{
  namespace curved = ReliefCpuMirror::Quadric;
  Scene scene;
  scene.Profiles = { VGroove, Ridge, Dovetail, DefaultGroove() };
  scene.Paths.push_back({ { { 0.05, 0.25 }, { 0.95, 0.3 } }, 0.08, 0 });
  scene.Paths.push_back({ { { 0.2, 0.05 }, { 0.25, 0.6 }, { 0.7, 0.8 } }, 0.06, 1 });
  scene.Paths.push_back({ { { 0.5, 0.1 }, { 0.55, 0.9 } }, 0.1, 2, 1 });
  Built built(scene);
  Reference reference(scene, built.Base);
  std::mt19937 random(19);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const double chord = 1.0 / 256.0;
  int hits = 0;
  int misses = 0;
  int bent = 0;
  const int rays = 400;
  for (int k = 0; k < rays; ++k)
  {
    // a convex surface's ray (bend < 0, which may come back out) or a concave one's
    const float angle = 6.2831853f * unit(random);
    const float run = 0.3f * unit(random);
    const float descent = 0.3f + 2.0f * unit(random);
    curved::ReliefRay ray;
    ray.origin = vec3(unit(random), unit(random), 0.0f);
    ray.direction = vec3(run * std::cos(angle), run * std::sin(angle), descent);
    ray.bend = -2.0f * unit(random) + 0.5f;
    ray.exact = vec4(0.0f);
    ray.screenRun = RELIEF_UNKNOWN_RUN;
    auto along = [&](double lift) {
      return [&ray, lift](double t) {
        return glm::dvec3(ray.origin.x + t * ray.direction.x, ray.origin.y + t * ray.direction.y,
          t * (ray.direction.z + t * ray.bend) + lift);
      };
    };
    const curved::ReliefHit hit = curved::reliefSearchPathFeatures(ray, 0, 0);
    const double expected = reference.HitAlong(along(0.0), 1.0, 5e-4);
    const double deeper = reference.HitAlong(along(chord), 1.0, 5e-4);
    const double shallower = reference.HitAlong(along(-chord), 1.0, 5e-4);
    bent += std::abs(ray.bend) > 0.5f ? 1 : 0;
    if (expected < 0.0)
    {
      misses += 1;
      EXPECT_FALSE(hit.hit && deeper < 0.0) << "ray " << k << " hits at " << hit.t;
      continue;
    }
    ASSERT_TRUE(hit.hit || shallower < 0.0) << "ray " << k << ", the reference at " << expected;
    hits += 1;
    // (a curve that misses, lifted, may let the walk miss: t = 1)
    const double low = std::min(deeper >= 0.0 ? deeper : 1.0, shallower >= 0.0 ? shallower : 1.0);
    const double high = std::max(deeper >= 0.0 ? deeper : 1.0, shallower >= 0.0 ? shallower : 1.0);
    EXPECT_TRUE(hit.t >= low - 1e-4 && hit.t <= high + 1e-4)
      << "ray " << k << " hits at " << hit.t << ", the reference at " << expected << " (" << low
      << " to " << high << " with the curve 1/256 deeper or shallower)";
    // the hit lies on the piece it was found on, its clear point in air: the shadow ray
    // starts there (not up to 1/256 off the piece's surface, on the curve)
    EXPECT_FALSE(reference.Solid(glm::dvec3(hit.clear))) << "ray " << k;
  }
  EXPECT_GE(hits, rays / 2);
  EXPECT_GE(misses, 10); // rays that come back out of a convex surface
  EXPECT_GE(bent, 100);
}

namespace
{
// A pixel's footprint in (u, v), its ray, and what region sampling makes of it.
struct Pixel
{
  vec2 UV;
  vec3 Direction;
  vec2 AlongX;
  vec2 AlongY;
};

// A random pixel at uv: 0.004 to 0.03 across, rays up to 60 degrees from the normal.
Pixel RandomPixel(vec2 uv, std::mt19937& random)
{
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const float angle = 6.2831853f * unit(random);
  const float run = 1.7f * unit(random);
  const float size = 0.004f + 0.026f * unit(random);
  const float turn = 6.2831853f * unit(random);
  Pixel pixel;
  pixel.UV = uv;
  pixel.Direction = vec3(run * std::cos(angle), run * std::sin(angle), 1.0f);
  pixel.AlongX = size * vec2(std::cos(turn), std::sin(turn));
  pixel.AlongY = size * (0.3f + 0.7f * unit(random)) *
    vec2(-std::sin(turn + 0.4f * (unit(random) - 0.5f)), std::cos(turn));
  return pixel;
}

// The regions of the pixel (none where they refuse) after its view ray's walk.
ReliefPathRegions RegionsOf(const Pixel& pixel)
{
  const ReliefRay ray = Ray(pixel.UV, pixel.Direction);
  reliefSearchPathFeatures(ray, 0, 0);
  EXPECT_GE(reliefPathNearest.element, 0);
  return reliefPathRegions(ray, reliefPathNearest, pixel.AlongX, pixel.AlongY);
}

// How far the share of the pixel that each surface takes in its regions (which must be
// taken, RegionsOf) is from what 96 x 96 rays through the pixel see; the surfaces (the
// facets and the base: planes in (u, v, depth)) are told apart by their normals and their
// planes' offsets along them (a groove's flat floor from the base); across a path's bend
// of `turn` radians, the facets of one side by their normals alone.
double RegionShareError(const Pixel& pixel, float turn = 0.0f)
{
  const ReliefRay ray = Ray(pixel.UV, pixel.Direction);
  const ReliefPathRegions regions = RegionsOf(pixel);
  const ReliefPathNearest nearest = reliefPathNearest;
  std::vector<std::pair<vec4, double>> expected;
  std::vector<std::pair<vec4, double>> got;
  const auto same = [turn](vec4 a, vec4 b) {
    return dot(vec3(a), vec3(b)) > std::cos(turn) - 1e-4f &&
      (turn > 0.0f || std::abs(a.w - b.w) < 1e-3f);
  };
  auto count = [&same](std::vector<std::pair<vec4, double>>& shares, const ReliefHit& hit,
                 double weight) {
    const vec3 normal = normalize(reliefPathHitNormal);
    const vec4 surface(normal, dot(normal, hit.position));
    for (auto& share : shares)
    {
      if (same(share.first, surface))
      {
        share.second += weight;
        return;
      }
    }
    shares.emplace_back(surface, weight);
  };
  const int n = 96;
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const float x = (i + 0.5f) / n - 0.5f;
      const float y = (j + 0.5f) / n - 0.5f;
      const ReliefHit hit = reliefSearchPathFeatures(
        Ray(pixel.UV + x * pixel.AlongX + y * pixel.AlongY, pixel.Direction), 0, 0);
      count(expected, hit, 1.0 / (n * n));
    }
  }
  double total = 0.0;
  for (int r = 0; r < regions.count; ++r)
  {
    const float offset = reliefPathEntry(regions.offsets, r);
    ReliefRay regionRay = ray;
    regionRay.origin.x += offset * regions.right.x;
    regionRay.origin.y += offset * regions.right.y;
    const ReliefHit hit =
      reliefPathElementWalk(regionRay, nearest.element, nearest.near, false);
    // what the shader lights the region with (reliefPathRegionSurfaces) is what its walk met
    const vec3 surface(reliefPathEntry(regions.normalsU, r), reliefPathEntry(regions.normalsV, r),
      reliefPathEntry(regions.normalsDepth, r));
    EXPECT_GT(dot(normalize(surface), normalize(reliefPathHitNormal)), 1.0f - 1e-5f)
      << "region " << r << " of " << regions.count;
    EXPECT_EQ(reliefPathEntry(regions.materials, r), reliefPathHitMaterial)
      << "region " << r << " of " << regions.count;
    const float weight = reliefPathEntry(regions.weights, r);
    EXPECT_GE(weight, 0.0f);
    total += weight;
    count(got, hit, weight);
  }
  EXPECT_NEAR(total, 1.0, 1e-5);
  double error = 0.0;
  for (const auto& share : expected)
  {
    double region = 0.0;
    for (const auto& other : got)
    {
      region += same(other.first, share.first) ? other.second : 0.0;
    }
    error = std::max(error, std::abs(region - share.second));
  }
  return error;
}

std::string Describe(const Pixel& pixel)
{
  return "pixel at " + std::to_string(pixel.UV.x) + " " + std::to_string(pixel.UV.y) + " of " +
    std::to_string(length(pixel.AlongX)) + ", ray " + std::to_string(pixel.Direction.x) + " " +
    std::to_string(pixel.Direction.y);
}
}

// Region sampling (s5.7) against the pixel sampled densely: over one straight element of
// each kind of profile (a V, a ridge, a dovetail's overhang, the default groove), pixels
// of random size, shape and slant; each surface the dense rays see takes the share of the
// pixel the regions give it. Near an end, and on a profile that both cuts and adds, the
// regions refuse (supersampling takes over).
TEST(ReliefPathSearch, RegionSamplingMatchesThePixelSampledDensely)
{
  const std::vector<dvec2> Rimmed = { { -1.0, 0.0 }, { -0.7, -0.2 }, { -0.4, 0.0 }, { 0.0, 0.8 },
    { 0.4, 0.0 }, { 0.7, -0.2 }, { 1.0, 0.0 } };
  std::mt19937 random(57);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (const std::vector<dvec2>& profile : { VGroove, Ridge, Dovetail, DefaultGroove() })
  {
    Scene scene;
    scene.Profiles = { profile };
    scene.Paths.push_back({ { { 0.3, 0.5 }, { 0.5, 0.5 } }, 0.1, 0 });
    Built built(scene);
    int sampled = 0;
    for (int k = 0; k < 60; ++k)
    {
      // across the groove and beside it, away from its ends
      const Pixel pixel = RandomPixel(
        vec2(0.36f + 0.08f * unit(random), 0.5f + 0.14f * (unit(random) - 0.5f)), random);
      if (RegionsOf(pixel).count > 0)
      {
        sampled += 1;
        EXPECT_LE(RegionShareError(pixel), 0.02) << Describe(pixel);
      }
    }
    EXPECT_GE(sampled, 30); // most: the others see past an end along slanting rays
  }
  // the regions refuse where the pixel's rays pass the element's end, or where the
  // profile both cuts and adds
  Scene scene;
  scene.Profiles = { VGroove, Rimmed };
  scene.Paths.push_back({ { { 0.3, 0.3 }, { 0.5, 0.3 } }, 0.1, 0 });
  scene.Paths.push_back({ { { 0.3, 0.7 }, { 0.5, 0.7 } }, 0.1, 1 });
  Built built(scene);
  const vec2 across(0.02f, 0.0f);
  const vec2 along(0.0f, 0.02f);
  for (const vec2& uv : { vec2(0.29f, 0.3f), vec2(0.505f, 0.31f), vec2(0.4f, 0.7f) })
  {
    EXPECT_EQ(RegionsOf({ uv, vec3(0.0f, 0.0f, 1.0f), across, along }).count, 0)
      << uv.x << " " << uv.y;
  }
  // the middle of the V's element, by contrast
  EXPECT_GT(RegionsOf({ vec2(0.4f, 0.3f), vec3(0.0f, 0.0f, 1.0f), across, along }).count, 0);
}

// Where a path goes on from one element to the next without a corner (a segment split
// into pieces, MaximumElementLength; a curve's pieces), the regions take it as one
// straight element across the joint, as long as the turn strays from straight by less
// than an eighth of the pixel where its rays pass: their shares stay within a sixteenth
// of the dense pixel's (supersampling's four rays are a quarter apart). Beyond
// that (rays that run far along the feature as they descend, past a bend), and at a
// corner (SmoothJointDegrees), as at an end, they refuse.
TEST(ReliefPathSearch, RegionSamplingGoesOnThroughSmoothJoints)
{
  std::mt19937 random(58);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  Scene scene;
  scene.Profiles = { VGroove };
  // split at 0.3, 0.5 and 0.7; bent by 6 degrees at (0.5, 0.7); a corner of 20 degrees
  // at (0.5, 0.9)
  scene.Paths.push_back({ { { 0.1, 0.3 }, { 0.9, 0.3 } }, 0.1, 0 });
  const auto bent = [](double degrees, double v) {
    const double turn = degrees * M_PI / 180.0;
    return std::vector<dvec2>{ { 0.3, v }, { 0.5, v },
      { 0.5 + 0.2 * std::cos(turn), v + 0.2 * std::sin(turn) } };
  };
  scene.Paths.push_back({ bent(6.0, 0.7), 0.1, 0 });
  scene.Paths.push_back({ bent(20.0, 0.9), 0.1, 0 });
  Built built(scene);
  for (const vec2 joint :
    { vec2(0.3f, 0.3f), vec2(0.5f, 0.3f), vec2(0.7f, 0.3f), vec2(0.5f, 0.7f) })
  {
    int sampled = 0;
    for (int k = 0; k < 40; ++k)
    {
      const vec2 offset(0.03f * (unit(random) - 0.5f), 0.12f * (unit(random) - 0.5f));
      const Pixel pixel = RandomPixel(joint + offset, random);
      if (RegionsOf(pixel).count > 0)
      {
        sampled += 1;
        // past a bend, what the straight regions miss: the turn strays by up to an eighth
        // of the pixel, across a wedge of at most half of it
        EXPECT_LE(RegionShareError(pixel, joint.y > 0.5f ? 0.11f : 0.0f),
          joint.y > 0.5f ? 0.0625 : 0.02)
          << Describe(pixel);
      }
    }
    EXPECT_GE(sampled, joint.y > 0.5f ? 20 : 30) << joint.x << " " << joint.y;
  }
  const vec2 across(0.0f, 0.02f);
  const vec2 along(0.02f, 0.0f);
  for (const vec2& uv : { vec2(0.3f, 0.3f), vec2(0.5f, 0.3f), vec2(0.5f, 0.7f) })
  {
    EXPECT_GT(RegionsOf({ uv, vec3(0.0f, 0.0f, 1.0f), across, along }).count, 0);
  }
  // rays that run along the bent groove as they descend pass the bend by more than the
  // pixel; the straight groove's go on
  EXPECT_EQ(RegionsOf({ vec2(0.5f, 0.7f), vec3(0.1f, 0.0f, 1.0f), across, along }).count, 0);
  EXPECT_GT(RegionsOf({ vec2(0.5f, 0.3f), vec3(0.1f, 0.0f, 1.0f), across, along }).count, 0);
  EXPECT_EQ(RegionsOf({ vec2(0.5f, 0.9f), vec3(0.0f, 0.0f, 1.0f), across, along }).count, 0);
  EXPECT_GT(RegionsOf({ vec2(0.4f, 0.9f), vec3(0.0f, 0.0f, 1.0f), across, along }).count, 0);
  // the pieces that go on are one feature to the walk's nearest: no second near
  for (const vec2 uv :
    { vec2(0.3f, 0.3f), vec2(0.5f, 0.32f), vec2(0.7f, 0.28f), vec2(0.5f, 0.7f) })
  {
    RegionsOf({ uv, vec3(0.0f, 0.0f, 1.0f), across, along });
    EXPECT_GT(reliefPathNearest.second, 0.05f) << uv.x << " " << uv.y;
  }
  RegionsOf({ vec2(0.5f, 0.9f), vec3(0.0f, 0.0f, 1.0f), across, along });
  EXPECT_LT(reliefPathNearest.second, 0.05f);
}

// At a bend the next piece's edge on the inside of the turn crosses the first one's a
// half width times tan(turn / 2) before the joint, and lies the half width times
// (1 / cos - 1) out at it: a wide groove's edge there moves by much of a small pixel
// even where the rays stop short of the joint. Pixels along the inner edge of a
// 12-degree bend of a groove 25 pixels wide are refused where their rays reach that
// stretch, and elsewhere their regions' shares stay within a sixteenth of the dense
// pixel's.
TEST(ReliefPathSearch, RegionSamplingMindsWhereAWideGroovesEdgesMeetAtABend)
{
  Scene scene;
  scene.Profiles = { VGroove };
  const double turn = 12.0 * M_PI / 180.0;
  scene.Paths.push_back(
    { { { 0.2, 0.5 }, { 0.5, 0.5 }, { 0.5 + 0.3 * std::cos(turn), 0.5 + 0.3 * std::sin(turn) } },
      0.1, 0 });
  Built built(scene);
  const float size = 0.004f;
  int sampled = 0;
  for (const float offset : { -3.0f, -2.0f, -1.5f, -1.0f, -0.5f, 0.0f, 0.5f, 1.0f })
  {
    const Pixel pixel = { vec2(0.5f + offset * size, 0.55f), vec3(0.0f, 0.0f, 1.0f),
      vec2(size, 0.0f), vec2(0.0f, size) };
    const int count = RegionsOf(pixel).count;
    sampled += count > 0 ? 1 : 0;
    if (offset == -1.5f || offset == -1.0f)
    {
      EXPECT_EQ(count, 0) << Describe(pixel); // their rays reach where the edges cross
    }
    else if (count > 0)
    {
      EXPECT_LE(RegionShareError(pixel, float(turn)), 0.0625) << Describe(pixel);
    }
  }
  EXPECT_GE(sampled, 5);
}

// Where the rays that fall into a groove run along it, below the view ray's hit, into
// another feature, the regions refuse (they would walk the one element alone): a pixel
// beside a deep slot, whose rays run along it as they descend into a crossing slot.
TEST(ReliefPathSearch, RegionSamplingRefusesWhereItsRaysReachAnotherFeature)
{
  const std::vector<dvec2> Slot = { { -1.0, 0.0 }, { -1.0, 2.0 }, { 1.0, 2.0 }, { 1.0, 0.0 } };
  // the pixel's rays: beside the slot along u, falling in, 0.15 along it per depth
  const Pixel pixel{ vec2(0.5f, 0.353f), vec3(0.15f, -0.02f, 1.0f), vec2(0.01f, 0.0f),
    vec2(0.0f, 0.01f) };
  for (bool crossed : { false, true })
  {
    Scene scene;
    scene.Profiles = { Slot };
    scene.Paths.push_back({ { { 0.25, 0.3 }, { 0.45, 0.3 }, { 0.65, 0.3 }, { 0.85, 0.3 } }, 0.1, 0 });
    if (crossed)
    {
      scene.Paths.push_back({ { { 0.7, 0.1 }, { 0.7, 0.5 } }, 0.06, 0 });
    }
    Built built(scene);
    const ReliefPathRegions regions = RegionsOf(pixel);
    if (crossed)
    {
      EXPECT_EQ(regions.count, 0);
      EXPECT_GT(reliefPathNearest.second, 0.05f); // the view ray's path stays far from it
    }
    else
    {
      EXPECT_GT(regions.count, 0);
      EXPECT_LE(RegionShareError(pixel), 0.02);
    }
  }
}

// Path features cut into a relief base (vtkReliefPathOnRelief.glsl): the field hangs from
// the base plane and fills what no feature holds; a groove cuts it where it is shallower
// than the groove, and the field shows where it is deeper.
namespace
{
// The depth a vertical ray at uv meets on the relief base.
ReliefHit OnReliefAt(vec2 uv)
{
  return reliefSearchPathFeaturesOnRelief(Ray(uv, vec3(0.0f, 0.0f, 1.0f)), 0, 0);
}

// Ground at depth 0 for u < 0.5 and `low` beyond, the step a bilinear ramp one texel wide.
DepthField Step(float low)
{
  return DepthField::FromFunction(
    64, 64, [low](float u, float) { return u < 0.5f ? 0.0f : low; });
}
}

TEST(ReliefPathSearch, GroovesCutIntoAReliefBase)
{
  Scene scene;
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1 });
  Built built(scene);
  const DepthField field = Step(0.6f);
  CurrentField = &field;
  // the groove's floor, 1 deep, on the high ground and on the low
  EXPECT_NEAR(OnReliefAt(vec2(0.25f, 0.5f)).position.z, 1.0f, 1e-5f);
  EXPECT_NEAR(OnReliefAt(vec2(0.75f, 0.5f)).position.z, 1.0f, 1e-5f);
  // beside it: the field, lit as the field, in the actor's colour
  EXPECT_NEAR(OnReliefAt(vec2(0.25f, 0.7f)).position.z, 0.0f, 1e-6f);
  const ReliefHit low = OnReliefAt(vec2(0.75f, 0.7f));
  EXPECT_TRUE(low.hit);
  EXPECT_NEAR(low.position.z, 0.6f, 1e-5f);
  EXPECT_NEAR(reliefPathHitNormal.z, -1.0f, 1e-6f);
  EXPECT_EQ(reliefPathHitMaterial, -1.0f);
  // near the groove's edge on the low ground the groove is shallower than the field: the
  // field (the half circle's facet there is a third deep)
  EXPECT_NEAR(OnReliefAt(vec2(0.75f, 0.5f + 0.0475f)).position.z, 0.6f, 1e-5f);
  // on the step's ramp the normal is the field's: its gradient 0.6 x 64 along u
  const ReliefHit ramp = OnReliefAt(vec2(0.5f, 0.7f));
  EXPECT_NEAR(ramp.position.z, 0.3f, 1e-5f);
  EXPECT_NEAR(reliefPathHitNormal.x / reliefPathHitNormal.z, -0.6f * 64.0f, 1e-2f);
  // a slanting ray from the groove's middle on the high ground meets its wall (the half
  // circle x^2 + y^2 = 1 where x = 2t, y = t: 0.45 deep, less on the facets' chords), not
  // the field
  const ReliefHit wall =
    reliefSearchPathFeaturesOnRelief(Ray(vec2(0.25f, 0.5f), vec3(0.0f, 0.1f, 1.0f)), 0, 0);
  EXPECT_NEAR(wall.position.z, 0.43f, 0.03f);
  EXPECT_LT(reliefPathHitNormal.y, 0.0f); // facing back toward the groove's middle
}

TEST(ReliefPathSearch, OnAReliefBaseAgreesWithTheMarchedReference)
{
  Scene scene;
  scene.Profiles = { VGroove, Ridge, Dovetail, DefaultGroove() };
  scene.Paths.push_back({ { { 0.05, 0.25 }, { 0.95, 0.3 } }, 0.08, 0 });
  scene.Paths.push_back({ { { 0.2, 0.05 }, { 0.25, 0.6 }, { 0.7, 0.8 } }, 0.06, 1 });
  scene.Paths.push_back({ { { 0.5, 0.1 }, { 0.55, 0.9 } }, 0.1, 2, 1 });
  scene.Paths.push_back({ { { 0.9, 0.6 }, { 1.15, 0.95 } }, 0.05, 3 }); // across the tile's edge
  // rolling ground from the base plane down to 0.9, shallower and deeper than the cuts
  const DepthField field = DepthField::FromFunction(48, 40, [](float u, float v) {
    return 0.45f + 0.45f * std::sin(6.2831853f * 3.0f * u) * std::cos(6.2831853f * 2.0f * v);
  });
  CurrentField = &field;
  Built built(scene);
  Reference reference(scene, built.Base);
  reference.SetReliefBase(&field);
  const Agreement agreement = AgreeWithTheReference(&reliefSearchPathFeaturesOnRelief,
    reference, std::max(built.Deepest, built.Base + 1.0), built.Base, 800, 8, "relief base");
  EXPECT_GE(agreement.Agreeing, agreement.Rays * 99 / 100) << agreement.Slivers << " slivers";
  EXPECT_GT(agreement.OnField, agreement.Rays / 4); // the field is met, not only the features
}

// A brick's side shades the mortar beside it, except where a groove cut through the brick
// lets the light along it.
TEST(ReliefPathSearch, OnAReliefBaseShadowsPassThroughCuts)
{
  Scene scene;
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.1 });
  Built built(scene);
  const DepthField field = DepthField::FromFunction(
    64, 64, [](float u, float) { return u > 0.3f && u < 0.5f ? 0.0f : 0.8f; });
  CurrentField = &field;
  const vec3 towardBrick(-0.2f, 0.0f, -1.0f);
  const vec3 awayFromBrick(0.2f, 0.0f, -1.0f);
  const ReliefHit mortar = OnReliefAt(vec2(0.55f, 0.7f));
  EXPECT_NEAR(mortar.position.z, 0.8f, 1e-5f);
  EXPECT_EQ(reliefPathOnReliefLightVisibility(mortar.clear, towardBrick, 0, 0), 0.0f);
  EXPECT_EQ(reliefPathOnReliefLightVisibility(mortar.clear, awayFromBrick, 0, 0), 1.0f);
  const ReliefHit groove = OnReliefAt(vec2(0.55f, 0.5f));
  EXPECT_NEAR(groove.position.z, 1.0f, 1e-5f);
  EXPECT_EQ(reliefPathOnReliefLightVisibility(groove.clear, towardBrick, 0, 0), 1.0f);
}
// Where the features add something, the base plane lies below the polygons; a ray's
// crossing of it rounds to either side, and the side above is no addition: under a light
// almost overhead, nothing on a smooth field shadows itself.
TEST(ReliefPathSearch, OnAReliefBaseTheLitFieldCastsNoShadowOnItself)
{
  Scene scene;
  scene.Profiles = { Ridge };
  scene.Paths.push_back({ { { 0.02, 0.33 }, { 0.98, 0.33 } }, 0.02, 0 });
  Built built(scene);
  ASSERT_NEAR(built.Base, 0.4, 1e-6);
  const DepthField field = DepthField::FromFunction(256, 256, [](float u, float v) {
    return 0.5f + 0.25f * (std::sin(6.2831853f * 2.0f * u) + std::sin(6.2831853f * 3.0f * v));
  });
  CurrentField = &field;
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // the waves slope up to 0.25 x 2 pi x 3 = 4.7 a unit of v; the light rises 33 a unit of
  // (u, v), its rays reach 0.03 across from depth 1: the ridge at v = 0.33 is out of reach
  const vec3 light(-1.0f, 1.0f, -33.0f);
  int shadowed = 0;
  for (int k = 0; k < 2000; ++k)
  {
    const vec2 uv(unit(random), 0.5f + 0.45f * unit(random));
    const ReliefHit hit =
      reliefSearchPathFeaturesOnRelief(Ray(uv, vec3(0.0f, 0.8f, 1.0f)), 0, 0);
    ASSERT_TRUE(hit.hit);
    shadowed += reliefPathOnReliefLightVisibility(hit.clear, light, 0, 0) == 0.0f ? 1 : 0;
  }
  EXPECT_EQ(shadowed, 0);
}

// Far from every feature the footprint's rays search the field alone: as the features'
// search on the relief base finds it there.
TEST(ReliefPathSearch, OnAReliefBaseTheFieldAloneIsWhatTheFeaturesLeave)
{
  Scene scene;
  scene.Profiles = { Ridge };
  scene.Paths.push_back({ { { 0.1, 0.2 }, { 0.9, 0.2 } }, 0.04, 0 });
  Built built(scene);
  ASSERT_GT(built.Base, 0.0);
  const DepthField field = DepthField::FromFunction(48, 40, [](float u, float v) {
    return 0.45f + 0.45f * std::sin(6.2831853f * 3.0f * u) * std::cos(6.2831853f * 2.0f * v);
  });
  CurrentField = &field;
  std::mt19937 random(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int k = 0; k < 300; ++k)
  {
    const float angle = 6.2831853f * unit(random);
    const float run = 0.2f * unit(random);
    const ReliefRay ray = Ray(vec2(unit(random), 0.45f + 0.35f * unit(random)),
      vec3(run * std::cos(angle), run * std::sin(angle), 1.0f));
    const ReliefHit both = reliefSearchPathFeaturesOnRelief(ray, 0, 0);
    const vec3 normal = reliefPathHitNormal;
    const ReliefHit alone = reliefPathBaseAlone(ray, 0, 0);
    ASSERT_TRUE(both.hit && alone.hit);
    EXPECT_NEAR(alone.t, both.t, 1e-5f);
    EXPECT_NEAR(glm::length(reliefPathHitNormal - normal), 0.0f, 1e-3f * glm::length(normal));
    EXPECT_EQ(reliefPathHitMaterial, -1.0f);
    EXPECT_LT(alone.clear.z, alone.position.z);
  }
}

// The field's search runs from where the walk stopped, on its own ray: the point at its
// parameter s is the ray's at t + s span, lowered by the base; its screen run is the
// ray's over that span, and an unknown run (which asks the Automatic search for an exact
// search) stays unknown.
TEST(ReliefPathSearch, OnAReliefBaseTheFieldsRayIsThePartBelowTheWalk)
{
  ReliefRay ray = Ray(vec2(0.3f, 0.6f), vec3(0.2f, -0.1f, 1.0f));
  ray.screenRun = 40.0f;
  const ReliefRay below = reliefPathBaseRay(ray, 0.5f, 0.4f, 1.1f);
  for (float s : { 0.0f, 0.5f, 1.0f })
  {
    const vec3 expected = reliefRayAt(ray, 0.5f + s * 1.1f) - vec3(0.0f, 0.0f, 0.4f);
    EXPECT_NEAR(glm::length(reliefRayAt(below, s) - expected), 0.0f, 1e-6f);
  }
  EXPECT_FLOAT_EQ(below.screenRun, 44.0f);
  ray.screenRun = RELIEF_UNKNOWN_RUN;
  EXPECT_EQ(reliefPathBaseRay(ray, 0.5f, 0.4f, 0.3f).screenRun, RELIEF_UNKNOWN_RUN);
}

// What the features add above the plane shades the field beside it.
TEST(ReliefPathSearch, OnAReliefBaseARidgeShadowsTheField)
{
  Scene scene;
  scene.Profiles = { Ridge };
  scene.Paths.push_back({ { { 0.1, 0.5 }, { 0.9, 0.5 } }, 0.04, 0 });
  Built built(scene);
  ASSERT_NEAR(built.Base, 0.4, 1e-6);
  const DepthField field = DepthField::FromFunction(32, 32, [](float, float) { return 0.3f; });
  CurrentField = &field;
  // beside the ridge (0.02 wide each side of v = 0.5), on the field 0.7 deep
  const ReliefHit ground = OnReliefAt(vec2(0.5f, 0.53f));
  EXPECT_NEAR(ground.position.z, 0.7f, 1e-5f);
  // toward the ridge, low: its top (0.4 above the plane) blocks the light
  EXPECT_EQ(reliefPathOnReliefLightVisibility(ground.clear, vec3(0.0f, -0.1f, -1.0f), 0, 0),
    0.0f);
  // away from it, and toward it steeply enough to pass over it: lit
  EXPECT_EQ(reliefPathOnReliefLightVisibility(ground.clear, vec3(0.0f, 0.1f, -1.0f), 0, 0),
    1.0f);
  EXPECT_EQ(reliefPathOnReliefLightVisibility(ground.clear, vec3(0.0f, -0.01f, -1.0f), 0, 0),
    1.0f);
}

// On a relief base the field's search starts where the features' walk stopped, below the
// polygon and on either side of the field: every exact search method finds there what
// ExactDDA finds (the mapper's SearchMethod searches the field; the mirror's turns use
// ExactDDA).
TEST(ReliefPathSearch, OnAReliefBaseEveryExactSearchStartsBelowThePolygon)
{
  const DepthField field = DepthField::FromFunction(40, 36, [](float u, float v) {
    return 0.5f + 0.3f * std::sin(6.2831853f * 4.0f * u) * std::sin(6.2831853f * 3.0f * v) +
      0.15f * std::cos(6.2831853f * 9.0f * (u + v));
  });
  CurrentField = &field;
  const DepthPyramid pyramid = PyramidOf(field);
  const ConeStepMap cones = ConeMapOf(field);
  const SafetyRadiusMap radii = RadiiOf(field, 0.0);
  CurrentPyramid = &pyramid;
  CurrentConeMap = &cones;
  CurrentRadii = &radii;
  std::mt19937 random(20);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (const char* name : { "reliefSearchMaximumMipmap", "reliefSearchConeStep",
         "reliefSearchSafetyRadius", "reliefSearchAutomatic" })
  {
    const Search search = FindSearch(name);
    ASSERT_NE(search, nullptr) << name;
    int agreeing = 0;
    for (int k = 0; k < 500; ++k)
    {
      const float angle = 6.2831853f * unit(random);
      const float run = 0.4f * unit(random);
      const ReliefRay ray = Ray(vec2(unit(random), unit(random)),
        vec3(run * std::cos(angle), run * std::sin(angle), 1.0f));
      // from a point 0 to 0.9 deep on, to depth 1 (reliefPathBaseRay)
      const float t = 0.9f * unit(random);
      const ReliefRay below = reliefPathBaseRay(ray, t, 0.0f, 1.0f - t);
      const ReliefHit exact = reliefSearchExactDDA(below, 0, 0);
      const ReliefHit hit = search(below, 0, 0);
      agreeing += hit.hit == exact.hit && std::abs(hit.t - exact.t) < 1e-4f ? 1 : 0;
    }
    EXPECT_GE(agreeing, 495) << name;
  }
}
