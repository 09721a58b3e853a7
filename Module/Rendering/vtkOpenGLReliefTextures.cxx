#include "vtkOpenGLReliefTextures.h"

#include "vtkConeStepMapFilter.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkReliefAccelerationFilter.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefSearchMethod.h"
#include "vtkReliefTextureFilter.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkOpenGLReliefTextures);

namespace
{
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
}

vtkOpenGLReliefTextures::vtkOpenGLReliefTextures() = default;

vtkOpenGLReliefTextures::~vtkOpenGLReliefTextures() = default;

//------------------------------------------------------------------------------
bool vtkOpenGLReliefTextures::UploadRelief(
  vtkOpenGLRenderWindow* window, vtkImageData* relief, bool inputNormals)
{
  // uploaded already: nothing to ask of GL, every frame
  if (this->DepthTexture->GetHandle() != 0 && this->ReliefUploadTime > relief->GetMTime())
  {
    return true;
  }
  int dimensions[3];
  relief->GetDimensions(dimensions);
  const int limit = vtkTextureObject::GetMaximumTextureSize(window);
  if (dimensions[0] > limit || dimensions[1] > limit)
  {
    if (this->OversizeReportTime <= relief->GetMTime())
    {
      this->OversizeReportTime.Modified(); // said once per height map
      vtkObject* reporter = this->GetReporter();
      vtkErrorWithObjectMacro(reporter,
        "The height map is " << dimensions[0] << "x" << dimensions[1]
                             << " texels; this OpenGL takes textures of at most " << limit << "x"
                             << limit << ". Resample it (vtkImageResize) to fit.");
    }
    return false;
  }

  // One 16-bit depth texture serves the searches and the shading, which rebuilds the
  // normal from it: the filter's depths lie on that grid, so it holds them exactly, in a
  // sixth of the bytes of float normals and depth. Only a normal map given with the
  // heights needs a texture of its own: its (nx, ny), nz >= 0 following from them.
  vtkDataArray* texels = relief->GetPointData()->GetScalars();
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
    vtkObject* reporter = this->GetReporter();
    vtkErrorWithObjectMacro(reporter,
      "Could not upload the " << dimensions[0] << "x" << dimensions[1]
                              << " relief texture to the GPU.");
    return false;
  }
  this->InputNormals = inputNormals;
  this->ReliefSize[0] = dimensions[0];
  this->ReliefSize[1] = dimensions[1];
  this->ReliefUploadTime.Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkOpenGLReliefTextures::UpdateAcceleration(vtkOpenGLRenderWindow* window,
  const vtkReliefSearchMethod& method, vtkImageData* relief, vtkImageData* precomputed,
  double safetyRadiusTolerance)
{
  vtkImageData* acceleration =
    precomputed ? precomputed : this->BuildAcceleration(method, relief, safetyRadiusTolerance);
  const bool current = acceleration && acceleration == this->UploadedAcceleration &&
    this->AccelerationMethod == method.Id &&
    this->AccelerationUploadTime > acceleration->GetMTime() &&
    this->AccelerationUploadTime > this->ReliefUploadTime;
  if (!current)
  {
    // checked and uploaded once per change: any message is given once
    this->UploadedAcceleration = acceleration;
    this->AccelerationMethod = method.Id;
    this->AccelerationUploadTime.Modified();
    this->AccelerationUsable = acceleration &&
      this->CheckAcceleration(method, relief, acceleration) &&
      this->UploadAcceleration(window, method, acceleration);
  }
  return this->AccelerationUsable;
}

vtkImageData* vtkOpenGLReliefTextures::BuildAcceleration(
  const vtkReliefSearchMethod& method, vtkImageData* relief, double safetyRadiusTolerance)
{
  // only the image the chosen method reads, rebuilt only when its input or settings change
  if (!this->AccelerationFilter || this->AccelerationFilterMethod != method.Id)
  {
    this->AccelerationFilter = vtk::TakeSmartPointer(method.NewAccelerationFilter());
    this->AccelerationFilterMethod = method.Id;
    vtkReliefForwardMessages(this->AccelerationFilter, this->GetReporter());
  }
  if (method.ConfigureFilter)
  {
    method.ConfigureFilter(this->AccelerationFilter, safetyRadiusTolerance);
  }
  this->AccelerationFilter->SetInputData(relief);
  this->AccelerationFilter->Update();
  return this->AccelerationFilter->GetOutput();
}

bool vtkOpenGLReliefTextures::CheckAcceleration(
  const vtkReliefSearchMethod& method, vtkImageData* relief, vtkImageData* acceleration)
{
  int reliefSize[3];
  relief->GetDimensions(reliefSize);
  // what the method's own filter would make of this height map
  auto producer = vtk::TakeSmartPointer(method.NewAccelerationFilter());
  int expected[2];
  producer->GetOutputSize(reliefSize[0], reliefSize[1], expected);
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
  vtkObject* reporter = this->GetReporter();
  vtkErrorWithObjectMacro(reporter, "The acceleration image is "
    << dimensions[0] << "x" << dimensions[1] << "x" << dimensions[2] << " with "
    << (values ? values->GetNumberOfComponents() : 0) << " component(s) of "
    << (values ? values->GetDataTypeAsString() : "nothing") << "; the " << method.Name
    << " search of this " << reliefSize[0] << "x" << reliefSize[1] << " height map needs "
    << producer->GetClassName() << "'s output for it: " << expected[0] << "x" << expected[1]
    << ", " << components << " component(s) of float. Connect that filter's "
    << "output, or none to let the mapper build it.");
  return false;
}

bool vtkOpenGLReliefTextures::UploadAcceleration(vtkOpenGLRenderWindow* window,
  const vtkReliefSearchMethod& method, vtkImageData* acceleration)
{
  this->AccelerationTextureBytes = 0;
  vtkSmartPointer<vtkDataArray> values = acceleration->GetPointData()->GetScalars();
  const bool cones = method.Encoding == vtkReliefSearchMethod::CONE_BYTES;
  if (cones)
  {
    values = EncodeConeMap(acceleration); // rounded conservatively
  }
  const unsigned int internalFormat = cones ? GL_RG8
    : values->GetNumberOfComponents() == 1  ? GL_R32F
                                            : GL_RG32F;
  if (!UploadTexture(this->AccelerationTexture, window, acceleration->GetDimensions(), values,
        internalFormat, false))
  {
    vtkObject* reporter = this->GetReporter();
    vtkErrorWithObjectMacro(
      reporter, "Could not upload the " << method.Name << " acceleration image to the GPU.");
    return false;
  }
  this->AccelerationTextureBytes = values->GetNumberOfValues() * values->GetDataTypeSize();
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefTextures::Activate(const vtkReliefSearchMethod& method)
{
  this->DepthTexture->Activate();
  if (this->InputNormals)
  {
    this->NormalTexture->Activate();
  }
  if (method.NeedsAcceleration())
  {
    this->AccelerationTexture->Activate();
  }
}

void vtkOpenGLReliefTextures::Deactivate(const vtkReliefSearchMethod& method)
{
  if (method.NeedsAcceleration())
  {
    this->AccelerationTexture->Deactivate();
  }
  if (this->InputNormals)
  {
    this->NormalTexture->Deactivate();
  }
  this->DepthTexture->Deactivate();
}

void vtkOpenGLReliefTextures::SetShaderParameters(
  vtkShaderProgram* program, const vtkReliefSearchMethod& method)
{
  program->SetUniformi("reliefDepthTexture", this->DepthTexture->GetTextureUnit());
  const float textureSize[2] = { static_cast<float>(this->DepthTexture->GetWidth()),
    static_cast<float>(this->DepthTexture->GetHeight()) };
  program->SetUniform2f("reliefTextureSize", textureSize);
  if (this->InputNormals)
  {
    program->SetUniformi("reliefNormalTexture", this->NormalTexture->GetTextureUnit());
  }
  if (method.NeedsAcceleration())
  {
    program->SetUniformi("reliefAccelerationTexture", this->AccelerationTexture->GetTextureUnit());
  }
  if (method.SetUniforms)
  {
    method.SetUniforms(program, this->ReliefSize);
  }
}

vtkIdType vtkOpenGLReliefTextures::GetTextureBytes(const vtkReliefSearchMethod& method) const
{
  return this->DepthTextureBytes + this->NormalTextureBytes +
    (method.NeedsAcceleration() ? this->AccelerationTextureBytes : 0);
}

void vtkOpenGLReliefTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  this->DepthTexture->ReleaseGraphicsResources(window);
  this->NormalTexture->ReleaseGraphicsResources(window);
  this->AccelerationTexture->ReleaseGraphicsResources(window);
  this->DepthTextureBytes = 0;
  this->NormalTextureBytes = 0;
  this->AccelerationTextureBytes = 0;
  this->UploadedAcceleration = nullptr;
}

void vtkOpenGLReliefTextures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Owner: " << this->Owner << "\n";
  os << indent << "ReliefSize: " << this->ReliefSize[0] << "x" << this->ReliefSize[1] << "\n";
  os << indent << "InputNormals: " << this->InputNormals << "\n";
  os << indent << "DepthTextureBytes: " << this->DepthTextureBytes << "\n";
  os << indent << "NormalTextureBytes: " << this->NormalTextureBytes << "\n";
  os << indent << "AccelerationTextureBytes: " << this->AccelerationTextureBytes << "\n";
  os << indent << "AccelerationUsable: " << this->AccelerationUsable << "\n";
}
