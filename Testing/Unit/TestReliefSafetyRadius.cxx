// The SafetyRadius search of vtkReliefSafetySearch.glsl and the radii of
// vtkSafetyRadiusFilter it trusts: exact against the brute-force reference at e = 0,
// within its documented bound at e > 0, and radii no ray can contradict.
#include "ReliefEventRecorder.h"
#include "ReliefSearchReference.h"
#include "vtkSafetyRadiusFilter.h"

#include "vtkCommand.h"

#include <map>
#include <numeric>
#include <sstream>

namespace
{
using namespace ReliefCpuMirror;

double MeanRadius(const SafetyRadiusMap& map)
{
  double sum = 0.0;
  for (float radius : map.Values)
  {
    sum += radius;
  }
  return sum / map.Values.size();
}

double ZeroShare(const SafetyRadiusMap& map)
{
  return double(std::count(map.Values.begin(), map.Values.end(), 0.0f)) / map.Values.size();
}

// Depth of the bilinear field at texel coordinates (x, y), in double.
double FieldAt(const DepthField& field, double x, double y)
{
  const double i = std::floor(x);
  const double j = std::floor(y);
  const double fx = x - i;
  const double fy = y - j;
  const int ii = static_cast<int>(i);
  const int jj = static_cast<int>(j);
  return (1 - fy) * ((1 - fx) * field.At(ii, jj) + fx * field.At(ii + 1, jj)) +
    fy * ((1 - fx) * field.At(ii, jj + 1) + fx * field.At(ii + 1, jj + 1));
}

// Sampled rays through cell (i, j) that contradict radius n with tolerance e: on or above
// the field at a point p over the cell, more than e below it at a later point a, above
// it at a later point b, before leaving the square of cells within n of (i, j). For a
// ray of slope s (depth per texel) along direction d, F(x) = f(p + x d) - s x; a ray
// through p at depth z is above at x when F(x) > z. It contradicts the radius if some
// depth z <= F(0) has F(a) + e < z < F(b): the scan keeps the least F(a) + e below F(0).
int CountViolations(
  const DepthField& field, int i, int j, int n, double e, int rays, unsigned seed)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int violations = 0;
  for (int r = 0; r < rays; ++r)
  {
    // points on the cell's borders too, where the search starts its squares
    const double px = i + (r % 4 == 0 ? std::round(unit(generator)) : unit(generator));
    const double py = j + (r % 4 == 1 ? std::round(unit(generator)) : unit(generator));
    const double angle = 2.0 * Pi * unit(generator);
    const double slope = std::exp(std::log(1e-3) + std::log(3e3) * unit(generator));
    const double dx = std::cos(angle);
    const double dy = std::sin(angle);
    // where the ray's projection leaves the square [i - n, i + n + 1] x [j - n, j + n + 1]
    const double exitX = dx > 0 ? (i + n + 1 - px) / dx : dx < 0 ? (i - n - px) / dx : 1e30;
    const double exitY = dy > 0 ? (j + n + 1 - py) / dy : dy < 0 ? (j - n - py) / dy : 1e30;
    const double exit = std::min(exitX, exitY);
    const double start = FieldAt(field, px, py);
    const int steps = std::max(200, static_cast<int>(exit / 0.02));
    double least = 1e30;
    for (int k = 1; k <= steps; ++k)
    {
      const double x = exit * k / steps;
      const double sheared = FieldAt(field, px + x * dx, py + x * dy) - slope * x;
      if (sheared > least + 1e-9)
      {
        ++violations;
        break;
      }
      if (sheared + e < start - 1e-9)
      {
        least = std::min(least, sheared + e);
      }
    }
  }
  return violations;
}

// A smooth tiling field: a few sines of periods dividing the tile.
DepthField Waves(int size, float amplitude)
{
  return DepthField::FromFunction(size, size, [amplitude](float u, float v) {
    const float w = 2.0f * float(Pi);
    return 0.5f + amplitude * (0.6f * std::sin(w * u) * std::cos(2.0f * w * v) +
                                0.4f * std::sin(w * (u + v) + 1.0f));
  });
}

class ReliefSafetyRadius : public ::testing::Test
{
protected:
  static void SetUpTestSuite() { AllScenes = new std::vector<Scene>(Scenes()); }
  static void TearDownTestSuite()
  {
    delete AllScenes;
    AllScenes = nullptr;
  }
  static std::vector<Scene>* AllScenes;
};
std::vector<Scene>* ReliefSafetyRadius::AllScenes = nullptr;

// Samples per ray over the scene's view rays, the rays whose hit breaks
// reference <= t <= (first point more than e below the field), and those whose hit is
// not on the field.
struct Tally
{
  double Samples = 0.0;
  int OutOfBound = 0;
  int OffTheField = 0;
};

using SearchFunction = ReliefHit (*)(ReliefRay, int, int);

Tally TallyWithin(const Scene& scene, const SafetyRadiusMap& radii, double tolerance,
  unsigned seed, SearchFunction search)
{
  DepthField deeper = scene.Field;
  for (float& depth : deeper.Depths)
  {
    depth += static_cast<float>(tolerance);
  }
  CurrentField = &scene.Field;
  CurrentRadii = &radii;
  Tally tally;
  for (const ReliefRay& ray : ViewRays(seed, 0.1f))
  {
    const ReliefHit hit = search(ray, 0, 0);
    tally.Samples += hit.samples;
    const double first = ReferenceHit(scene.Field, ray);
    const double deep = ReferenceHit(deeper, ray);
    const double gap = FieldAt(scene.Field, double(hit.position.x) * scene.Field.Width - 0.5,
                         double(hit.position.y) * scene.Field.Height - 0.5) -
      hit.position.z;
    const bool inside = HitError(scene.Field, ray, hit.t, first) <= Tolerance ||
      (hit.t >= first && (hit.t <= deep || HitError(scene.Field, ray, hit.t, deep) <= Tolerance));
    tally.OutOfBound += hit.hit && inside ? 0 : 1;
    tally.OffTheField += hit.hit && std::abs(gap) <= Tolerance ? 0 : 1;
    if ((!inside || std::abs(gap) > Tolerance) && tally.OutOfBound + tally.OffTheField <= 3)
    {
      std::cout << scene.Name << ", e " << tolerance << ": t " << hit.t << ", first hit "
                << first << ", first point " << tolerance << " below " << deep
                << ", gap at the hit " << gap << "\n";
    }
  }
  tally.Samples /= RayCount;
  return tally;
}

// SafetyRadius's tally; every ray must keep the bound.
Tally SearchWithin(
  const Scene& scene, const SafetyRadiusMap& radii, double tolerance, unsigned seed)
{
  const Tally tally = TallyWithin(scene, radii, tolerance, seed, &reliefSearchSafetyRadius);
  EXPECT_EQ(tally.OutOfBound, 0) << scene.Name << ", e " << tolerance;
  EXPECT_EQ(tally.OffTheField, 0) << scene.Name << ", e " << tolerance;
  return tally;
}
}

TEST_F(ReliefSafetyRadius, ExactOnEveryRayAtZeroTolerance)
{
  std::map<std::string, SafetyRadiusMap> radii;
  for (const Scene& scene : *AllScenes)
  {
    radii[scene.Name] = RadiiOf(scene.Field, 0.0);
    std::cout << scene.Name << ": mean radius " << MeanRadius(radii[scene.Name]) << ", "
              << 100.0 * ZeroShare(radii[scene.Name]) << "% zero\n";
  }
  ExpectExact(
    *AllScenes, "SafetyRadius",
    [](const ReliefRay& ray) { return reliefSearchSafetyRadius(ray, 0, 0); },
    Tolerance, [&radii](const Scene& scene) { CurrentRadii = &radii[scene.Name]; });
  ExpectGrazingHits(*AllScenes, "SafetyRadius",
    [](const ReliefRay& ray) { return reliefSearchSafetyRadius(ray, 0, 0); },
    [&radii](const Scene& scene) { CurrentRadii = &radii[scene.Name]; });
}

TEST_F(ReliefSafetyRadius, NoSampledRayContradictsARadius)
{
  // small tiling fields where radii range from 0 to tens of cells, checked on the cells
  // with the largest radii (the most at risk) and on random ones
  const std::vector<std::pair<std::string, DepthField>> fields = { { "waves", Waves(32, 0.3f) },
    { "low waves", Waves(48, 0.05f) },
    { "terraces",
      DepthField::FromFunction(32, 32,
        [](float u, float v)
        {
          return (std::fmod(3.0f * u, 1.0f) < 0.5f) != (std::fmod(2.0f * v, 1.0f) < 0.4f) ? 0.2f
                                                                                          : 0.7f;
        }) },
    { "bumps", RandomField(24, 24, 41, 0.45f, 0.55f) } };
  std::mt19937 generator(7);
  int checked = 0;
  for (const auto& entry : fields)
  {
    const DepthField& field = entry.second;
    for (double tolerance : { 0.0, 0.02, 0.05, 0.1 })
    {
      const SafetyRadiusMap radii = RadiiOf(field, tolerance);
      std::vector<int> cells(radii.Values.size());
      std::iota(cells.begin(), cells.end(), 0);
      std::partial_sort(cells.begin(), cells.begin() + 4, cells.end(),
        [&radii](int a, int b) { return radii.Values[a] > radii.Values[b]; });
      std::uniform_int_distribution<int> any(0, static_cast<int>(cells.size()) - 1);
      for (int k = 0; k < 10; ++k)
      {
        const int cell = k < 4 ? cells[k] : any(generator);
        const int i = cell % field.Width;
        const int j = cell / field.Width;
        const int radius = static_cast<int>(radii.Values[cell]);
        if (radius == 0)
        {
          continue; // promises nothing
        }
        ++checked;
        EXPECT_EQ(CountViolations(field, i, j, radius, tolerance, 800, 100 + k), 0)
          << entry.first << ", e " << tolerance << ": cell (" << i << ", " << j << "), radius "
          << radius;
      }
    }
  }
  EXPECT_GT(checked, 60);
}

TEST_F(ReliefSafetyRadius, TheCheckFindsRaysThroughAPeak)
{
  // Baboud and Decoret 2006, Fig. 7: next to a peak a ray can meet the field twice arbitrarily
  // close, so radius 0 is the only one possible there, and the filter says so (no clamping)
  DepthField peak = DepthField::FromFunction(16, 16, [](float u, float v) {
    const float x = u - 0.53f;
    const float y = v - 0.47f;
    return 0.2f + 3.0f * (x * x + y * y);
  });
  const SafetyRadiusMap radii = RadiiOf(peak, 0.0);
  // the highest texel is (8, 7); these four cells share it
  for (int j = 6; j <= 7; ++j)
  {
    for (int i = 7; i <= 8; ++i)
    {
      EXPECT_EQ(radii.At(vec2(i, j)), 0.0f) << "cell " << i << ", " << j;
      EXPECT_GT(CountViolations(peak, i, j, 1, 0.0, 2000, 5), 0) << "cell " << i << ", " << j;
    }
  }
  // a flat field: no ray ever comes back up, every radius is the cap
  const SafetyRadiusMap flat =
    RadiiOf(DepthField::FromFunction(20, 12, [](float, float) { return 0.4f; }), 0.0, 17);
  EXPECT_EQ(*std::min_element(flat.Values.begin(), flat.Values.end()), 17.0f);
}

TEST_F(ReliefSafetyRadius, ToleranceTradesBoundedErrorForFewerSamples)
{
  std::vector<double> previous;
  double exact = 0.0; // samples over the scenes at e = 0
  for (double tolerance : { 0.0, 0.02, 0.05, 0.1 })
  {
    double samples = 0.0;
    std::vector<double> perScene;
    unsigned seed = 400;
    for (const Scene& scene : *AllScenes)
    {
      const SafetyRadiusMap zero = RadiiOf(scene.Field, 0.0);
      const SafetyRadiusMap radii = RadiiOf(scene.Field, tolerance);
      for (size_t k = 0; k < radii.Values.size(); ++k)
      {
        ASSERT_GE(radii.Values[k], zero.Values[k]) << scene.Name << ", e " << tolerance;
      }
      const Tally tally = SearchWithin(scene, radii, tolerance, seed++);
      std::cout << "e " << tolerance << ", " << scene.Name << ": mean radius "
                << MeanRadius(radii) << ", " << tally.Samples << " samples per ray\n";
      perScene.push_back(tally.Samples);
      samples += tally.Samples;
    }
    if (!previous.empty())
    {
      for (size_t s = 0; s < perScene.size(); ++s)
      {
        // radii only grow with e; the rays are the same
        EXPECT_LE(perScene[s], previous[s] * 1.01 + 0.01)
          << (*AllScenes)[s].Name << ", e " << tolerance;
      }
    }
    previous = perScene;
    std::cout << "e " << tolerance << ": " << samples / AllScenes->size()
              << " samples per ray over the scenes\n";
    if (tolerance == 0.0)
    {
      exact = samples;
    }
    else
    {
      EXPECT_LT(samples, 0.9 * exact) << "e " << tolerance;
    }
  }
}

TEST_F(ReliefSafetyRadius, GrazingRaysKeepTheirHits)
{
  // reliefViewRay lets a grazing ray run for up to a thousand tiles before it is one
  // depth unit down, so texel coordinates reach 10^5 and float positions are good to
  // about 10^-3 texel: along such a ray the hit is only defined to the depth that buys,
  // whatever the search. The search recomputes its position from t at every step, so it
  // must stay within that, and neither lose the hit nor stall on the way.
  std::mt19937 generator(23);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (const Scene& scene : *AllScenes)
  {
    if (scene.Name != "smooth" && scene.Name != "noisy" && scene.Name != "cliffs")
    {
      continue;
    }
    for (double tolerance : { 0.0, 0.05 })
    {
      const SafetyRadiusMap radii = RadiiOf(scene.Field, tolerance);
      DepthField deeper = scene.Field;
      for (float& depth : deeper.Depths)
      {
        depth += static_cast<float>(tolerance);
      }
      CurrentField = &scene.Field;
      CurrentRadii = &radii;
      int driftingDDA = 0;
      for (int k = 0; k < 20; ++k)
      {
        const float azimuth = 2.0f * float(Pi) * unit(generator);
        const ReliefRay ray = reliefViewRay(vec2(unit(generator), unit(generator)),
          vec3(std::cos(azimuth), std::sin(azimuth), k % 2 ? 1e-3f : 1e-6f));
        const ReliefHit hit = reliefSearchSafetyRadius(ray, 0, 0);
        const double first = ReferenceHit(scene.Field, ray);
        const double last = tolerance > 0.0 ? ReferenceHit(deeper, ray) : first;
        const double slack = 2e-3 / ray.direction.z; // 2e-3 in depth
        ASSERT_TRUE(hit.hit) << scene.Name;
        EXPECT_GE(hit.t, first - slack) << scene.Name << ", e " << tolerance;
        EXPECT_LE(hit.t, last + slack) << scene.Name << ", e " << tolerance;
        driftingDDA += std::abs(reliefSearchExactDDA(ray, 0, 0).t - first) > slack ? 1 : 0;
      }
      std::cout << scene.Name << ", e " << tolerance << ": ExactDDA off by more than 2e-3 "
                << "in depth on " << driftingDDA << " of 20 grazing rays\n";
    }
  }
}

TEST_F(ReliefSafetyRadius, SamplesDoNotGrowWithResolution)
{
  // Baboud and Decoret 2006, s5: doubling the resolution doubles the radii, so the search takes
  // about as many steps; ExactDDA's cost doubles
  const auto smooth = [](float u, float v) {
    return 0.5f + 0.2f * std::sin(2.0f * float(Pi) * u) * std::cos(4.0f * float(Pi) * v);
  };
  std::mt19937 generator(17);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<ReliefRay> rays;
  for (int k = 0; k < 4000; ++k)
  {
    const float azimuth = 2.0f * float(Pi) * unit(generator);
    rays.push_back(reliefViewRay(vec2(unit(generator), unit(generator)),
      vec3(0.1f * std::cos(azimuth), 0.1f * std::sin(azimuth), 0.1f))); // 45 degrees
  }
  for (double tolerance : { 0.05, 0.1 })
  {
    double safety[2];
    double dda[2];
    for (int doubled = 0; doubled < 2; ++doubled)
    {
      const int size = doubled ? 256 : 128;
      const DepthField field = DepthField::FromFunction(size, size, smooth);
      const SafetyRadiusMap radii = RadiiOf(field, tolerance, 64);
      CurrentField = &field;
      CurrentRadii = &radii;
      long safe = 0;
      long exact = 0;
      for (const ReliefRay& ray : rays)
      {
        safe += reliefSearchSafetyRadius(ray, 0, 0).samples;
        exact += reliefSearchExactDDA(ray, 0, 0).samples;
      }
      safety[doubled] = double(safe) / rays.size();
      dda[doubled] = double(exact) / rays.size();
      std::cout << "e " << tolerance << ", " << size << "x" << size << ": mean radius "
                << MeanRadius(radii) << ", SafetyRadius " << safety[doubled]
                << " samples per ray, ExactDDA " << dda[doubled] << "\n";
    }
    EXPECT_GT(dda[1], 1.8 * dda[0]);
    EXPECT_LT(safety[1], 1.2 * safety[0]) << "e " << tolerance;
    EXPECT_LT(safety[1], 0.25 * dda[1]) << "e " << tolerance;
  }
}

TEST_F(ReliefSafetyRadius, RobustBinaryMissesOnlyWhereItsClampSteps)
{
  // Baboud and Decoret 2006, s3.4 as written: a radius of 0 is clamped to the cell, tested
  // only at its exit. Every hit is still on the field; it may lie past the bound only on
  // rays that dip into such a cell and out again, which SafetyRadius intersects exactly.
  for (double tolerance : { 0.0, 0.05 })
  {
    int outOfBound = 0;
    int exactOutOfBound = 0;
    unsigned seed = 700;
    for (const Scene& scene : *AllScenes)
    {
      const SafetyRadiusMap radii = RadiiOf(scene.Field, tolerance);
      const Tally robust = TallyWithin(scene, radii, tolerance, seed, &reliefSearchRobustBinary);
      const Tally exact = TallyWithin(scene, radii, tolerance, seed++, &reliefSearchSafetyRadius);
      std::cout << "e " << tolerance << ", " << scene.Name << ": RobustBinary " << robust.Samples
                << " samples per ray, " << robust.OutOfBound << " rays past the bound; "
                << "SafetyRadius " << exact.Samples << ", " << exact.OutOfBound << "\n";
      EXPECT_EQ(robust.OffTheField, 0) << scene.Name << ", e " << tolerance;
      // the most on the checkerboard (4% at e = 0), a saddle in every cell
      EXPECT_LE(robust.OutOfBound, RayCount / 20) << scene.Name << ", e " << tolerance;
      outOfBound += robust.OutOfBound;
      exactOutOfBound += exact.OutOfBound;
    }
    EXPECT_EQ(exactOutOfBound, 0) << "e " << tolerance;
    // the clamp is in effect: some dip through a radius-0 cell is stepped over
    EXPECT_GT(outOfBound, 0) << "e " << tolerance;
  }
}

TEST(ReliefSafetyRadiusFilter, OutputIsOneFloatRadiusPerCell)
{
  const DepthField field = RandomField(21, 13, 3, 0.3f, 0.7f);
  vtkNew<vtkSafetyRadiusFilter> filter;
  filter->SetErrorTolerance(0.05);
  filter->SetMaximumRadius(9);
  vtkSmartPointer<vtkImageData> image = Accelerate(filter, field);
  EXPECT_EQ(image->GetDimensions()[0], 21);
  EXPECT_EQ(image->GetDimensions()[1], 13);
  vtkDataArray* radii = image->GetPointData()->GetScalars();
  ASSERT_NE(radii, nullptr);
  EXPECT_STREQ(radii->GetName(), "SafetyRadius");
  EXPECT_EQ(radii->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(radii->GetNumberOfComponents(), 1);
  for (vtkIdType k = 0; k < radii->GetNumberOfTuples(); ++k)
  {
    const double radius = radii->GetComponent(k, 0);
    ASSERT_EQ(radius, std::floor(radius));
    ASSERT_GE(radius, 0.0);
    ASSERT_LE(radius, 9.0);
  }
}

TEST(ReliefSafetyRadiusFilter, NegativeToleranceBecomesZeroWithAWarning)
{
  vtkNew<vtkSafetyRadiusFilter> filter;
  vtkNew<ReliefEventRecorder> recorder;
  filter->AddObserver(vtkCommand::WarningEvent, recorder);
  filter->SetErrorTolerance(0.03);
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 0);
  filter->SetErrorTolerance(-0.1);
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 1);
  EXPECT_TRUE(recorder->AnyMessageContains("ErrorTolerance"));
  EXPECT_EQ(filter->GetErrorTolerance(), 0.0);
  filter->SetErrorTolerance(std::nan(""));
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 2);
  EXPECT_EQ(filter->GetErrorTolerance(), 0.0);
  // more than the whole depth, up to infinity, is the whole depth
  for (double tolerance : { 1.5, std::numeric_limits<double>::infinity() })
  {
    filter->SetErrorTolerance(tolerance);
    EXPECT_EQ(filter->GetErrorTolerance(), 1.0);
  }
  EXPECT_EQ(recorder->Count(vtkCommand::WarningEvent), 4);
  filter->SetErrorTolerance(0.0);
  // the clamped filter computes the radii of e = 0
  const DepthField field = Waves(24, 0.2f);
  filter->SetInputData(DepthImage(field));
  filter->Update();
  const SafetyRadiusMap exact = RadiiOf(field, 0.0);
  vtkDataArray* radii = filter->GetOutput()->GetPointData()->GetScalars();
  for (vtkIdType k = 0; k < radii->GetNumberOfTuples(); ++k)
  {
    ASSERT_EQ(radii->GetComponent(k, 0), exact.Values[k]);
  }
  std::ostringstream printed;
  filter->Print(printed);
  EXPECT_NE(printed.str().find("ErrorTolerance: 0"), std::string::npos);
  EXPECT_NE(printed.str().find("MaximumRadius: 32"), std::string::npos);
}
