#include "vtkSafetyRadiusFilter.h"

#include "vtkFloatArray.h"
#include "vtkObjectFactory.h"
#include "vtkReliefDepthImage.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkSafetyRadiusFilter);

namespace
{
constexpr double Pi = 3.14159265358979323846;
constexpr int Wedges = 16; // of 22.5 degrees, each inside one quadrant
constexpr int FineRings = 16; // rings read cell by cell; beyond, runs of rings from blocks
constexpr int MaximumLevel = 4; // blocks of 16 cells a side cover rings 128 to 255
constexpr int ProgressSlices = 10;

// Relative slack for float rounding, always in the direction that finds more danger.
constexpr float Slack = 4e-6f;

double WrapAngle(double angle)
{
  return std::remainder(angle, 2.0 * Pi);
}

// Unit vector of wedge boundary `w`, exact on the axes so that a slope along an axis
// does not leak into the perpendicular wedge.
std::array<double, 2> BoundaryDirection(int w)
{
  const double angle = 2.0 * Pi * w / Wedges;
  double c = std::cos(angle);
  double s = std::sin(angle);
  return { std::abs(c) < 1e-12 ? 0.0 : c, std::abs(s) < 1e-12 ? 0.0 : s };
}

// Whether a ray leaving some point of cell (0, 0) with a direction in wedge `w` passes
// through the interior of one of the cells (x0..x1, y0..y1): whether the open rectangle
// (x0 - 1, x1 + 1) x (y0 - 1, y1 + 1) of displacements, the union of those of the cells,
// meets the wedge. Open, so that a ray that only runs along a cell's border does not
// count the cell: the points of that border also belong to the cell across, which does.
bool MeetsWedge(int x0, int x1, int y0, int y1, int w)
{
  if (x0 <= 0 && x1 >= 0 && y0 <= 0 && y1 >= 0)
  {
    return true;
  }
  const double width = 2.0 * Pi / Wedges;
  const double centre = std::atan2(0.5 * (y0 + y1), 0.5 * (x0 + x1));
  double low = Pi;
  double high = -Pi;
  for (int x : { x0 - 1, x1 + 1 })
  {
    for (int y : { y0 - 1, y1 + 1 })
    {
      if (x != 0 || y != 0)
      {
        const double angle = WrapAngle(std::atan2(double(y), double(x)) - centre);
        low = std::min(low, angle);
        high = std::max(high, angle);
      }
    }
  }
  // touching the wedge's side is no overlap (a real overlap is far above rounding: the
  // angles come from small integers)
  const double offset = WrapAngle(centre - (w + 0.5) * width);
  return offset + low < 0.5 * width - 1e-9 && offset + high > -0.5 * width + 1e-9;
}

// The extreme slopes along the directions of wedge `w` of a gradient: the slope g . d is
// linear in the direction d, so over the wedge's arc it is extreme at a side of the
// wedge, or along g itself when g points into the wedge. A little is added (taken off the
// least), to cover rounding.
struct WedgeSlopes
{
  std::array<double, 2> First;
  std::array<double, 2> Last;
  bool PositiveX;
  bool PositiveY;

  explicit WedgeSlopes(int w = 0)
    : First(BoundaryDirection(w))
    , Last(BoundaryDirection(w + 1))
    , PositiveX(std::cos((w + 0.5) * 2.0 * Pi / Wedges) > 0.0)
    , PositiveY(std::sin((w + 0.5) * 2.0 * Pi / Wedges) > 0.0)
  {
  }

  template <typename Real>
  Real Most(Real gx, Real gy) const
  {
    const Real x0 = static_cast<Real>(this->First[0]);
    const Real y0 = static_cast<Real>(this->First[1]);
    const Real x1 = static_cast<Real>(this->Last[0]);
    const Real y1 = static_cast<Real>(this->Last[1]);
    const bool inside = x0 * gy - y0 * gx >= 0 && gx * y1 - gy * x1 >= 0;
    const Real most =
      inside ? std::sqrt(gx * gx + gy * gy) : std::max(gx * x0 + gy * y0, gx * x1 + gy * y1);
    return most + Real(1e-6) * (std::abs(gx) + std::abs(gy));
  }

  template <typename Real>
  Real Least(Real gx, Real gy) const
  {
    return -this->Most(-gx, -gy);
  }

  // Over a box [gx0, gx1] x [gy0, gy1] of gradients: the wedge lies in one quadrant, where
  // one corner of the box has the most slope for every direction, the opposite corner
  // the least.
  float MostOfBox(float gx0, float gx1, float gy0, float gy1) const
  {
    return this->Most(this->PositiveX ? gx1 : gx0, this->PositiveY ? gy1 : gy0);
  }

  float LeastOfBox(float gx0, float gx1, float gy0, float gy1) const
  {
    return this->Least(this->PositiveX ? gx0 : gx1, this->PositiveY ? gy0 : gy1);
  }
};

// Per cell or per block: depth range and gradient box.
struct Bounds
{
  std::vector<float> Least, Deepest, GradientX0, GradientX1, GradientY0, GradientY1;

  void Resize(size_t count)
  {
    for (std::vector<float>* plane :
      { &this->Least, &this->Deepest, &this->GradientX0, &this->GradientX1, &this->GradientY0,
        &this->GradientY1 })
    {
      plane->resize(count);
    }
  }
};

// A run of rings [First, Last] and, per wedge, the cells (level 0: offsets into the
// padded planes) or blocks (level > 0: offsets (dx, dy) of their lower-left cell) that
// cover its corridor.
struct Run
{
  int Level;
  int First;
  int Last;
  std::array<std::vector<long>, Wedges> Cells;
  std::array<std::vector<std::array<int, 2>>, Wedges> Blocks;
};

class SafetyRadii
{
public:
  SafetyRadii(const vtkReliefDepthImage& field, double tolerance, int maximumRadius)
    : Field(field)
    , Width(field.Width)
    , Height(field.Height)
    , MaximumRadius(maximumRadius)
  {
    // the tolerance rounded down: a larger one would hide danger
    this->Tolerance = static_cast<float>(tolerance);
    if (double(this->Tolerance) > tolerance)
    {
      this->Tolerance = std::nextafter(this->Tolerance, 0.0f);
    }
    for (int w = 0; w < Wedges; ++w)
    {
      this->Slopes[w] = WedgeSlopes(w);
    }
    this->BuildRuns();
    this->BuildCellPlanes();
    this->BuildBlocks();
    this->BuildDistances();
    // wrapped column and row starts for offsets up to the farthest run
    this->WrapMargin = this->Runs.back().Last + 1;
    for (int x = -this->WrapMargin; x < this->Width + this->WrapMargin; ++x)
    {
      this->WrappedColumns.push_back(((x % this->Width) + this->Width) % this->Width);
    }
    for (int y = -this->WrapMargin; y < this->Height + this->WrapMargin; ++y)
    {
      this->WrappedRows.push_back(
        static_cast<size_t>(((y % this->Height) + this->Height) % this->Height) * this->Width);
    }
  }

  // Radii of rows [begin, end) of cells, written to `radii`.
  void Rows(int begin, int end, float* radii) const
  {
    const size_t runs = this->Runs.size();
    std::vector<float> scratch(4 * Wedges * runs);
    for (int j = begin; j < end; ++j)
    {
      for (int i = 0; i < this->Width; ++i)
      {
        radii[static_cast<size_t>(j) * this->Width + i] =
          static_cast<float>(this->Radius(i, j, scratch.data()));
      }
    }
  }

private:
  void BuildRuns()
  {
    for (int first = 0; first <= this->MaximumRadius;)
    {
      int level = 0;
      while (level < MaximumLevel && first >= (FineRings << level))
      {
        ++level;
      }
      Run run;
      run.Level = level;
      run.First = first;
      run.Last = first + (1 << level) - 1;
      this->Runs.push_back(run);
      first = run.Last + 1;
    }
    this->Levels = this->Runs.back().Level;
    this->Padding = std::min(FineRings, this->Runs.back().Last + 1);
    const long paddedWidth = this->Width + 2 * this->Padding;
    for (Run& run : this->Runs)
    {
      const int side = 1 << run.Level;
      // blocks of side x side cells tiling the square annulus of rings [First, Last]
      // (single cells at level 0): two strips of `side` rows, above and below, and two
      // of `side` columns between them; the last block of a strip is moved back to end
      // with it (the overlap only repeats cells)
      std::vector<std::array<int, 2>> blocks;
      auto strip = [&](int fixed, bool horizontal, int from, int to) {
        for (int start = from; start <= to; start += side)
        {
          const int at = std::min(start, to - side + 1);
          blocks.push_back(
            horizontal ? std::array<int, 2>{ at, fixed } : std::array<int, 2>{ fixed, at });
        }
      };
      if (run.Level == 0)
      {
        for (int dy = -run.First; dy <= run.First; ++dy)
        {
          for (int dx = -run.First; dx <= run.First; ++dx)
          {
            if (std::max(std::abs(dx), std::abs(dy)) == run.First)
            {
              blocks.push_back({ dx, dy });
            }
          }
        }
      }
      else
      {
        strip(run.First, true, -run.Last, run.Last);
        strip(-run.Last, true, -run.Last, run.Last);
        strip(run.First, false, -run.First + 1, run.First - 1);
        strip(-run.Last, false, -run.First + 1, run.First - 1);
      }
      for (const std::array<int, 2>& block : blocks)
      {
        for (int w = 0; w < Wedges; ++w)
        {
          if (!MeetsWedge(block[0], block[0] + side - 1, block[1], block[1] + side - 1, w))
          {
            continue;
          }
          if (run.Level == 0)
          {
            run.Cells[w].push_back(long(block[1]) * paddedWidth + block[0]);
          }
          else
          {
            run.Blocks[w].push_back(block);
          }
        }
      }
    }
  }

  // Level 0, one cell: depth range and, per wedge, slope range from the gradients at
  // the four corners; padded so that every cell of the fine rings lies at a fixed offset.
  void BuildCellPlanes()
  {
    const int paddedWidth = this->Width + 2 * this->Padding;
    const int paddedHeight = this->Height + 2 * this->Padding;
    const size_t padded = static_cast<size_t>(paddedWidth) * paddedHeight;
    this->PaddedWidth = paddedWidth;
    this->Least.resize(padded);
    this->Deepest.resize(padded);
    this->MostSlope.resize(Wedges * padded);
    this->LeastSlope.resize(Wedges * padded);
    this->CellBounds.Resize(static_cast<size_t>(this->Width) * this->Height);
    vtkSMPTools::For(0, paddedHeight, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType y = begin; y < end; ++y)
      {
        for (int x = 0; x < paddedWidth; ++x)
        {
          const int i = x - this->Padding;
          const int j = static_cast<int>(y) - this->Padding;
          const double d00 = this->Field.At(i, j);
          const double d10 = this->Field.At(i + 1, j);
          const double d01 = this->Field.At(i, j + 1);
          const double d11 = this->Field.At(i + 1, j + 1);
          const size_t at = static_cast<size_t>(y) * paddedWidth + x;
          this->Least[at] = static_cast<float>(std::min(std::min(d00, d10), std::min(d01, d11)));
          this->Deepest[at] = static_cast<float>(std::max(std::max(d00, d10), std::max(d01, d11)));
          // the gradient (b + t y, c + t x) at the corners of depth = d00 + b x + c y + t x y
          const double b = d10 - d00;
          const double c = d01 - d00;
          const double t = d11 - d10 - d01 + d00;
          const double corners[4][2] = { { b, c }, { b, c + t }, { b + t, c }, { b + t, c + t } };
          for (int w = 0; w < Wedges; ++w)
          {
            double most = -1e300;
            double least = 1e300;
            for (const auto& g : corners)
            {
              most = std::max(most, this->Slopes[w].Most(g[0], g[1]));
              least = std::min(least, this->Slopes[w].Least(g[0], g[1]));
            }
            this->MostSlope[w * padded + at] = static_cast<float>(most);
            this->LeastSlope[w * padded + at] = static_cast<float>(least);
          }
          if (i >= 0 && i < this->Width && j >= 0 && j < this->Height)
          {
            const size_t cell = static_cast<size_t>(j) * this->Width + i;
            this->CellBounds.Least[cell] = this->Least[at];
            this->CellBounds.Deepest[cell] = this->Deepest[at];
            this->CellBounds.GradientX0[cell] = static_cast<float>(std::min(b, b + t));
            this->CellBounds.GradientX1[cell] = static_cast<float>(std::max(b, b + t));
            this->CellBounds.GradientY0[cell] = static_cast<float>(std::min(c, c + t));
            this->CellBounds.GradientY1[cell] = static_cast<float>(std::max(c, c + t));
          }
        }
      }
    });
  }

  // Level L: the bounds of the 2^L x 2^L cells from each cell up and right (wrapping),
  // each from four blocks of the level below.
  void BuildBlocks()
  {
    const size_t count = static_cast<size_t>(this->Width) * this->Height;
    this->BlockBounds.resize(this->Levels + 1);
    for (int level = 1; level <= this->Levels; ++level)
    {
      const Bounds& below = level == 1 ? this->CellBounds : this->BlockBounds[level - 1];
      Bounds& bounds = this->BlockBounds[level];
      bounds.Resize(count);
      const int half = 1 << (level - 1);
      vtkSMPTools::For(0, this->Height, [&](vtkIdType begin, vtkIdType end) {
        for (vtkIdType y = begin; y < end; ++y)
        {
          const size_t rows[2] = { static_cast<size_t>(y) * this->Width,
            static_cast<size_t>((y + half) % this->Height) * this->Width };
          for (int x = 0; x < this->Width; ++x)
          {
            const size_t quarters[4] = { rows[0] + x, rows[0] + (x + half) % this->Width,
              rows[1] + x, rows[1] + (x + half) % this->Width };
            const size_t at = rows[0] + x;
            bounds.Least[at] = below.Least[quarters[0]];
            bounds.Deepest[at] = below.Deepest[quarters[0]];
            bounds.GradientX0[at] = below.GradientX0[quarters[0]];
            bounds.GradientX1[at] = below.GradientX1[quarters[0]];
            bounds.GradientY0[at] = below.GradientY0[quarters[0]];
            bounds.GradientY1[at] = below.GradientY1[quarters[0]];
            for (int q = 1; q < 4; ++q)
            {
              bounds.Least[at] = std::min(bounds.Least[at], below.Least[quarters[q]]);
              bounds.Deepest[at] = std::max(bounds.Deepest[at], below.Deepest[quarters[q]]);
              bounds.GradientX0[at] =
                std::min(bounds.GradientX0[at], below.GradientX0[quarters[q]]);
              bounds.GradientX1[at] =
                std::max(bounds.GradientX1[at], below.GradientX1[quarters[q]]);
              bounds.GradientY0[at] =
                std::min(bounds.GradientY0[at], below.GradientY0[quarters[q]]);
              bounds.GradientY1[at] =
                std::max(bounds.GradientY1[at], below.GradientY1[quarters[q]]);
            }
          }
        }
      });
    }
  }

  // Distances along a ray of the wedge from a point of the cell to a point of a run:
  // the point's offset in cells is at least First - 1 and at most Last + 1 along the
  // larger axis, and the ray covers max(|cos|, |sin|) of that axis per unit of length.
  void BuildDistances()
  {
    const size_t runs = this->Runs.size();
    this->InverseReach.resize(Wedges * runs);
    this->Apart.resize(Wedges * runs * runs);
    this->ToleranceOverSpan.resize(Wedges * runs * runs);
    const double width = 2.0 * Pi / Wedges;
    for (int w = 0; w < Wedges; ++w)
    {
      double least = 1.0;
      double most = 0.0;
      std::vector<double> angles = { w * width, (w + 1) * width };
      for (int octant = 0; octant <= 8; ++octant)
      {
        if (octant * Pi / 4 > angles[0] && octant * Pi / 4 < angles[1])
        {
          angles.push_back(octant * Pi / 4);
        }
      }
      for (double angle : angles)
      {
        const double axis = std::max(std::abs(std::cos(angle)), std::abs(std::sin(angle)));
        least = std::min(least, axis);
        most = std::max(most, axis);
      }
      std::vector<double> nearest(runs);
      std::vector<double> farthest(runs);
      for (size_t r = 0; r < runs; ++r)
      {
        nearest[r] = std::max(0, this->Runs[r].First - 1) / most * (1.0 - 1e-6);
        farthest[r] = (this->Runs[r].Last + 1) / least * (1.0 + 1e-6);
        this->InverseReach[w * runs + r] = 1.0 / farthest[r];
      }
      for (size_t b = 0; b < runs; ++b)
      {
        for (size_t a = 0; a <= b; ++a)
        {
          const size_t at = (w * runs + b) * runs + a;
          // least |ab| when positive; a tiny positive value is treated as none
          const double apart = nearest[b] - farthest[a];
          this->Apart[at] = static_cast<float>(apart > 1e-6 ? apart : 0.0);
          // e / most |ab|, rounded down
          this->ToleranceOverSpan[at] =
            static_cast<float>(this->Tolerance / (farthest[b] - nearest[a]) * (1.0 - 1e-6));
        }
      }
    }
  }

  // Least depth, deepest depth, most and least slope of the corridor of run `r` in wedge
  // `w`, for cell (i, j).
  void Aggregate(const Run& run, int w, int i, int j, float& least, float& deepest,
    float& most, float& flattest) const
  {
    least = 2.0f;
    deepest = -1.0f;
    most = -1e30f;
    flattest = 1e30f;
    if (run.Level == 0)
    {
      const size_t padded = this->Least.size();
      const size_t at =
        static_cast<size_t>(j + this->Padding) * this->PaddedWidth + i + this->Padding;
      const float* leastPlane = this->Least.data() + at;
      const float* deepestPlane = this->Deepest.data() + at;
      const float* mostPlane = this->MostSlope.data() + w * padded + at;
      const float* leastSlopePlane = this->LeastSlope.data() + w * padded + at;
      for (long offset : run.Cells[w])
      {
        least = std::min(least, leastPlane[offset]);
        deepest = std::max(deepest, deepestPlane[offset]);
        most = std::max(most, mostPlane[offset]);
        flattest = std::min(flattest, leastSlopePlane[offset]);
      }
      return;
    }
    const Bounds& bounds = this->BlockBounds[run.Level];
    const WedgeSlopes& slopes = this->Slopes[w];
    const int* columns = this->WrappedColumns.data() + this->WrapMargin + i;
    const size_t* rows = this->WrappedRows.data() + this->WrapMargin + j;
    for (const std::array<int, 2>& block : run.Blocks[w])
    {
      const size_t at = rows[block[1]] + columns[block[0]];
      least = std::min(least, bounds.Least[at]);
      deepest = std::max(deepest, bounds.Deepest[at]);
      most = std::max(most,
        slopes.MostOfBox(bounds.GradientX0[at], bounds.GradientX1[at], bounds.GradientY0[at],
          bounds.GradientY1[at]));
      flattest = std::min(flattest,
        slopes.LeastOfBox(bounds.GradientX0[at], bounds.GradientX1[at], bounds.GradientY0[at],
          bounds.GradientY1[at]));
    }
  }

  // The scan of the class description: run by run, for every wedge, is there a slope s
  // with  lower(a) < s < upper(a, b)  for some earlier run a?
  int Radius(int i, int j, float* scratch) const
  {
    const size_t runs = this->Runs.size();
    float* leastPlusTolerance = scratch;       // least depth of run a + e, rounded down
    float* lower = scratch + Wedges * runs;     // lower bound on s for a dip in run a
    float* steepest = scratch + 2 * Wedges * runs; // most slope over runs a..b
    float* flattest = scratch + 3 * Wedges * runs; // least slope over runs 0..a
    const double top =
      this->Deepest[static_cast<size_t>(j + this->Padding) * this->PaddedWidth + i + this->Padding];
    const float grow = 1.0f + Slack;
    for (size_t b = 0; b < runs; ++b)
    {
      const Run& run = this->Runs[b];
      for (int w = 0; w < Wedges; ++w)
      {
        float least, deepest, most, flat;
        this->Aggregate(run, w, i, j, least, deepest, most, flat);
        const size_t base = w * runs;
        const double inverseReach = this->InverseReach[base + b];
        flattest[base + b] = b > 0 ? std::min(flattest[base + b - 1], flat) : flat;
        const double plus = double(least) + this->Tolerance;
        leastPlusTolerance[base + b] = static_cast<float>(plus * (1.0 - 1e-7)); // not above plus
        // s > (f(a) + e - f(p)) / |pa|  and  s > least slope + e / |pa|
        const double bound = std::max(std::max(0.0, (plus - top) * inverseReach),
          double(flattest[base + b]) + this->Tolerance * inverseReach);
        lower[base + b] = static_cast<float>(bound * (1.0 - 1e-6));
        steepest[base + b] = -1e30f;
        const float* apart = this->Apart.data() + (base + b) * runs;
        const float* overSpan = this->ToleranceOverSpan.data() + (base + b) * runs;
        float* steep = steepest + base;
        const float* dip = leastPlusTolerance + base;
        const float* low = lower + base;
        int any = 0;
        for (size_t a = 0; a <= b; ++a)
        {
          const float slope = std::max(steep[a], most);
          steep[a] = slope;
          // s < most slope - e / |ab|  and, apart, s < (f(b) - f(a) - e) / |ab|
          const float upper = slope + std::abs(slope) * Slack - overSpan[a];
          const float rise = deepest - dip[a];
          any |= (rise > 0.0f) & (low[a] < upper) &
            ((apart[a] <= 0.0f) | (low[a] * apart[a] < rise * grow));
        }
        if (any != 0)
        {
          return std::max(0, std::min(run.First - 1, this->MaximumRadius));
        }
      }
    }
    return this->MaximumRadius;
  }

  const vtkReliefDepthImage& Field;
  const int Width;
  const int Height;
  const int MaximumRadius;
  float Tolerance = 0.0f;
  std::array<WedgeSlopes, Wedges> Slopes;
  std::vector<Run> Runs;
  int Levels = 0;
  int Padding = 0;
  int PaddedWidth = 0;
  std::vector<float> Least, Deepest, MostSlope, LeastSlope; // level 0, padded
  Bounds CellBounds;
  std::vector<Bounds> BlockBounds; // per level, unpadded
  std::vector<double> InverseReach; // per wedge and run: 1 / most distance to the run
  std::vector<float> Apart, ToleranceOverSpan; // per wedge and pair of runs
  int WrapMargin = 0;
  std::vector<int> WrappedColumns; // x + WrapMargin -> wrapped column
  std::vector<size_t> WrappedRows; // y + WrapMargin -> start of the wrapped row
};
}

vtkSafetyRadiusFilter::vtkSafetyRadiusFilter() = default;

void vtkSafetyRadiusFilter::SetErrorTolerance(double tolerance)
{
  if (!(tolerance >= 0.0))
  {
    vtkWarningMacro("ErrorTolerance " << tolerance
                                      << " is not a depth (it must be 0 or more); using 0.");
    tolerance = 0.0;
  }
  else if (tolerance > 1.0)
  {
    vtkWarningMacro("ErrorTolerance " << tolerance
                                      << " is more than the whole relief depth; using 1.");
    tolerance = 1.0;
  }
  if (this->ErrorTolerance != tolerance)
  {
    this->ErrorTolerance = tolerance;
    this->Modified();
  }
}

void vtkSafetyRadiusFilter::Compute(const vtkReliefDepthImage& field, vtkFloatArray* output)
{
  const SafetyRadii computer(field, this->ErrorTolerance, this->MaximumRadius);
  this->UpdateProgress(0.1);
  float* values = output->GetPointer(0);
  this->ForRows(field.Height, ProgressSlices, 0.1, 1.0,
    [&](int begin, int end) { computer.Rows(begin, end, values); });
}

void vtkSafetyRadiusFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ErrorTolerance: " << this->ErrorTolerance << "\n";
  os << indent << "MaximumRadius: " << this->MaximumRadius << "\n";
}
