#include "vtkOpenGLDerivativeReliefMapper.h"

#include "vtkDataArray.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefSurfaceFilter.h"

vtkStandardNewMacro(vtkOpenGLDerivativeReliefMapper);

vtkOpenGLDerivativeReliefMapper::vtkOpenGLDerivativeReliefMapper()
{
  vtkReliefForwardMessages(this->Surface, this);
  vtkReliefForwardMessages(this->Normals, this);
  this->Normals->SetInputConnection(this->Surface->GetOutputPort());
  this->Normals->SplittingOff();
  this->Normals->ComputeCellNormalsOff();
}

vtkOpenGLDerivativeReliefMapper::~vtkOpenGLDerivativeReliefMapper() = default;

vtkPolyData* vtkOpenGLDerivativeReliefMapper::GetReliefSurface()
{
  vtkPolyData* surface = this->Surface->GetOutput();
  const bool computed = this->ComputeNormals && !surface->GetPointData()->GetNormals();
  return computed ? this->Normals->GetOutput() : surface;
}

void vtkOpenGLDerivativeReliefMapper::SetComputeNormals(bool compute)
{
  if (compute != this->ComputeNormals)
  {
    this->ComputeNormals = compute;
    this->Modified();
  }
}

bool vtkOpenGLDerivativeReliefMapper::UpdateReliefSurface()
{
  this->Surface->SetInputData(this->CurrentInput);
  this->Surface->Update();
  if (!this->Surface->GetHasSurface())
  {
    return false; // the filter has said why, once per change of the mesh
  }
  this->CurrentInput = this->GetReliefSurface();
  if (this->CurrentInput == this->Normals->GetOutput())
  {
    this->Normals->Update(); // once per change of the mesh
  }
  const bool vertexNormals = this->CurrentInput->GetPointData()->GetNormals() != nullptr;
  if (vertexNormals != this->VertexNormals)
  {
    this->VertexNormals = vertexNormals;
    this->ShaderOptionsTime.Modified();
  }
  return true;
}

void vtkOpenGLDerivativeReliefMapper::MapReliefAttributes(bool relief)
{
  vtkPointData* pointData = this->CurrentInput->GetPointData();
  this->MapReliefAttribute(TCoordAttribute, relief ? pointData->GetTCoords()->GetName() : nullptr);
  this->MapReliefAttribute(NormalAttribute,
    relief && this->VertexNormals ? pointData->GetNormals()->GetName() : nullptr);
  // the tangent frame's inputs stay unbound: this frame never reads them
  this->MapReliefAttribute(TangentAttribute, nullptr);
  this->MapReliefAttribute(TextureScaleAttribute, nullptr);
}

std::string vtkOpenGLDerivativeReliefMapper::GetFrameDefines()
{
  return this->VertexNormals ? "#define RELIEF_DERIVATIVE_FRAME\n#define RELIEF_VERTEX_NORMALS\n"
                             : "#define RELIEF_DERIVATIVE_FRAME\n";
}

void vtkOpenGLDerivativeReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ComputeNormals: " << this->ComputeNormals << "\n";
  os << indent << "VertexNormals: " << this->VertexNormals << "\n";
  os << indent << "Surface:\n";
  this->Surface->PrintSelf(os, indent.GetNextIndent());
}
