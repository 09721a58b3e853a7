#include "vtkReliefSurfaceFilter.h"

#include "vtkBoundingBox.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReliefCoincidentPoints.h"
#include "vtkTriangleFilter.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkReliefSurfaceFilter);

namespace
{
// True when the mesh holds triangles and nothing else (no vertices, lines or strips).
bool IsTrianglesOnly(vtkPolyData* mesh)
{
  if (mesh->GetNumberOfStrips() > 0 || mesh->GetNumberOfVerts() > 0 ||
    mesh->GetNumberOfLines() > 0)
  {
    return false;
  }
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    polys->GetCurrentCell(size, ids);
    if (size != 3)
    {
      return false;
    }
  }
  return true;
}

// The array itself when it has a name, else a named copy.
vtkSmartPointer<vtkDataArray> Named(vtkDataArray* array, const char* name)
{
  if (array->GetName())
  {
    return array;
  }
  auto named = vtk::TakeSmartPointer(array->NewInstance());
  named->DeepCopy(array);
  named->SetName(name);
  return named;
}
}

bool vtkReliefSurfaceFilter::IsClosed(vtkPolyData* mesh)
{
  if (!mesh || mesh->GetNumberOfPolys() == 0)
  {
    return false;
  }
  const std::vector<vtkIdType> canonical = vtkReliefCoincidentPoints(mesh);
  if (canonical.empty())
  {
    return false;
  }
  // per undirected edge: runs from its lower id (low 32 bits) and from its higher id
  constexpr std::uint64_t Backward = std::uint64_t(1) << 32;
  std::unordered_map<std::uint64_t, std::uint64_t> runs;
  const std::uint64_t stride = static_cast<std::uint64_t>(canonical.size());
  double volume = 0.0;
  double centre[3];
  mesh->GetPoint(0, centre);
  std::vector<vtkIdType> corners;
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    polys->GetCurrentCell(size, ids);
    corners.clear();
    for (vtkIdType k = 0; k < size; ++k)
    {
      corners.push_back(canonical[ids[k]]);
    }
    std::vector<vtkIdType> sorted = corners;
    std::sort(sorted.begin(), sorted.end());
    if (size < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    {
      continue; // degenerate: no area, no side
    }
    for (vtkIdType k = 0; k < size; ++k)
    {
      const vtkIdType from = corners[k];
      const vtkIdType to = corners[(k + 1) % size];
      const std::uint64_t low = static_cast<std::uint64_t>(std::min(from, to));
      const std::uint64_t high = static_cast<std::uint64_t>(std::max(from, to));
      runs[low * stride + high] += from < to ? 1 : Backward;
    }
    // the polygon's fan, as tetrahedra with the mesh's first point: an apex on the mesh
    // keeps the sign of a small mesh far from the origin
    double corner[3], a[3], b[3];
    mesh->GetPoint(corners[0], corner);
    vtkMath::Subtract(corner, centre, corner);
    for (vtkIdType k = 1; k + 1 < size; ++k)
    {
      mesh->GetPoint(corners[k], a);
      mesh->GetPoint(corners[k + 1], b);
      vtkMath::Subtract(a, centre, a);
      vtkMath::Subtract(b, centre, b);
      double across[3];
      vtkMath::Cross(a, b, across);
      volume += vtkMath::Dot(corner, across);
    }
  }
  if (runs.empty() || !(volume > 0.0))
  {
    return false;
  }
  for (const auto& edge : runs)
  {
    if (edge.second != 1 + Backward)
    {
      return false;
    }
  }
  return true;
}

vtkReliefSurfaceFilter::vtkReliefSurfaceFilter() = default;
vtkReliefSurfaceFilter::~vtkReliefSurfaceFilter() = default;

namespace
{
// Whether a cell names a point id outside [0, points).
bool NamesMissingPoint(vtkIdType size, const vtkIdType* ids, vtkIdType points)
{
  return std::any_of(ids, ids + size, [points](vtkIdType id) { return id < 0 || id >= points; });
}

// Whether a cell of `cells` names a point id outside [0, points).
bool RefersOutside(vtkCellArray* cells, vtkIdType points)
{
  auto iterator = vtk::TakeSmartPointer(cells->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    iterator->GetCurrentCell(size, ids);
    if (NamesMissingPoint(size, ids, points))
    {
      return true;
    }
  }
  return false;
}

}

vtkSmartPointer<vtkPolyData> vtkReliefSurfaceFilter::LeaveOutCells(vtkPolyData* mesh,
  const std::function<bool(vtkIdType, const vtkIdType*)>& leave, vtkIdType& left)
{
  // vtkPolyData numbers its cells verts, lines, polys, strips: the cell data follows
  vtkCellData* cellData = mesh->GetCellData();
  vtkNew<vtkCellData> keptData;
  keptData->CopyAllocate(cellData, mesh->GetNumberOfCells());
  vtkCellArray* all[4] = { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(),
    mesh->GetStrips() };
  vtkSmartPointer<vtkCellArray> kept[4];
  vtkIdType cell = 0;
  vtkIdType keptCells = 0;
  for (int kind = 0; kind < 4; ++kind)
  {
    kept[kind] = vtkSmartPointer<vtkCellArray>::New();
    auto iterator = vtk::TakeSmartPointer(all[kind]->NewIterator());
    for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
    {
      vtkIdType size;
      const vtkIdType* ids;
      iterator->GetCurrentCell(size, ids);
      if (leave(size, ids))
      {
        ++left;
      }
      else
      {
        kept[kind]->InsertNextCell(size, ids);
        keptData->CopyData(cellData, cell, keptCells++);
      }
      ++cell;
    }
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->SetPoints(mesh->GetPoints());
  result->GetPointData()->ShallowCopy(mesh->GetPointData());
  result->GetFieldData()->ShallowCopy(mesh->GetFieldData());
  result->SetVerts(kept[0]);
  result->SetLines(kept[1]);
  result->SetPolys(kept[2]);
  result->SetStrips(kept[3]);
  result->GetCellData()->ShallowCopy(keptData);
  return result;
}

bool vtkReliefSurfaceFilter::RefersToMissingPoints(vtkPolyData* mesh)
{
  const vtkIdType points = mesh->GetNumberOfPoints();
  return RefersOutside(mesh->GetVerts(), points) || RefersOutside(mesh->GetLines(), points) ||
    RefersOutside(mesh->GetPolys(), points) || RefersOutside(mesh->GetStrips(), points);
}

vtkSmartPointer<vtkPolyData> vtkReliefSurfaceFilter::LeaveOutCellsWithMissingPoints(
  vtkPolyData* mesh)
{
  if (!RefersToMissingPoints(mesh))
  {
    return mesh;
  }
  const vtkIdType points = mesh->GetNumberOfPoints();
  vtkIdType left = 0;
  auto result = LeaveOutCells(
    mesh,
    [points](vtkIdType size, const vtkIdType* ids) { return NamesMissingPoint(size, ids, points); },
    left);
  vtkErrorMacro("The mesh is broken: " << left << " of its cells refer to points it does not "
                                       << "have (it has " << points
                                       << "); they are left out. Check the file or the filter "
                                          "that made it.");
  return result;
}

vtkSmartPointer<vtkPolyData> vtkReliefSurfaceFilter::ExtractTriangles(vtkPolyData* mesh)
{
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    vtkErrorMacro("The mesh has no 2D point texture coordinates, so relief has nowhere to go "
                  "and the mesh is drawn without it. Map some first with vtkTextureMapToPlane, "
                  "vtkTextureMapToCylinder or vtkTextureMapToSphere.");
    return nullptr;
  }
  if (tcoords->GetNumberOfTuples() < mesh->GetNumberOfPoints())
  {
    vtkErrorMacro("The mesh's texture coordinates cover " << tcoords->GetNumberOfTuples()
                  << " of its " << mesh->GetNumberOfPoints()
                  << " points, so the mesh is drawn without relief. Give one pair a point.");
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> triangles = mesh;
  if (!IsTrianglesOnly(triangles))
  {
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->SetInputData(triangles);
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->Update();
    triangles = triangulate->GetOutput();
  }
  triangles = this->LeaveOutNonFinitePoints(triangles);
  if (triangles->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The mesh has no polygons: relief is drawn on polygons only. Give a "
                  "surface (vtkGeometryFilter extracts one from other datasets).");
    return nullptr;
  }
  this->ReportNonFiniteTextureCoordinates(triangles);
  this->ReportTextureCoordinatesWithoutArea(triangles);
  return this->WithUsableNormals(triangles);
}

bool vtkReliefSurfaceFilter::HasDirection(vtkDataArray* normals, vtkIdType point)
{
  double normal[3];
  normals->GetTuple(point, normal);
  const double length = vtkMath::Norm(normal);
  return std::isfinite(length) && length > 0.0;
}

vtkSmartPointer<vtkPolyData> vtkReliefSurfaceFilter::WithUsableNormals(vtkPolyData* mesh)
{
  vtkPointData* pointData = mesh->GetPointData();
  vtkDataArray* normals = pointData->GetNormals();
  vtkDataArray* tangents = pointData->GetTangents();
  const vtkIdType points = mesh->GetNumberOfPoints();
  auto tooShort = [points](vtkDataArray* array) {
    return array && (array->GetNumberOfTuples() < points || array->GetNumberOfComponents() < 3);
  };
  if (tooShort(normals) || tooShort(tangents))
  {
    vtkWarningMacro("The mesh's " << (tooShort(normals) ? "normals" : "tangents")
                                  << " do not give three numbers for each of its " << points
                                  << " points: they are left out, and computed where needed.");
    auto result = vtkSmartPointer<vtkPolyData>::New();
    result->ShallowCopy(mesh);
    if (tooShort(normals))
    {
      result->GetPointData()->SetNormals(nullptr);
    }
    if (tooShort(tangents))
    {
      result->GetPointData()->SetTangents(nullptr);
    }
    return result;
  }
  if (!normals)
  {
    return mesh;
  }
  vtkIdType count = 0;
  vtkIdType first = -1;
  for (vtkIdType point = 0; point < points; ++point)
  {
    if (!HasDirection(normals, point))
    {
      first = count++ == 0 ? point : first;
    }
  }
  if (count > 0)
  {
    vtkWarningMacro(<< count << " of the mesh's " << points << " points (the first: point "
                    << first
                    << ") have normals without a direction (zero or not finite): the surface's "
                       "own normal is used there. Give unit normals, or none to have them "
                       "computed.");
  }
  return mesh;
}

bool vtkReliefSurfaceFilter::GetFiniteBounds(vtkPolyData* mesh, double bounds[6])
{
  vtkBoundingBox box;
  for (vtkIdType point = 0; point < mesh->GetNumberOfPoints(); ++point)
  {
    double position[3];
    mesh->GetPoint(point, position);
    if (std::isfinite(position[0]) && std::isfinite(position[1]) && std::isfinite(position[2]))
    {
      box.AddPoint(position);
    }
  }
  if (!box.IsValid())
  {
    vtkMath::UninitializeBounds(bounds);
    return false;
  }
  box.GetBounds(bounds);
  return true;
}

vtkSmartPointer<vtkPolyData> vtkReliefSurfaceFilter::LeaveOutNonFinitePoints(vtkPolyData* mesh)
{
  auto isFinite = [](const double* p) {
    return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
  };
  vtkIdType count = 0;
  vtkIdType first = -1;
  vtkIdType finite = -1;
  for (vtkIdType point = 0; point < mesh->GetNumberOfPoints(); ++point)
  {
    if (!isFinite(mesh->GetPoint(point)))
    {
      first = count++ == 0 ? point : first;
    }
    else if (finite < 0)
    {
      finite = point;
    }
  }
  if (count == 0)
  {
    return mesh;
  }
  vtkWarningMacro(<< count << " of the mesh's " << mesh->GetNumberOfPoints()
                  << " points (the first: point " << first
                  << ") are not finite: the triangles that use them are left out. Fix or remove "
                     "those points.");
  // The points stay, with their data, so that bounds and buffers stay finite: moved next
  // to a finite point, 1e-6 of the finite points' size away, not onto it (the filters
  // take coincident points as one, see vtkReliefCoincidentPoints). Their triangles go.
  double finiteBounds[6];
  const double size = GetFiniteBounds(mesh, finiteBounds)
    ? vtkBoundingBox(finiteBounds).GetDiagonalLength()
    : 0.0;
  double stand[3] = { 0.0, 0.0, 0.0 };
  if (finite >= 0)
  {
    mesh->GetPoint(finite, stand);
  }
  stand[0] += size > 0.0 ? 1e-6 * size : 1e-6;
  vtkIdType left = 0;
  auto result = LeaveOutCells(
    mesh,
    [mesh, &isFinite](vtkIdType size, const vtkIdType* ids) {
      return std::any_of(
        ids, ids + size, [mesh, &isFinite](vtkIdType id) { return !isFinite(mesh->GetPoint(id)); });
    },
    left);
  vtkNew<vtkPoints> points;
  points->DeepCopy(mesh->GetPoints());
  for (vtkIdType point = 0; point < points->GetNumberOfPoints(); ++point)
  {
    if (!isFinite(points->GetPoint(point)))
    {
      points->SetPoint(point, stand);
    }
  }
  result->SetPoints(points);
  return result;
}

bool vtkReliefSurfaceFilter::HasFiniteTextureCoordinates(vtkDataArray* tcoords, vtkIdType point)
{
  return std::isfinite(tcoords->GetComponent(point, 0)) &&
    std::isfinite(tcoords->GetComponent(point, 1));
}

void vtkReliefSurfaceFilter::ReportNonFiniteTextureCoordinates(vtkPolyData* mesh)
{
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  vtkIdType count = 0;
  vtkIdType first = -1;
  for (vtkIdType point = 0; point < tcoords->GetNumberOfTuples(); ++point)
  {
    if (!HasFiniteTextureCoordinates(tcoords, point))
    {
      first = count++ == 0 ? point : first;
    }
  }
  if (count > 0)
  {
    vtkWarningMacro(<< count << " of the mesh's " << tcoords->GetNumberOfTuples()
                    << " points (the first: point " << first
                    << ") have texture coordinates that are not finite: the triangles around "
                       "them are drawn without relief. Give every point finite texture "
                       "coordinates (vtkTextureMapToPlane, vtkTextureMapToCylinder or "
                       "vtkTextureMapToSphere map new ones).");
  }
}

bool vtkReliefSurfaceFilter::MapsTextureArea(vtkDataArray* tcoords, const vtkIdType ids[3])
{
  double corner[3][2];
  for (int k = 0; k < 3; ++k)
  {
    corner[k][0] = tcoords->GetComponent(ids[k], 0);
    corner[k][1] = tcoords->GetComponent(ids[k], 1);
  }
  const double edge1[2] = { corner[1][0] - corner[0][0], corner[1][1] - corner[0][1] };
  const double edge2[2] = { corner[2][0] - corner[0][0], corner[2][1] - corner[0][1] };
  const double twiceArea = std::abs(edge1[0] * edge2[1] - edge1[1] * edge2[0]);
  const double scale = std::max(edge1[0] * edge1[0] + edge1[1] * edge1[1],
    edge2[0] * edge2[0] + edge2[1] * edge2[1]);
  // the shader's test on the pixel's derivatives (vtkReliefFragmentImpl.glsl), on the corners
  return twiceArea > 1e-6 * scale; // false for NaN too
}

void vtkReliefSurfaceFilter::ReportTextureCoordinatesWithoutArea(vtkPolyData* triangles)
{
  vtkDataArray* tcoords = triangles->GetPointData()->GetTCoords();
  vtkCellArray* polys = triangles->GetPolys();
  vtkIdType count = 0;
  vtkIdType first = -1;
  vtkIdType size = 0;
  const vtkIdType* ids = nullptr;
  auto iterator = vtk::TakeSmartPointer(polys->NewIterator());
  for (iterator->GoToFirstCell(); !iterator->IsDoneWithTraversal(); iterator->GoToNextCell())
  {
    iterator->GetCurrentCell(size, ids);
    // corners that are not finite are ReportNonFiniteTextureCoordinates' to report
    const bool finite = size == 3 && HasFiniteTextureCoordinates(tcoords, ids[0]) &&
      HasFiniteTextureCoordinates(tcoords, ids[1]) && HasFiniteTextureCoordinates(tcoords, ids[2]);
    if (finite && !MapsTextureArea(tcoords, ids))
    {
      first = count++ == 0 ? iterator->GetCurrentCellId() : first;
    }
  }
  if (count > 0)
  {
    vtkWarningMacro(<< count << " of the mesh's " << polys->GetNumberOfCells()
                    << " triangles (the first: triangle " << first
                    << ") have texture coordinates without area (their points share one "
                       "(u, v), or lie on a line): relief has no direction there, and they are "
                       "drawn without it. Map texture coordinates over them "
                       "(vtkTextureMapToPlane, vtkTextureMapToCylinder or vtkTextureMapToSphere).");
  }
}

void vtkReliefSurfaceFilter::NameAttributes(vtkPolyData* output)
{
  vtkPointData* pointData = output->GetPointData();
  pointData->SetTCoords(Named(pointData->GetTCoords(), "TCoords"));
  if (pointData->GetNormals())
  {
    pointData->SetNormals(Named(pointData->GetNormals(), "Normals"));
  }
}

int vtkReliefSurfaceFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  // without a surface the output is the mesh drawn plainly: its broken cells left out too
  vtkSmartPointer<vtkPolyData> mesh = this->LeaveOutCellsWithMissingPoints(input);
  vtkSmartPointer<vtkPolyData> triangles = this->ExtractTriangles(mesh);
  this->HasSurface = triangles != nullptr;
  output->ShallowCopy(this->HasSurface ? triangles.Get() : mesh.Get());
  if (this->HasSurface)
  {
    NameAttributes(output);
  }
  return 1;
}

void vtkReliefSurfaceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "HasSurface: " << this->HasSurface << "\n";
}
