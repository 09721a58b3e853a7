#include "vtkReliefTangentFrameFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkPolyDataTangents.h"
#include "vtkSmartPointer.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkReliefTangentFrameFilter);

namespace
{
glm::dvec3 PointOf(vtkPolyData* mesh, vtkIdType id)
{
  double p[3];
  mesh->GetPoint(id, p);
  return glm::dvec3(p[0], p[1], p[2]);
}

// The first three components (a tangent array may carry handedness in a fourth).
glm::dvec3 TupleOf3(vtkDataArray* array, vtkIdType id)
{
  return glm::dvec3(
    array->GetComponent(id, 0), array->GetComponent(id, 1), array->GetComponent(id, 2));
}

// The unit normal of a point; +z where the normal has no direction (a point on
// degenerate triangles only), so every frame stays finite.
glm::dvec3 UnitNormal(vtkDataArray* normals, vtkIdType id)
{
  const glm::dvec3 normal = TupleOf3(normals, id);
  const double length = glm::length(normal);
  return std::isfinite(length) && length > 0.0 ? normal / length : glm::dvec3(0.0, 0.0, 1.0);
}

// Unit tangents perpendicular to the unit normals. A tangent that is missing its
// direction (not finite, or along the normal: a triangle with no texture area gives
// one) becomes any direction in the tangent plane, so no NaN reaches the shader.
vtkSmartPointer<vtkFloatArray> OrthonormalTangents(vtkDataArray* normals, vtkDataArray* tangents)
{
  auto result = vtkSmartPointer<vtkFloatArray>::New();
  result->SetName(tangents->GetName() ? tangents->GetName() : "Tangents");
  result->SetNumberOfComponents(3);
  result->SetNumberOfTuples(tangents->GetNumberOfTuples());
  for (vtkIdType id = 0; id < tangents->GetNumberOfTuples(); ++id)
  {
    const glm::dvec3 normal = UnitNormal(normals, id);
    glm::dvec3 tangent = TupleOf3(tangents, id);
    tangent -= normal * glm::dot(normal, tangent);
    const double length = glm::length(tangent);
    if (!std::isfinite(length) || length < 1e-12)
    {
      const glm::dvec3 axis =
        std::abs(normal.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
      tangent = glm::cross(normal, axis);
    }
    tangent = glm::normalize(tangent);
    result->SetTuple3(id, tangent.x, tangent.y, tangent.z);
  }
  return result;
}

glm::dvec2 TupleOf2(vtkDataArray* array, vtkIdType id)
{
  return glm::dvec2(array->GetComponent(id, 0), array->GetComponent(id, 1));
}

// Area-weighted mean, over the triangles around each point, of the model length of
// one texture unit projected on the point's tangent and bitangent.
vtkSmartPointer<vtkFloatArray> ComputeTextureScale(vtkPolyData* mesh)
{
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* tangents = mesh->GetPointData()->GetTangents();
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  const vtkIdType numberOfPoints = mesh->GetNumberOfPoints();
  std::vector<glm::dvec3> sums(numberOfPoints, glm::dvec3(0.0)); // (area s_x, area s_y, area)

  auto triangles = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (triangles->GoToFirstCell(); !triangles->IsDoneWithTraversal(); triangles->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    triangles->GetCurrentCell(size, ids);
    const glm::dvec3 edge1 = PointOf(mesh, ids[1]) - PointOf(mesh, ids[0]);
    const glm::dvec3 edge2 = PointOf(mesh, ids[2]) - PointOf(mesh, ids[0]);
    const glm::dvec2 uv1 = TupleOf2(tcoords, ids[1]) - TupleOf2(tcoords, ids[0]);
    const glm::dvec2 uv2 = TupleOf2(tcoords, ids[2]) - TupleOf2(tcoords, ids[0]);
    const double uvArea = uv1.x * uv2.y - uv2.x * uv1.y;
    const double area = 0.5 * glm::length(glm::cross(edge1, edge2));
    if (!(std::abs(uvArea) >= 1e-300 && area > 0.0 && std::isfinite(uvArea) &&
          std::isfinite(area)))
    {
      continue; // no parametrization to measure on a degenerate or broken triangle
    }
    const glm::dvec3 dPdu = (edge1 * uv2.y - edge2 * uv1.y) / uvArea;
    const glm::dvec3 dPdv = (edge2 * uv1.x - edge1 * uv2.x) / uvArea;
    for (int corner = 0; corner < 3; ++corner)
    {
      const glm::dvec3 normal = UnitNormal(normals, ids[corner]);
      const glm::dvec3 tangent = TupleOf3(tangents, ids[corner]);
      const glm::dvec3 bitangent = glm::cross(normal, tangent);
      sums[ids[corner]] +=
        glm::dvec3(area * glm::dot(dPdu, tangent), area * glm::dot(dPdv, bitangent), area);
    }
  }

  glm::dvec3 total(0.0);
  for (const auto& sum : sums)
  {
    total += glm::dvec3(std::abs(sum.x), sum.y, sum.z);
  }
  // points on no measurable triangle take the mesh's mean scale
  const glm::dvec2 fallback =
    total.z > 0.0 ? glm::dvec2(total.x, std::abs(total.y)) / total.z : glm::dvec2(1.0);

  vtkNew<vtkFloatArray> scale;
  scale->SetName(vtkReliefTangentFrameFilter::TextureScaleArrayName());
  scale->SetNumberOfComponents(2);
  scale->SetNumberOfTuples(numberOfPoints);
  for (vtkIdType id = 0; id < numberOfPoints; ++id)
  {
    const glm::dvec3& sum = sums[id];
    const glm::dvec2 value = sum.z > 0.0 ? glm::dvec2(sum.x, sum.y) / sum.z : fallback;
    scale->SetTuple2(id, value.x, value.y);
  }
  return scale;
}

// The mesh, its normals without direction (zero, not finite) replaced by the surface's
// own (vtkPolyDataNormals, not split), so that every frame has one.
vtkSmartPointer<vtkPolyData> WithDirectedNormals(vtkPolyData* mesh)
{
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  std::vector<vtkIdType> undirected;
  for (vtkIdType point = 0; point < normals->GetNumberOfTuples(); ++point)
  {
    if (!vtkReliefSurfaceFilter::HasDirection(normals, point))
    {
      undirected.push_back(point);
    }
  }
  if (undirected.empty())
  {
    return mesh;
  }
  vtkNew<vtkPolyData> bare;
  bare->ShallowCopy(mesh);
  bare->GetPointData()->SetNormals(nullptr);
  vtkNew<vtkPolyDataNormals> surface;
  surface->SetInputData(bare);
  surface->SplittingOff();
  surface->ConsistencyOff();
  surface->ComputePointNormalsOn();
  surface->ComputeCellNormalsOff();
  surface->Update();
  vtkDataArray* computed = surface->GetOutput()->GetPointData()->GetNormals();
  auto repaired = vtk::TakeSmartPointer(normals->NewInstance());
  repaired->DeepCopy(normals);
  const double up[3] = { 0.0, 0.0, 1.0 }; // a point on degenerate triangles only
  for (vtkIdType point : undirected)
  {
    const bool directed = vtkReliefSurfaceFilter::HasDirection(computed, point);
    repaired->SetTuple(point, directed ? computed->GetTuple(point) : up);
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(mesh);
  result->GetPointData()->SetNormals(repaired);
  return result;
}

// The mesh with the point tangents vtkPolyDataTangents finds over `source`: the same
// points, the triangles whose tangents may be trusted.
vtkSmartPointer<vtkPolyData> WithTangents(vtkPolyData* mesh, vtkPolyData* source)
{
  vtkNew<vtkPolyDataTangents> tangents;
  tangents->SetInputData(source);
  tangents->ComputePointTangentsOn();
  tangents->ComputeCellTangentsOff();
  tangents->Update();
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(mesh);
  result->GetPointData()->SetTangents(tangents->GetOutput()->GetPointData()->GetTangents());
  return result;
}
}

vtkReliefTangentFrameFilter::vtkReliefTangentFrameFilter() = default;

vtkReliefTangentFrameFilter::~vtkReliefTangentFrameFilter() = default;

void vtkReliefTangentFrameFilter::SetFeatureAngle(double degrees)
{
  if (std::isnan(degrees))
  {
    vtkWarningMacro("FeatureAngle is NaN, not an angle; it stays " << this->FeatureAngle << ".");
    return;
  }
  const double clamped = std::min(std::max(degrees, 0.0), 180.0);
  if (clamped != degrees)
  {
    vtkWarningMacro("FeatureAngle " << degrees << " is out of [0, 180] degrees; using "
                                    << clamped << ".");
  }
  if (clamped != this->FeatureAngle)
  {
    this->FeatureAngle = clamped;
    this->Modified();
  }
}

int vtkReliefTangentFrameFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  // without a surface the output is the mesh drawn plainly: its broken cells left out too
  vtkSmartPointer<vtkPolyData> valid = this->LeaveOutCellsWithMissingPoints(input);
  vtkSmartPointer<vtkPolyData> mesh = this->ExtractTriangles(valid);
  this->HasSurface = mesh != nullptr;
  if (!this->HasSurface)
  {
    output->ShallowCopy(valid);
    return 1;
  }
  this->UpdateProgress(0.25);

  if (!mesh->GetPointData()->GetNormals())
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(mesh);
    normals->SetFeatureAngle(this->FeatureAngle);
    normals->ComputePointNormalsOn();
    normals->ComputeCellNormalsOff();
    normals->Update();
    mesh = normals->GetOutput();
  }
  else
  {
    mesh = WithDirectedNormals(mesh);
  }
  this->UpdateProgress(0.5);

  if (!mesh->GetPointData()->GetTangents())
  {
    // over the triangles whose texture coordinates are all finite: a broken triangle's
    // tangents would spoil those of every point it shares with good ones
    vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
    vtkIdType broken = 0;
    auto finite = LeaveOutCells(
      mesh,
      [tcoords](vtkIdType size, const vtkIdType* ids) {
        return std::any_of(ids, ids + size,
          [tcoords](vtkIdType id) { return !HasFiniteTextureCoordinates(tcoords, id); });
      },
      broken);
    mesh = WithTangents(mesh, finite);
  }
  this->UpdateProgress(0.75);

  output->ShallowCopy(mesh);
  // the mapper binds arrays to shader inputs by name
  NameAttributes(output);
  vtkPointData* pointData = output->GetPointData();
  pointData->SetTangents(OrthonormalTangents(pointData->GetNormals(), pointData->GetTangents()));
  pointData->AddArray(ComputeTextureScale(output));
  this->UpdateProgress(1.0);
  return 1;
}

void vtkReliefTangentFrameFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
}
