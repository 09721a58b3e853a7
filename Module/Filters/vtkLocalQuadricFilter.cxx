#include "vtkLocalQuadricFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReliefCoincidentPoints.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefTangentFrameFilter.h"
#include "vtkSMPTools.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>
#include <vector>

vtkStandardNewMacro(vtkLocalQuadricFilter);

namespace
{
constexpr int ProgressSlices = 10;
// 1 - cos^2 of the angle between the columns (x^2) and (y^2) of Eq. 2 below which the
// system is taken as singular: neighbours along one line through the point, or none.
constexpr double SingularSine2 = 1e-9;
// Copies of a point whose normals differ by more than about a degree stand on a crease.
constexpr double CreaseCosine = 0.9998;

// The triangles around each point, in compressed rows.
struct PointTriangles
{
  std::vector<vtkIdType> Corners;   // three point ids per triangle
  std::vector<vtkIdType> Offsets;   // point p's triangles: Triangles[Offsets[p], Offsets[p+1])
  std::vector<vtkIdType> Triangles; // triangle indices
};

// The three point ids of every triangle (the tangent frame filter triangulates: nothing
// else is left).
std::vector<vtkIdType> TriangleCorners(vtkPolyData* mesh)
{
  std::vector<vtkIdType> corners;
  corners.reserve(3 * static_cast<size_t>(mesh->GetNumberOfPolys()));
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    polys->GetCurrentCell(size, ids);
    if (size == 3)
    {
      corners.insert(corners.end(), ids, ids + 3);
    }
  }
  return corners;
}

// The triangles around each point, coincident points taken as one (`merged`: a point's
// stand-in), so that a texture seam's two copies of a point share one neighbourhood.
PointTriangles TrianglesAroundPoints(vtkPolyData* mesh, const std::vector<vtkIdType>& merged)
{
  PointTriangles incidence;
  const vtkIdType pointCount = mesh->GetNumberOfPoints();
  incidence.Corners = TriangleCorners(mesh);
  for (vtkIdType& corner : incidence.Corners)
  {
    corner = merged[corner];
  }
  incidence.Offsets.assign(static_cast<size_t>(pointCount) + 1, 0);
  for (vtkIdType corner : incidence.Corners)
  {
    ++incidence.Offsets[corner + 1];
  }
  for (vtkIdType p = 0; p < pointCount; ++p)
  {
    incidence.Offsets[p + 1] += incidence.Offsets[p];
  }
  incidence.Triangles.resize(incidence.Corners.size());
  std::vector<vtkIdType> cursor(incidence.Offsets.begin(), incidence.Offsets.end() - 1);
  for (size_t corner = 0; corner < incidence.Corners.size(); ++corner)
  {
    incidence.Triangles[cursor[incidence.Corners[corner]]++] =
      static_cast<vtkIdType>(corner / 3);
  }
  return incidence;
}

// The other points of the triangles around `point`, `rings` rings deep, each once.
void Neighbours(const PointTriangles& incidence, vtkIdType point, int rings,
  std::vector<vtkIdType>& neighbours)
{
  neighbours.clear();
  auto addRing = [&](vtkIdType centre) {
    for (vtkIdType k = incidence.Offsets[centre]; k < incidence.Offsets[centre + 1]; ++k)
    {
      const vtkIdType* corners = incidence.Corners.data() + 3 * incidence.Triangles[k];
      neighbours.insert(neighbours.end(), corners, corners + 3);
    }
  };
  addRing(point);
  if (rings > 1)
  {
    const size_t firstRing = neighbours.size();
    for (size_t k = 0; k < firstRing; ++k)
    {
      addRing(neighbours[k]);
    }
  }
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  neighbours.erase(std::remove(neighbours.begin(), neighbours.end(), point), neighbours.end());
}

bool IsFinite(const glm::dvec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

glm::dvec3 TupleOf(vtkDataArray* array, vtkIdType id)
{
  double tuple[3];
  array->GetTuple(id, tuple);
  return glm::dvec3(tuple[0], tuple[1], tuple[2]);
}

// Least squares of Eq. 2 in the frame (normal, tangent) at `origin`: false, with a and
// b left at 0, when it is undetermined.
bool FitQuadric(const glm::dvec3& origin, const glm::dvec3& normal, const glm::dvec3& tangent,
  vtkPoints* points, const std::vector<vtkIdType>& neighbours, double quadric[2])
{
  quadric[0] = 0.0;
  quadric[1] = 0.0;
  const double normalLength = glm::length(normal);
  if (!IsFinite(origin) || !IsFinite(normal) || !IsFinite(tangent) || !(normalLength > 0.0))
  {
    return false;
  }
  const glm::dvec3 n = normal / normalLength;
  glm::dvec3 t = tangent - n * glm::dot(n, tangent);
  const double tangentLength = glm::length(t);
  if (!(tangentLength > 1e-12 * glm::length(tangent)))
  {
    return false;
  }
  t /= tangentLength;
  const glm::dvec3 b = glm::cross(n, t);
  double xxxx = 0.0, yyyy = 0.0, xxyy = 0.0, xxz = 0.0, yyz = 0.0;
  for (vtkIdType id : neighbours)
  {
    double position[3];
    points->GetPoint(id, position);
    const glm::dvec3 d = glm::dvec3(position[0], position[1], position[2]) - origin;
    if (!IsFinite(d))
    {
      continue;
    }
    const double xx = glm::dot(d, t) * glm::dot(d, t);
    const double yy = glm::dot(d, b) * glm::dot(d, b);
    const double z = glm::dot(d, n);
    xxxx += xx * xx;
    yyyy += yy * yy;
    xxyy += xx * yy;
    xxz += xx * z;
    yyz += yy * z;
  }
  const double determinant = xxxx * yyyy - xxyy * xxyy;
  if (!(xxxx > 0.0 && yyyy > 0.0 && determinant > SingularSine2 * xxxx * yyyy))
  {
    return false;
  }
  quadric[0] = (xxz * yyyy - yyz * xxyy) / determinant;
  quadric[1] = (yyz * xxxx - xxz * xxyy) / determinant;
  return std::isfinite(quadric[0]) && std::isfinite(quadric[1]);
}

// A point's frame and quadric, for the hull's lift.
struct PointQuadric
{
  glm::dvec3 Position;
  glm::dvec3 Normal;
  glm::dvec3 Tangent;
  glm::dvec3 Bitangent;
  double A = 0.0;
  double B = 0.0;
};

PointQuadric PointQuadricOf(vtkPolyData* mesh, vtkDataArray* quadrics, vtkIdType p)
{
  PointQuadric point;
  double position[3];
  mesh->GetPoint(p, position);
  point.Position = glm::dvec3(position[0], position[1], position[2]);
  point.Normal = TupleOf(mesh->GetPointData()->GetNormals(), p);
  point.Normal /= std::max(glm::length(point.Normal), 1e-300);
  const glm::dvec3 tangent = TupleOf(mesh->GetPointData()->GetTangents(), p);
  point.Tangent = tangent - point.Normal * glm::dot(point.Normal, tangent);
  point.Tangent /= std::max(glm::length(point.Tangent), 1e-300);
  point.Bitangent = glm::cross(point.Normal, point.Tangent);
  point.A = quadrics->GetComponent(p, 0);
  point.B = quadrics->GetComponent(p, 1);
  return point;
}

// How far the quadric at `point` rises along its normal over the tangent-plane step
// `edge`: a x^2 + b y^2 (negative where it bends away from the normal).
double Rise(const PointQuadric& point, const glm::dvec3& edge)
{
  const double x = glm::dot(edge, point.Tangent);
  const double y = glm::dot(edge, point.Bitangent);
  return point.A * x * x + point.B * y * y;
}

// The most the curved surface rises above a triangle: over the edge from p to q it
// stands -s (1 - s) Q(q - p) above the chord (Q the mean of both ends' rises), so over
// the triangle, with barycentric coordinates l, sum l_i l_j w_ij with w_ij = -Q_ij, at
// most max(w) / 3. The shader computes the same (vtkReliefQuadricFrame.glsl).
double TriangleRise(const PointQuadric corners[3])
{
  double most = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const PointQuadric& from = corners[k];
    const PointQuadric& to = corners[(k + 1) % 3];
    const glm::dvec3 edge = to.Position - from.Position;
    most = std::max(most, -0.5 * (Rise(from, edge) + Rise(to, -edge)));
  }
  return most / 3.0;
}

// The lift of each point (vtkLocalQuadricFilter::HullLiftArrayName): the most the
// surface rises above any triangle around its position, shared by every copy there so
// that the hull stays closed; 0 where the copies' normals part (a crease: lifted apart,
// they would open a crack), or where the rise is not finite.
std::vector<float> HullLifts(vtkPolyData* mesh, vtkDataArray* quadrics)
{
  const vtkIdType pointCount = mesh->GetNumberOfPoints();
  std::vector<vtkIdType> position = vtkReliefCoincidentPoints(mesh);
  if (position.empty())
  {
    position.resize(static_cast<size_t>(pointCount));
    std::iota(position.begin(), position.end(), 0);
  }
  const std::vector<vtkIdType> corners = TriangleCorners(mesh);
  const vtkIdType triangleCount = static_cast<vtkIdType>(corners.size() / 3);
  std::vector<double> rises(static_cast<size_t>(triangleCount));
  vtkSMPTools::For(0, triangleCount, [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType t = begin; t < end; ++t)
    {
      const vtkIdType* ids = corners.data() + 3 * t;
      const PointQuadric triangle[3] = { PointQuadricOf(mesh, quadrics, ids[0]),
        PointQuadricOf(mesh, quadrics, ids[1]), PointQuadricOf(mesh, quadrics, ids[2]) };
      rises[t] = TriangleRise(triangle);
    }
  });
  std::vector<double> lift(static_cast<size_t>(pointCount), 0.0);
  for (vtkIdType t = 0; t < triangleCount; ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      double& shared = lift[position[corners[3 * t + k]]];
      shared = std::isfinite(rises[t]) ? std::max(shared, rises[t]) : shared;
    }
  }
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  for (vtkIdType p = 0; p < pointCount; ++p)
  {
    const vtkIdType shared = position[p];
    const glm::dvec3 normal = glm::normalize(TupleOf(normals, p));
    const glm::dvec3 sharedNormal = glm::normalize(TupleOf(normals, shared));
    if (!(glm::dot(normal, sharedNormal) > CreaseCosine))
    {
      lift[shared] = 0.0;
    }
  }
  std::vector<float> lifts(static_cast<size_t>(pointCount));
  for (vtkIdType p = 0; p < pointCount; ++p)
  {
    lifts[p] = static_cast<float>(lift[position[p]]);
  }
  return lifts;
}
}

//------------------------------------------------------------------------------
vtkLocalQuadricFilter::vtkLocalQuadricFilter() = default;
vtkLocalQuadricFilter::~vtkLocalQuadricFilter() = default;

int vtkLocalQuadricFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfFallbacks = 0;

  vtkNew<vtkPolyData> source;
  source->ShallowCopy(input);
  vtkNew<vtkReliefTangentFrameFilter> frame;
  vtkReliefForwardMessages(frame, this);
  frame->SetInputData(source);
  frame->Update();
  if (!frame->GetHasSurface())
  {
    output->ShallowCopy(frame->GetOutput()); // the mesh, its broken cells left out
    return 1;
  }
  vtkPolyData* mesh = frame->GetOutput();
  this->UpdateProgress(0.3);

  // a texture seam's copies of a point share one neighbourhood, the sides of a crease that
  // the normals split keep their own (vtkReliefTangentFrameFilter's feature angle)
  std::vector<vtkIdType> merged = vtkReliefCoincidentPoints(
    mesh, mesh->GetPointData()->GetNormals(), frame->GetFeatureAngle());
  if (merged.empty()) // a point is not finite: no point stands for another
  {
    merged.resize(static_cast<size_t>(mesh->GetNumberOfPoints()));
    std::iota(merged.begin(), merged.end(), 0);
  }
  const PointTriangles incidence = TrianglesAroundPoints(mesh, merged);
  this->UpdateProgress(0.4);

  const vtkIdType pointCount = mesh->GetNumberOfPoints();
  vtkNew<vtkFloatArray> quadrics;
  quadrics->SetName(QuadricArrayName());
  quadrics->SetNumberOfComponents(2);
  quadrics->SetNumberOfTuples(pointCount);
  quadrics->Fill(0.0); // what an aborted update leaves: flat
  vtkPoints* points = mesh->GetPoints();
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* tangents = mesh->GetPointData()->GetTangents();
  std::atomic<vtkIdType> fallbacks(0);
  const int rings = this->NeighbourhoodRings;
  auto fitRange = [&](vtkIdType begin, vtkIdType end) {
    std::vector<vtkIdType> neighbours;
    vtkIdType undetermined = 0;
    for (vtkIdType p = begin; p < end; ++p)
    {
      Neighbours(incidence, merged[p], rings, neighbours);
      double position[3];
      points->GetPoint(p, position);
      double quadric[2];
      if (!FitQuadric(glm::dvec3(position[0], position[1], position[2]),
            TupleOf(normals, p), TupleOf(tangents, p), points, neighbours, quadric))
      {
        ++undetermined;
      }
      quadrics->SetTypedTuple(
        p, std::array<float, 2>{ static_cast<float>(quadric[0]), static_cast<float>(quadric[1]) }
             .data());
    }
    fallbacks += undetermined;
  };
  for (int slice = 0; slice < ProgressSlices && !this->GetAbortExecute(); ++slice)
  {
    vtkSMPTools::For(pointCount * slice / ProgressSlices,
      pointCount * (slice + 1) / ProgressSlices, fitRange);
    this->UpdateProgress(0.4 + 0.6 * (slice + 1) / ProgressSlices);
  }

  output->ShallowCopy(mesh);
  output->GetPointData()->AddArray(quadrics);
  output->GetPointData()->AddArray(vtk::TakeSmartPointer(NewHullLifts(output)));
  this->NumberOfFallbacks = fallbacks;
  vtkNew<vtkIdTypeArray> fallbackCount;
  fallbackCount->SetName(FallbackCountArrayName());
  fallbackCount->InsertNextValue(this->NumberOfFallbacks);
  output->GetFieldData()->AddArray(fallbackCount);
  return 1;
}

vtkFloatArray* vtkLocalQuadricFilter::NewHullLifts(vtkPolyData* framed)
{
  vtkPointData* pointData = framed ? framed->GetPointData() : nullptr;
  vtkDataArray* quadrics = pointData ? pointData->GetArray(QuadricArrayName()) : nullptr;
  const vtkIdType count = framed ? framed->GetNumberOfPoints() : 0;
  auto holds = [count](vtkDataArray* array, int components) {
    return array && array->GetNumberOfComponents() == components &&
      array->GetNumberOfTuples() == count;
  };
  if (!holds(quadrics, 2) || !holds(pointData->GetNormals(), 3) ||
    !holds(pointData->GetTangents(), 3) || !framed->GetPolys())
  {
    return nullptr;
  }
  const std::vector<float> lift = HullLifts(framed, quadrics);
  vtkFloatArray* lifts = vtkFloatArray::New();
  lifts->SetName(HullLiftArrayName());
  lifts->SetNumberOfTuples(count);
  std::copy(lift.begin(), lift.end(), lifts->GetPointer(0));
  return lifts;
}

void vtkLocalQuadricFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NeighbourhoodRings: " << this->NeighbourhoodRings << "\n";
  os << indent << "NumberOfFallbacks: " << this->NumberOfFallbacks << "\n";
}
