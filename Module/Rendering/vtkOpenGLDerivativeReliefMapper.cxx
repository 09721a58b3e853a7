#include "vtkOpenGLDerivativeReliefMapper.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefSurfaceFilter.h"

#include "vtkReliefDerivativeFrame.h"
#include "vtkReliefFlatFrame.h"

vtkStandardNewMacro(vtkOpenGLDerivativeReliefMapper);

vtkOpenGLDerivativeReliefMapper::vtkOpenGLDerivativeReliefMapper()
{
  vtkReliefForwardMessages(this->SurfaceFilter, this);
  vtkReliefForwardMessages(this->NormalsFilter, this);
  this->NormalsFilter->SetInputConnection(this->SurfaceFilter->GetOutputPort());
  this->NormalsFilter->SplittingOff();
  this->NormalsFilter->ComputeCellNormalsOff();
}

vtkOpenGLDerivativeReliefMapper::~vtkOpenGLDerivativeReliefMapper() = default;

vtkPolyData* vtkOpenGLDerivativeReliefMapper::GetReliefSurface()
{
  return this->DrawnSurface ? this->DrawnSurface.Get() : this->SurfaceFilter->GetOutput();
}

bool vtkOpenGLDerivativeReliefMapper::UpdateReliefSurface()
{
  this->SurfaceFilter->SetInputData(this->CurrentInput);
  this->SurfaceFilter->Update();
  if (!this->SurfaceFilter->GetHasSurface())
  {
    // the filter has said why, once per change of the mesh; drawn plainly as it passes it
    this->CurrentInput = this->SurfaceFilter->GetOutput();
    return false;
  }
  vtkPolyData* surface = this->SurfaceFilter->GetOutput();
  this->DrawnSurface = surface;
  if (this->ComputeNormals && !surface->GetPointData()->GetNormals())
  {
    this->DrawnSurface = this->WithComputedNormals(surface);
  }
  this->CurrentInput = this->DrawnSurface;
  const bool vertexNormals = this->CurrentInput->GetPointData()->GetNormals() != nullptr;
  if (vertexNormals != this->HasVertexNormals)
  {
    this->HasVertexNormals = vertexNormals;
    this->ShaderOptionsTime.Modified();
  }
  return true;
}

vtkPolyData* vtkOpenGLDerivativeReliefMapper::WithComputedNormals(vtkPolyData* surface)
{
  // vtkPolyDataNormals orders the windings consistently to average across edges; only
  // its normals are taken, so the triangles drawn (and culled) stay the mesh's own
  this->NormalsFilter->Update(); // runs once per change of the mesh
  vtkPolyData* normals = this->NormalsFilter->GetOutput();
  if (this->NormalsSurface->GetMTime() < normals->GetMTime() ||
    this->NormalsSurface->GetMTime() < surface->GetMTime())
  {
    this->NormalsSurface->ShallowCopy(surface);
    this->NormalsSurface->GetPointData()->SetNormals(normals->GetPointData()->GetNormals());
  }
  return this->NormalsSurface;
}

void vtkOpenGLDerivativeReliefMapper::MapFrameAttributes(bool relief)
{
  vtkPointData* pointData = this->CurrentInput->GetPointData();
  this->MapReliefAttribute(NormalAttribute,
    relief && this->HasVertexNormals ? pointData->GetNormals()->GetName() : nullptr);
}

std::string vtkOpenGLDerivativeReliefMapper::GetFrameSource()
{
  return std::string(vtkReliefFlatFrame) + vtkReliefDerivativeFrame;
}

std::string vtkOpenGLDerivativeReliefMapper::GetFrameDefines()
{
  return this->HasVertexNormals ? "#define RELIEF_VERTEX_NORMALS\n" : "";
}

void vtkOpenGLDerivativeReliefMapper::CopyReliefSettings(vtkOpenGLReliefMapper* source)
{
  this->Superclass::CopyReliefSettings(source);
  if (auto* same = vtkOpenGLDerivativeReliefMapper::SafeDownCast(source))
  {
    this->SetComputeNormals(same->ComputeNormals);
  }
}

void vtkOpenGLDerivativeReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ComputeNormals: " << this->ComputeNormals << "\n";
  os << indent << "HasVertexNormals: " << this->HasVertexNormals << "\n";
  os << indent << "SurfaceFilter:\n";
  this->SurfaceFilter->PrintSelf(os, indent.GetNextIndent());
  os << indent << "NormalsFilter:\n";
  this->NormalsFilter->PrintSelf(os, indent.GetNextIndent());
}
