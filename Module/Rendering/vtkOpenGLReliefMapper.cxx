#include "vtkOpenGLReliefMapper.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLReliefTextures.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefSearchMethod.h"
#include "vtkReliefShaderRewrites.h"
#include "vtkReliefSurfaceFilter.h"
#include "vtkReliefTangentFrameFilter.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtk_glew.h"

#include "vtkReliefCommon.h"
#include "vtkReliefAutomaticSearch.h"
#include "vtkReliefConeSearch.h"
#include "vtkReliefFlatFrame.h"
#include "vtkReliefFragmentDec.h"
#include "vtkReliefFragmentImpl.h"
#include "vtkReliefGeometryDec.h"
#include "vtkReliefGeometryImpl.h"
#include "vtkReliefGridSearch.h"
#include "vtkReliefSafetySearch.h"
#include "vtkReliefSlopeSearch.h"
#include "vtkReliefSearch.h"
#include "vtkReliefTangentBasis.h"
#include "vtkReliefTangentFrame.h"
#include "vtkReliefVertexDec.h"
#include "vtkReliefVertexImpl.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkOpenGLReliefMapper);

namespace
{
constexpr int MinimumLinearSteps = 1;
constexpr int MaximumLinearSteps = 512;
constexpr double MaximumScreenTolerance = 100.0;
constexpr int MaximumBinarySteps = 32;

// Upper-left 3x3 of a VTK key matrix (stored transposed, ready for OpenGL).
void UpperLeft(vtkMatrix4x4* matrix, vtkMatrix3x3* result)
{
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      result->SetElement(row, column, matrix->GetElement(row, column));
    }
  }
}
}

vtkOpenGLReliefMapper::vtkOpenGLReliefMapper()
{
  this->SetNumberOfInputPorts(3);
  // The internal filters' and the helper's errors and warnings are the mapper's.
  vtkReliefForwardMessages(this->ReliefTextureFilter, this);
  this->Textures->SetOwner(this);
}

vtkOpenGLReliefMapper::~vtkOpenGLReliefMapper() = default;

int vtkOpenGLReliefMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1 || port == 2)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

void vtkOpenGLReliefMapper::ComputeBounds()
{
  vtkPolyData* input = this->GetInput();
  // VTK takes the bounds of the points that cells use, and reads past the points of a
  // broken mesh whose cells refer to points it does not have
  if (input && (input != this->CheckedInput || input->GetMTime() != this->CheckedInputTime))
  {
    this->CheckedInput = input;
    this->CheckedInputTime = input->GetMTime();
    this->InputRefersToMissingPoints = vtkReliefSurfaceFilter::RefersToMissingPoints(input);
  }
  if (!input || !this->InputRefersToMissingPoints)
  {
    this->Superclass::ComputeBounds();
    if (std::all_of(this->Bounds, this->Bounds + 6, [](double b) { return std::isfinite(b); }))
    {
      return;
    }
  }
  if (!input || !vtkReliefSurfaceFilter::GetFiniteBounds(input, this->Bounds))
  {
    vtkMath::UninitializeBounds(this->Bounds);
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefMapper::SetSearchMethod(int method)
{
  if (!vtkReliefSearchMethod::Get(method))
  {
    vtkErrorMacro("Unknown search method " << method
                                           << "; use one of the SetSearchMethodTo...() methods.");
    return;
  }
  if (method != this->SearchMethod)
  {
    this->SearchMethod = method;
    this->WarnedAccelerationFallback = false;
    this->WarnedUnsupportedSearchMethod = false;
    this->SetActiveSearchMethod(method);
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetActiveSearchMethod(int method)
{
  if (method != this->ActiveSearchMethod)
  {
    this->ActiveSearchMethod = method;
    this->ShaderOptionsTime.Modified();
  }
}

const char* vtkOpenGLReliefMapper::GetSearchMethodAsString(int method)
{
  const vtkReliefSearchMethod* description = vtkReliefSearchMethod::Get(method);
  return description ? description->Name : nullptr;
}

const char* vtkOpenGLReliefMapper::GetSearchMethodAsString()
{
  return GetSearchMethodAsString(this->SearchMethod);
}

const vtkReliefSearchMethod& vtkOpenGLReliefMapper::GetActiveSearch()
{
  // a method this frame cannot search with is LinearBinary until the next render says so
  const vtkReliefSearchMethod* method = this->DescribeSearch(this->ActiveSearchMethod);
  return method ? *method : *vtkReliefSearchMethod::Get(LINEAR_BINARY);
}

const vtkReliefSearchMethod* vtkOpenGLReliefMapper::DescribeSearch(int method)
{
  return method == AUTOMATIC ? vtkReliefSearchMethod::GetAutomatic(this->AutomaticAcceleration)
                             : vtkReliefSearchMethod::Get(method);
}

void vtkOpenGLReliefMapper::SetAutomaticAcceleration(int method)
{
  if (!vtkReliefSearchMethod::GetAutomatic(method))
  {
    const char* name = GetSearchMethodAsString(method);
    vtkErrorMacro("AutomaticAcceleration " << (name ? name : std::to_string(method))
                                           << " is neither ConeStep nor SlopeMipmap; keeping "
                                           << this->GetAutomaticAccelerationAsString()
                                           << ". Use SetAutomaticAccelerationTo...().");
    return;
  }
  if (method != this->AutomaticAcceleration)
  {
    this->AutomaticAcceleration = method;
    this->WarnedAccelerationFallback = false;
    this->ModifiedShaderOptions();
    this->ShaderOptionsTime.Modified();
  }
}

void vtkOpenGLReliefMapper::SetLinearSteps(int steps)
{
  int clamped = std::clamp(steps, MinimumLinearSteps, MaximumLinearSteps);
  if (clamped != steps)
  {
    vtkWarningMacro("LinearSteps " << steps << " is out of [" << MinimumLinearSteps << ", "
                                   << MaximumLinearSteps << "]; using " << clamped << ".");
  }
  if (clamped != this->LinearSteps)
  {
    this->LinearSteps = clamped;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetScreenTolerance(double pixels)
{
  const double clamped =
    std::isnan(pixels) ? 0.5 : std::clamp(pixels, 0.0, MaximumScreenTolerance);
  if (clamped != pixels)
  {
    vtkWarningMacro("ScreenTolerance " << pixels << " is not a number of pixels in [0, "
                                       << MaximumScreenTolerance << "]; using " << clamped
                                       << " (0 searches exactly everywhere).");
  }
  if (clamped != this->ScreenTolerance)
  {
    this->ScreenTolerance = clamped;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetBinarySteps(int steps)
{
  int clamped = std::clamp(steps, 0, MaximumBinarySteps);
  if (clamped != steps)
  {
    vtkWarningMacro("BinarySteps " << steps << " is out of [0, " << MaximumBinarySteps
                                   << "]; using " << clamped << ".");
  }
  if (clamped != this->BinarySteps)
  {
    this->BinarySteps = clamped;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetSafetyRadiusTolerance(double tolerance)
{
  if (!(tolerance >= 0.0))
  {
    vtkWarningMacro("SafetyRadiusTolerance " << tolerance
                                             << " is not a depth (it must be 0 or more); using 0.");
    tolerance = 0.0;
  }
  else if (tolerance > 1.0)
  {
    vtkWarningMacro("SafetyRadiusTolerance " << tolerance
                                             << " is more than the whole relief depth; using 1.");
    tolerance = 1.0;
  }
  // read by the next render's acceleration update: no shader to rebuild
  if (tolerance != this->SafetyRadiusTolerance)
  {
    this->SafetyRadiusTolerance = tolerance;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetDepthScale(double depthScale)
{
  const bool same = depthScale == this->DepthScale ||
    (std::isnan(depthScale) && std::isnan(this->DepthScale));
  if (!same)
  {
    this->DepthScale = depthScale;
    this->WarnedDepthScale = false;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetSelfShadowing(bool enabled)
{
  if (enabled != this->SelfShadowing)
  {
    this->SelfShadowing = enabled;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetFootprintShading(bool enabled)
{
  if (enabled != this->FootprintShading)
  {
    this->FootprintShading = enabled;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetDepthCorrection(bool enabled)
{
  if (enabled != this->DepthCorrection)
  {
    this->DepthCorrection = enabled;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetTwoSidedRelief(bool enabled)
{
  if (enabled != this->TwoSidedRelief)
  {
    this->TwoSidedRelief = enabled;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::SetDisplayMode(int mode)
{
  if (mode != SHADED && mode != SAMPLE_COUNT)
  {
    vtkErrorMacro("Unknown display mode " << mode << "; use SetDisplayModeToShaded() or "
                                             "SetDisplayModeToSampleCount().");
    return;
  }
  if (mode != this->DisplayMode)
  {
    this->DisplayMode = mode;
    this->ModifiedShaderOptions();
  }
}

void vtkOpenGLReliefMapper::ModifiedShaderOptions()
{
  const vtkMTimeType before = this->Superclass::GetMTime();
  if (before != this->ShaderOptionsMTime)
  {
    this->OtherChangesMTime = before; // a change of another kind came since the last one
  }
  this->Modified();
  this->ShaderOptionsMTime = this->Superclass::GetMTime();
}

vtkMTimeType vtkOpenGLReliefMapper::GetMTime()
{
  const vtkMTimeType time = this->Superclass::GetMTime();
  return this->HidingShaderOptions && time == this->ShaderOptionsMTime ? this->OtherChangesMTime
                                                                       : time;
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefMapper::ShallowCopy(vtkAbstractMapper* mapper)
{
  this->Superclass::ShallowCopy(mapper);
  if (auto* relief = vtkOpenGLReliefMapper::SafeDownCast(mapper))
  {
    this->CopyReliefSettings(relief);
  }
}

void vtkOpenGLReliefMapper::CopyReliefSettings(vtkOpenGLReliefMapper* source)
{
  if (!source || source == this)
  {
    return;
  }
  this->SetSearchMethod(source->SearchMethod);
  this->SetAutomaticAcceleration(source->AutomaticAcceleration);
  this->SetScreenTolerance(source->ScreenTolerance);
  this->SetLinearSteps(source->LinearSteps);
  this->SetBinarySteps(source->BinarySteps);
  this->SetSafetyRadiusTolerance(source->SafetyRadiusTolerance);
  this->SetDepthScale(source->DepthScale);
  this->SetSelfShadowing(source->SelfShadowing);
  this->SetFootprintShading(source->FootprintShading);
  this->SetDepthCorrection(source->DepthCorrection);
  this->SetTwoSidedRelief(source->TwoSidedRelief);
  this->SetDisplayMode(source->DisplayMode);
  for (int port = 1; port <= 2; ++port)
  {
    vtkAlgorithmOutput* output =
      source->GetNumberOfInputConnections(port) ? source->GetInputConnection(port, 0) : nullptr;
    if (output != (this->GetNumberOfInputConnections(port) ? this->GetInputConnection(port, 0)
                                                           : nullptr))
    {
      this->SetInputConnection(port, output);
    }
  }
  vtkReliefTextureFilter* from = source->ReliefTextureFilter;
  this->ReliefTextureFilter->SetInputConvention(from->GetInputConvention());
  this->ReliefTextureFilter->SetComponent(from->GetComponent());
  this->ReliefTextureFilter->SetDepthToTexelRatio(from->GetDepthToTexelRatio());
  this->ReliefTextureFilter->SetUseInputNormals(from->GetUseInputNormals());
}

vtkMTimeType vtkOpenGLReliefMapper::GetReliefSettingsMTime()
{
  return std::max(this->GetMTime(), this->ReliefTextureFilter->GetMTime());
}

void vtkOpenGLReliefMapper::SetHeightMapConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkOpenGLReliefMapper::SetHeightMapData(vtkImageData* image)
{
  this->SetInputDataInternal(1, image);
}

vtkImageData* vtkOpenGLReliefMapper::GetHeightMap()
{
  return this->GetImageOnPort(1);
}

vtkImageData* vtkOpenGLReliefMapper::GetImageOnPort(int port)
{
  if (this->GetNumberOfInputConnections(port) == 0)
  {
    return nullptr;
  }
  return vtkImageData::SafeDownCast(this->GetInputDataObject(port, 0));
}

void vtkOpenGLReliefMapper::SetAccelerationConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(2, output);
}

void vtkOpenGLReliefMapper::SetAccelerationData(vtkImageData* image)
{
  this->SetInputDataInternal(2, image);
}

vtkImageData* vtkOpenGLReliefMapper::GetAcceleration()
{
  return this->GetImageOnPort(2);
}

vtkReliefTextureFilter* vtkOpenGLReliefMapper::GetReliefTextureFilter()
{
  return this->ReliefTextureFilter;
}

vtkPolyData* vtkOpenGLReliefMapper::GetReliefSurface()
{
  return this->GetTangentFrameFilter()->GetOutput();
}

vtkReliefTangentFrameFilter* vtkOpenGLReliefMapper::GetTangentFrameFilter()
{
  // made on first use: the frames that need no tangents never make it
  if (!this->TangentFrame)
  {
    this->TangentFrame = vtkSmartPointer<vtkReliefTangentFrameFilter>::New();
    vtkReliefForwardMessages(this->TangentFrame, this);
  }
  return this->TangentFrame;
}

//------------------------------------------------------------------------------
bool vtkOpenGLReliefMapper::UpdateReliefSurface()
{
  // a mesh it cannot frame (no texture coordinates, no polygons) is an error of the
  // filter, reported through the mapper once per change of the mesh
  this->GetTangentFrameFilter()->SetInputData(this->CurrentInput);
  this->TangentFrame->Update();
  // without relief the mesh is drawn plainly, as the filter passes it: broken cells left out
  this->CurrentInput = this->TangentFrame->GetOutput();
  return this->TangentFrame->GetHasSurface();
}

bool vtkOpenGLReliefMapper::UpdateReliefTexture(vtkRenderer* ren)
{
  if (this->GetNumberOfInputConnections(1) > 0)
  {
    this->GetInputAlgorithm(1, 0)->Update();
  }
  vtkImageData* heights = this->GetHeightMap();
  if (!heights)
  {
    if (!this->WarnedMissingHeightMap)
    {
      this->WarnedMissingHeightMap = true;
      vtkWarningMacro("No height map: the mesh is drawn without relief. Give one with "
                      "SetHeightMapConnection() or SetHeightMapData() (in ParaView: the "
                      "Relief Surface's Height Map).");
    }
    return false;
  }
  this->WarnedMissingHeightMap = false;

  // The mapper's own filter holds the settings, and its output port serves filters
  // downstream; what is drawn is made once for all mappers of these heights and settings.
  this->ReliefTextureFilter->SetInputData(heights);
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkImageData* relief = this->Textures->UpdateRelief(window, heights, this->ReliefTextureFilter);
  if (!relief)
  {
    return false; // said why, once
  }
  // the shallowest depth, where the relief comes closest to the surface (the range is
  // cached with the array)
  vtkDataArray* texels = relief->GetPointData()->GetScalars();
  this->ReliefTopDepth =
    texels && texels->GetNumberOfComponents() == 4 ? texels->GetRange(3)[0] : 0.0;
  if (this->Textures->GetInputNormals() != this->InputNormals)
  {
    this->InputNormals = this->Textures->GetInputNormals();
    this->ShaderOptionsTime.Modified();
  }
  return true;
}

//------------------------------------------------------------------------------
vtkReliefAccelerationFilter* vtkOpenGLReliefMapper::NewAccelerationFilter(int method)
{
  const vtkReliefSearchMethod* description = vtkReliefSearchMethod::Get(method);
  return description && description->NewAccelerationFilter ? description->NewAccelerationFilter()
                                                           : nullptr;
}

void vtkOpenGLReliefMapper::UpdateAcceleration(vtkRenderer* ren)
{
  const vtkReliefSearchMethod* described = this->DescribeSearch(this->SearchMethod);
  if (!described)
  {
    if (!this->WarnedUnsupportedSearchMethod)
    {
      this->WarnedUnsupportedSearchMethod = true;
      vtkWarningMacro(<< this->GetClassName() << " cannot search with "
                      << GetSearchMethodAsString(this->SearchMethod) << ": "
                      << this->GetUnsupportedSearchReason()
                      << " Searching with LinearBinary; Automatic (the default) suits "
                         "every frame.");
    }
    this->SetActiveSearchMethod(LINEAR_BINARY);
    return;
  }
  const vtkReliefSearchMethod& method = *described;
  if (method.NeedsAcceleration() && this->GetNumberOfInputConnections(2) > 0)
  {
    this->GetInputAlgorithm(2, 0)->Update();
  }
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (this->Textures->UpdateAcceleration(window, method,
        method.NeedsAcceleration() ? this->GetAcceleration() : nullptr,
        this->SafetyRadiusTolerance))
  {
    this->SetActiveSearchMethod(this->SearchMethod);
    return;
  }
  if (!this->WarnedAccelerationFallback)
  {
    this->WarnedAccelerationFallback = true;
    vtkWarningMacro("The " << method.Name
                           << " search has no usable acceleration image; searching with "
                              "LinearBinary instead.");
  }
  this->SetActiveSearchMethod(LINEAR_BINARY);
}

void vtkOpenGLReliefMapper::MapReliefAttributes(bool relief)
{
  vtkPointData* pointData = this->CurrentInput->GetPointData();
  this->MapReliefAttribute(TCoordAttribute, relief ? pointData->GetTCoords()->GetName() : nullptr);
  this->MapFrameAttributes(relief);
}

void vtkOpenGLReliefMapper::MapFrameAttributes(bool relief)
{
  vtkPointData* pointData = this->CurrentInput->GetPointData();
  this->MapReliefAttribute(NormalAttribute, relief ? pointData->GetNormals()->GetName() : nullptr);
  this->MapReliefAttribute(
    TangentAttribute, relief ? pointData->GetTangents()->GetName() : nullptr);
  this->MapReliefAttribute(
    TextureScaleAttribute, relief ? vtkReliefTangentFrameFilter::TextureScaleArrayName() : nullptr);
}

void vtkOpenGLReliefMapper::MapReliefAttribute(const char* shaderInput, const char* arrayName)
{
  // Remapping calls Modified(), which rebuilds the buffers: only when a name changes.
  // Mappings of the user's own are left alone.
  const auto mapped = this->ExtraAttributes.find(shaderInput);
  const bool isMapped = mapped != this->ExtraAttributes.end();
  if (!arrayName)
  {
    if (isMapped)
    {
      this->RemoveVertexAttributeMapping(shaderInput);
    }
  }
  else if (!isMapped || mapped->second.DataArrayName != arrayName)
  {
    this->MapDataArrayToVertexAttribute(
      shaderInput, arrayName, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  }
}

std::string vtkOpenGLReliefMapper::GetFrameSource()
{
  return std::string(vtkReliefTangentBasis) + vtkReliefFlatFrame + vtkReliefTangentFrame;
}

std::string vtkOpenGLReliefMapper::GetFrameDefines()
{
  return "";
}

std::string vtkOpenGLReliefMapper::GetFrameShaderCode(const char* stage)
{
  return std::string("#define ") + stage + "\n" + this->GetFrameSource() + "\n#undef " + stage +
    "\n";
}

bool vtkOpenGLReliefMapper::UpdateRelief(vtkRenderer* ren)
{
  const bool relief = this->UpdateReliefSurface() && this->UpdateReliefTexture(ren);
  if (relief)
  {
    this->UpdateAcceleration(ren);
  }
  return relief;
}

double vtkOpenGLReliefMapper::UsableDepthScale(vtkActor* actor)
{
  const double depth = this->DepthScale;
  const double size = actor->GetLength(); // the world diagonal of what the actor draws
  if (std::isfinite(depth) && depth > 0.0 && !(depth > size))
  {
    return depth;
  }
  if (!this->WarnedDepthScale)
  {
    this->WarnedDepthScale = true;
    const double suggestion = 0.05 * size;
    if (!std::isfinite(depth))
    {
      vtkWarningMacro("DepthScale is " << depth << ", not a world depth: the relief is drawn "
                                       << "flat. Set a positive, finite depth, a few percent of "
                                       << "the mesh's size (for example " << suggestion << ").");
    }
    else if (depth <= 0.0)
    {
      vtkWarningMacro("DepthScale is " << depth
                                       << ": the relief is flat. Set a positive world depth.");
    }
    else
    {
      vtkWarningMacro("DepthScale " << depth << " is deeper than the whole mesh is large ("
                                    << size << " across): the relief is drawn flat. Relief is "
                                    << "a few percent of the mesh's size: try " << suggestion
                                    << ".");
    }
  }
  return 0.0;
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* actor)
{
  const bool relief = this->UpdateRelief(ren);
  if (relief != this->DrawingRelief)
  {
    this->DrawingRelief = relief;
    this->ShaderOptionsTime.Modified();
  }
  this->MapReliefAttributes(relief);
  this->DrawnDepthScale = relief ? this->UsableDepthScale(actor) : 0.0;
  this->Superclass::RenderPieceStart(ren, actor);
  this->BackFacesLeftOut = this->ShouldCullBackFaces(ren, actor);
  if (this->BackFacesLeftOut)
  {
    // what the render passes around it had, restored in RenderPieceFinish
    vtkOpenGLState* state = static_cast<vtkOpenGLRenderer*>(ren)->GetState();
    this->SavedCullFace = state->GetEnumState(GL_CULL_FACE);
    GLint mode = GL_BACK;
    state->vtkglGetIntegerv(GL_CULL_FACE_MODE, &mode);
    this->SavedCullFaceMode = static_cast<unsigned int>(mode);
    state->vtkglEnable(GL_CULL_FACE);
    state->vtkglCullFace(GL_BACK);
  }
  if (this->DrawingRelief)
  {
    this->ActivateReliefTextures(true);
  }
}

void vtkOpenGLReliefMapper::ActivateReliefTextures(bool activate)
{
  if (activate)
  {
    this->Textures->Activate(this->GetActiveSearch());
  }
  else
  {
    this->Textures->Deactivate(this->GetActiveSearch());
  }
}

void vtkOpenGLReliefMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingRelief)
  {
    this->ActivateReliefTextures(false);
  }
  if (this->BackFacesLeftOut)
  {
    vtkOpenGLState* state = static_cast<vtkOpenGLRenderer*>(ren)->GetState();
    state->vtkglCullFace(this->SavedCullFaceMode);
    state->SetEnumState(GL_CULL_FACE, this->SavedCullFace);
  }
  this->Superclass::RenderPieceFinish(ren, actor);
}

bool vtkOpenGLReliefMapper::ShouldCullBackFaces(vtkRenderer* ren, vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  // the actor's own culling, clipping planes (which open the mesh), translucency (the far
  // side shows through) and two-sided relief leave the faces as VTK draws them
  if (!this->DrawingRelief || this->TwoSidedRelief || property->GetBackfaceCulling() ||
    property->GetFrontfaceCulling() || this->GetNumberOfClippingPlanes() > 0 ||
    actor->HasTranslucentPolygonalGeometry())
  {
    return false;
  }
  // a mirroring actor matrix turns the windings, and with them the faces, round
  if (actor->GetMatrix()->Determinant() <= 0.0)
  {
    return false;
  }
  if (this->SurfaceClosedMesh != this->CurrentInput ||
    this->SurfaceClosedTime != this->CurrentInput->GetMTime())
  {
    this->SurfaceClosedMesh = this->CurrentInput;
    this->SurfaceClosedTime = this->CurrentInput->GetMTime();
    this->SurfaceClosed = vtkReliefSurfaceFilter::IsClosed(this->CurrentInput);
  }
  if (!this->SurfaceClosed)
  {
    return false;
  }
  // from inside the bounds the camera may be inside the shape, whose back faces it sees
  double bounds[6];
  actor->GetBounds(bounds);
  const double* eye = ren->GetActiveCamera()->GetPosition();
  for (int axis = 0; axis < 3; ++axis)
  {
    if (eye[axis] < bounds[2 * axis] || eye[axis] > bounds[2 * axis + 1])
    {
      return true;
    }
  }
  return false;
}

bool vtkOpenGLReliefMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  // VTK rebuilds the shaders whenever the mapper is modified: the relief's options say
  // themselves what they change (ShaderOptionsTime)
  this->HidingShaderOptions = true;
  const bool vtkRebuilds = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor);
  this->HidingShaderOptions = false;
  // footprint shading is compiled in or out (RELIEF_FOOTPRINT_SHADING): on llvmpipe, which
  // runs every branch, a uniform that turned it off would still cost its walks one pass
  const bool reliefPrimitive = this->DrawingRelief &&
    &cellBO == &this->Primitives[PrimitiveTris] &&
    actor->GetProperty()->GetRepresentation() == VTK_SURFACE;
  return vtkRebuilds || cellBO.ShaderSourceTime < this->ShaderOptionsTime ||
    (reliefPrimitive && this->CompiledFootprintShading != this->FootprintShading);
}

bool vtkOpenGLReliefMapper::GetNeedToRebuildBufferObjects(vtkRenderer* ren, vtkActor* actor)
{
  // and the buffers: no relief option changes them
  this->HidingShaderOptions = true;
  const bool vtkRebuilds = this->Superclass::GetNeedToRebuildBufferObjects(ren, actor);
  this->HidingShaderOptions = false;
  return vtkRebuilds;
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  const bool reliefPrimitive = this->DrawingRelief &&
    this->LastBoundBO == &this->Primitives[PrimitiveTris] &&
    actor->GetProperty()->GetRepresentation() == VTK_SURFACE;
  if (!reliefPrimitive)
  {
    this->Superclass::ReplaceShaderValues(shaders, ren, actor);
    return;
  }
  const int lightComplexity = this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity;

  // Insertions keep VTK's tags, so VTK's own code still lands before ours.
  this->MissingShaderTags.clear();
  this->InsertReliefVertexShader(shaders[vtkShader::Vertex]);
  this->InsertReliefFragmentShader(shaders[vtkShader::Fragment], lightComplexity);
  this->InsertReliefGeometryShader(shaders[vtkShader::Geometry]);

  this->Superclass::ReplaceShaderValues(shaders, ren, actor);

  std::string vertexSource = shaders[vtkShader::Vertex]->GetSource();
  vtkReliefShaderRewrites::DeclareModelToView(vertexSource, "//VTK::Relief::CameraDec");
  shaders[vtkShader::Vertex]->SetSource(vertexSource);
  std::string fragmentSource = shaders[vtkShader::Fragment]->GetSource();
  this->LightThroughRelief(fragmentSource, lightComplexity, actor);
  // VTK reads the actor's textures with implicit derivatives, which jump wherever the
  // hit jumps (relief edges, silhouettes) and pick far too coarse a level there: read
  // them at the level of the entry coordinates.
  const int textureReads =
    vtkReliefShaderRewrites::ReadTexturesThrough(
      fragmentSource, "reliefTextureAtRay", "reliefColourAtRay");
  if (textureReads == 0 && actor->GetTexture() && !this->WarnedTextureReads)
  {
    this->WarnedTextureReads = true;
    vtkWarningMacro("This VTK's shader reads the actor's texture otherwise than "
                    "vtkReliefShaderRewrites::ReadTexturesThrough follows (VTK 9.1 and 9.2): "
                    "the colours are read at the hit with the texture's own filtering, which "
                    "may blur at relief edges.");
  }
  shaders[vtkShader::Fragment]->SetSource(fragmentSource);
  this->ReportMissingShaderTags();
}

void vtkOpenGLReliefMapper::Insert(std::string& source, const char* tag, const std::string& code,
  bool (*insertion)(std::string&, const char*, const std::string&))
{
  if (!insertion(source, tag, code))
  {
    this->MissingShaderTags.push_back(tag);
  }
}

void vtkOpenGLReliefMapper::ReportMissingShaderTags()
{
  if (this->MissingShaderTags.empty() || this->WarnedMissingShaderTags)
  {
    return;
  }
  this->WarnedMissingShaderTags = true;
  std::string tags;
  for (const char* tag : this->MissingShaderTags)
  {
    tags += std::string(tags.empty() ? "" : ", ") + tag;
  }
  vtkWarningMacro("This VTK's shader templates lack " << tags
                  << ", where the relief's code goes (vtkReliefShaderRewrites follows VTK 9.1 "
                     "and 9.2): the relief may be drawn wrong or not at all. Build vtkRelief "
                     "against one of those, or update vtkReliefShaderRewrites.");
}

void vtkOpenGLReliefMapper::InsertReliefVertexShader(vtkShader* vertexShader)
{
  using Rewrites = vtkReliefShaderRewrites;
  std::string vertexSource = vertexShader->GetSource();
  this->Insert(vertexSource, Rewrites::VertexDeclarations,
    this->GetFrameDefines() + vtkReliefVertexDec + this->GetFrameShaderCode("RELIEF_VERTEX_STAGE"),
    &Rewrites::InsertAfter);
  this->Insert(vertexSource, Rewrites::VertexEnd, vtkReliefVertexImpl, &Rewrites::InsertBefore);
  vertexShader->SetSource(vertexSource);
}

void vtkOpenGLReliefMapper::InsertReliefFragmentShader(
  vtkShader* fragmentShader, int lightComplexity)
{
  using Rewrites = vtkReliefShaderRewrites;
  std::string declarations = vtkReliefFragmentDec;
  vtkShaderProgram::Substitute(declarations, "//VTK::Relief::Common", vtkReliefCommon);
  vtkShaderProgram::Substitute(declarations, "//VTK::Relief::Search", this->GetSearchSource());
  vtkShaderProgram::Substitute(
    declarations, "//VTK::Relief::Frame", this->GetFrameShaderCode("RELIEF_FRAGMENT_STAGE"));
  // VTK's texture and normal-map code reads its texture coordinates: make it read at the
  // hit, unless that slot carries the colour coordinates of scalars mapped through a texture.
  vtkShaderProgram::Substitute(declarations, "//VTK::Relief::TCoordAtHit",
    this->ColorTextureMap
      ? ""
      : std::string("#define ") + Rewrites::GetTextureCoordinates() + " reliefHitTCoord");
  this->CompiledFootprintShading = this->FootprintShading;
  std::string fragmentSource = fragmentShader->GetSource();
  // exact cell tests read a cell's four corners in one gather where GL offers it
  this->Insert(fragmentSource, Rewrites::FragmentSystem,
    "#extension GL_ARB_texture_gather : enable\n", &Rewrites::InsertAfter);
  this->Insert(fragmentSource, Rewrites::FragmentDeclarations,
    this->GetSearchDefines() + this->GetFrameDefines() +
      (this->InputNormals ? "#define RELIEF_INPUT_NORMALS\n" : "") +
      (this->FootprintShading ? "#define RELIEF_FOOTPRINT_SHADING\n" : "") + declarations,
    &Rewrites::InsertAfter);
  this->Insert(
    fragmentSource, Rewrites::FragmentStart, vtkReliefFragmentImpl, &Rewrites::InsertBefore);
  this->Insert(fragmentSource, Rewrites::FragmentDepth, "gl_FragDepth = reliefFragDepth;\n",
    &Rewrites::Replace);
  if (lightComplexity > 0)
  {
    this->Insert(fragmentSource, Rewrites::FragmentNormal,
      "  normalVCVSOutput = reliefLitNormalVC;\n"
      "  vertexVC = vec4(reliefHitVC, 1.0);\n" +
        this->GetHitColourCode(),
      &Rewrites::InsertAfter);
  }
  this->Insert(fragmentSource, Rewrites::FragmentOutput,
    "if (reliefDisplayMode == 1)\n"
    "  {\n"
    "    float reliefSamples = min(float(reliefViewHit.samples), 255.0);\n"
    "    gl_FragData[0] = vec4(reliefSamples / 255.0, 0.0, 0.0, 1.0);\n"
    "  }",
    &Rewrites::InsertBefore);
  fragmentShader->SetSource(fragmentSource);
}

std::string vtkOpenGLReliefMapper::GetSearchDefines()
{
  return this->GetActiveSearch().GetShaderDefine();
}

std::string vtkOpenGLReliefMapper::GetSearchSource()
{
  return std::string(vtkReliefSearch) + vtkReliefGridSearch + vtkReliefSafetySearch +
    vtkReliefSlopeSearch + vtkReliefConeSearch + vtkReliefAutomaticSearch;
}

void vtkOpenGLReliefMapper::InsertReliefGeometryShader(vtkShader* geometryShader)
{
  // With a geometry shader (edges, wide lines) VTK renames the fragment inputs from
  // VSOutput to GSOutput: pass the frame through it.
  using Rewrites = vtkReliefShaderRewrites;
  std::string geometrySource = geometryShader->GetSource();
  if (!geometrySource.empty())
  {
    this->Insert(geometrySource, Rewrites::GeometryDeclarations,
      this->GetFrameDefines() + vtkReliefGeometryDec +
        this->GetFrameShaderCode("RELIEF_GEOMETRY_STAGE"),
      &Rewrites::InsertAfter);
    this->Insert(
      geometrySource, Rewrites::GeometryVertex, vtkReliefGeometryImpl, &Rewrites::InsertAfter);
    geometryShader->SetSource(geometrySource);
  }
}

void vtkOpenGLReliefMapper::LightThroughRelief(
  std::string& fragmentSource, int lightComplexity, vtkActor* actor)
{
  const bool shadowsLost = this->SelfShadowing && lightComplexity >= 2;
  if (lightComplexity < 1 ||
    vtkReliefShaderRewrites::LightThrough(fragmentSource, "reliefDiffuse", "reliefShadow") > 0 ||
    this->WarnedUnmatchedLighting || !(shadowsLost || this->FootprintShading))
  {
    return;
  }
  this->WarnedUnmatchedLighting = true;
  if (actor->GetProperty()->GetInterpolation() == VTK_PBR)
  {
    vtkWarningMacro("Self-shadowing and the relief's footprint shading are not available "
                    "with this lighting model (physically based interpolation); the relief "
                    "is lit by the normal at each hit, without self-shadows.");
  }
  else
  {
    vtkWarningMacro("This VTK's lighting code does not hold the diffuse terms "
                    "vtkReliefShaderRewrites::LightThrough follows (VTK 9.1 and 9.2): the "
                    "relief is lit by the normal at each hit, without self-shadows.");
  }
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  vtkShaderProgram* program = cellBO.Program;
  if (!this->DrawingRelief || !program->IsUniformUsed("reliefDepthScale"))
  {
    return;
  }
  this->SetReliefTextureParameters(program);
  if (this->InputNormals)
  {
    program->SetUniformf(
      "reliefNormalRatio", static_cast<float>(this->ReliefTextureFilter->GetDepthToTexelRatio()));
  }
  program->SetUniformf("reliefDepthScale", static_cast<float>(this->DrawnDepthScale));
  program->SetUniformf("reliefScreenTolerance", static_cast<float>(this->ScreenTolerance));
  program->SetUniformi("reliefLinearSteps", this->LinearSteps);
  program->SetUniformi("reliefBinarySteps", this->BinarySteps);
  program->SetUniformi("reliefSelfShadowing", this->SelfShadowing ? 1 : 0);
  program->SetUniformi("reliefDepthCorrection", this->DepthCorrection ? 1 : 0);
  program->SetUniformi("reliefDisplayMode", this->DisplayMode);
  program->SetUniformi("reliefTwoSided", this->TwoSidedRelief ? 1 : 0);
}

void vtkOpenGLReliefMapper::SetReliefTextureParameters(vtkShaderProgram* program)
{
  this->Textures->SetShaderParameters(program, this->GetActiveSearch());
}

void vtkOpenGLReliefMapper::SetCameraShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetCameraShaderParameters(cellBO, ren, actor);
  vtkShaderProgram* program = cellBO.Program;
  if (!this->DrawingRelief || !program->IsUniformUsed("reliefVCDCMatrix"))
  {
    return;
  }
  vtkMatrix4x4* worldToView;
  vtkMatrix3x3* normalWorldToView;
  vtkMatrix4x4* viewToDisplay;
  vtkMatrix4x4* worldToDisplay;
  static_cast<vtkOpenGLCamera*>(ren->GetActiveCamera())
    ->GetKeyMatrices(ren, worldToView, normalWorldToView, viewToDisplay, worldToDisplay);
  program->SetUniformMatrix("reliefVCDCMatrix", viewToDisplay);
  program->SetUniformi("reliefMirrored", actor->GetMatrix()->Determinant() < 0.0 ? 1 : 0);

  // Directions in model units, free of the position VBO's shift and scale.
  vtkNew<vtkMatrix4x4> modelToView;
  if (actor->GetIsIdentity())
  {
    modelToView->DeepCopy(worldToView);
  }
  else
  {
    vtkMatrix4x4* modelToWorld;
    vtkMatrix3x3* normalModelToWorld;
    static_cast<vtkOpenGLActor*>(actor)->GetKeyMatrices(modelToWorld, normalModelToWorld);
    vtkMatrix4x4::Multiply4x4(modelToWorld, worldToView, modelToView);
  }
  // key matrices are stored transposed: the inverse transpose of the GLSL matrix is
  // stored as the transpose of the stored matrix's inverse
  vtkNew<vtkMatrix3x3> directions;
  UpperLeft(modelToView, directions);
  vtkNew<vtkMatrix3x3> normals;
  vtkMatrix3x3::Invert(directions, normals);
  normals->Transpose();
  // each frame reads what it needs of them
  if (program->IsUniformUsed("reliefDirectionMatrix"))
  {
    program->SetUniformMatrix("reliefDirectionMatrix", directions);
  }
  if (program->IsUniformUsed("reliefNormalMatrix"))
  {
    program->SetUniformMatrix("reliefNormalMatrix", normals);
  }
}

vtkIdType vtkOpenGLReliefMapper::GetTextureBytes()
{
  return this->Textures->GetTextureBytes(this->GetActiveSearch());
}

vtkIdType vtkOpenGLReliefMapper::GetTextureBytesInUse(vtkRenderWindow* window)
{
  return vtkOpenGLReliefTextures::GetTextureBytesInUse(window);
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->Textures->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SearchMethod: " << this->GetSearchMethodAsString() << "\n";
  os << indent << "AutomaticAcceleration: " << this->GetAutomaticAccelerationAsString() << "\n";
  os << indent << "ScreenTolerance: " << this->ScreenTolerance << " pixels\n";
  os << indent << "ActiveSearchMethod: " << GetSearchMethodAsString(this->ActiveSearchMethod)
     << "\n";
  os << indent << "Acceleration: " << this->GetAcceleration() << "\n";
  os << indent << "LinearSteps: " << this->LinearSteps << "\n";
  os << indent << "BinarySteps: " << this->BinarySteps << "\n";
  os << indent << "SafetyRadiusTolerance: " << this->SafetyRadiusTolerance << "\n";
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "SelfShadowing: " << this->SelfShadowing << "\n";
  os << indent << "FootprintShading: " << this->FootprintShading << "\n";
  os << indent << "DepthCorrection: " << this->DepthCorrection << "\n";
  os << indent << "TwoSidedRelief: " << this->TwoSidedRelief << "\n";
  os << indent << "BackFacesLeftOut: " << this->BackFacesLeftOut << "\n";
  os << indent << "DisplayMode: " << (this->DisplayMode == SAMPLE_COUNT ? "SampleCount" : "Shaded")
     << "\n";
  os << indent << "HeightMap: " << this->GetHeightMap() << "\n";
  os << indent << "TextureBytes: " << this->GetTextureBytes() << "\n";
  os << indent << "Textures:\n";
  this->Textures->PrintSelf(os, indent.GetNextIndent());
  os << indent << "ReliefTextureFilter:\n";
  this->ReliefTextureFilter->PrintSelf(os, indent.GetNextIndent());
  if (this->TangentFrame)
  {
    os << indent << "TangentFrame:\n";
    this->TangentFrame->PrintSelf(os, indent.GetNextIndent());
  }
}
