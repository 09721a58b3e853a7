#include "vtkOpenGLQuadricReliefMapper.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkLocalQuadricFilter.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefSearchMethod.h"

#include "vtkReliefQuadricFrame.h"
#include "vtkReliefTangentBasis.h"
#include "vtkReliefTriangleGS.h"

#include "vtkActor.h"
#include "vtkOpenGLHelper.h"
#include "vtkProperty.h"
#include "vtkShader.h"
#include "vtkShaderProgram.h"

#include <algorithm>
#include <string>

vtkStandardNewMacro(vtkOpenGLQuadricReliefMapper);

namespace
{
constexpr const char* QuadricAttribute = "reliefQuadricMC";
constexpr const char* LiftAttribute = "reliefHullLiftMC";

// A point array of one number per point.
bool IsPointScalar(vtkAbstractArray* array, vtkPolyData* mesh)
{
  return vtkDataArray::SafeDownCast(array) && array->GetNumberOfComponents() == 1 &&
    array->GetNumberOfTuples() == mesh->GetNumberOfPoints();
}
}

vtkOpenGLQuadricReliefMapper::vtkOpenGLQuadricReliefMapper()
  : QuadricFilter(vtkLocalQuadricFilter::New())
{
  vtkReliefForwardMessages(this->QuadricFilter, this);
}

vtkOpenGLQuadricReliefMapper::~vtkOpenGLQuadricReliefMapper()
{
  this->QuadricFilter->Delete();
}

vtkLocalQuadricFilter* vtkOpenGLQuadricReliefMapper::GetLocalQuadricFilter()
{
  return this->QuadricFilter;
}

vtkPolyData* vtkOpenGLQuadricReliefMapper::GetReliefSurface()
{
  if (this->ComputesQuadrics)
  {
    return this->QuadricFilter->GetOutput();
  }
  // quadrics of the user's own: with the lifts computed for them, when they had none
  vtkPolyData* framed = this->Superclass::GetReliefSurface();
  return framed && framed == this->LiftedFrom ? this->LiftedSurface.GetPointer() : framed;
}

bool vtkOpenGLQuadricReliefMapper::HasUsableQuadrics(vtkPolyData* mesh)
{
  vtkAbstractArray* array =
    mesh->GetPointData()->GetAbstractArray(vtkLocalQuadricFilter::QuadricArrayName());
  if (!array)
  {
    return false;
  }
  if (vtkDataArray::SafeDownCast(array) && array->GetNumberOfComponents() == 2 &&
    array->GetNumberOfTuples() == mesh->GetNumberOfPoints())
  {
    return true;
  }
  if (this->WarnedQuadricsTime != mesh->GetMTime())
  {
    this->WarnedQuadricsTime = mesh->GetMTime();
    vtkWarningMacro("The mesh's \"" << vtkLocalQuadricFilter::QuadricArrayName() << "\" array is a "
                    << array->GetClassName() << " of " << array->GetNumberOfComponents()
                    << " component(s) and " << array->GetNumberOfTuples()
                    << " tuple(s), not 2 numbers for each of its " << mesh->GetNumberOfPoints()
                    << " points: computing the quadrics instead. Remove it, or give "
                       "vtkLocalQuadricFilter's output.");
  }
  return false;
}

bool vtkOpenGLQuadricReliefMapper::UpdateReliefSurface()
{
  this->ComputesQuadrics = !this->HasUsableQuadrics(this->CurrentInput);
  if (!this->ComputesQuadrics)
  {
    return this->Superclass::UpdateReliefSurface() && this->UpdateHullLifts();
  }
  // the quadric filter frames the mesh itself (vtkReliefTangentFrameFilter) and runs
  // again only when the mesh changes
  this->QuadricFilter->SetInputData(this->CurrentInput);
  this->QuadricFilter->Update();
  // without relief (no texture coordinates or polygons: the filter has said so) the mesh
  // is drawn plainly, as the filter passes it
  vtkPolyData* framed = this->QuadricFilter->GetOutput();
  this->CurrentInput = framed;
  return framed->GetPointData()->GetArray(vtkLocalQuadricFilter::QuadricArrayName()) != nullptr;
}

bool vtkOpenGLQuadricReliefMapper::UpdateHullLifts()
{
  vtkPolyData* framed = this->CurrentInput;
  if (IsPointScalar(
        framed->GetPointData()->GetAbstractArray(vtkLocalQuadricFilter::HullLiftArrayName()),
        framed))
  {
    this->LiftedFrom = nullptr;
    this->LiftedSurface->Initialize();
    return true;
  }
  // quadrics of the user's own, without their lifts: lift the hull off them
  if (this->LiftedFrom != framed || this->LiftedTime != framed->GetMTime())
  {
    this->LiftedFrom = framed;
    this->LiftedTime = framed->GetMTime();
    this->LiftedSurface->ShallowCopy(framed);
    auto lifts = vtk::TakeSmartPointer(vtkLocalQuadricFilter::NewHullLifts(framed));
    if (lifts)
    {
      this->LiftedSurface->GetPointData()->AddArray(lifts);
    }
  }
  this->CurrentInput = this->LiftedSurface;
  return true;
}

void vtkOpenGLQuadricReliefMapper::MapFrameAttributes(bool relief)
{
  this->Superclass::MapFrameAttributes(relief);
  this->MapReliefAttribute(
    QuadricAttribute, relief ? vtkLocalQuadricFilter::QuadricArrayName() : nullptr);
  this->MapReliefAttribute(
    LiftAttribute, relief ? vtkLocalQuadricFilter::HullLiftArrayName() : nullptr);
}

void vtkOpenGLQuadricReliefMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  if (this->DrawingRelief && cellBO.Program->IsUniformUsed("reliefHullClearance"))
  {
    cellBO.Program->SetUniformf(
      "reliefHullClearance", static_cast<float>(this->ReliefTopDepth * this->DrawnDepthScale));
  }
}

void vtkOpenGLQuadricReliefMapper::GetShaderTemplate(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::GetShaderTemplate(shaders, ren, actor);
  // the hull's height over the quadric surface takes each triangle's three corners: a
  // geometry shader, VTK's own where it draws edges
  if (this->DrawingRelief && this->LastBoundBO == &this->Primitives[PrimitiveTris] &&
    actor->GetProperty()->GetRepresentation() == VTK_SURFACE &&
    shaders[vtkShader::Geometry]->GetSource().empty())
  {
    shaders[vtkShader::Geometry]->SetSource(vtkReliefTriangleGS);
  }
}

const vtkReliefSearchMethod* vtkOpenGLQuadricReliefMapper::DescribeSearch(int method)
{
  return vtkReliefSearchMethod::GetForCurvedRays(method);
}

const char* vtkOpenGLQuadricReliefMapper::GetUnsupportedSearchReason()
{
  return "its cells, radii, cones or pyramid assume depth linear along a straight line in "
         "texture space, and below a quadric the ray's depth is quadratic.";
}

std::string vtkOpenGLQuadricReliefMapper::GetFrameSource()
{
  return std::string(vtkReliefTangentBasis) + vtkReliefQuadricFrame;
}

std::string vtkOpenGLQuadricReliefMapper::GetFrameDefines()
{
  // the view ray bends below the quadric (ReliefRay::bend)
  return std::string("#define RELIEF_CURVED_FRAME\n") +
    (this->DistanceMode == EXACT ? "#define RELIEF_EXACT_DISTANCE\n" : "");
}

void vtkOpenGLQuadricReliefMapper::SetDistanceMode(int mode)
{
  if (mode != APPROXIMATE && mode != EXACT)
  {
    vtkErrorMacro("Unknown distance mode " << mode
                                           << "; use SetDistanceModeToApproximate() or "
                                              "SetDistanceModeToExact().");
    return;
  }
  if (mode != this->DistanceMode)
  {
    this->DistanceMode = mode;
    this->ShaderOptionsTime.Modified();
    this->ModifiedShaderOptions();
  }
}

const char* vtkOpenGLQuadricReliefMapper::GetDistanceModeAsString()
{
  return this->DistanceMode == EXACT ? "Exact" : "Approximate";
}

void vtkOpenGLQuadricReliefMapper::CopyReliefSettings(vtkOpenGLReliefMapper* source)
{
  this->Superclass::CopyReliefSettings(source);
  if (auto* same = vtkOpenGLQuadricReliefMapper::SafeDownCast(source))
  {
    this->SetDistanceMode(same->DistanceMode);
    this->QuadricFilter->SetNeighbourhoodRings(same->QuadricFilter->GetNeighbourhoodRings());
  }
}

vtkMTimeType vtkOpenGLQuadricReliefMapper::GetReliefSettingsMTime()
{
  return std::max(this->Superclass::GetReliefSettingsMTime(), this->QuadricFilter->GetMTime());
}

void vtkOpenGLQuadricReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DistanceMode: " << this->GetDistanceModeAsString() << "\n";
  os << indent << "LocalQuadricFilter:\n";
  this->QuadricFilter->PrintSelf(os, indent.GetNextIndent());
}
