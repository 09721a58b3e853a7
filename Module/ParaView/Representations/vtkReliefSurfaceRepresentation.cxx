#include "vtkReliefSurfaceRepresentation.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCompositeReliefMapper.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLDerivativeReliefMapper.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkPVView.h"
#include "vtkReliefTextureFilter.h"
#include "vtkTexture.h"

vtkStandardNewMacro(vtkReliefSurfaceRepresentation);

vtkReliefSurfaceRepresentation::vtkReliefSurfaceRepresentation()
{
  // Surface's mapper replaced; its level-of-detail mapper (decimated, plain) kept
  this->Mapper->Delete();
  this->Mapper = vtkCompositeReliefMapper::New();
  this->SetupDefaults();
}

vtkReliefSurfaceRepresentation::~vtkReliefSurfaceRepresentation() = default;

vtkCompositeReliefMapper* vtkReliefSurfaceRepresentation::GetReliefMapper()
{
  return static_cast<vtkCompositeReliefMapper*>(this->Mapper);
}

void vtkReliefSurfaceRepresentation::SetReliefFrame(int frame)
{
  if (frame < TANGENT || frame > DERIVATIVE)
  {
    vtkErrorMacro("Unknown relief frame " << frame
                                          << "; use 0 (tangent), 1 (quadric) or 2 (derivative).");
    return;
  }
  if (frame == this->ReliefFrame)
  {
    return;
  }
  vtkSmartPointer<vtkOpenGLReliefMapper> mapper;
  switch (frame)
  {
    case QUADRIC:
      mapper = vtkSmartPointer<vtkOpenGLQuadricReliefMapper>::New();
      break;
    case DERIVATIVE:
      mapper = vtkSmartPointer<vtkOpenGLDerivativeReliefMapper>::New();
      break;
    default:
      mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
  }
  mapper->CopyReliefSettings(this->GetReliefMapper()->GetReliefMapper());
  this->GetReliefMapper()->SetReliefMapper(mapper);
  this->ReliefFrame = frame;
  this->Modified();
}

void vtkReliefSurfaceRepresentation::SetReliefHeightMap(vtkTexture* texture)
{
  if (texture != this->HeightMap)
  {
    this->HeightMap = texture;
    this->ConnectHeightMap();
    this->Modified();
  }
}

void vtkReliefSurfaceRepresentation::ConnectHeightMap()
{
  vtkTexture* texture = this->HeightMap;
  vtkAlgorithmOutput* heights = texture && texture->GetNumberOfInputConnections(0)
    ? texture->GetInputConnection(0, 0)
    : nullptr;
  vtkOpenGLReliefMapper* prototype = this->GetReliefMapper()->GetReliefMapper();
  vtkAlgorithmOutput* current =
    prototype->GetNumberOfInputConnections(1) ? prototype->GetInputConnection(1, 0) : nullptr;
  if (heights != current)
  {
    prototype->SetHeightMapConnection(heights);
  }
}

void vtkReliefSurfaceRepresentation::SetArrayIdNames(const char*, const char*) {}

int vtkReliefSurfaceRepresentation::ProcessViewRequest(vtkInformationRequestKey* request,
  vtkInformation* inputInformation, vtkInformation* outputInformation)
{
  if (request == vtkPVView::REQUEST_RENDER())
  {
    this->ConnectHeightMap();
  }
  return this->Superclass::ProcessViewRequest(request, inputInformation, outputInformation);
}

vtkTexture* vtkReliefSurfaceRepresentation::GetReliefHeightMap()
{
  return this->HeightMap;
}

void vtkReliefSurfaceRepresentation::SetReliefDepthScale(double depth)
{
  this->GetReliefMapper()->GetReliefMapper()->SetDepthScale(depth);
}

void vtkReliefSurfaceRepresentation::SetReliefSearchMethod(int method)
{
  this->GetReliefMapper()->GetReliefMapper()->SetSearchMethod(method);
}

void vtkReliefSurfaceRepresentation::SetReliefScreenTolerance(double pixels)
{
  this->GetReliefMapper()->GetReliefMapper()->SetScreenTolerance(pixels);
}

void vtkReliefSurfaceRepresentation::SetReliefAutomaticAcceleration(int method)
{
  this->GetReliefMapper()->GetReliefMapper()->SetAutomaticAcceleration(method);
}

void vtkReliefSurfaceRepresentation::SetReliefSafetyRadiusTolerance(double tolerance)
{
  this->GetReliefMapper()->GetReliefMapper()->SetSafetyRadiusTolerance(tolerance);
}

void vtkReliefSurfaceRepresentation::SetReliefSelfShadowing(bool enabled)
{
  this->GetReliefMapper()->GetReliefMapper()->SetSelfShadowing(enabled);
}

void vtkReliefSurfaceRepresentation::SetReliefHeightConvention(int convention)
{
  this->GetReliefMapper()->GetReliefMapper()->GetReliefTextureFilter()->SetInputConvention(
    convention);
}

void vtkReliefSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReliefFrame: " << this->ReliefFrame << "\n";
  os << indent << "ReliefHeightMap: " << this->HeightMap.Get() << "\n";
  os << indent << "ReliefMapper:\n";
  this->GetReliefMapper()->PrintSelf(os, indent.GetNextIndent());
}
