#include "vtkOpenGLReliefTextures.h"

#include "vtkCommand.h"
#include "vtkConeStepMapFilter.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkReliefAccelerationFilter.h"
#include "vtkReliefForwardMessages.h"
#include "vtkReliefSearchMethod.h"
#include "vtkReliefTextureFilter.h"
#include "vtkSMPTools.h"
#include "vtkShaderProgram.h"
#include "vtkSlopeMipmapFilter.h"
#include "vtkSmartPointer.h"
#include "vtkTextureObject.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"
#include "vtkUnsignedShortArray.h"
#include "vtkWindow.h"
#include "vtk_glew.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

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

// A repeating 2D texture of `values` (one to four components; four unsigned integers are
// read as integers) in `internalFormat`, read with `filter`:
// vtkTextureObject::LinearMipmapLinear (trilinear, its mipmaps made), Linear (bilinear, at
// full resolution) or Nearest (texel by texel: the acceleration images, one texel per
// cell, repeating as the height map does).
bool UploadTexture(vtkTextureObject* texture, vtkOpenGLRenderWindow* window,
  const int dimensions[3], vtkDataArray* values, unsigned int internalFormat, int filter)
{
  const bool mipmapped = filter == vtkTextureObject::LinearMipmapLinear;
  const int components = values->GetNumberOfComponents();
  texture->SetContext(window);
  // vtkTextureObject keeps the formats and data type of an earlier upload, and one
  // method's image would be read with another's layout
  texture->ResetFormatAndType();
  texture->SetInternalFormat(internalFormat);
  // integer images (the slope pyramid's codes) are read through an integer format
  const bool integers = values->GetDataType() == VTK_UNSIGNED_INT;
  texture->SetFormat(components == 1 ? GL_RED
      : components == 2             ? GL_RG
      : components == 3             ? GL_RGB
      : integers                    ? GL_RGBA_INTEGER
                                    : GL_RGBA);
  texture->SetWrapS(vtkTextureObject::Repeat);
  texture->SetWrapT(vtkTextureObject::Repeat);
  texture->SetMinificationFilter(filter);
  texture->SetMagnificationFilter(mipmapped ? vtkTextureObject::Linear : filter);
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

// vtkSlopeMipmapFilter's atlas of a reliefSize map as uploaded: four integers a node
// (PackNode), from level 1's first column on: SlopeMipmap solves single cells from the
// height map and never reads level 0 (vtkReliefGridSearch.glsl's RELIEF_SLOPE_NODE), two
// thirds of the atlas. `dimensions` become the uploaded image's (the last column where the
// atlas has no level 1).
vtkSmartPointer<vtkDataArray> EncodeSlopeMipmap(
  vtkImageData* atlas, const int reliefSize[2], int dimensions[3])
{
  vtkDataArray* nodes = atlas->GetPointData()->GetScalars();
  atlas->GetDimensions(dimensions);
  const int atlasWidth = dimensions[0];
  int levelOne[2];
  int levelOneSize[2];
  const int first = vtkSlopeMipmapFilter::GetLevelPlacement(
                      reliefSize[0], reliefSize[1], 1, levelOne, levelOneSize)
    ? levelOne[0]
    : atlasWidth - 1;
  dimensions[0] = atlasWidth - first;
  auto packed = vtkSmartPointer<vtkUnsignedIntArray>::New();
  packed->SetNumberOfComponents(4);
  packed->SetNumberOfTuples(static_cast<vtkIdType>(dimensions[0]) * dimensions[1]);
  vtkSMPTools::For(0, packed->GetNumberOfTuples(), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType node = begin; node < end; ++node)
    {
      const vtkIdType row = node / dimensions[0];
      const vtkIdType column = first + node % dimensions[0];
      double values[8];
      nodes->GetTuple(row * atlasWidth + column, values);
      vtkSlopeMipmapFilter::PackNode(values, packed->GetPointer(4 * node));
    }
  });
  return packed;
}

// Runs `algorithm` with its errors and warnings the reporter's: a shared texture is made
// once, by whichever helper asks for it first.
void UpdateReportingTo(vtkAlgorithm* algorithm, vtkObject* reporter)
{
  vtkReliefForwardMessages(algorithm, reporter);
  algorithm->Update();
  algorithm->RemoveObservers(vtkCommand::ErrorEvent);
  algorithm->RemoveObservers(vtkCommand::WarningEvent);
}

// Registries of what helpers share, keyed by what makes it; the helpers own the entries.
template <typename Registry>
void ForgetReleased(Registry& registry)
{
  for (auto entry = registry.begin(); entry != registry.end();)
  {
    entry = entry->second.expired() ? registry.erase(entry) : std::next(entry);
  }
}

}

// One relief texture: its window, the height map (held, so its address stays its own),
// its modification time and the four settings of vtkReliefTextureFilter.
using ReliefKey = std::tuple<vtkWindow*, vtkImageData*, vtkMTimeType, int, int, double, bool>;
// One acceleration image of a relief: its kind (methods reading the same image share
// it), its setting, and the precomputed image with its modification time when one is
// given.
using AccelerationKey = std::tuple<const vtkOpenGLReliefTextures::SharedRelief*, int, double,
  vtkImageData*, vtkMTimeType>;

struct vtkOpenGLReliefTextures::SharedRelief
{
  vtkWindow* Window = nullptr;
  vtkNew<vtkReliefTextureFilter> Filter;  // its output is the relief texture
  vtkNew<vtkTextureObject> DepthTexture;  // 16-bit depth: searched, and shaded from
  vtkNew<vtkTextureObject> NormalTexture; // (nx, ny) of an input normal map, if one is used
  bool InputNormals = false;              // NormalTexture holds the normals the shading reads
  bool Failed = false; // not drawable, and said why: the helpers asking later say nothing
  int Size[2] = { 0, 0 };
  vtkIdType DepthBytes = 0;
  vtkIdType NormalBytes = 0;

  vtkImageData* GetRelief() { return this->Filter->GetOutput(); }
  // Zero when the window released the textures, as it does when it closes
  vtkIdType GetBytes() const
  {
    return this->DepthTexture->GetHandle() != 0 ? this->DepthBytes + this->NormalBytes : 0;
  }
  bool Upload(vtkOpenGLRenderWindow* window, vtkObject* reporter);
};

struct vtkOpenGLReliefTextures::SharedAcceleration
{
  std::shared_ptr<SharedRelief> Relief; // made of it
  vtkSmartPointer<vtkReliefAccelerationFilter> Filter; // when built here
  vtkSmartPointer<vtkImageData> Image;  // the filter's output, or the precomputed image
  vtkNew<vtkTextureObject> Texture;     // what the search method reads besides the depths
  bool Failed = false;
  vtkIdType Bytes = 0;

  vtkIdType GetBytes() const { return this->Texture->GetHandle() != 0 ? this->Bytes : 0; }
  bool Check(const vtkReliefSearchMethod& method, vtkObject* reporter);
  bool Upload(
    vtkOpenGLRenderWindow* window, const vtkReliefSearchMethod& method, vtkObject* reporter);
};

namespace
{
std::map<ReliefKey, std::weak_ptr<vtkOpenGLReliefTextures::SharedRelief>>& SharedReliefs()
{
  static std::map<ReliefKey, std::weak_ptr<vtkOpenGLReliefTextures::SharedRelief>> registry;
  return registry;
}

std::map<AccelerationKey, std::weak_ptr<vtkOpenGLReliefTextures::SharedAcceleration>>&
SharedAccelerations()
{
  static std::map<AccelerationKey, std::weak_ptr<vtkOpenGLReliefTextures::SharedAcceleration>>
    registry;
  return registry;
}
}

vtkOpenGLReliefTextures::vtkOpenGLReliefTextures() = default;

vtkOpenGLReliefTextures::~vtkOpenGLReliefTextures() = default;

//------------------------------------------------------------------------------
vtkImageData* vtkOpenGLReliefTextures::UpdateRelief(
  vtkOpenGLRenderWindow* window, vtkImageData* heights, vtkReliefTextureFilter* settings)
{
  const ReliefKey key{ window, heights, heights->GetMTime(), settings->GetInputConvention(),
    settings->GetComponent(), settings->GetDepthToTexelRatio(),
    settings->GetUseInputNormals() != 0 };
  auto& registry = SharedReliefs();
  std::shared_ptr<SharedRelief> shared = registry[key].lock();
  if (!shared)
  {
    ForgetReleased(registry); // when an entry is made, not at every frame
    shared = std::make_shared<SharedRelief>();
    shared->Window = window;
    shared->Filter->SetInputConvention(std::get<3>(key));
    shared->Filter->SetComponent(std::get<4>(key));
    shared->Filter->SetDepthToTexelRatio(std::get<5>(key));
    shared->Filter->SetUseInputNormals(std::get<6>(key));
    shared->InputNormals = std::get<6>(key);
    shared->Filter->SetInputData(heights);
    UpdateReportingTo(shared->Filter, this->GetReporter());
    vtkImageData* relief = shared->GetRelief();
    shared->Failed = !relief->GetPointData()->GetScalars() || relief->GetNumberOfPoints() == 0;
    registry[key] = shared;
  }
  if (this->Acceleration && this->Acceleration->Relief != shared)
  {
    this->Acceleration.reset(); // of the relief before: released if it was the last user
  }
  this->Relief = shared;
  // uploaded once; again only if the window released it
  if (!shared->Failed && shared->DepthTexture->GetHandle() == 0)
  {
    shared->Failed = !shared->Upload(window, this->GetReporter());
  }
  return shared->Failed ? nullptr : shared->GetRelief();
}

bool vtkOpenGLReliefTextures::SharedRelief::Upload(
  vtkOpenGLRenderWindow* window, vtkObject* reporter)
{
  vtkImageData* relief = this->GetRelief();
  int dimensions[3];
  relief->GetDimensions(dimensions);
  const int limit = vtkTextureObject::GetMaximumTextureSize(window);
  if (dimensions[0] > limit || dimensions[1] > limit)
  {
    vtkErrorWithObjectMacro(reporter,
      "The height map is " << dimensions[0] << "x" << dimensions[1]
                           << " texels; this OpenGL takes textures of at most " << limit << "x"
                           << limit << ". Resample it (vtkImageResize) to fit.");
    return false;
  }

  // One 16-bit depth texture serves the searches and the shading, which rebuilds the
  // normal from it: the filter's depths lie on that grid, so it holds them exactly, in an
  // eighth of the bytes of float normals and depth; without mipmaps, as every read is at
  // full resolution. Only a normal map given with the heights needs a texture of its own:
  // its (nx, ny), nz >= 0 following from them, mipmapped as colour textures are.
  vtkDataArray* texels = relief->GetPointData()->GetScalars();
  const vtkIdType texelCount = relief->GetNumberOfPoints();
  vtkNew<vtkUnsignedShortArray> depths;
  depths->SetNumberOfValues(texelCount);
  for (vtkIdType texel = 0; texel < texelCount; ++texel)
  {
    depths->SetValue(texel, static_cast<unsigned short>(std::lround(
      texels->GetComponent(texel, 3) * vtkReliefTextureFilter::DEPTH_LEVELS)));
  }
  bool uploaded = UploadTexture(
    this->DepthTexture, window, dimensions, depths, GL_R16, vtkTextureObject::Linear);
  this->DepthBytes = 2 * relief->GetNumberOfPoints();
  this->NormalBytes = 0;
  if (this->InputNormals)
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
      UploadTexture(this->NormalTexture, window, dimensions, normals, GL_RG16_SNORM,
        vtkTextureObject::LinearMipmapLinear);
    this->NormalBytes = MipmappedBytes(dimensions[0], dimensions[1], 4);
  }
  if (!uploaded)
  {
    vtkErrorWithObjectMacro(reporter,
      "Could not upload the " << dimensions[0] << "x" << dimensions[1]
                              << " relief texture to the GPU.");
    this->DepthTexture->ReleaseGraphicsResources(window);
    this->NormalTexture->ReleaseGraphicsResources(window);
    return false;
  }
  this->Size[0] = dimensions[0];
  this->Size[1] = dimensions[1];
  return true;
}

bool vtkOpenGLReliefTextures::GetInputNormals() const
{
  return this->Relief && this->Relief->InputNormals;
}

//------------------------------------------------------------------------------
bool vtkOpenGLReliefTextures::UpdateAcceleration(vtkOpenGLRenderWindow* window,
  const vtkReliefSearchMethod& method, vtkImageData* precomputed, double safetyRadiusTolerance)
{
  if (!method.NeedsAcceleration() || !this->Relief || this->Relief->Failed)
  {
    this->Acceleration.reset(); // none read: released if this was the last user
    return !method.NeedsAcceleration();
  }
  // the setting counts only where the method's own filter reads it
  const double setting = precomputed || !method.ConfigureFilter ? 0.0 : safetyRadiusTolerance;
  const AccelerationKey key{ this->Relief.get(), method.GetAccelerationKind(), setting, precomputed,
    precomputed ? precomputed->GetMTime() : 0 };
  auto& registry = SharedAccelerations();
  std::shared_ptr<SharedAcceleration> shared = registry[key].lock();
  if (!shared)
  {
    ForgetReleased(registry); // when an entry is made, not at every frame
    shared = std::make_shared<SharedAcceleration>();
    shared->Relief = this->Relief;
    shared->Image = precomputed;
    if (!precomputed)
    {
      // only the image the chosen method reads, built once per relief and setting
      shared->Filter = vtk::TakeSmartPointer(method.NewAccelerationFilter());
      if (method.ConfigureFilter)
      {
        method.ConfigureFilter(shared->Filter, setting);
      }
      shared->Filter->SetInputData(this->Relief->GetRelief());
      UpdateReportingTo(shared->Filter, this->GetReporter());
      shared->Image = shared->Filter->GetOutput();
    }
    shared->Failed = precomputed && !shared->Check(method, this->GetReporter());
    registry[key] = shared;
  }
  this->Acceleration = shared;
  if (!shared->Failed && shared->Texture->GetHandle() == 0)
  {
    shared->Failed = !shared->Upload(window, method, this->GetReporter());
  }
  return !shared->Failed;
}

bool vtkOpenGLReliefTextures::SharedAcceleration::Check(
  const vtkReliefSearchMethod& method, vtkObject* reporter)
{
  int reliefSize[3];
  this->Relief->GetRelief()->GetDimensions(reliefSize);
  // what the method's own filter would make of this height map
  auto producer = vtk::TakeSmartPointer(method.NewAccelerationFilter());
  int expected[2];
  producer->GetOutputSize(reliefSize[0], reliefSize[1], expected);
  const int components = producer->GetOutputComponents();
  int dimensions[3];
  this->Image->GetDimensions(dimensions);
  vtkDataArray* values = this->Image->GetPointData()->GetScalars();
  if (values && values->GetDataType() == VTK_FLOAT &&
    values->GetNumberOfComponents() == components && dimensions[0] == expected[0] &&
    dimensions[1] == expected[1] && dimensions[2] == 1)
  {
    return true;
  }
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

bool vtkOpenGLReliefTextures::SharedAcceleration::Upload(
  vtkOpenGLRenderWindow* window, const vtkReliefSearchMethod& method, vtkObject* reporter)
{
  vtkSmartPointer<vtkDataArray> values = this->Image->GetPointData()->GetScalars();
  if (!values)
  {
    return false; // its filter has said why
  }
  int dimensions[3];
  this->Image->GetDimensions(dimensions);
  const bool cones = method.Encoding == vtkReliefSearchMethod::CONE_BYTES;
  if (cones)
  {
    values = EncodeConeMap(this->Image); // rounded conservatively
  }
  else if (method.Encoding == vtkReliefSearchMethod::SLOPE_CODES)
  {
    values = EncodeSlopeMipmap(this->Image, this->Relief->Size, dimensions);
  }
  const int components = values->GetNumberOfComponents();
  const unsigned int internalFormat = cones ? GL_RG8
    : values->GetDataType() == VTK_UNSIGNED_INT ? GL_RGBA32UI
    : components == 1                       ? GL_R32F
    : components == 2                       ? GL_RG32F
    : components == 3                       ? GL_RGB32F
                                            : GL_RGBA32F;
  if (!UploadTexture(this->Texture, window, dimensions, values, internalFormat,
        vtkTextureObject::Nearest))
  {
    vtkErrorWithObjectMacro(
      reporter, "Could not upload the " << method.Name << " acceleration image to the GPU.");
    this->Texture->ReleaseGraphicsResources(window);
    return false;
  }
  this->Bytes = values->GetNumberOfValues() * values->GetDataTypeSize();
  return true;
}

//------------------------------------------------------------------------------
void vtkOpenGLReliefTextures::Activate(const vtkReliefSearchMethod& method)
{
  this->Relief->DepthTexture->Activate();
  if (this->Relief->InputNormals)
  {
    this->Relief->NormalTexture->Activate();
  }
  if (method.NeedsAcceleration())
  {
    this->Acceleration->Texture->Activate();
  }
}

void vtkOpenGLReliefTextures::Deactivate(const vtkReliefSearchMethod& method)
{
  if (method.NeedsAcceleration())
  {
    this->Acceleration->Texture->Deactivate();
  }
  if (this->Relief->InputNormals)
  {
    this->Relief->NormalTexture->Deactivate();
  }
  this->Relief->DepthTexture->Deactivate();
}

void vtkOpenGLReliefTextures::SetShaderParameters(
  vtkShaderProgram* program, const vtkReliefSearchMethod& method)
{
  vtkTextureObject* depths = this->Relief->DepthTexture;
  program->SetUniformi("reliefDepthTexture", depths->GetTextureUnit());
  const float textureSize[2] = { static_cast<float>(depths->GetWidth()),
    static_cast<float>(depths->GetHeight()) };
  program->SetUniform2f("reliefTextureSize", textureSize);
  if (this->Relief->InputNormals)
  {
    program->SetUniformi("reliefNormalTexture", this->Relief->NormalTexture->GetTextureUnit());
  }
  if (method.NeedsAcceleration())
  {
    program->SetUniformi(
      "reliefAccelerationTexture", this->Acceleration->Texture->GetTextureUnit());
  }
  if (method.SetUniforms)
  {
    method.SetUniforms(program, this->Relief->Size);
  }
}

vtkIdType vtkOpenGLReliefTextures::GetTextureBytes(const vtkReliefSearchMethod& method) const
{
  const vtkIdType relief = this->Relief ? this->Relief->GetBytes() : 0;
  return relief +
    (method.NeedsAcceleration() && this->Acceleration ? this->Acceleration->GetBytes() : 0);
}

vtkIdType vtkOpenGLReliefTextures::GetTextureBytesInUse(vtkWindow* window)
{
  vtkIdType bytes = 0;
  for (const auto& entry : SharedReliefs())
  {
    const auto relief = entry.second.lock();
    bytes += relief && relief->Window == window ? relief->GetBytes() : 0;
  }
  for (const auto& entry : SharedAccelerations())
  {
    const auto acceleration = entry.second.lock();
    bytes += acceleration && acceleration->Relief->Window == window ? acceleration->GetBytes() : 0;
  }
  return bytes;
}

void vtkOpenGLReliefTextures::ReleaseGraphicsResources(vtkWindow*)
{
  // the last holder of a shared texture deletes it, with its context current
  this->Acceleration.reset();
  this->Relief.reset();
}

void vtkOpenGLReliefTextures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Owner: " << this->Owner << "\n";
  if (this->Relief)
  {
    os << indent << "ReliefSize: " << this->Relief->Size[0] << "x" << this->Relief->Size[1]
       << "\n";
    os << indent << "InputNormals: " << this->Relief->InputNormals << "\n";
    os << indent << "ReliefTextureBytes: " << this->Relief->GetBytes() << "\n";
  }
  else
  {
    os << indent << "Relief: (none)\n";
  }
  if (this->Acceleration)
  {
    os << indent << "AccelerationTextureBytes: " << this->Acceleration->GetBytes() << "\n";
    os << indent << "AccelerationUsable: " << !this->Acceleration->Failed << "\n";
  }
  else
  {
    os << indent << "Acceleration: (none)\n";
  }
}
