#include "vtkConeStepMapFilter.h"

#include "vtkFloatArray.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkObjectFactory.h"
#include "vtkReliefDepthImage.h"
#include "vtkSMPTools.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkConeStepMapFilter);

namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();
// Half-width, in cells, of the window whose roughness the curvature bound uses: farther
// away that bound is weaker than the distance bound anyway.
constexpr int RoughnessRadius = 8;
constexpr int ProgressSlices = 20;
// Stored ratios are shrunk by this factor so that float rounding in the search cannot
// carry a step past the edge of a cone.
constexpr double RatioSafety = 1.0 - 1e-5;

double Cross(double ax, double ay, double bx, double by)
{
  return ax * by - ay * bx;
}

// A set of horizontal directions: from A counterclockwise to B (at most half a turn;
// the vectors need not be unit), every direction, or none.
struct Arc
{
  bool Full = false;
  bool Empty = false;
  double AX = 0.0;
  double AY = 0.0;
  double BX = 0.0;
  double BY = 0.0;
};

Arc MakeArc(double ax, double ay, double bx, double by)
{
  Arc arc;
  arc.AX = ax;
  arc.AY = ay;
  arc.BX = bx;
  arc.BY = by;
  return arc;
}

bool InArc(double x, double y, const Arc& arc)
{
  return arc.Full || (Cross(arc.AX, arc.AY, x, y) >= 0.0 && Cross(x, y, arc.BX, arc.BY) >= 0.0);
}

// One end of the arc two arcs share: the first of the two arcs' ends on that side
// (x1, y1 of the first, x2, y2 of the second) that lies in the other arc; false if none.
bool SharedEnd(double x1, double y1, const Arc& first, double x2, double y2, const Arc& second,
  double& x, double& y)
{
  const bool firstsEnd = InArc(x1, y1, second);
  if (!firstsEnd && !InArc(x2, y2, first))
  {
    return false;
  }
  x = firstsEnd ? x1 : x2;
  y = firstsEnd ? y1 : y2;
  return true;
}

// The directions two arcs share; they span less than a full turn together, so they
// share one arc at most.
Arc Intersect(const Arc& a, const Arc& b)
{
  if (a.Full || b.Empty)
  {
    return b;
  }
  if (b.Full || a.Empty)
  {
    return a;
  }
  Arc shared;
  const bool start = SharedEnd(a.AX, a.AY, a, b.AX, b.AY, b, shared.AX, shared.AY);
  const bool end = SharedEnd(a.BX, a.BY, a, b.BX, b.BY, b, shared.BX, shared.BY);
  shared.Empty = !(start && end);
  return shared;
}

// Quadrant (sx, sy) of directions, closed.
Arc Quadrant(int sx, int sy)
{
  if (sx > 0)
  {
    return sy > 0 ? MakeArc(1.0, 0.0, 0.0, 1.0) : MakeArc(0.0, -1.0, 1.0, 0.0);
  }
  return sy > 0 ? MakeArc(0.0, 1.0, -1.0, 0.0) : MakeArc(-1.0, 0.0, 0.0, -1.0);
}

// Half-plane of directions whose component along axis (0: x, 1: y) has sign s, closed.
Arc HalfPlane(int axis, int s)
{
  if (axis == 0)
  {
    return s > 0 ? MakeArc(0.0, -1.0, 0.0, 1.0) : MakeArc(0.0, 1.0, 0.0, -1.0);
  }
  return s > 0 ? MakeArc(1.0, 0.0, -1.0, 0.0) : MakeArc(-1.0, 0.0, 1.0, 0.0);
}

// Every direction from a point of the square [i, i + 1] x [j, j + 1] to a point of the box
// [x0, x1] x [y0, y1]: the directions of the difference box R. All of them when R holds
// the origin inside; otherwise R lies in a wedge of at most half a turn (half a turn
// when the origin lies inside one of its sides), spanned by the two corners that the
// side of R facing the origin picks.
Arc DirectionsToward(int i, int j, double x0, double x1, double y0, double y1)
{
  const double left = x0 - (i + 1);
  const double right = x1 - i;
  const double bottom = y0 - (j + 1);
  const double top = y1 - j;
  const int sideX = left >= 0.0 ? 1 : (right <= 0.0 ? -1 : 0);
  const int sideY = bottom >= 0.0 ? 1 : (top <= 0.0 ? -1 : 0);
  if (sideX > 0)
  {
    return sideY > 0 ? MakeArc(right, bottom, left, top)
                     : (sideY < 0 ? MakeArc(left, bottom, right, top)
                                  : MakeArc(left, bottom, left, top));
  }
  if (sideX < 0)
  {
    return sideY > 0 ? MakeArc(right, top, left, bottom)
                     : (sideY < 0 ? MakeArc(left, top, right, bottom)
                                  : MakeArc(right, top, right, bottom));
  }
  if (sideY != 0)
  {
    return sideY > 0 ? MakeArc(right, bottom, left, bottom) : MakeArc(left, top, right, top);
  }
  Arc all;
  all.Full = true;
  return all;
}

// Does some direction u of the arc give sign * (u . g) >= 0? Over an arc of at most half
// a turn, the dot product is largest at an end unless g points inside, and then one
// end is within a quarter turn of g.
bool Reaches(const Arc& arc, const double g[2], double sign)
{
  return arc.Full || sign * (arc.AX * g[0] + arc.AY * g[1]) >= 0.0 ||
    sign * (arc.BX * g[0] + arc.BY * g[1]) >= 0.0;
}

// Can the field's depth along some ray of the arc stop falling (the field rising
// toward the ray, before the point: gradients `before`) and start rising (after it:
// gradients `after`)? Each set is the corners of a convex set of gradients; the two
// conditions are tested apart, which can only keep more points.
bool Turns(const Arc& arc, const double before[][2], int beforeCount, const double after[][2],
  int afterCount)
{
  if (arc.Empty)
  {
    return false;
  }
  bool falls = false;
  for (int k = 0; k < beforeCount && !falls; ++k)
  {
    falls = Reaches(arc, before[k], -1.0);
  }
  bool rises = false;
  for (int k = 0; k < afterCount && !rises; ++k)
  {
    rises = Reaches(arc, after[k], 1.0);
  }
  return falls && rises;
}

// Gradients of the depth, in double so that differences of float texels are exact.
struct GradientBox
{
  double XMin;
  double XMax;
  double YMin;
  double YMax;
};

// Turns with every gradient of the box before and after the point: the dot product
// with a direction is least and largest at corners the direction's signs pick.
bool TurnsWithin(const Arc& arc, const GradientBox& box)
{
  if (arc.Full)
  {
    return true;
  }
  auto least = [&box](double ux, double uy) {
    return ux * (ux >= 0.0 ? box.XMin : box.XMax) + uy * (uy >= 0.0 ? box.YMin : box.YMax);
  };
  auto most = [&box](double ux, double uy) {
    return ux * (ux >= 0.0 ? box.XMax : box.XMin) + uy * (uy >= 0.0 ? box.YMax : box.YMin);
  };
  return (least(arc.AX, arc.AY) <= 0.0 || least(arc.BX, arc.BY) <= 0.0) &&
    (most(arc.AX, arc.AY) >= 0.0 || most(arc.BX, arc.BY) >= 0.0);
}

// A pyramid node in one of the repeated tiles, with the lower bound of its ratio.
struct Node
{
  int Level;
  int X;
  int Y;
  int TileX;
  int TileY;
  double Bound;
};

// The cell whose ratio is sought, and the best ratio found so far.
struct Apex
{
  int I;
  int J;
  double Top;
  double Rough;     // variation of the slope along a ray, per texel travelled
  double RoughKink; // ... and at most once more per axis
  double Ratio;
  int LimitX; // the cell owning the feature that set the ratio, relative to the apex
  int LimitY;
};

class ConeGenerator
{
public:
  ConeGenerator(const vtkReliefDepthImage& field, double maximumRatio);

  float Top(int i, int j) const { return this->MinDepth[0][this->Index(i, j)]; }
  double Ratio(int i, int j, int& limitX, int& limitY, std::vector<Node>& heap) const;

private:
  size_t Index(int i, int j) const { return static_cast<size_t>(j) * this->Width + i; }
  void BuildRoughness();
  bool Windowed(const Apex& apex, int x0, int x1, int y0, int y1) const;
  double CurvatureBound(const Apex& apex, double x0, double x1, double y0, double y1) const;
  double NodeBound(const Apex& apex, const Node& node) const;
  void VisitCell(Apex& apex, int x0, int y0) const;
  double FeatureBound(const Apex& apex, double x0, double x1, double y0, double y1,
    double least, bool windowed, double& nearest) const;

  const vtkReliefDepthImage& Field;
  int Width;
  int Height;
  double MaximumRatio;
  float Least = 1.0f;
  std::vector<int> LevelWidths;
  std::vector<int> LevelHeights;
  std::vector<std::vector<float>> MinDepth;
  std::vector<std::vector<GradientBox>> Gradients;
  std::vector<double> Rough;
  std::vector<double> RoughKink;
};

ConeGenerator::ConeGenerator(const vtkReliefDepthImage& field, double maximumRatio)
  : Field(field)
  , Width(field.Width)
  , Height(field.Height)
  , MaximumRatio(maximumRatio)
{
  const int top = [&]() {
    int level = 0;
    while ((this->Width >> (level + 1)) > 0 || (this->Height >> (level + 1)) > 0)
    {
      ++level;
    }
    return level;
  }();
  const size_t cells = static_cast<size_t>(this->Width) * this->Height;
  std::vector<float> tops(cells);
  std::vector<GradientBox> patches(cells);
  vtkSMPTools::For(0, this->Height, [&](vtkIdType begin, vtkIdType end) {
    for (int j = static_cast<int>(begin); j < end; ++j)
    {
      for (int i = 0; i < this->Width; ++i)
      {
        const double d00 = field.At(i, j);
        const double d10 = field.At(i + 1, j);
        const double d01 = field.At(i, j + 1);
        const double d11 = field.At(i + 1, j + 1);
        tops[this->Index(i, j)] =
          static_cast<float>(std::min(std::min(d00, d10), std::min(d01, d11)));
        // the patch's gradient (b + e y, c + e x) spans the box of its edge differences
        patches[this->Index(i, j)] = GradientBox{ std::min(d10 - d00, d11 - d01),
          std::max(d10 - d00, d11 - d01), std::min(d01 - d00, d11 - d10),
          std::max(d01 - d00, d11 - d10) };
      }
    }
  });
  // a cell's features (its lower-left vertex, left and bottom edges, interior) see the
  // gradients of its patch and of the three patches to its left and below
  std::vector<GradientBox> features(cells);
  vtkSMPTools::For(0, this->Height, [&](vtkIdType begin, vtkIdType end) {
    for (int j = static_cast<int>(begin); j < end; ++j)
    {
      for (int i = 0; i < this->Width; ++i)
      {
        GradientBox box = patches[this->Index(i, j)];
        for (int k = 1; k < 4; ++k)
        {
          const int x = ((i - (k & 1)) % this->Width + this->Width) % this->Width;
          const int y = ((j - (k >> 1)) % this->Height + this->Height) % this->Height;
          const GradientBox& other = patches[this->Index(x, y)];
          box.XMin = std::min(box.XMin, other.XMin);
          box.XMax = std::max(box.XMax, other.XMax);
          box.YMin = std::min(box.YMin, other.YMin);
          box.YMax = std::max(box.YMax, other.YMax);
        }
        features[this->Index(i, j)] = box;
      }
    }
  });
  this->Least = *std::min_element(tops.begin(), tops.end());
  this->LevelWidths.push_back(this->Width);
  this->LevelHeights.push_back(this->Height);
  this->MinDepth.push_back(std::move(tops));
  this->Gradients.push_back(std::move(features));
  for (int level = 1; level <= top; ++level)
  {
    const int width = vtkMaximumMipmapFilter::GetLevelSize(this->Width, level);
    const int height = vtkMaximumMipmapFilter::GetLevelSize(this->Height, level);
    std::vector<float> least(static_cast<size_t>(width) * height, 1.0f);
    std::vector<GradientBox> boxes(static_cast<size_t>(width) * height);
    const std::vector<float>& childLeast = this->MinDepth[level - 1];
    const std::vector<GradientBox>& childBoxes = this->Gradients[level - 1];
    const int childWidth = this->LevelWidths[level - 1];
    for (int y = 0; y < height; ++y)
    {
      int firstRow, lastRow;
      vtkMaximumMipmapFilter::GetChildRange(y, this->Height, level, firstRow, lastRow);
      for (int x = 0; x < width; ++x)
      {
        int firstColumn, lastColumn;
        vtkMaximumMipmapFilter::GetChildRange(x, this->Width, level, firstColumn, lastColumn);
        GradientBox box = childBoxes[static_cast<size_t>(firstRow) * childWidth + firstColumn];
        float value = 1.0f;
        for (int cy = firstRow; cy <= lastRow; ++cy)
        {
          for (int cx = firstColumn; cx <= lastColumn; ++cx)
          {
            const size_t child = static_cast<size_t>(cy) * childWidth + cx;
            value = std::min(value, childLeast[child]);
            box.XMin = std::min(box.XMin, childBoxes[child].XMin);
            box.XMax = std::max(box.XMax, childBoxes[child].XMax);
            box.YMin = std::min(box.YMin, childBoxes[child].YMin);
            box.YMax = std::max(box.YMax, childBoxes[child].YMax);
          }
        }
        least[static_cast<size_t>(y) * width + x] = value;
        boxes[static_cast<size_t>(y) * width + x] = box;
      }
    }
    this->LevelWidths.push_back(width);
    this->LevelHeights.push_back(height);
    this->MinDepth.push_back(std::move(least));
    this->Gradients.push_back(std::move(boxes));
  }
  this->BuildRoughness();
}

// Per cell, over the window of cells within RoughnessRadius (and the texels on their
// sides): the largest twist |e| of a patch, where the slope along a ray changes by at
// most |e| per texel, and the largest second differences across the centrelines, by
// which the slope jumps where the ray crosses one.
void ConeGenerator::BuildRoughness()
{
  const int width = this->Width;
  const int height = this->Height;
  const size_t cells = static_cast<size_t>(width) * height;
  std::vector<double> twist(cells);
  std::vector<double> kinkX(cells);
  std::vector<double> kinkY(cells);
  const vtkReliefDepthImage& field = this->Field;
  auto at = [&field](int i, int j) { return static_cast<double>(field.At(i, j)); };
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const double d = at(i, j);
      twist[this->Index(i, j)] = std::abs(d - at(i + 1, j) - at(i, j + 1) + at(i + 1, j + 1));
      kinkX[this->Index(i, j)] = std::abs(at(i + 1, j) - 2.0 * d + at(i - 1, j));
      kinkY[this->Index(i, j)] = std::abs(at(i, j + 1) - 2.0 * d + at(i, j - 1));
    }
  }
  // sliding maxima over [-R, R + 1] in each axis, repeating: a superset of the window
  const int reach = RoughnessRadius;
  auto windowMax = [&](std::vector<double>& values) {
    std::vector<double> rows(cells);
    for (int j = 0; j < height; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        double most = 0.0;
        for (int k = -reach; k <= reach + 1 && k - (-reach) < width; ++k)
        {
          most = std::max(most, values[this->Index(((i + k) % width + width) % width, j)]);
        }
        rows[this->Index(i, j)] = most;
      }
    }
    for (int j = 0; j < height; ++j)
    {
      for (int i = 0; i < width; ++i)
      {
        double most = 0.0;
        for (int k = -reach; k <= reach + 1 && k - (-reach) < height; ++k)
        {
          most = std::max(most, rows[this->Index(i, ((j + k) % height + height) % height)]);
        }
        values[this->Index(i, j)] = most;
      }
    }
  };
  windowMax(twist);
  windowMax(kinkX);
  windowMax(kinkY);
  this->Rough.resize(cells);
  this->RoughKink.resize(cells);
  for (size_t k = 0; k < cells; ++k)
  {
    this->Rough[k] = twist[k] + kinkX[k] + kinkY[k];
    this->RoughKink[k] = kinkX[k] + kinkY[k];
  }
}

// Are the cells [x0, x1) x [y0, y1) inside the roughness window of the apex?
bool ConeGenerator::Windowed(const Apex& apex, int x0, int x1, int y0, int y1) const
{
  return x0 >= apex.I - RoughnessRadius && x1 - 1 <= apex.I + RoughnessRadius &&
    y0 >= apex.J - RoughnessRadius && y1 - 1 <= apex.J + RoughnessRadius;
}

// Along a ray from p to a ridge point m at distance s, the slope of the field's depth
// is >= 0 just after m and changes by at most Rough per texel plus RoughKink, so
// T - D(m) <= s^2 Rough / 2 + s RoughKink: the ratio s / (T - D(m)) is at least the
// value below, s being at most the farthest distance from the cell to the box.
double ConeGenerator::CurvatureBound(
  const Apex& apex, double x0, double x1, double y0, double y1) const
{
  const double dx = std::max(x1 - apex.I, apex.I + 1.0 - x0);
  const double dy = std::max(y1 - apex.J, apex.J + 1.0 - y0);
  const double variation = 0.5 * std::sqrt(dx * dx + dy * dy) * apex.Rough + apex.RoughKink;
  return variation > 0.0 ? 1.0 / variation : Infinity;
}

// The lower bound of the ratio over the features of a node, from its distance and least
// depth and, near the apex, the curvature; infinity when the node holds nothing higher
// than the top, when the bound cannot improve the ratio found, or when no direction
// from the apex sees the field's slope turn inside it.
double ConeGenerator::NodeBound(const Apex& apex, const Node& node) const
{
  const int span = 1 << node.Level;
  const int x0 = node.TileX * this->Width + node.X * span;
  const int y0 = node.TileY * this->Height + node.Y * span;
  const int x1 = node.X == this->LevelWidths[node.Level] - 1 ? (node.TileX + 1) * this->Width
                                                             : x0 + span;
  const int y1 = node.Y == this->LevelHeights[node.Level] - 1 ? (node.TileY + 1) * this->Height
                                                              : y0 + span;
  const size_t index = static_cast<size_t>(node.Y) * this->LevelWidths[node.Level] + node.X;
  const double least = this->MinDepth[node.Level][index];
  if (least >= apex.Top)
  {
    return Infinity;
  }
  const double dx = x0 > apex.I + 1 ? x0 - (apex.I + 1.0) : (x1 < apex.I ? apex.I - x1 : 0.0);
  const double dy = y0 > apex.J + 1 ? y0 - (apex.J + 1.0) : (y1 < apex.J ? apex.J - y1 : 0.0);
  const double reach = apex.Ratio * (apex.Top - least);
  if (dx * dx + dy * dy >= reach * reach)
  {
    return Infinity;
  }
  double bound = std::sqrt(dx * dx + dy * dy) / (apex.Top - least);
  if (this->Windowed(apex, x0, x1, y0, y1))
  {
    bound = std::max(bound, this->CurvatureBound(apex, x0, x1, y0, y1));
  }
  if (bound >= apex.Ratio)
  {
    return Infinity;
  }
  return TurnsWithin(DirectionsToward(apex.I, apex.J, x0, x1, y0, y1),
           this->Gradients[node.Level][index])
    ? bound
    : Infinity;
}

// The lower bound of |m - p| / (T - D(m)) for the points m of a feature in the closed box
// whose least depth is `least`, from the distance and, near the apex, the curvature;
// infinity for a feature no higher than the top. `nearest` returns the distance.
double ConeGenerator::FeatureBound(const Apex& apex, double x0, double x1, double y0,
  double y1, double least, bool windowed, double& nearest) const
{
  if (least >= apex.Top)
  {
    return Infinity;
  }
  const double dx = std::max({ 0.0, x0 - (apex.I + 1.0), apex.I - x1 });
  const double dy = std::max({ 0.0, y0 - (apex.J + 1.0), apex.J - y1 });
  nearest = std::sqrt(dx * dx + dy * dy);
  const double bound = nearest / (apex.Top - least);
  return windowed ? std::max(bound, this->CurvatureBound(apex, x0, x1, y0, y1)) : bound;
}

// The ridge features cell (x0, y0) owns (unwrapped indices): its lower-left vertex, the
// centreline segments from it to the right and up, and its patch's interior.
void ConeGenerator::VisitCell(Apex& apex, int x0, int y0) const
{
  // d[a][b]: depth of texel (x0 - 1 + a, y0 - 1 + b)
  double d[3][3];
  for (int a = 0; a < 3; ++a)
  {
    for (int b = 0; b < 3; ++b)
    {
      d[a][b] = this->Field.At(x0 - 1 + a, y0 - 1 + b);
    }
  }
  const double top = apex.Top;
  const int di = x0 - apex.I;
  const int dj = y0 - apex.J;
  const bool windowed = std::abs(di) <= RoughnessRadius && std::abs(dj) <= RoughnessRadius;
  auto keep = [&](double bound) {
    if (bound < apex.Ratio)
    {
      apex.Ratio = bound;
      apex.LimitX = di;
      apex.LimitY = dj;
    }
  };
  double nearest = 0.0;

  // the vertex: a ray through it comes from the patch of the opposite quadrant and
  // goes on into the patch of its own, whose gradients at the vertex are its edges'
  double bound = this->FeatureBound(apex, x0, x0, y0, y0, d[1][1], windowed, nearest);
  if (bound < apex.Ratio)
  {
    const Arc toward = DirectionsToward(apex.I, apex.J, x0, x0, y0, y0);
    for (int q = 0; q < 4; ++q)
    {
      const int sx = q & 1 ? -1 : 1;
      const int sy = q & 2 ? -1 : 1;
      const double before[1][2] = { { sx * (d[1][1] - d[1 - sx][1]),
        sy * (d[1][1] - d[1][1 - sy]) } };
      const double after[1][2] = { { sx * (d[1 + sx][1] - d[1][1]),
        sy * (d[1][1 + sy] - d[1][1]) } };
      if (Turns(Intersect(toward, Quadrant(sx, sy)), before, 1, after, 1))
      {
        keep(bound);
        break;
      }
    }
  }

  // the centreline segments: a ray crosses from one patch to the other; the slope along
  // the segment is shared, the slope across it is each patch's at its side, linear
  // along the segment
  for (int axis = 0; axis < 2; ++axis)
  {
    // axis 0: x = x0 from y0 to y0 + 1, between the patches to its left and right;
    // axis 1: y = y0 from x0 to x0 + 1, between the patches below and above
    const double ends[2] = { d[1][1], axis == 0 ? d[1][2] : d[2][1] };
    bound = this->FeatureBound(apex, x0, x0 + axis, y0, y0 + 1 - axis,
      std::min(ends[0], ends[1]), windowed, nearest);
    if (nearest == 0.0 && bound < apex.Ratio)
    {
      // a segment from a corner of the cell: the depth is linear along it, at least T at
      // that corner, so T - D(m) <= (T - D(far end)) |m - corner|
      const bool firstInside = x0 >= apex.I && x0 <= apex.I + 1 && y0 >= apex.J &&
        y0 <= apex.J + 1;
      bound = std::max(bound, 1.0 / (top - (firstInside ? ends[1] : ends[0])));
    }
    if (bound >= apex.Ratio)
    {
      continue;
    }
    const double along = ends[1] - ends[0];
    double low[2][2];  // gradients on the lower-coordinate side, at both ends
    double high[2][2]; // ... and on the higher side
    for (int end = 0; end < 2; ++end)
    {
      // texels across the segment at this end: (x0 - 1, x0, x0 + 1) or (y0 - 1, y0, y0 + 1)
      const double minus = axis == 0 ? d[0][1 + end] : d[1 + end][0];
      const double middle = axis == 0 ? d[1][1 + end] : d[1 + end][1];
      const double plus = axis == 0 ? d[2][1 + end] : d[1 + end][2];
      low[end][axis] = middle - minus;
      low[end][1 - axis] = along;
      high[end][axis] = plus - middle;
      high[end][1 - axis] = along;
    }
    const Arc toward = DirectionsToward(apex.I, apex.J, x0, x0 + axis, y0, y0 + 1 - axis);
    if (Turns(Intersect(toward, HalfPlane(axis, 1)), low, 2, high, 2) ||
      Turns(Intersect(toward, HalfPlane(axis, -1)), high, 2, low, 2))
    {
      keep(bound);
    }
  }

  // the interior of a twisted patch: the slope along a ray is zero there and the patch
  // curves up along it, e ux uy > 0; planar patches have no such point
  const double d00 = d[1][1];
  const double d10 = d[2][1];
  const double d01 = d[1][2];
  const double d11 = d[2][2];
  const double twist = d00 - d10 - d01 + d11;
  if (twist == 0.0)
  {
    return;
  }
  bound = this->FeatureBound(apex, x0, x0 + 1, y0, y0 + 1,
    std::min(std::min(d00, d10), std::min(d01, d11)), windowed, nearest);
  if (nearest == 0.0 && bound < apex.Ratio)
  {
    if (std::abs(di) + std::abs(dj) == 1)
    {
      // next to the cell across an edge: along the perpendicular from that edge (depth
      // >= T) the patch is linear, so T - D(m) <= (T - D(far edge)) |m - edge|
      const double far = di != 0 ? (di > 0 ? std::min(d10, d11) : std::min(d00, d01))
                                 : (dj > 0 ? std::min(d01, d11) : std::min(d00, d10));
      bound = std::max(bound, 1.0 / (top - far));
    }
    else
    {
      // across a corner v (depth >= T): with m = v + r (a, b), max(a, b) = 1, r <= 1,
      // D(v) - D(m) <= r * slope, slope bounding both the slope at v and the drop to the
      // far sides; r / (T - D(v) + r slope) is least at r = 1
      const int vx = di > 0 ? 1 : 2;
      const int ax = di > 0 ? 2 : 1;
      const int vy = dj > 0 ? 1 : 2;
      const int ay = dj > 0 ? 2 : 1;
      const double dv = d[vx][vy];
      const double da = d[ax][vy];
      const double db = d[vx][ay];
      const double dc = d[ax][ay];
      const double slope = std::max(
        { dv - da, dv - db, 2.0 * dv - da - db, dv - std::min({ da, db, dc }) });
      const double rise = top - dv + slope;
      bound = std::max(bound, rise > 0.0 ? 1.0 / rise : Infinity);
    }
  }
  if (bound >= apex.Ratio)
  {
    return;
  }
  const double gradients[4][2] = { { d10 - d00, d01 - d00 }, { d10 - d00, d11 - d10 },
    { d11 - d01, d01 - d00 }, { d11 - d01, d11 - d10 } };
  const Arc toward = DirectionsToward(apex.I, apex.J, x0, x0 + 1, y0, y0 + 1);
  const int sy = twist > 0.0 ? 1 : -1;
  if (Turns(Intersect(toward, Quadrant(1, sy)), gradients, 4, gradients, 4) ||
    Turns(Intersect(toward, Quadrant(-1, -sy)), gradients, 4, gradients, 4))
  {
    keep(bound);
  }
}

// limitX, limitY: on entry, where the neighbour's cone was limited, tried first (a
// feature near it likely limits this cone too, and then prunes most nodes); on return,
// where this one is.
double ConeGenerator::Ratio(int i, int j, int& limitX, int& limitY, std::vector<Node>& heap) const
{
  Apex apex;
  apex.I = i;
  apex.J = j;
  apex.Top = this->Top(i, j);
  apex.Rough = this->Rough[this->Index(i, j)];
  apex.RoughKink = this->RoughKink[this->Index(i, j)];
  apex.Ratio = this->MaximumRatio;
  apex.LimitX = limitX;
  apex.LimitY = limitY;
  if (apex.Top <= this->Least)
  {
    return apex.Ratio;
  }
  this->VisitCell(apex, i + limitX, j + limitY);
  // best first: the node of least bound is opened next, so no node whose bound reaches
  // the final ratio is ever opened
  auto later = [](const Node& a, const Node& b) { return a.Bound > b.Bound; };
  auto push = [&](Node node) {
    node.Bound = this->NodeBound(apex, node);
    if (node.Bound < apex.Ratio)
    {
      heap.push_back(node);
      std::push_heap(heap.begin(), heap.end(), later);
    }
  };
  heap.clear();
  const int topLevel = static_cast<int>(this->MinDepth.size()) - 1;
  // the repeated tiles, ring by ring around the map, each once it can hold a bound
  // below every open node's
  const double ringStep = std::min(this->Width, this->Height) / (apex.Top - this->Least);
  int ring = 0;
  for (;;)
  {
    for (double ringBound = std::max(0.0, ring - 1.0) * ringStep;
         ringBound < apex.Ratio && (heap.empty() || ringBound <= heap.front().Bound);
         ringBound = std::max(0.0, ring - 1.0) * ringStep)
    {
      for (int ty = -ring; ty <= ring; ++ty)
      {
        for (int tx = -ring; tx <= ring; ++tx)
        {
          if (std::max(std::abs(tx), std::abs(ty)) == ring)
          {
            push(Node{ topLevel, 0, 0, tx, ty, 0.0 });
          }
        }
      }
      ++ring;
    }
    if (heap.empty() || heap.front().Bound >= apex.Ratio)
    {
      break;
    }
    std::pop_heap(heap.begin(), heap.end(), later);
    const Node node = heap.back();
    heap.pop_back();
    if (node.Level == 0)
    {
      this->VisitCell(apex, node.TileX * this->Width + node.X, node.TileY * this->Height + node.Y);
      continue;
    }
    int firstX, lastX, firstY, lastY;
    vtkMaximumMipmapFilter::GetChildRange(node.X, this->Width, node.Level, firstX, lastX);
    vtkMaximumMipmapFilter::GetChildRange(node.Y, this->Height, node.Level, firstY, lastY);
    for (int cy = firstY; cy <= lastY; ++cy)
    {
      for (int cx = firstX; cx <= lastX; ++cx)
      {
        push(Node{ node.Level - 1, cx, cy, node.TileX, node.TileY, 0.0 });
      }
    }
  }
  limitX = apex.LimitX;
  limitY = apex.LimitY;
  return apex.Ratio;
}
}

vtkConeStepMapFilter::vtkConeStepMapFilter() = default;

double vtkConeStepMapFilter::GetMaximumRatio(int width, int height)
{
  return 4.0 * std::max(width, height);
}

void vtkConeStepMapFilter::EncodeCone(
  double top, double ratio, double maximumRatio, unsigned char code[2])
{
  // 1e-6 below the top: a GPU's unorm conversion may round code / 255 up by an ulp
  code[0] = static_cast<unsigned char>(std::clamp(std::floor((top - 1e-6) * 255.0), 0.0, 255.0));
  const double bound = RatioSafety * ratio;
  auto decoded = [&](int level) {
    return maximumRatio * std::exp2(RATIO_OCTAVES * (level - 255.0) / 254.0);
  };
  int level = 0;
  if (bound > 0.0 && maximumRatio > 0.0)
  {
    const double exact = 255.0 + 254.0 * std::log2(bound / maximumRatio) / RATIO_OCTAVES;
    level = static_cast<int>(std::clamp(std::floor(exact), 0.0, 255.0));
    while (level > 0 && decoded(level) > bound)
    {
      --level;
    }
  }
  code[1] = static_cast<unsigned char>(level);
}

void vtkConeStepMapFilter::Compute(const vtkReliefDepthImage& field, vtkFloatArray* output)
{
  const int width = field.Width;
  const ConeGenerator generator(field, GetMaximumRatio(width, field.Height));
  this->UpdateProgress(0.05);
  float* values = output->GetPointer(0);
  this->ForRows(field.Height, ProgressSlices, 0.05, 1.0, [&](int begin, int end) {
    std::vector<Node> heap;
    for (int j = begin; j < end; ++j)
    {
      int limitX = 0;
      int limitY = 0;
      for (int i = 0; i < width; ++i)
      {
        float* cone = values + 2 * (static_cast<size_t>(j) * width + i);
        cone[0] = generator.Top(i, j);
        // rounded down, so the float never exceeds the proven ratio
        const double ratio = RatioSafety * generator.Ratio(i, j, limitX, limitY, heap);
        const float stored = static_cast<float>(ratio);
        cone[1] = stored > ratio ? std::nextafter(stored, 0.0f) : stored;
      }
    }
  });
}

void vtkConeStepMapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
