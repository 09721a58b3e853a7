// ConeStep: the cone maps of vtkConeStepMapFilter and the search of
// vtkReliefConeSearch.glsl, run on the CPU through the very source the GPU compiles.
// The cones are checked against their definition by brute force, the search against the
// brute-force reference of ReliefSearchReference.h, and the classic texel-centre
// generator is shown to break on the bilinear field.
#include "ReliefEventRecorder.h"
#include "ReliefSearchReference.h"
#include "vtkConeStepMapFilter.h"

#include "vtkCommand.h"

#include <limits>

namespace
{
using namespace ReliefCpuMirror;

// The field's depth and the ray's along a straight horizontal path, in double: the gap
// (field minus ray) is a quadratic in each cell.
struct Path
{
  const DepthField* Field;
  double X; // texel coordinates at s = 0
  double Y;
  double UX; // unit direction
  double UY;
  double Depth;   // ray depth at s = 0
  double Descent; // ray depth per texel travelled

  // gap(s) = c[0] + c[1] (s - from) + c[2] (s - from)^2 within the cell under the middle
  void Gap(double from, double to, double c[3]) const
  {
    const double middle = 0.5 * (from + to);
    const int ci = static_cast<int>(std::floor(this->X + middle * this->UX));
    const int cj = static_cast<int>(std::floor(this->Y + middle * this->UY));
    const double d00 = this->Field->At(ci, cj);
    const double b = this->Field->At(ci + 1, cj) - d00;
    const double cc = this->Field->At(ci, cj + 1) - d00;
    const double e = this->Field->At(ci + 1, cj + 1) - this->Field->At(ci + 1, cj) -
      this->Field->At(ci, cj + 1) + d00;
    const double px = this->X + from * this->UX - ci;
    const double py = this->Y + from * this->UY - cj;
    c[0] = d00 + b * px + cc * py + e * px * py - (this->Depth + from * this->Descent);
    c[1] = b * this->UX + cc * this->UY + e * (px * this->UY + py * this->UX) - this->Descent;
    c[2] = e * this->UX * this->UY;
  }

  // Cell borders crossed in (0, length), in order, with 0 and length.
  std::vector<double> Breaks(double length) const
  {
    std::vector<double> breaks = { 0.0, length };
    auto add = [&](double origin, double run) {
      if (run == 0.0)
      {
        return;
      }
      const double end = origin + run * length;
      const double last = std::max(origin, end);
      for (double line = std::ceil(std::min(origin, end)); line <= last; line += 1.0)
      {
        const double s = (line - origin) / run;
        if (s > 0.0 && s < length)
        {
          breaks.push_back(s);
        }
      }
    };
    add(this->X, this->UX);
    add(this->Y, this->UY);
    std::sort(breaks.begin(), breaks.end());
    return breaks;
  }

  // The largest gap (ray above the field) after the ray first reaches the field within
  // [0, length]; -infinity when it never does. A positive value is a second crossing.
  double RiseAfterEntry(double length) const
  {
    const std::vector<double> breaks = this->Breaks(length);
    bool entered = false;
    double rise = -std::numeric_limits<double>::infinity();
    for (size_t k = 0; k + 1 < breaks.size(); ++k)
    {
      const double span = breaks[k + 1] - breaks[k];
      if (span <= 0.0)
      {
        continue;
      }
      double c[3];
      this->Gap(breaks[k], breaks[k + 1], c);
      auto gap = [&c](double s) { return c[0] + s * (c[1] + s * c[2]); };
      double start = 0.0;
      if (!entered)
      {
        // the first s in [0, span] with gap <= 0
        double first = -1.0;
        if (c[0] <= 0.0)
        {
          first = 0.0;
        }
        else
        {
          // the roots without cancellation: q / c2 and c0 / q
          std::vector<double> roots;
          const double discriminant = c[1] * c[1] - 4.0 * c[2] * c[0];
          if (discriminant >= 0.0)
          {
            const double root = std::sqrt(discriminant);
            const double q = -0.5 * (c[1] >= 0.0 ? c[1] + root : c[1] - root);
            if (c[2] != 0.0)
            {
              roots.push_back(q / c[2]);
            }
            if (q != 0.0)
            {
              roots.push_back(c[0] / q);
            }
          }
          std::sort(roots.begin(), roots.end());
          for (double r : roots)
          {
            if (r >= 0.0 && r <= span)
            {
              first = r;
              break;
            }
          }
        }
        if (first < 0.0)
        {
          continue;
        }
        entered = true;
        start = first;
      }
      rise = std::max({ rise, gap(start), gap(span) });
      if (c[2] < 0.0)
      {
        const double vertex = -c[1] / (2.0 * c[2]);
        if (vertex > start && vertex < span)
        {
          rise = std::max(rise, gap(vertex));
        }
      }
    }
    return rise;
  }
};

// Depth of the bilinear field at texel coordinates (x, y), in double.
double FieldAt(const DepthField& field, double x, double y)
{
  const int i = static_cast<int>(std::floor(x));
  const int j = static_cast<int>(std::floor(y));
  const double fx = x - i;
  const double fy = y - j;
  return (1 - fy) * ((1 - fx) * field.At(i, j) + fx * field.At(i + 1, j)) +
    fy * ((1 - fx) * field.At(i, j + 1) + fx * field.At(i + 1, j + 1));
}

// Rays over every cell, inside its cone: how many leave the field after entering it
// (beyond `tolerance` in depth). Half start over a random point of the cell in a random
// direction, slopes from nearly vertical to grazing, depths biased toward the cell's
// top where the cone is narrowest; half are aimed to pass just under the field at a
// random point near the cell, where a ridge would make them leave it again.
int ConeViolations(const DepthField& field, const ConeStepMap& cones, int raysPerCell,
  unsigned seed, double tolerance)
{
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int violations = 0;
  for (int j = 0; j < field.Height; ++j)
  {
    for (int i = 0; i < field.Width; ++i)
    {
      const vec2 cone = cones.At(vec2(i, j));
      const double top = cone.x;
      const double ratio = cone.y;
      for (int r = 0; r < raysPerCell; ++r)
      {
        const double run = std::pow(10.0, -1.5 + 4.5 * unit(generator)); // texels per depth
        const double px = i + unit(generator);
        const double py = j + unit(generator);
        double angle = 2.0 * Pi * unit(generator);
        const double below = r % 4 == 0 ? std::pow(unit(generator), 4.0) : unit(generator);
        double depth = top * (1.0 - below);
        if (r % 2)
        {
          const double mx = i + 0.5 + 8.0 * (2.0 * unit(generator) - 1.0);
          const double my = j + 0.5 + 8.0 * (2.0 * unit(generator) - 1.0);
          angle = std::atan2(my - py, mx - px);
          depth = FieldAt(field, mx, my) + 1e-4 * unit(generator) -
            std::hypot(mx - px, my - py) / run;
          if (depth > top)
          {
            continue;
          }
        }
        const Path path{ &field, px, py, std::cos(angle), std::sin(angle), depth, 1.0 / run };
        // where |x - p| = ratio (top - depth): the part of the ray inside the cone
        const double length = ratio * (top - path.Depth) / (1.0 + ratio / run);
        if (length > 0.0 && path.RiseAfterEntry(length) > tolerance)
        {
          ++violations;
        }
      }
    }
  }
  return violations;
}

// The classic generator (GPU Gems 3 ch. 18), on texel centres only: the apex is the
// cell's highest corner texel; for every higher texel b, the view ray from above the
// apex at depth 0 through b's centre is followed past b, reading the nearest texel's
// depth, until it comes out above the field; that point bounds the cone.
ConeStepMap ClassicConeMap(const DepthField& field)
{
  ConeStepMap map;
  map.Width = field.Width;
  map.Height = field.Height;
  const double maximum = vtkConeStepMapFilter::GetMaximumRatio(field.Width, field.Height);
  for (int j = 0; j < field.Height; ++j)
  {
    for (int i = 0; i < field.Width; ++i)
    {
      int ax = i;
      int ay = j;
      for (int k = 1; k < 4; ++k)
      {
        if (field.At(i + (k & 1), j + (k >> 1)) < field.At(ax, ay))
        {
          ax = i + (k & 1);
          ay = j + (k >> 1);
        }
      }
      const double top = field.At(ax, ay);
      double ratio = maximum;
      for (int by = ay - field.Height; by <= ay + field.Height; ++by)
      {
        for (int bx = ax - field.Width; bx <= ax + field.Width; ++bx)
        {
          const double depth = field.At(bx, by);
          const double distance = std::hypot(bx - ax, by - ay);
          if (depth >= top || distance == 0.0)
          {
            continue;
          }
          const double run = distance / depth; // texels per unit depth of that ray
          double s = distance;
          for (; s < distance + 4.0 * std::max(field.Width, field.Height); s += 0.25)
          {
            const double x = ax + (bx - ax) * s / distance;
            const double y = ay + (by - ay) * s / distance;
            const int nx = static_cast<int>(std::floor(x + 0.5));
            const int ny = static_cast<int>(std::floor(y + 0.5));
            if (field.At(nx, ny) > s / run)
            {
              break;
            }
          }
          if (s / run < top)
          {
            ratio = std::min(ratio, s / (top - s / run));
          }
        }
      }
      map.Values.emplace_back(float(top), float(ratio));
    }
  }
  return map;
}

class ReliefConeStep : public ReliefConeScenes
{
};
}

TEST_F(ReliefConeStep, MatchesTheReferenceEverywhere)
{
  // exact: the walk that ends every bracket leaves only float rounding, as for ExactDDA
  ExpectExact(*AllScenes, "ConeStep",
    [](const ReliefRay& ray) { return reliefSearchConeStep(ray, 0, 0); }, Tolerance,
    [](const Scene& scene) { CurrentConeMap = &(*ConeMaps)[Find(scene.Name)]; });
}

TEST_F(ReliefConeStep, ConesHoldOnRandomFields)
{
  // rough, gentle and smooth fields, and one whose cells are mostly saddles
  const DepthField fields[] = { RandomField(12, 12, 41, 0.0f, 1.0f),
    RandomField(16, 9, 42, 0.4f, 0.6f),
    DepthField::FromFunction(16, 16, [](float u, float v) {
      return 0.5f + 0.3f * std::sin(2.0f * float(Pi) * u) * std::sin(4.0f * float(Pi) * v);
    }),
    DepthField::FromFunction(12, 12, [](float u, float v) {
      return 0.5f + 0.4f * std::sin(12.0f * float(Pi) * u) * std::sin(12.0f * float(Pi) * v);
    }) };
  int index = 0;
  for (const DepthField& field : fields)
  {
    const ConeStepMap cones = ConeMapOf(field);
    const int violations = ConeViolations(field, cones, 2000, 50 + index, 1e-6);
    std::cout << "field " << index << ": " << violations
              << " rays leave the field inside a cone\n";
    EXPECT_EQ(violations, 0) << "field " << index;
    ++index;
  }
}

TEST_F(ReliefConeStep, ClassicTexelCentreConesFailOnTheBilinearField)
{
  // the same check finds rays through the classic cones: texel centres miss the field
  // between them and a single apex misses the rest of the cell
  const DepthField field = RandomField(12, 12, 41, 0.0f, 1.0f);
  const int classic = ConeViolations(field, ClassicConeMap(field), 2000, 60, 1e-6);
  const int robust = ConeViolations(field, ConeMapOf(field), 2000, 60, 1e-6);
  std::cout << "rays leaving the field inside a cone: classic " << classic << ", robust "
            << robust << "\n";
  EXPECT_GT(classic, 0);
  EXPECT_EQ(robust, 0);

  // and the search, trusting them, skips intersections
  int classicTotal = 0;
  for (size_t k : { Find("noisy"), Find("non-power-of-two") })
  {
    Use(k);
    const Scene& scene = (*AllScenes)[k];
    const ConeStepMap classicMap = ClassicConeMap(scene.Field);
    int classicWrong = 0;
    int robustWrong = 0;
    for (const ReliefRay& ray : ViewRays(400 + unsigned(k), 0.1f))
    {
      const double reference = ReferenceHit(scene.Field, ray);
      CurrentConeMap = &(*ConeMaps)[k];
      const ReliefHit robust = reliefSearchConeStep(ray, 0, 0);
      CurrentConeMap = &classicMap;
      const ReliefHit classicHit = reliefSearchConeStep(ray, 0, 0);
      robustWrong += HitError(scene.Field, ray, robust.t, reference) > Tolerance ? 1 : 0;
      if (HitError(scene.Field, ray, classicHit.t, reference) > Tolerance && classicWrong++ == 0)
      {
        std::cout << scene.Name << ": the ray from (" << ray.origin.x << ", " << ray.origin.y
                  << ") along (" << ray.direction.x << ", " << ray.direction.y << ", "
                  << ray.direction.z << ") meets the field at t = " << reference
                  << "; with classic cones the search answers " << classicHit.t
                  << ", with these " << robust.t << "\n";
      }
    }
    std::cout << scene.Name << ": rays off the reference, classic cones " << classicWrong
              << ", robust cones " << robustWrong << " of " << RayCount << "\n";
    classicTotal += classicWrong;
    EXPECT_EQ(robustWrong, 0) << scene.Name;
  }
  EXPECT_GT(classicTotal, 0);
}

TEST_F(ReliefConeStep, AFloorAtTheDeepestLevelIsMetAtTheEndOfTheRay)
{
  // depth 1 is met at t = 1 exactly, where rounding may let the cell tests pass it: the
  // hit must still be a hit, with its clear point above it (else it shadows itself)
  const DepthField floor = DepthField::FromFunction(64, 64, [](float, float) { return 1.0f; });
  const ConeStepMap cones = ConeMapOf(floor);
  CurrentField = &floor;
  CurrentConeMap = &cones;
  for (const ReliefRay& ray : ViewRays(300, 0.1f))
  {
    const ReliefHit hit = reliefSearchConeStep(ray, 0, 0);
    ASSERT_TRUE(hit.hit);
    ASSERT_NEAR(hit.t, 1.0f, 1e-5f);
    ASSERT_LT(hit.clear.z, hit.position.z);
  }
}

TEST_F(ReliefConeStep, TakesFarFewerSamplesThanExactDDAOnSmoothFieldsAndTerrain)
{
  for (size_t k = 0; k < AllScenes->size(); ++k)
  {
    Use(k);
    long dda = 0;
    long cone = 0;
    for (const ReliefRay& ray : ViewRays(300 + unsigned(k), 0.1f))
    {
      dda += reliefSearchExactDDA(ray, 0, 0).samples;
      cone += reliefSearchConeStep(ray, 0, 0).samples;
    }
    const std::string& name = (*AllScenes)[k].Name;
    std::cout << name << ": samples per ray, ExactDDA " << double(dda) / RayCount
              << ", ConeStep " << double(cone) / RayCount << "\n";
    if (name == "smooth" || name == "16-bit terrain")
    {
      EXPECT_LT(2 * cone, dda) << name;
    }
  }
}

TEST_F(ReliefConeStep, KeepsItsHitsOnGrazingRaysThousandsOfCellsLong)
{
  ExpectGrazingHits(*AllScenes, "ConeStep",
    [](const ReliefRay& ray) { return reliefSearchConeStep(ray, 0, 0); },
    [](const Scene& scene) { CurrentConeMap = &(*ConeMaps)[Find(scene.Name)]; });
}

TEST(ReliefConeStepMapFilter, OutputIsTopAndRatioPerCell)
{
  const DepthField field = RandomField(7, 5, 3, 0.0f, 1.0f);
  vtkNew<vtkConeStepMapFilter> filter;
  filter->SetInputData(DepthImage(field));
  filter->Update();
  vtkImageData* output = filter->GetOutput();
  EXPECT_EQ(output->GetDimensions()[0], 7);
  EXPECT_EQ(output->GetDimensions()[1], 5);
  vtkDataArray* cones = output->GetPointData()->GetScalars();
  ASSERT_NE(cones, nullptr);
  EXPECT_EQ(cones->GetDataType(), VTK_FLOAT);
  EXPECT_STREQ(cones->GetName(), "ConeStep");
  ASSERT_EQ(cones->GetNumberOfComponents(), 2);
  float highest = 1.0f;
  for (int j = 0; j < 5; ++j)
  {
    for (int i = 0; i < 7; ++i)
    {
      const float top = std::min(
        { field.At(i, j), field.At(i + 1, j), field.At(i, j + 1), field.At(i + 1, j + 1) });
      highest = std::min(highest, top);
      EXPECT_EQ(cones->GetComponent(j * 7 + i, 0), top);
      EXPECT_GE(cones->GetComponent(j * 7 + i, 1), 0.0);
      EXPECT_LE(cones->GetComponent(j * 7 + i, 1), vtkConeStepMapFilter::GetMaximumRatio(7, 5));
    }
  }
  // the highest cells see nothing above them: their cones are as wide as stored cones go
  for (int k = 0; k < 35; ++k)
  {
    if (cones->GetComponent(k, 0) == highest)
    {
      EXPECT_NEAR(cones->GetComponent(k, 1), vtkConeStepMapFilter::GetMaximumRatio(7, 5), 0.01);
    }
  }
}

TEST(ReliefConeStepMapFilter, TwoByteCellsRoundInsideTheCone)
{
  // What the mapper uploads, as the shader decodes it: an apex no deeper than the top
  // (strictly higher for a top below the surface, within 1/255) and a ratio no wider
  // than the proven one (within a code step, 2^(16/254), 4.5%), or 0 below the codes.
  const double maximum = vtkConeStepMapFilter::GetMaximumRatio(512, 256);
  const vec2 range(static_cast<float>(maximum),
    static_cast<float>(vtkConeStepMapFilter::RATIO_OCTAVES));
  const double step = std::exp2(vtkConeStepMapFilter::RATIO_OCTAVES / 254.0);
  const double lowest = maximum * std::exp2(-double(vtkConeStepMapFilter::RATIO_OCTAVES));
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < 20000; ++k)
  {
    // tops on the 16-bit grid (k = 0 and 1: the surface and the deepest level)
    const double top = k < 2 ? k : std::round(unit(generator) * 65535.0) / 65535.0;
    // ratios from far below the lowest code to the maximum
    const double ratio = k == 2 ? 0.0 : maximum * std::exp2(-20.0 * unit(generator));
    unsigned char code[2];
    vtkConeStepMapFilter::EncodeCone(top, ratio, maximum, code);
    const vec2 decoded = reliefConeDecode(vec2(code[0] / 255.0f, code[1] / 255.0f), range);
    ASSERT_LE(decoded.x, top) << "top " << top;
    if (top > 0.0)
    {
      ASSERT_LT(decoded.x, top) << "top " << top;
    }
    ASSERT_GT(decoded.x, top - 1.0 / 255.0 - 1e-6) << "top " << top;
    ASSERT_LE(decoded.y, ratio) << "ratio " << ratio;
    if (ratio >= lowest * 1.0001)
    {
      ASSERT_GT(decoded.y * step * 1.0001, ratio) << "ratio " << ratio;
    }
    else
    {
      ASSERT_LT(decoded.y, lowest * 1.0001) << "ratio " << ratio;
    }
  }
}
