#include "vtkReliefDisplacementFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLinearSubdivisionFilter.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkReliefDepthImage.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkTriangleFilter.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkReliefDisplacementFilter);

namespace
{
constexpr double MinimumEdgeTexels = 1e-3;

// The longest triangle edge of `mesh`, in texels of a width x height image.
double LongestEdgeInTexels(vtkPolyData* mesh, double width, double height)
{
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  auto texelAt = [&](vtkIdType id) {
    return glm::dvec2(tcoords->GetComponent(id, 0) * width, tcoords->GetComponent(id, 1) * height);
  };
  double longest = 0.0;
  auto triangles = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (triangles->GoToFirstCell(); !triangles->IsDoneWithTraversal(); triangles->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    triangles->GetCurrentCell(size, ids);
    for (vtkIdType corner = 0; corner < size; ++corner)
    {
      const double length = glm::length(texelAt(ids[(corner + 1) % size]) - texelAt(ids[corner]));
      longest = std::isfinite(length) ? std::max(longest, length) : longest;
    }
  }
  return longest;
}

// Moves every point inward along its unit normal by depthScale times the field's depth.
void Displace(vtkPolyData* mesh, const vtkReliefDepthImage& field, double depthScale)
{
  vtkPoints* points = mesh->GetPoints();
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  vtkSMPTools::For(0, mesh->GetNumberOfPoints(), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType id = begin; id < end; ++id)
    {
      double normal[3];
      normals->GetTuple(id, normal);
      const glm::dvec3 n(normal[0], normal[1], normal[2]);
      const double length = glm::length(n);
      if (!(length > 0.0) || !std::isfinite(length))
      {
        continue; // a point of degenerate triangles only: no direction to move it in
      }
      const double u = tcoords->GetComponent(id, 0);
      const double v = tcoords->GetComponent(id, 1);
      if (!std::isfinite(u) || !std::isfinite(v) || std::abs(u) > 1e6 || std::abs(v) > 1e6)
      {
        continue; // no texel to read: the point stays on the surface
      }
      const double depth = field.Interpolate(u, v);
      double point[3];
      points->GetPoint(id, point);
      const glm::dvec3 moved =
        glm::dvec3(point[0], point[1], point[2]) - n * (depth * depthScale / length);
      points->SetPoint(id, moved.x, moved.y, moved.z);
    }
  });
  points->Modified();
}
}

vtkReliefDisplacementFilter::vtkReliefDisplacementFilter()
{
  this->SetNumberOfInputPorts(2);
}

vtkReliefDisplacementFilter::~vtkReliefDisplacementFilter() = default;

void vtkReliefDisplacementFilter::SetReliefData(vtkImageData* image)
{
  this->SetInputData(1, image);
}

void vtkReliefDisplacementFilter::SetDepthScale(double depthScale)
{
  if (!std::isfinite(depthScale))
  {
    vtkWarningMacro("DepthScale " << depthScale << " is not a length; it stays "
                                  << this->DepthScale << ".");
    return;
  }
  if (depthScale < 0.0)
  {
    vtkWarningMacro("DepthScale " << depthScale << " is negative; using 0 (no displacement).");
    depthScale = 0.0;
  }
  if (depthScale != this->DepthScale)
  {
    this->DepthScale = depthScale;
    this->Modified();
  }
}

void vtkReliefDisplacementFilter::SetMaximumEdgeTexels(double texels)
{
  if (std::isnan(texels))
  {
    vtkWarningMacro("MaximumEdgeTexels is NaN, not a length; it stays "
                    << this->MaximumEdgeTexels << ".");
    return;
  }
  if (texels < MinimumEdgeTexels)
  {
    vtkWarningMacro("MaximumEdgeTexels " << texels << " is below " << MinimumEdgeTexels
                                         << " texel; using " << MinimumEdgeTexels << ".");
    texels = MinimumEdgeTexels;
  }
  if (texels != this->MaximumEdgeTexels)
  {
    this->MaximumEdgeTexels = texels;
    this->Modified();
  }
}

int vtkReliefDisplacementFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

int vtkReliefDisplacementFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkImageData* relief = vtkImageData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->SubdivisionLevels = 0;
  this->LongestEdgeTexels = 0.0;

  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    vtkErrorMacro("The mesh has no 2D point texture coordinates, so the relief has nowhere to "
                  "go; the output is the mesh unchanged. Map some first with "
                  "vtkTextureMapToPlane, vtkTextureMapToCylinder or vtkTextureMapToSphere.");
    output->ShallowCopy(input);
    return 1;
  }
  vtkReliefDepthImage field;
  std::string error;
  if (!field.Read(relief, error))
  {
    vtkErrorMacro("Cannot displace by the relief image: " << error
                                                         << "; the output is the mesh unchanged.");
    output->ShallowCopy(input);
    return 1;
  }

  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(input);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkSmartPointer<vtkPolyData> mesh = triangles->GetOutput();
  if (mesh->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The mesh has no polygons, so the relief has no surface to sink; the "
                  "output is the mesh unchanged. Give it polygons or triangle strips.");
    output->ShallowCopy(input);
    return 1;
  }
  if (!mesh->GetPointData()->GetNormals())
  {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(mesh);
    normals->SetFeatureAngle(30.0);
    normals->Update();
    mesh = normals->GetOutput();
  }
  this->UpdateProgress(0.1);

  const double longest = LongestEdgeInTexels(mesh, field.Width, field.Height);
  int levels = longest > this->MaximumEdgeTexels
    ? static_cast<int>(std::ceil(std::log2(longest / this->MaximumEdgeTexels)))
    : 0;
  const vtkIdType cells = mesh->GetNumberOfPolys();
  int affordable = 0;
  // compared by shifting the cap down, so that a cap near VTK_ID_MAX cannot overflow
  const vtkIdType cap = this->MaximumNumberOfTriangles;
  while (affordable < 30 && cells <= (cap >> (2 * (affordable + 1))))
  {
    ++affordable;
  }
  if (levels > affordable)
  {
    vtkWarningMacro("Subdividing until edges span " << this->MaximumEdgeTexels
                                                    << " texels would make more than "
                                                    << this->MaximumNumberOfTriangles
                                                    << " triangles; stopping at edges of "
                                                    << std::ldexp(longest, -affordable)
                                                    << " texels. Raise MaximumNumberOfTriangles "
                                                       "or MaximumEdgeTexels.");
    levels = affordable;
  }
  if (levels > 0)
  {
    vtkNew<vtkLinearSubdivisionFilter> subdivision;
    subdivision->SetInputData(mesh);
    subdivision->SetNumberOfSubdivisions(levels);
    subdivision->Update();
    mesh = subdivision->GetOutput();
  }
  this->SubdivisionLevels = levels;
  this->LongestEdgeTexels = std::ldexp(longest, -levels);
  this->UpdateProgress(0.6);

  // the triangle and subdivision filters may hand on the input's own points: move a copy
  auto moved = vtkSmartPointer<vtkPolyData>::New();
  moved->ShallowCopy(mesh);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->DeepCopy(mesh->GetPoints());
  moved->SetPoints(points);
  mesh = moved;
  Displace(mesh, field, this->DepthScale);
  this->UpdateProgress(0.8);

  // one surface now: no splitting, which would tear it along the relief's creases
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->ConsistencyOff();
  normals->Update();
  output->ShallowCopy(normals->GetOutput());
  return 1;
}

void vtkReliefDisplacementFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "MaximumEdgeTexels: " << this->MaximumEdgeTexels << "\n";
  os << indent << "MaximumNumberOfTriangles: " << this->MaximumNumberOfTriangles << "\n";
  os << indent << "SubdivisionLevels: " << this->SubdivisionLevels << "\n";
  os << indent << "LongestEdgeTexels: " << this->LongestEdgeTexels << "\n";
}
