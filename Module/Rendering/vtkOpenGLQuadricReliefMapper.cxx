#include "vtkOpenGLQuadricReliefMapper.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkLocalQuadricFilter.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefSearchMethod.h"

#include "vtkReliefQuadricFrame.h"
#include "vtkReliefTangentBasis.h"

vtkStandardNewMacro(vtkOpenGLQuadricReliefMapper);

namespace
{
constexpr const char* QuadricAttribute = "reliefQuadricMC";
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
  return this->ComputesQuadrics ? this->QuadricFilter->GetOutput()
                                : this->Superclass::GetReliefSurface();
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
    return this->Superclass::UpdateReliefSurface();
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

void vtkOpenGLQuadricReliefMapper::MapFrameAttributes(bool relief)
{
  this->Superclass::MapFrameAttributes(relief);
  this->MapReliefAttribute(
    QuadricAttribute, relief ? vtkLocalQuadricFilter::QuadricArrayName() : nullptr);
}

bool vtkOpenGLQuadricReliefMapper::SupportsSearchMethod(const vtkReliefSearchMethod& method)
{
  return method.FollowsCurvedRays;
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
  return this->DistanceMode == EXACT ? "#define RELIEF_EXACT_DISTANCE\n" : "";
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

void vtkOpenGLQuadricReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DistanceMode: " << this->GetDistanceModeAsString() << "\n";
  os << indent << "LocalQuadricFilter:\n";
  this->QuadricFilter->PrintSelf(os, indent.GetNextIndent());
}
