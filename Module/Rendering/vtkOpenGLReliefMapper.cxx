#include "vtkOpenGLReliefMapper.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkConeStepMapFilter.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMath.h"
#include "vtkMatrix3x3.h"
#include "vtkMatrix4x4.h"
#include "vtkMaximumMipmapFilter.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLActor.h"
#include "vtkOpenGLCamera.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkOpenGLRenderer.h"
#include "vtkOpenGLState.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefSurfaceFilter.h"
#include "vtkReliefTangentFrameFilter.h"
#include "vtkReliefTextureFilter.h"
#include "vtkRenderer.h"
#include "vtkSMPTools.h"
#include "vtkSafetyRadiusFilter.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"
#include "vtk_glew.h"

#include "vtkReliefCommon.h"
#include "vtkReliefConeSearch.h"
#include "vtkReliefFragmentDec.h"
#include "vtkReliefFragmentImpl.h"
#include "vtkReliefGeometryDec.h"
#include "vtkReliefGeometryImpl.h"
#include "vtkReliefGridSearch.h"
#include "vtkReliefSafetySearch.h"
#include "vtkReliefSearch.h"
#include "vtkReliefTangentBasis.h"
#include "vtkReliefTangentFrame.h"
#include "vtkReliefVertexDec.h"
#include "vtkReliefVertexImpl.h"

#include <algorithm>
#include <cmath>
#include <regex>
#include <vector>

vtkStandardNewMacro(vtkOpenGLReliefMapper);

namespace
{
constexpr int MinimumLinearSteps = 1;
constexpr int MaximumLinearSteps = 512;
constexpr int MaximumBinarySteps = 32;

// Bytes of a w x h texture of `texelBytes` a texel with all its mipmap levels.
vtkIdType MipmappedBytes(int width, int height, int texelBytes)
{
  vtkIdType bytes = 0;
  for (int level = 0; width >> level > 0 || height >> level > 0; ++level)
  {
    bytes += static_cast<vtkIdType>(std::max(width >> level, 1)) * std::max(height >> level, 1);
  }
  return bytes * texelBytes;
}

// A repeating 2D texture of `values` (one or two components) in `internalFormat`:
// mipmapped and trilinearly filtered, or read texel by texel (nearest filtering: the
// acceleration images, one texel per cell, repeating as the height map does).
bool UploadTexture(vtkTextureObject* texture, vtkOpenGLRenderWindow* window,
  const int dimensions[3], vtkDataArray* values, unsigned int internalFormat, bool mipmapped)
{
  const int components = values->GetNumberOfComponents();
  texture->SetContext(window);
  // vtkTextureObject keeps the formats and data type of an earlier upload, and one
  // method's image would be read with another's layout
  texture->ResetFormatAndType();
  texture->SetInternalFormat(internalFormat);
  texture->SetFormat(components == 1 ? GL_RED : GL_RG);
  texture->SetWrapS(vtkTextureObject::Repeat);
  texture->SetWrapT(vtkTextureObject::Repeat);
  texture->SetMinificationFilter(
    mipmapped ? vtkTextureObject::LinearMipmapLinear : vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(mipmapped ? vtkTextureObject::Linear : vtkTextureObject::Nearest);
  if (!texture->Create2DFromRaw(dimensions[0], dimensions[1], components,
        values->GetDataType(), values->GetVoidPointer(0)))
  {
    return false;
  }
  if (mipmapped)
  {
    // vtkTextureObject makes mipmaps for cube maps only
    texture->Activate();
    glGenerateMipmap(GL_TEXTURE_2D);
    texture->Deactivate();
  }
  return true;
}

// The two bytes a cell of vtkConeStepMapFilter's map is uploaded as.
vtkSmartPointer<vtkDataArray> EncodeConeMap(vtkImageData* coneMap)
{
  vtkDataArray* cones = coneMap->GetPointData()->GetScalars();
  const double maximumRatio = vtkConeStepMapFilter::GetMaximumRatio(
    coneMap->GetDimensions()[0], coneMap->GetDimensions()[1]);
  auto codes = vtkSmartPointer<vtkUnsignedCharArray>::New();
  codes->SetNumberOfComponents(2);
  codes->SetNumberOfTuples(cones->GetNumberOfTuples());
  vtkSMPTools::For(0, cones->GetNumberOfTuples(), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType cell = begin; cell < end; ++cell)
    {
      vtkConeStepMapFilter::EncodeCone(cones->GetComponent(cell, 0), cones->GetComponent(cell, 1),
        maximumRatio, codes->GetPointer(2 * cell));
    }
  });
  return codes;
}

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
  // The internal filters' errors and warnings are the mapper's.
  vtkReliefForwardMessages(this->ReliefTextureFilter, this);
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
  if (!GetSearchMethodAsString(method))
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
  switch (method)
  {
    case LINEAR:
      return "Linear";
    case LINEAR_BINARY:
      return "LinearBinary";
    case SECANT:
      return "Secant";
    case EXACT_DDA:
      return "ExactDDA";
    case SAFETY_RADIUS:
      return "SafetyRadius";
    case CONE_STEP:
      return "ConeStep";
    case MAXIMUM_MIPMAP:
      return "MaximumMipmap";
    default:
      return nullptr;
  }
}

const char* vtkOpenGLReliefMapper::GetSearchMethodAsString()
{
  return GetSearchMethodAsString(this->SearchMethod);
}

std::string vtkOpenGLReliefMapper::GetSearchDefines()
{
  switch (this->ActiveSearchMethod)
  {
    case LINEAR:
      return "#define RELIEF_SEARCH reliefSearchLinear\n";
    case SECANT:
      return "#define RELIEF_SEARCH reliefSearchSecant\n";
    case EXACT_DDA:
      return "#define RELIEF_SEARCH reliefSearchExactDDA\n";
    case SAFETY_RADIUS:
      return "#define RELIEF_SEARCH reliefSearchSafetyRadius\n";
    case CONE_STEP:
      return "#define RELIEF_SEARCH reliefSearchConeStep\n";
    case MAXIMUM_MIPMAP:
      return "#define RELIEF_SEARCH reliefSearchMaximumMipmap\n";
    default:
      return "#define RELIEF_SEARCH reliefSearchLinearBinary\n";
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
  this->LinearSteps = clamped;
}

void vtkOpenGLReliefMapper::SetBinarySteps(int steps)
{
  int clamped = std::clamp(steps, 0, MaximumBinarySteps);
  if (clamped != steps)
  {
    vtkWarningMacro("BinarySteps " << steps << " is out of [0, " << MaximumBinarySteps
                                   << "]; using " << clamped << ".");
  }
  this->BinarySteps = clamped;
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
  // read by the next render's acceleration update: nothing to rebuild here
  this->SafetyRadiusTolerance = tolerance;
}

void vtkOpenGLReliefMapper::SetDepthScale(double depthScale)
{
  const bool same = depthScale == this->DepthScale ||
    (std::isnan(depthScale) && std::isnan(this->DepthScale));
  if (!same)
  {
    this->DepthScale = depthScale;
    this->WarnedDepthScale = false;
  }
}

void vtkOpenGLReliefMapper::SetSelfShadowing(bool enabled)
{
  this->SelfShadowing = enabled;
}

void vtkOpenGLReliefMapper::SetDepthCorrection(bool enabled)
{
  this->DepthCorrection = enabled;
}

void vtkOpenGLReliefMapper::SetTwoSidedRelief(bool enabled)
{
  this->TwoSidedRelief = enabled;
}

void vtkOpenGLReliefMapper::SetDisplayMode(int mode)
{
  if (mode != SHADED && mode != SAMPLE_COUNT)
  {
    vtkErrorMacro("Unknown display mode " << mode << "; use SetDisplayModeToShaded() or "
                                             "SetDisplayModeToSampleCount().");
    return;
  }
  this->DisplayMode = mode;
}

//------------------------------------------------------------------------------
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
                      "SetHeightMapConnection() or SetHeightMapData().");
    }
    return false;
  }
  this->WarnedMissingHeightMap = false;

  // A failed (empty) output would make the pipeline run the filter, and repeat its
  // error, every frame: run it only when the heights or its settings change.
  this->ReliefTextureFilter->SetInputData(heights);
  const vtkMTimeType inputTime =
    std::max(heights->GetMTime(), this->ReliefTextureFilter->GetMTime());
  if (inputTime != this->ReliefTextureInputTime)
  {
    this->ReliefTextureInputTime = inputTime;
    this->ReliefTextureFilter->Update();
  }
  vtkImageData* relief = this->ReliefTextureFilter->GetOutput();
  vtkDataArray* texels = relief->GetPointData()->GetScalars();
  if (!texels || relief->GetNumberOfPoints() == 0)
  {
    return false; // the filter has said why
  }

  int dimensions[3];
  relief->GetDimensions(dimensions);
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  const int limit = vtkTextureObject::GetMaximumTextureSize(window);
  if (dimensions[0] > limit || dimensions[1] > limit)
  {
    if (this->OversizeReportTime <= relief->GetMTime())
    {
      this->OversizeReportTime.Modified(); // said once per height map
      vtkErrorMacro("The height map is " << dimensions[0] << "x" << dimensions[1]
                                         << " texels; this OpenGL takes textures of at most "
                                         << limit << "x" << limit
                                         << ". Resample it (vtkImageResize) to fit.");
    }
    return false;
  }

  if (this->DepthTexture->GetHandle() != 0 &&
    this->ReliefTextureUploadTime > relief->GetMTime())
  {
    return true;
  }

  // One 16-bit depth texture serves the searches and the shading, which rebuilds the
  // normal from it: the filter's depths lie on that grid, so it holds them exactly, in a
  // sixth of the bytes of float normals and depth. Only a normal map given with the
  // heights needs a texture of its own: its (nx, ny), nz >= 0 following from them.
  const vtkIdType texelCount = relief->GetNumberOfPoints();
  vtkNew<vtkUnsignedShortArray> depths;
  depths->SetNumberOfValues(texelCount);
  for (vtkIdType texel = 0; texel < texelCount; ++texel)
  {
    depths->SetValue(texel, static_cast<unsigned short>(std::lround(
      texels->GetComponent(texel, 3) * vtkReliefTextureFilter::DEPTH_LEVELS)));
  }
  bool uploaded = UploadTexture(this->DepthTexture, window, dimensions, depths, GL_R16, true);
  this->DepthTextureBytes = MipmappedBytes(dimensions[0], dimensions[1], 2);
  const bool inputNormals = this->ReliefTextureFilter->GetUseInputNormals();
  this->NormalTextureBytes = 0;
  if (inputNormals)
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetNumberOfComponents(2);
    normals->SetNumberOfTuples(texelCount);
    for (vtkIdType texel = 0; texel < texelCount; ++texel)
    {
      normals->SetTypedComponent(texel, 0, static_cast<float>(texels->GetComponent(texel, 0)));
      normals->SetTypedComponent(texel, 1, static_cast<float>(texels->GetComponent(texel, 1)));
    }
    uploaded = uploaded &&
      UploadTexture(this->NormalTexture, window, dimensions, normals, GL_RG16_SNORM, true);
    this->NormalTextureBytes = MipmappedBytes(dimensions[0], dimensions[1], 4);
  }
  else
  {
    this->NormalTexture->ReleaseGraphicsResources(window);
  }
  if (!uploaded)
  {
    vtkErrorMacro("Could not upload the " << dimensions[0] << "x" << dimensions[1]
                                          << " relief texture to the GPU.");
    return false;
  }
  if (inputNormals != this->InputNormals)
  {
    this->InputNormals = inputNormals;
    this->ShaderOptionsTime.Modified();
  }
  this->ReliefTextureUploadTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
namespace
{
bool NeedsAcceleration(int method)
{
  return method == vtkOpenGLReliefMapper::SAFETY_RADIUS ||
    method == vtkOpenGLReliefMapper::CONE_STEP || method == vtkOpenGLReliefMapper::MAXIMUM_MIPMAP;
}
}

vtkReliefAccelerationFilter* vtkOpenGLReliefMapper::NewAccelerationFilter(int method)
{
  switch (method)
  {
    case SAFETY_RADIUS:
      return vtkSafetyRadiusFilter::New();
    case CONE_STEP:
      return vtkConeStepMapFilter::New();
    case MAXIMUM_MIPMAP:
      return vtkMaximumMipmapFilter::New();
    default:
      return nullptr;
  }
}

void vtkOpenGLReliefMapper::UpdateAcceleration(vtkRenderer* ren)
{
  if (!this->SupportsSearchMethod(this->SearchMethod))
  {
    if (!this->WarnedUnsupportedSearchMethod)
    {
      this->WarnedUnsupportedSearchMethod = true;
      vtkWarningMacro(<< this->GetClassName() << " cannot search with "
                      << this->GetSearchMethodAsString() << ": "
                      << this->GetUnsupportedSearchReason() << " Searching with LinearBinary.");
    }
    this->SetActiveSearchMethod(LINEAR_BINARY);
    return;
  }
  if (!NeedsAcceleration(this->SearchMethod))
  {
    this->SetActiveSearchMethod(this->SearchMethod);
    return;
  }
  if (this->GetNumberOfInputConnections(2) > 0)
  {
    this->GetInputAlgorithm(2, 0)->Update();
  }
  vtkImageData* acceleration =
    this->GetAcceleration() ? this->GetAcceleration() : this->ComputeAcceleration();
  const bool current = acceleration && acceleration == this->UploadedAcceleration &&
    this->AccelerationMethod == this->SearchMethod &&
    this->AccelerationUploadTime > acceleration->GetMTime() &&
    this->AccelerationUploadTime > this->ReliefTextureUploadTime;
  if (!current)
  {
    // checked and uploaded once per change: any message is given once
    this->UploadedAcceleration = acceleration;
    this->AccelerationMethod = this->SearchMethod;
    this->AccelerationUploadTime.Modified();
    this->AccelerationUsable = acceleration && this->CheckAcceleration(acceleration) &&
      this->UploadAcceleration(ren, acceleration);
  }
  if (this->AccelerationUsable)
  {
    this->SetActiveSearchMethod(this->SearchMethod);
    return;
  }
  if (!this->WarnedAccelerationFallback)
  {
    this->WarnedAccelerationFallback = true;
    vtkWarningMacro("The " << this->GetSearchMethodAsString()
                           << " search has no usable acceleration image; searching with "
                              "LinearBinary instead.");
  }
  this->SetActiveSearchMethod(LINEAR_BINARY);
}

vtkImageData* vtkOpenGLReliefMapper::ComputeAcceleration()
{
  // only the image the chosen method reads, rebuilt only when its input or settings change
  if (!this->AccelerationFilter || this->AccelerationFilterMethod != this->SearchMethod)
  {
    this->AccelerationFilter = vtk::TakeSmartPointer(NewAccelerationFilter(this->SearchMethod));
    this->AccelerationFilterMethod = this->SearchMethod;
    vtkReliefForwardMessages(this->AccelerationFilter, this);
  }
  if (auto* safety = vtkSafetyRadiusFilter::SafeDownCast(this->AccelerationFilter))
  {
    safety->SetErrorTolerance(this->SafetyRadiusTolerance);
  }
  this->AccelerationFilter->SetInputData(this->ReliefTextureFilter->GetOutput());
  this->AccelerationFilter->Update();
  return this->AccelerationFilter->GetOutput();
}

bool vtkOpenGLReliefMapper::CheckAcceleration(vtkImageData* acceleration)
{
  int relief[3];
  this->ReliefTextureFilter->GetOutput()->GetDimensions(relief);
  // what the method's own filter would make of this height map
  auto producer = vtk::TakeSmartPointer(NewAccelerationFilter(this->SearchMethod));
  int expected[2];
  producer->GetOutputSize(relief[0], relief[1], expected);
  const int components = producer->GetOutputComponents();
  int dimensions[3];
  acceleration->GetDimensions(dimensions);
  vtkDataArray* values = acceleration->GetPointData()->GetScalars();
  if (values && values->GetDataType() == VTK_FLOAT &&
    values->GetNumberOfComponents() == components && dimensions[0] == expected[0] &&
    dimensions[1] == expected[1] && dimensions[2] == 1)
  {
    return true;
  }
  vtkErrorMacro("The acceleration image is "
    << dimensions[0] << "x" << dimensions[1] << "x" << dimensions[2] << " with "
    << (values ? values->GetNumberOfComponents() : 0) << " component(s) of "
    << (values ? values->GetDataTypeAsString() : "nothing") << "; the "
    << this->GetSearchMethodAsString() << " search of this " << relief[0] << "x" << relief[1]
    << " height map needs " << producer->GetClassName() << "'s output for it: " << expected[0] << "x"
    << expected[1] << ", " << components << " component(s) of float. Connect that filter's "
    << "output, or none to let the mapper build it.");
  return false;
}

bool vtkOpenGLReliefMapper::UploadAcceleration(vtkRenderer* ren, vtkImageData* acceleration)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  this->AccelerationTextureBytes = 0;
  // the cone map in two bytes a cell, rounded conservatively; the other maps as computed
  vtkSmartPointer<vtkDataArray> values = acceleration->GetPointData()->GetScalars();
  const bool cones = this->SearchMethod == CONE_STEP;
  if (cones)
  {
    values = EncodeConeMap(acceleration);
  }
  const unsigned int internalFormat = cones ? GL_RG8
    : values->GetNumberOfComponents() == 1  ? GL_R32F
                                            : GL_RG32F;
  if (!UploadTexture(this->AccelerationTexture, window, acceleration->GetDimensions(), values,
        internalFormat, false))
  {
    vtkErrorMacro("Could not upload the " << this->GetSearchMethodAsString()
                                          << " acceleration image to the GPU.");
    return false;
  }
  this->AccelerationTextureBytes = values->GetNumberOfValues() * values->GetDataTypeSize();
  return true;
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
  return std::string(vtkReliefTangentBasis) + vtkReliefTangentFrame;
}

std::string vtkOpenGLReliefMapper::GetFrameDefines()
{
  return "";
}

std::string vtkOpenGLReliefMapper::GetFrameShaderCode(const char* stage)
{
  return std::string("#define ") + stage + "\n" + this->GetFrameDefines() +
    this->GetFrameSource() + "\n#undef " + stage + "\n";
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
    this->DepthTexture->Activate();
    if (this->InputNormals)
    {
      this->NormalTexture->Activate();
    }
    if (NeedsAcceleration(this->ActiveSearchMethod))
    {
      this->AccelerationTexture->Activate();
    }
  }
}

void vtkOpenGLReliefMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* actor)
{
  if (this->DrawingRelief)
  {
    if (NeedsAcceleration(this->ActiveSearchMethod))
    {
      this->AccelerationTexture->Deactivate();
    }
    if (this->InputNormals)
    {
      this->NormalTexture->Deactivate();
    }
    this->DepthTexture->Deactivate();
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
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor) ||
    cellBO.ShaderSourceTime < this->ShaderOptionsTime;
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
  this->InsertReliefVertexShader(shaders[vtkShader::Vertex]);
  this->InsertReliefFragmentShader(shaders[vtkShader::Fragment], lightComplexity);
  this->InsertReliefGeometryShader(shaders[vtkShader::Geometry]);

  this->Superclass::ReplaceShaderValues(shaders, ren, actor);

  // VTK declares the model-to-view matrix only for lit surfaces.
  std::string vertexSource = shaders[vtkShader::Vertex]->GetSource();
  vtkShaderProgram::Substitute(vertexSource, "//VTK::Relief::CameraDec",
    vertexSource.find("uniform mat4 MCVCMatrix;") == std::string::npos
      ? "uniform mat4 MCVCMatrix;"
      : "");
  shaders[vtkShader::Vertex]->SetSource(vertexSource);

  this->ReplaceReliefLightVisibility(shaders[vtkShader::Fragment], lightComplexity);
  this->ReplaceReliefTextureReads(shaders[vtkShader::Fragment]);
}

void vtkOpenGLReliefMapper::ReplaceReliefTextureReads(vtkShader* fragmentShader)
{
  // VTK reads the actor's textures with implicit derivatives, which jump wherever the
  // hit jumps (relief edges, silhouettes) and pick far too coarse a level there: read
  // them at the level of the entry coordinates, as the relief itself is read.
  const std::regex implicitRead(R"(texture\((\w+), tcoordVCVSOutput\))");
  fragmentShader->SetSource(std::regex_replace(
    fragmentShader->GetSource(), implicitRead, "reliefTextureAtRay($1, tcoordVCVSOutput)"));
}

void vtkOpenGLReliefMapper::InsertReliefVertexShader(vtkShader* vertexShader)
{
  std::string vertexSource = vertexShader->GetSource();
  vtkShaderProgram::Substitute(vertexSource, "//VTK::PositionVC::Dec",
    "//VTK::PositionVC::Dec\n" + std::string(vtkReliefVertexDec) +
      this->GetFrameShaderCode("RELIEF_VERTEX_STAGE"));
  vtkShaderProgram::Substitute(vertexSource, "//VTK::CustomEnd::Impl",
    std::string(vtkReliefVertexImpl) + "\n  //VTK::CustomEnd::Impl");
  vertexShader->SetSource(vertexSource);
}

void vtkOpenGLReliefMapper::InsertReliefFragmentShader(
  vtkShader* fragmentShader, int lightComplexity)
{
  std::string declarations = vtkReliefFragmentDec;
  vtkShaderProgram::Substitute(declarations, "//VTK::Relief::Common", vtkReliefCommon);
  vtkShaderProgram::Substitute(declarations, "//VTK::Relief::Search",
    std::string(vtkReliefSearch) + vtkReliefGridSearch + vtkReliefSafetySearch +
      vtkReliefConeSearch);
  vtkShaderProgram::Substitute(
    declarations, "//VTK::Relief::Frame", this->GetFrameShaderCode("RELIEF_FRAGMENT_STAGE"));
  // VTK's texture and normal-map code reads tcoordVCVSOutput: make it read at the hit,
  // unless that slot carries the colour coordinates of scalars mapped through a texture.
  vtkShaderProgram::Substitute(declarations, "//VTK::Relief::TCoordAtHit",
    this->ColorTextureMap ? "" : "#define tcoordVCVSOutput reliefHitTCoord");
  std::string fragmentSource = fragmentShader->GetSource();
  // exact cell tests read a cell's four corners in one gather where GL offers it
  vtkShaderProgram::Substitute(fragmentSource, "//VTK::System::Dec",
    "//VTK::System::Dec\n#extension GL_ARB_texture_gather : enable\n");
  vtkShaderProgram::Substitute(fragmentSource, "//VTK::Edges::Dec",
    "//VTK::Edges::Dec\n" + this->GetSearchDefines() +
      (this->InputNormals ? "#define RELIEF_INPUT_NORMALS\n" : "") + declarations);
  vtkShaderProgram::Substitute(fragmentSource, "//VTK::UniformFlow::Impl",
    std::string(vtkReliefFragmentImpl) + "\n  //VTK::UniformFlow::Impl");
  vtkShaderProgram::Substitute(
    fragmentSource, "//VTK::Depth::Impl", "gl_FragDepth = reliefFragDepth;\n");
  if (lightComplexity > 0)
  {
    vtkShaderProgram::Substitute(fragmentSource, "//VTK::Normal::Impl",
      "//VTK::Normal::Impl\n"
      "  normalVCVSOutput = reliefLitNormalVC;\n"
      "  vertexVC = vec4(reliefHitVC, 1.0);\n");
  }
  vtkShaderProgram::Substitute(fragmentSource, "//VTK::DepthPeeling::Impl",
    "if (reliefDisplayMode == 1)\n"
    "  {\n"
    "    float reliefSamples = min(float(reliefViewHit.samples), 255.0);\n"
    "    gl_FragData[0] = vec4(reliefSamples / 255.0, 0.0, 0.0, 1.0);\n"
    "  }\n"
    "  //VTK::DepthPeeling::Impl");
  fragmentShader->SetSource(fragmentSource);
}

void vtkOpenGLReliefMapper::InsertReliefGeometryShader(vtkShader* geometryShader)
{
  // With a geometry shader (edges, wide lines) VTK renames the fragment inputs from
  // VSOutput to GSOutput: pass the frame through it.
  std::string geometrySource = geometryShader->GetSource();
  if (!geometrySource.empty())
  {
    vtkShaderProgram::Substitute(geometrySource, "//VTK::Normal::Dec",
      "//VTK::Normal::Dec\n" + std::string(vtkReliefGeometryDec) +
        this->GetFrameShaderCode("RELIEF_GEOMETRY_STAGE"));
    vtkShaderProgram::Substitute(geometrySource, "//VTK::Normal::Impl",
      std::string("//VTK::Normal::Impl\n") + vtkReliefGeometryImpl);
    geometryShader->SetSource(geometrySource);
  }
}

void vtkOpenGLReliefMapper::ReplaceReliefLightVisibility(
  vtkShader* fragmentShader, int lightComplexity)
{
  if (lightComplexity < 2)
  {
    return; // unlit, or a headlight: it lights what the camera sees, no self-shadow
  }
  // Each light's diffuse term of VTK's (non-PBR) lighting code is weighted by the
  // visibility of that light from the hit; the specular term follows through sign(df).
  std::string source = fragmentShader->GetSource();
  const std::regex directional(
    R"(df = max\(0\.0, dot\(normalVCVSOutput, -lightDirectionVC(\d+)\)\);)");
  std::string shadowed = std::regex_replace(source, directional,
    "df = max(0.0, dot(normalVCVSOutput, -lightDirectionVC$1)) * "
    "reliefShadow(-lightDirectionVC$1);");
  vtkShaderProgram::Substitute(shadowed,
    "df = max(0.0,attenuation*dot(normalVCVSOutput, -vertLightDirectionVC));",
    "df = max(0.0,attenuation*dot(normalVCVSOutput, -vertLightDirectionVC)) * "
    "reliefShadow(-vertLightDirectionVC);");
  if (shadowed == source)
  {
    if (this->SelfShadowing && !this->WarnedNoSelfShadowing)
    {
      this->WarnedNoSelfShadowing = true;
      vtkWarningMacro("Self-shadowing is not available with this lighting model "
                      "(physically based interpolation); the relief is lit without it.");
    }
    return;
  }
  fragmentShader->SetSource(shadowed);
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  vtkShaderProgram* program = cellBO.Program;
  if (!this->DrawingRelief || !program->IsUniformUsed("reliefDepthTexture"))
  {
    return;
  }
  program->SetUniformi("reliefDepthTexture", this->DepthTexture->GetTextureUnit());
  const float textureSize[2] = { static_cast<float>(this->DepthTexture->GetWidth()),
    static_cast<float>(this->DepthTexture->GetHeight()) };
  program->SetUniform2f("reliefTextureSize", textureSize);
  if (this->InputNormals)
  {
    program->SetUniformi("reliefNormalTexture", this->NormalTexture->GetTextureUnit());
    program->SetUniformf(
      "reliefNormalRatio", static_cast<float>(this->ReliefTextureFilter->GetDepthToTexelRatio()));
  }
  program->SetUniformf("reliefDepthScale", static_cast<float>(this->DrawnDepthScale));
  program->SetUniformi("reliefLinearSteps", this->LinearSteps);
  program->SetUniformi("reliefBinarySteps", this->BinarySteps);
  program->SetUniformi("reliefSelfShadowing", this->SelfShadowing ? 1 : 0);
  program->SetUniformi("reliefDepthCorrection", this->DepthCorrection ? 1 : 0);
  program->SetUniformi("reliefDisplayMode", this->DisplayMode);
  program->SetUniformi("reliefTwoSided", this->TwoSidedRelief ? 1 : 0);
  if (NeedsAcceleration(this->ActiveSearchMethod))
  {
    program->SetUniformi("reliefAccelerationTexture", this->AccelerationTexture->GetTextureUnit());
  }
  if (this->ActiveSearchMethod == CONE_STEP)
  {
    const float coneRange[2] = { static_cast<float>(vtkConeStepMapFilter::GetMaximumRatio(
                                   this->AccelerationTexture->GetWidth(),
                                   this->AccelerationTexture->GetHeight())),
      static_cast<float>(vtkConeStepMapFilter::RATIO_OCTAVES) };
    program->SetUniform2f("reliefConeRange", coneRange);
  }
  if (this->ActiveSearchMethod == MAXIMUM_MIPMAP)
  {
    int relief[3];
    this->ReliefTextureFilter->GetOutput()->GetDimensions(relief);
    float rows[32] = {};
    int origin[2];
    int size[2];
    int top = 0;
    while (top + 1 < 32 &&
      vtkMaximumMipmapFilter::GetLevelPlacement(relief[0], relief[1], top + 1, origin, size))
    {
      rows[++top] = static_cast<float>(origin[1]);
    }
    program->SetUniformi("reliefPyramidTop", top);
    program->SetUniform1fv("reliefPyramidRows", 32, rows);
  }
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
  return this->DepthTextureBytes + this->NormalTextureBytes +
    (NeedsAcceleration(this->ActiveSearchMethod) ? this->AccelerationTextureBytes : 0);
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->DepthTexture->ReleaseGraphicsResources(window);
  this->NormalTexture->ReleaseGraphicsResources(window);
  this->AccelerationTexture->ReleaseGraphicsResources(window);
  this->DepthTextureBytes = 0;
  this->NormalTextureBytes = 0;
  this->AccelerationTextureBytes = 0;
  this->UploadedAcceleration = nullptr;
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "SearchMethod: " << this->GetSearchMethodAsString() << "\n";
  os << indent << "ActiveSearchMethod: " << GetSearchMethodAsString(this->ActiveSearchMethod)
     << "\n";
  os << indent << "Acceleration: " << this->GetAcceleration() << "\n";
  os << indent << "LinearSteps: " << this->LinearSteps << "\n";
  os << indent << "BinarySteps: " << this->BinarySteps << "\n";
  os << indent << "SafetyRadiusTolerance: " << this->SafetyRadiusTolerance << "\n";
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "SelfShadowing: " << this->SelfShadowing << "\n";
  os << indent << "DepthCorrection: " << this->DepthCorrection << "\n";
  os << indent << "TwoSidedRelief: " << this->TwoSidedRelief << "\n";
  os << indent << "BackFacesLeftOut: " << this->BackFacesLeftOut << "\n";
  os << indent << "DisplayMode: " << (this->DisplayMode == SAMPLE_COUNT ? "SampleCount" : "Shaded")
     << "\n";
  os << indent << "HeightMap: " << this->GetHeightMap() << "\n";
  os << indent << "TextureBytes: " << this->GetTextureBytes() << "\n";
  os << indent << "ReliefTextureFilter:\n";
  this->ReliefTextureFilter->PrintSelf(os, indent.GetNextIndent());
  if (this->TangentFrame)
  {
    os << indent << "TangentFrame:\n";
    this->TangentFrame->PrintSelf(os, indent.GetNextIndent());
  }
}
