#include "vtkReliefSurfaceFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTriangleFilter.h"

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

vtkReliefSurfaceFilter::vtkReliefSurfaceFilter() = default;
vtkReliefSurfaceFilter::~vtkReliefSurfaceFilter() = default;

vtkSmartPointer<vtkPolyData> vtkReliefSurfaceFilter::ExtractTriangles(vtkPolyData* input)
{
  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    vtkErrorMacro("The mesh has no 2D point texture coordinates, so relief has nowhere to go "
                  "and the mesh is drawn without it. Map some first with vtkTextureMapToPlane, "
                  "vtkTextureMapToCylinder or vtkTextureMapToSphere.");
    return nullptr;
  }
  vtkSmartPointer<vtkPolyData> mesh = input;
  if (!IsTrianglesOnly(mesh))
  {
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->SetInputData(mesh);
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->Update();
    mesh = triangulate->GetOutput();
  }
  if (mesh->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("The mesh has no polygons: relief is drawn on polygons only. Give a "
                  "surface (vtkGeometryFilter extracts one from other datasets).");
    return nullptr;
  }
  return mesh;
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
  vtkSmartPointer<vtkPolyData> triangles = this->ExtractTriangles(input);
  this->HasSurface = triangles != nullptr;
  output->ShallowCopy(this->HasSurface ? triangles.Get() : input);
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
