#include "vtkReliefImpostorFilter.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLookupTable.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

vtkStandardNewMacro(vtkReliefImpostorFilter);

namespace
{
// Rows a rasterizing task takes: triangles are binned by these bands.
constexpr int BandRows = 8;
// The depth a hit is kept below: exactly 1 means an empty column.
constexpr float DeepestHit = 1.0f - 1.0f / 1048576.0f;
// How far behind a view's field a surface point still counts as seen by it.
constexpr double SeenTolerance = 1e-3;

// The mesh as triangles, with what colours it and its normals.
struct Mesh
{
  std::vector<glm::dvec3> Points;
  std::vector<std::array<vtkIdType, 3>> Triangles;
  vtkSmartPointer<vtkUnsignedCharArray> Colours; // RGBA per point, or null
  vtkDataArray* Normals = nullptr;               // per point, or null
  vtkDataArray* TCoords = nullptr;               // per point, with Texture
  vtkImageData* Texture = nullptr;
};

// A view's depth test: per texel the nearest depth, its triangle (-1: none) and the
// triangle's perspective-correct barycentric weights of its second and third corners.
struct Raster
{
  int Size = 0;
  std::vector<double> Depth;
  std::vector<vtkIdType> Triangle;
  std::vector<glm::dvec2> Weights;
};

// One triangle in a view's texel space: x, y in texels (centres at integers), depth, 1/w.
struct Projected
{
  std::array<glm::dvec3, 3> Corner;
  std::array<double, 3> InverseW;
  bool Seen = false; // not edge on, not degenerate
};

glm::dvec4 Project(const glm::dmat4& projection, const glm::dvec3& point)
{
  return projection * glm::dvec4(point, 1.0);
}

std::vector<Projected> ProjectMesh(const Mesh& mesh, const glm::dmat4& projection, int size)
{
  std::vector<Projected> projected(mesh.Triangles.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(mesh.Triangles.size()),
    [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType t = begin; t < end; ++t)
      {
        Projected& triangle = projected[t];
        for (int c = 0; c < 3; ++c)
        {
          const glm::dvec4 h = Project(projection, mesh.Points[mesh.Triangles[t][c]]);
          triangle.InverseW[c] = 1.0 / h.w;
          triangle.Corner[c] = glm::dvec3(
            h.x / h.w * size - 0.5, h.y / h.w * size - 0.5, h.z / h.w);
        }
        const glm::dvec3 a = triangle.Corner[1] - triangle.Corner[0];
        const glm::dvec3 b = triangle.Corner[2] - triangle.Corner[0];
        const double area = a.x * b.y - a.y * b.x;
        triangle.Seen = std::isfinite(area) && std::abs(area) > 1e-12;
      }
    });
  return projected;
}

// The rows [first, last] whose centres lie within `margin` of a triangle's rows, clamped
// to the raster (last < first: none).
void RowsOf(const Projected& triangle, int size, double margin, int& first, int& last)
{
  double low = triangle.Corner[0].y;
  double high = low;
  for (int c = 1; c < 3; ++c)
  {
    low = std::min(low, triangle.Corner[c].y);
    high = std::max(high, triangle.Corner[c].y);
  }
  // clamped before the cast: no int overflow from far or non-finite corners
  first = static_cast<int>(std::max(0.0, std::ceil(low - margin - 1e-9)));
  last = static_cast<int>(std::min(size - 1.0, std::floor(high + margin + 1e-9)));
}

// Rasterizes triangle t into rows [rowBegin, rowEnd), keeping the nearest.
void RasterizeTriangle(const Projected& triangle, vtkIdType t, int rowBegin, int rowEnd,
  Raster& raster)
{
  const glm::dvec3& p0 = triangle.Corner[0];
  const glm::dvec3& p1 = triangle.Corner[1];
  const glm::dvec3& p2 = triangle.Corner[2];
  const double area = (p1.x - p0.x) * (p2.y - p0.y) - (p2.x - p0.x) * (p1.y - p0.y);
  int first = 0;
  int last = -1;
  RowsOf(triangle, raster.Size, 0.0, first, last);
  first = std::max(first, rowBegin);
  last = std::min(last, rowEnd - 1);
  const double left = std::min({ p0.x, p1.x, p2.x });
  const double right = std::max({ p0.x, p1.x, p2.x });
  const int columnFirst = static_cast<int>(std::max(0.0, std::ceil(left - 1e-9)));
  const int columnLast = static_cast<int>(std::min(raster.Size - 1.0, std::floor(right + 1e-9)));
  // centres on an edge belong to both triangles (the depth test keeps one): no cracks
  const double inside = -1e-9;
  for (int j = first; j <= last; ++j)
  {
    for (int i = columnFirst; i <= columnLast; ++i)
    {
      const double x = i - p0.x;
      const double y = j - p0.y;
      const double l1 = (x * (p2.y - p0.y) - (p2.x - p0.x) * y) / area;
      const double l2 = ((p1.x - p0.x) * y - x * (p1.y - p0.y)) / area;
      const double l0 = 1.0 - l1 - l2;
      if (l0 < inside || l1 < inside || l2 < inside)
      {
        continue;
      }
      // a plane stays a plane under the projective map: depth is affine on the texels
      const double depth = l0 * p0.z + l1 * p1.z + l2 * p2.z;
      const size_t texel = static_cast<size_t>(j) * raster.Size + i;
      if (depth < raster.Depth[texel])
      {
        raster.Depth[texel] = depth;
        raster.Triangle[texel] = t;
        const double w0 = l0 * triangle.InverseW[0];
        const double w1 = l1 * triangle.InverseW[1];
        const double w2 = l2 * triangle.InverseW[2];
        const double sum = w0 + w1 + w2;
        raster.Weights[texel] = glm::dvec2(w1 / sum, w2 / sum);
      }
    }
  }
}

// The least depth of segment a-b (texel space, depth in z) within the texel square
// centred on `centre`, or +infinity where it does not pass through it (Liang and Barsky's
// clipping; depth is affine along a projected line).
double SegmentDepthInTexel(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec2& centre)
{
  double enter = 0.0;
  double leave = 1.0;
  const double run[2] = { b.x - a.x, b.y - a.y };
  const double start[2] = { a.x - centre.x, a.y - centre.y };
  for (int axis = 0; axis < 2; ++axis)
  {
    if (run[axis] == 0.0)
    {
      if (std::abs(start[axis]) > 0.5)
      {
        return std::numeric_limits<double>::infinity();
      }
      continue;
    }
    const double first = (-0.5 - start[axis]) / run[axis];
    const double second = (0.5 - start[axis]) / run[axis];
    enter = std::max(enter, std::min(first, second));
    leave = std::min(leave, std::max(first, second));
  }
  if (!(enter <= leave))
  {
    return std::numeric_limits<double>::infinity();
  }
  return std::min(a.z + enter * (b.z - a.z), a.z + leave * (b.z - a.z));
}

// Gives texels that no triangle covers at their centre, but that triangle t reaches into,
// the least depth of the triangle within the texel's square: seen edge on, a sheet falls
// between texel centres and would leave its view empty, and the impostor, which keeps
// only what every view holds, would lose it. The least depth lies where the triangle's
// edges cross the square, or at a corner of the square the triangle covers.
void TouchTriangle(const Projected& triangle, vtkIdType t, int rowBegin, int rowEnd,
  const std::vector<vtkIdType>& covered, Raster& raster)
{
  int first = 0;
  int last = -1;
  RowsOf(triangle, raster.Size, 0.5, first, last);
  first = std::max(first, rowBegin);
  last = std::min(last, rowEnd - 1);
  const std::array<glm::dvec3, 3>& p = triangle.Corner;
  const double left = std::min({ p[0].x, p[1].x, p[2].x });
  const double right = std::max({ p[0].x, p[1].x, p[2].x });
  const int columnFirst = static_cast<int>(std::max(0.0, std::ceil(left - 0.5 - 1e-9)));
  const int columnLast =
    static_cast<int>(std::min(raster.Size - 1.0, std::floor(right + 0.5 + 1e-9)));
  const double area = (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
  for (int j = first; j <= last; ++j)
  {
    for (int i = columnFirst; i <= columnLast; ++i)
    {
      const size_t texel = static_cast<size_t>(j) * raster.Size + i;
      if (covered[texel] >= 0)
      {
        continue;
      }
      const glm::dvec2 centre(i, j);
      double depth = std::numeric_limits<double>::infinity();
      for (int c = 0; c < 3; ++c)
      {
        depth = std::min(depth, SegmentDepthInTexel(p[c], p[(c + 1) % 3], centre));
      }
      for (int corner = 0; triangle.Seen && corner < 4; ++corner)
      {
        const double x = i + (corner & 1 ? 0.5 : -0.5) - p[0].x;
        const double y = j + (corner & 2 ? 0.5 : -0.5) - p[0].y;
        const double l1 = (x * (p[2].y - p[0].y) - (p[2].x - p[0].x) * y) / area;
        const double l2 = ((p[1].x - p[0].x) * y - x * (p[1].y - p[0].y)) / area;
        if (l1 >= 0.0 && l2 >= 0.0 && l1 + l2 <= 1.0)
        {
          depth = std::min(depth, (1.0 - l1 - l2) * p[0].z + l1 * p[1].z + l2 * p[2].z);
        }
      }
      if (depth < raster.Depth[texel])
      {
        raster.Depth[texel] = depth;
        raster.Triangle[texel] = t;
        raster.Weights[texel] = glm::dvec2(1.0 / 3.0);
      }
    }
  }
}

// The view's nearest surface at each texel centre of a size x size raster; with `touch`,
// also in the texels triangles only reach into (TouchTriangle).
Raster Rasterize(const Mesh& mesh, const glm::dmat4& projection, int size, bool touch)
{
  Raster raster;
  raster.Size = size;
  const size_t texels = static_cast<size_t>(size) * size;
  raster.Depth.assign(texels, 2.0);
  raster.Triangle.assign(texels, -1);
  raster.Weights.assign(texels, glm::dvec2(0.0));
  const std::vector<Projected> projected = ProjectMesh(mesh, projection, size);
  const int bands = (size + BandRows - 1) / BandRows;
  std::vector<std::vector<vtkIdType>> binned(bands);
  for (vtkIdType t = 0; t < static_cast<vtkIdType>(projected.size()); ++t)
  {
    int first = 0;
    int last = -1;
    // edge-on triangles touch texels without covering any centre
    if (projected[t].Seen || touch)
    {
      RowsOf(projected[t], size, touch ? 0.5 : 0.0, first, last);
    }
    for (int band = first / BandRows; first <= last && band <= last / BandRows; ++band)
    {
      binned[band].push_back(t);
    }
  }
  vtkSMPTools::For(0, bands, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType band = begin; band < end; ++band)
    {
      const int rowBegin = static_cast<int>(band) * BandRows;
      const int rowEnd = std::min(size, rowBegin + BandRows);
      for (vtkIdType t : binned[band])
      {
        if (projected[t].Seen)
        {
          RasterizeTriangle(projected[t], t, rowBegin, rowEnd, raster);
        }
      }
    }
  });
  if (touch)
  {
    // after every centre is settled, so that only texels no centre hit are filled
    const std::vector<vtkIdType> covered = raster.Triangle;
    vtkSMPTools::For(0, bands, [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType band = begin; band < end; ++band)
      {
        const int rowBegin = static_cast<int>(band) * BandRows;
        const int rowEnd = std::min(size, rowBegin + BandRows);
        for (vtkIdType t : binned[band])
        {
          TouchTriangle(projected[t], t, rowBegin, rowEnd, covered, raster);
        }
      }
    });
  }
  return raster;
}

// The bilinear colour of an unsigned char image at (s, t), repeating.
glm::dvec4 SampleTexture(vtkImageData* image, double s, double t)
{
  int dimensions[3];
  image->GetDimensions(dimensions);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  const int components = scalars->GetNumberOfComponents();
  const double x = (s - std::floor(s)) * dimensions[0] - 0.5;
  const double y = (t - std::floor(t)) * dimensions[1] - 0.5;
  const double fx = x - std::floor(x);
  const double fy = y - std::floor(y);
  glm::dvec4 colour(0.0);
  for (int corner = 0; corner < 4; ++corner)
  {
    const int dx = corner & 1;
    const int dy = corner >> 1;
    const int i = (static_cast<int>(std::floor(x)) + dx + dimensions[0]) % dimensions[0];
    const int j = (static_cast<int>(std::floor(y)) + dy + dimensions[1]) % dimensions[1];
    const double weight = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy);
    const vtkIdType texel = static_cast<vtkIdType>(j) * dimensions[0] + i;
    glm::dvec4 value(255.0);
    for (int c = 0; c < std::min(components, 4); ++c)
    {
      value[c] = scalars->GetComponent(texel, c);
    }
    if (components < 3)
    {
      value = glm::dvec4(value.x, value.x, value.x, components == 2 ? value.y : 255.0);
    }
    colour += weight * value;
  }
  return colour;
}

// The mesh's colour (RGBA, 0 to 255) at weights (b0, b1, b2) of triangle t.
glm::dvec4 ColourAt(const Mesh& mesh, vtkIdType t, const glm::dvec3& weights)
{
  const std::array<vtkIdType, 3>& corners = mesh.Triangles[t];
  if (mesh.Colours)
  {
    glm::dvec4 colour(0.0);
    for (int c = 0; c < 3; ++c)
    {
      for (int k = 0; k < 4; ++k)
      {
        colour[k] += weights[c] * mesh.Colours->GetValue(4 * corners[c] + k);
      }
    }
    return colour;
  }
  if (mesh.Texture)
  {
    glm::dvec2 st(0.0);
    for (int c = 0; c < 3; ++c)
    {
      st += weights[c] *
        glm::dvec2(mesh.TCoords->GetComponent(corners[c], 0),
          mesh.TCoords->GetComponent(corners[c], 1));
    }
    return SampleTexture(mesh.Texture, st.x, st.y);
  }
  return glm::dvec4(255.0);
}

// Triangle t's unit normal (its corners' order: counter-clockwise seen from its front).
glm::dvec3 TriangleNormal(const Mesh& mesh, vtkIdType t)
{
  const std::array<vtkIdType, 3>& corners = mesh.Triangles[t];
  const glm::dvec3 normal = glm::cross(mesh.Points[corners[1]] - mesh.Points[corners[0]],
    mesh.Points[corners[2]] - mesh.Points[corners[0]]);
  const double length = glm::length(normal);
  return length > 0.0 ? normal / length : glm::dvec3(0.0, 0.0, 1.0);
}

// The mesh's normal at weights (b0, b1, b2) of triangle t: its point normals interpolated,
// or the triangle's.
glm::dvec3 NormalAt(const Mesh& mesh, vtkIdType t, const glm::dvec3& weights)
{
  const std::array<vtkIdType, 3>& corners = mesh.Triangles[t];
  glm::dvec3 normal(0.0);
  if (mesh.Normals)
  {
    for (int c = 0; c < 3; ++c)
    {
      double n[3];
      mesh.Normals->GetTuple(corners[c], n);
      normal += weights[c] * glm::dvec3(n[0], n[1], n[2]);
    }
  }
  const double length = glm::length(normal);
  return length > 1e-12 ? normal / length : TriangleNormal(mesh, t);
}

vtkSmartPointer<vtkImageData> NewSlices(int size, int views)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(size, size, views);
  image->SetSpacing(1.0 / size, 1.0 / size, 1.0);
  image->SetOrigin(0.5 / size, 0.5 / size, 0.0);
  return image;
}

// A point of triangle t for coverage sample s of `count` spread by area: the share
// `along` of the triangle's area, and a second coordinate from the golden ratio.
glm::dvec3 SurfacePoint(const Mesh& mesh, vtkIdType t, double along, int s)
{
  const double second = std::fmod((s + 1) * 0.6180339887498949, 1.0);
  const double root = std::sqrt(glm::clamp(along, 0.0, 1.0));
  const std::array<vtkIdType, 3>& corners = mesh.Triangles[t];
  return (1.0 - root) * mesh.Points[corners[0]] + root * (1.0 - second) * mesh.Points[corners[1]] +
    root * second * mesh.Points[corners[2]];
}

// Whether a view sees `point` of a surface whose normal is `normal`: its ray there (toward
// `apex`, homogeneous: a direction where w = 0) is not along the surface, and the point
// lies at most SeenTolerance behind the field interpolated between the four texels around
// it (exact on a plane, which stays a plane in the view's unit cube; empty texels as 1).
bool SeenBy(const glm::dmat4& projection, const glm::dvec4& apex, const Raster& raster,
  const glm::dvec3& point, const glm::dvec3& normal)
{
  const glm::dvec3 ray = glm::dvec3(apex) - apex.w * point;
  if (std::abs(glm::dot(normal, ray)) < 0.02 * glm::length(ray))
  {
    return false; // edge on: no texel's ray meets it
  }
  const glm::dvec4 h = Project(projection, point);
  const double x = h.x / h.w * raster.Size - 0.5;
  const double y = h.y / h.w * raster.Size - 0.5;
  if (!(x > -0.5 && y > -0.5 && x < raster.Size - 0.5 && y < raster.Size - 0.5))
  {
    return false;
  }
  const double fx = x - std::floor(x);
  const double fy = y - std::floor(y);
  double field = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    const int i = glm::clamp(static_cast<int>(std::floor(x)) + (corner & 1), 0, raster.Size - 1);
    const int j = glm::clamp(static_cast<int>(std::floor(y)) + (corner >> 1), 0, raster.Size - 1);
    const size_t texel = static_cast<size_t>(j) * raster.Size + i;
    const double depth = raster.Triangle[texel] < 0 ? 1.0 : raster.Depth[texel];
    field += ((corner & 1) ? fx : 1.0 - fx) * ((corner >> 1) ? fy : 1.0 - fy) * depth;
  }
  return h.z / h.w <= field + SeenTolerance;
}

// The share of CoverageSamples points spread over the mesh by area that no view sees.
double UnseenShare(const Mesh& mesh, const std::vector<glm::dmat4>& projections,
  const std::vector<glm::dvec4>& apexes, const std::vector<Raster>& fields)
{
  std::vector<double> cumulative(mesh.Triangles.size());
  double total = 0.0;
  for (size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const std::array<vtkIdType, 3>& corners = mesh.Triangles[t];
    total += 0.5 *
      glm::length(glm::cross(mesh.Points[corners[1]] - mesh.Points[corners[0]],
        mesh.Points[corners[2]] - mesh.Points[corners[0]]));
    cumulative[t] = total;
  }
  if (!(total > 0.0))
  {
    return 0.0;
  }
  const int samples = vtkReliefImpostorFilter::CoverageSamples;
  std::vector<unsigned char> unseen(samples, 0);
  vtkSMPTools::For(0, samples, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType s = begin; s < end; ++s)
    {
      const double target = (s + 0.5) / samples * total;
      const size_t t = std::min(
        static_cast<size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), target) -
          cumulative.begin()),
        cumulative.size() - 1);
      const double before = t > 0 ? cumulative[t - 1] : 0.0;
      const double area = cumulative[t] - before;
      const glm::dvec3 normal = TriangleNormal(mesh, static_cast<vtkIdType>(t));
      const double along = area > 0.0 ? (target - before) / area : 0.5;
      const glm::dvec3 point =
        SurfacePoint(mesh, static_cast<vtkIdType>(t), along, static_cast<int>(s));
      bool seen = false;
      for (size_t view = 0; view < fields.size() && !seen; ++view)
      {
        seen = SeenBy(projections[view], apexes[view], fields[view], point, normal);
      }
      unseen[s] = seen ? 0 : 1;
    }
  });
  return static_cast<double>(std::count(unseen.begin(), unseen.end(), 1)) / samples;
}
} // namespace

struct vtkReliefImpostorFilter::Internals
{
  std::vector<glm::dmat4> Projections;
  std::vector<glm::dvec4> Apexes; // where each view's rays go: a point, or a direction (w = 0)
};

vtkReliefImpostorFilter::vtkReliefImpostorFilter()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

vtkReliefImpostorFilter::~vtkReliefImpostorFilter() = default;

void vtkReliefImpostorFilter::SetInputData(vtkPolyData* mesh)
{
  this->SetInputDataInternal(0, reinterpret_cast<vtkDataObject*>(mesh));
}

void vtkReliefImpostorFilter::SetColourTextureData(vtkImageData* image)
{
  this->SetInputDataInternal(1, reinterpret_cast<vtkDataObject*>(image));
}

vtkImageData* vtkReliefImpostorFilter::GetDepthOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(0));
}

vtkImageData* vtkReliefImpostorFilter::GetColourOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

void vtkReliefImpostorFilter::SetNumberOfViews(int views)
{
  const int chosen = views <= 3 ? 1 : 6;
  if (chosen != this->NumberOfViews)
  {
    this->NumberOfViews = chosen;
    this->Modified();
  }
}

bool vtkReliefImpostorFilter::GetViewProjection(int view, double matrix[16])
{
  if (view < 0 || view >= static_cast<int>(this->Internal->Projections.size()))
  {
    return false;
  }
  const glm::dmat4& projection = this->Internal->Projections[view];
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      matrix[4 * row + column] = projection[column][row]; // glm is column major
    }
  }
  return true;
}

int vtkReliefImpostorFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), port == 0 ? "vtkPolyData" : "vtkImageData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

bool vtkReliefImpostorFilter::CheckSettings()
{
  for (int resolution : { this->DepthResolution, this->ColourResolution })
  {
    if (resolution < 1 || resolution > MaximumResolution)
    {
      vtkErrorMacro("DepthResolution " << this->DepthResolution << " and ColourResolution "
                                       << this->ColourResolution << " must lie in [1, "
                                       << MaximumResolution
                                       << "]: set them to the texels a side each texture needs.");
      return false;
    }
  }
  if (this->Projection == REVERSE_PERSPECTIVE && !(this->ApexDistance > 1.0))
  {
    vtkErrorMacro("ApexDistance " << this->ApexDistance
                                  << " puts the reverse perspective's apex inside the box: it "
                                     "must be over 1 (box depths from the face); 2 is the "
                                     "default.");
    return false;
  }
  return true;
}

int vtkReliefImpostorFilter::PadBounds(const double bounds[6], double padding, double box[6])
{
  double largest = 0.0;
  double diagonal = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    const double side = bounds[2 * axis + 1] - bounds[2 * axis];
    largest = std::max(largest, side);
    diagonal += side * side;
  }
  diagonal = std::sqrt(diagonal);
  const double pad = padding * diagonal;
  const double thinnest = 0.01 * largest;
  int thickened = 0;
  for (int axis = 0; axis < 3; ++axis)
  {
    double low = bounds[2 * axis] - pad;
    double high = bounds[2 * axis + 1] + pad;
    if (high - low < thinnest)
    {
      const double middle = 0.5 * (low + high);
      low = middle - 0.5 * thinnest;
      high = middle + 0.5 * thinnest;
      thickened |= 1 << axis;
    }
    box[2 * axis] = low;
    box[2 * axis + 1] = high;
  }
  return thickened;
}

unsigned short vtkReliefImpostorFilter::EncodeDepth(float depth)
{
  if (!(depth < 1.0f))
  {
    return 65535;
  }
  const float code = std::round(std::max(depth, 0.0f) * 65535.0f);
  return static_cast<unsigned short>(std::min(code, 65534.0f));
}

void vtkReliefImpostorFilter::ChooseBox(const double bounds[6])
{
  const int thickened = PadBounds(bounds, this->Padding, this->Box);
  for (int axis = 0; axis < 3; ++axis)
  {
    if (thickened & (1 << axis))
    {
      vtkWarningMacro("The mesh is flat along " << "xyz"[axis]
                                                << ": its box is thickened to a hundredth of its "
                                                   "largest side. Raise Padding to set it.");
    }
  }
}

void vtkReliefImpostorFilter::MakeProjections()
{
  this->Internal->Projections.clear();
  this->Internal->Apexes.clear();
  const glm::dvec3 low(this->Box[0], this->Box[2], this->Box[4]);
  const glm::dvec3 high(this->Box[1], this->Box[3], this->Box[5]);
  const glm::dvec3 centre = 0.5 * (low + high);
  const glm::dvec3 size = high - low;
  // the views' faces: outward normals, in the documented order
  const std::array<glm::dvec3, 6> outward = { glm::dvec3(1, 0, 0), glm::dvec3(-1, 0, 0),
    glm::dvec3(0, 1, 0), glm::dvec3(0, -1, 0), glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1) };
  const int first = this->NumberOfViews == 1 ? 4 : 0;
  const int last = this->NumberOfViews == 1 ? 4 : 5;
  for (int face = first; face <= last; ++face)
  {
    const glm::dvec3 n = outward[face];
    const int axis = face / 2;
    // u and v across the face as seen from outside: u x v = n
    glm::dvec3 uAxis(0.0);
    uAxis[(axis + 1) % 3] = 1.0;
    glm::dvec3 vAxis = glm::cross(n, uAxis);
    // reverse perspective: the frustum holds the box, its far end the far face; its near
    // end, on the face's plane, is the far end seen from the apex (k / (k - 1) as large)
    const bool perspective = this->Projection == REVERSE_PERSPECTIVE;
    const double widening = perspective ? this->ApexDistance / (this->ApexDistance - 1.0) : 1.0;
    const double uLength = widening * size[(axis + 1) % 3];
    const double vLength = widening * size[(axis + 2) % 3];
    const double depth = size[axis];
    const glm::dvec3 faceCentre = centre + 0.5 * depth * n;
    const glm::dvec3 origin = faceCentre - 0.5 * uLength * uAxis - 0.5 * vLength * vAxis;
    // w = 1 - zeta / (k D), zeta the depth below the face; orthographic: w = 1, k infinite.
    // u w = (A - O).uAxis w + (X - A).uAxis (over its length), depth w = (1 - w)(k - 1).
    const double apexDistance = this->ApexDistance * depth;
    const glm::dvec3 apex = faceCentre - apexDistance * n;
    // rows as (coefficients of X, constant)
    const glm::dvec4 wRow = perspective
      ? glm::dvec4(n / apexDistance, 1.0 - glm::dot(faceCentre, n) / apexDistance)
      : glm::dvec4(0.0, 0.0, 0.0, 1.0);
    auto across = [&](const glm::dvec3& axisVector, double length) {
      if (!perspective)
      {
        return glm::dvec4(axisVector, -glm::dot(origin, axisVector)) / length;
      }
      return (glm::dot(apex - origin, axisVector) * wRow +
               glm::dvec4(axisVector, -glm::dot(apex, axisVector))) /
        length;
    };
    const glm::dvec4 uRow = across(uAxis, uLength);
    const glm::dvec4 vRow = across(vAxis, vLength);
    const glm::dvec4 depthRow = perspective
      ? (glm::dvec4(0.0, 0.0, 0.0, 1.0) - wRow) * (this->ApexDistance - 1.0)
      : glm::dvec4(-n / depth, glm::dot(faceCentre, n) / depth);
    glm::dmat4 projection(0.0);
    const std::array<glm::dvec4, 4> rows = { uRow, vRow, depthRow, wRow };
    for (int row = 0; row < 4; ++row)
    {
      for (int column = 0; column < 4; ++column)
      {
        projection[column][row] = rows[row][column];
      }
    }
    this->Internal->Projections.push_back(projection);
    this->Internal->Apexes.push_back(perspective ? glm::dvec4(apex, 1.0) : glm::dvec4(-n, 0.0));
  }
}

int vtkReliefImpostorFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  vtkPolyData* input = vtkPolyData::GetData(inputs[0]);
  vtkImageData* texture = vtkImageData::GetData(inputs[1]);
  vtkImageData* depthOutput = vtkImageData::GetData(outputs, 0);
  vtkImageData* colourOutput = vtkImageData::GetData(outputs, 1);
  this->Internal->Projections.clear();
  this->UnseenSurfaceFraction = 0.0;
  if (!this->CheckSettings())
  {
    return 1;
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkPolyData* surface = triangles->GetOutput();
  if (!input || surface->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The mesh has no polygons to capture: give vtkReliefImpostorFilter a "
                  "surface (vtkGeometryFilter makes one from any dataset).");
    return 1;
  }

  Mesh mesh;
  mesh.Points.resize(surface->GetNumberOfPoints());
  for (vtkIdType p = 0; p < surface->GetNumberOfPoints(); ++p)
  {
    double x[3];
    surface->GetPoint(p, x);
    mesh.Points[p] = glm::dvec3(x[0], x[1], x[2]);
  }
  vtkCellArray* polys = surface->GetPolys();
  mesh.Triangles.reserve(polys->GetNumberOfCells());
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    mesh.Triangles.push_back({ ids[0], ids[1], ids[2] });
  }
  vtkDataArray* scalars = surface->GetPointData()->GetScalars();
  mesh.Normals = surface->GetPointData()->GetNormals();
  mesh.TCoords = surface->GetPointData()->GetTCoords();
  if (scalars)
  {
    vtkNew<vtkLookupTable> table;
    table->SetRange(scalars->GetRange(-1));
    table->Build();
    mesh.Colours.TakeReference(vtkUnsignedCharArray::SafeDownCast(
      table->MapScalars(scalars, VTK_COLOR_MODE_DEFAULT, -1, VTK_RGBA)));
  }
  else if (texture && mesh.TCoords && texture->GetPointData()->GetScalars() &&
    texture->GetNumberOfPoints() > 0)
  {
    mesh.Texture = texture;
  }
  else
  {
    vtkWarningMacro("The mesh has no colour (point scalars, or texture coordinates with a "
                    "colour image on input 1): the impostor is white.");
  }

  double bounds[6];
  surface->GetBounds(bounds);
  this->ChooseBox(bounds);
  this->MakeProjections();
  const int views = static_cast<int>(this->Internal->Projections.size());

  vtkSmartPointer<vtkImageData> depths = NewSlices(this->DepthResolution, views);
  vtkNew<vtkFloatArray> depthArray;
  depthArray->SetName("Depth");
  depthArray->SetNumberOfTuples(static_cast<vtkIdType>(depths->GetNumberOfPoints()));
  vtkSmartPointer<vtkImageData> colours = NewSlices(this->ColourResolution, views);
  vtkNew<vtkUnsignedCharArray> colourArray;
  colourArray->SetName("Colour");
  colourArray->SetNumberOfComponents(4);
  colourArray->SetNumberOfTuples(colours->GetNumberOfPoints());
  vtkNew<vtkFloatArray> normalArray;
  normalArray->SetName("Normals");
  normalArray->SetNumberOfComponents(3);
  normalArray->SetNumberOfTuples(colours->GetNumberOfPoints());

  std::vector<Raster> fields;
  for (int view = 0; view < views && !this->AbortExecute; ++view)
  {
    const glm::dmat4& projection = this->Internal->Projections[view];
    fields.push_back(Rasterize(mesh, projection, this->DepthResolution, true));
    const Raster& field = fields.back();
    const size_t slice = field.Depth.size();
    for (size_t texel = 0; texel < slice; ++texel)
    {
      const float depth = field.Triangle[texel] < 0
        ? 1.0f
        : std::min(static_cast<float>(std::max(field.Depth[texel], 0.0)), DeepestHit);
      depthArray->SetValue(static_cast<vtkIdType>(view * slice + texel), depth);
    }
    this->UpdateProgress((view + 0.5) / (views + 1.0));

    const Raster seen = Rasterize(mesh, projection, this->ColourResolution, false);
    const size_t colourSlice = seen.Depth.size();
    vtkSMPTools::For(0, static_cast<vtkIdType>(colourSlice), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType texel = begin; texel < end; ++texel)
      {
        const vtkIdType tuple = static_cast<vtkIdType>(view * colourSlice) + texel;
        const vtkIdType t = seen.Triangle[texel];
        if (t < 0)
        {
          const unsigned char transparent[4] = { 0, 0, 0, 0 };
          const float none[3] = { 0.0f, 0.0f, 0.0f };
          colourArray->SetTypedTuple(tuple, transparent);
          normalArray->SetTypedTuple(tuple, none);
          continue;
        }
        const glm::dvec2 w = seen.Weights[texel];
        const glm::dvec3 weights(1.0 - w.x - w.y, w.x, w.y);
        const glm::dvec4 colour = glm::clamp(ColourAt(mesh, t, weights), 0.0, 255.0);
        const std::array<unsigned char, 4> rgba = { static_cast<unsigned char>(colour.r + 0.5),
          static_cast<unsigned char>(colour.g + 0.5), static_cast<unsigned char>(colour.b + 0.5),
          255 };
        colourArray->SetTypedTuple(tuple, rgba.data());
        const glm::dvec3 normal = NormalAt(mesh, t, weights);
        const float n[3] = { static_cast<float>(normal.x), static_cast<float>(normal.y),
          static_cast<float>(normal.z) };
        normalArray->SetTypedTuple(tuple, n);
      }
    });
    this->UpdateProgress((view + 1.0) / (views + 1.0));
  }
  if (this->AbortExecute)
  {
    return 1;
  }
  this->UnseenSurfaceFraction =
    UnseenShare(mesh, this->Internal->Projections, this->Internal->Apexes, fields);

  vtkNew<vtkDoubleArray> projections;
  projections->SetName("ViewProjections");
  projections->SetNumberOfComponents(16);
  projections->SetNumberOfTuples(views);
  for (int view = 0; view < views; ++view)
  {
    double matrix[16];
    this->GetViewProjection(view, matrix);
    projections->SetTypedTuple(view, matrix);
  }
  vtkNew<vtkDoubleArray> unseen;
  unseen->SetName("UnseenSurfaceFraction");
  unseen->InsertNextValue(this->UnseenSurfaceFraction);
  depths->GetPointData()->SetScalars(depthArray);
  depths->GetFieldData()->AddArray(projections);
  depths->GetFieldData()->AddArray(unseen);
  colours->GetPointData()->SetScalars(colourArray);
  colours->GetPointData()->SetNormals(normalArray);
  colours->GetFieldData()->AddArray(projections);
  depthOutput->ShallowCopy(depths);
  colourOutput->ShallowCopy(colours);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkReliefImpostorFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfViews: " << this->NumberOfViews << "\n";
  os << indent << "Projection: "
     << (this->Projection == ORTHOGRAPHIC ? "Orthographic" : "ReversePerspective") << "\n";
  os << indent << "ApexDistance: " << this->ApexDistance << "\n";
  os << indent << "DepthResolution: " << this->DepthResolution << "\n";
  os << indent << "ColourResolution: " << this->ColourResolution << "\n";
  os << indent << "Padding: " << this->Padding << "\n";
  os << indent << "Box: " << this->Box[0] << " " << this->Box[1] << " " << this->Box[2] << " "
     << this->Box[3] << " " << this->Box[4] << " " << this->Box[5] << "\n";
  os << indent << "UnseenSurfaceFraction: " << this->UnseenSurfaceFraction << "\n";
}
