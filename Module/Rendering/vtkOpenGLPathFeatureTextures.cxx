#include "vtkOpenGLPathFeatureTextures.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefForwardMessages.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkReliefGridSearch.h"
#include "vtkReliefPathSearch.h"
#include "vtkReliefSearch.h"

#include <algorithm>

vtkStandardNewMacro(vtkOpenGLPathFeatureTextures);

vtkOpenGLPathFeatureTextures::vtkOpenGLPathFeatureTextures() = default;

vtkOpenGLPathFeatureTextures::~vtkOpenGLPathFeatureTextures() = default;

void vtkOpenGLPathFeatureTextures::SetOwner(vtkObject* owner)
{
  this->Owner = owner;
  vtkReliefForwardMessages(this->Filter, owner);
}

vtkPathFeatureTextureFilter* vtkOpenGLPathFeatureTextures::GetFilter()
{
  return this->Filter;
}

bool vtkOpenGLPathFeatureTextures::Update(vtkOpenGLRenderWindow* window)
{
  if (this->Filter->GetNumberOfInputConnections(0) == 0)
  {
    vtkNew<vtkPolyData> none;
    this->Filter->SetPathsData(none);
  }
  this->Filter->Update();
  vtkImageData* grid = this->Filter->GetGridOutput();
  vtkImageData* data = this->Filter->GetDataOutput();
  const vtkMTimeType made = std::max(grid->GetMTime(), data->GetMTime());
  if (made == this->UploadedTime && window == this->UploadedWindow)
  {
    return true;
  }
  if (!this->Upload(this->GridTexture, grid, window) ||
    !this->Upload(this->DataTexture, data, window))
  {
    return false;
  }
  this->UploadedTime = made;
  this->UploadedWindow = window;
  return true;
}

bool vtkOpenGLPathFeatureTextures::Upload(
  vtkTextureObject* texture, vtkImageData* image, vtkOpenGLRenderWindow* window)
{
  auto* texels = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  int size[3];
  image->GetDimensions(size);
  texture->SetContext(window);
  const int largest = texture->GetMaximumTextureSize(window);
  if (!texels || texels->GetNumberOfComponents() != 4 || size[0] > largest || size[1] > largest)
  {
    vtkErrorWithObjectMacro(this->Owner ? this->Owner : this,
      "The path features' " << (texture == this->GridTexture ? "grid" : "data") << " texture ("
                            << size[0] << " x " << size[1]
                            << ") cannot be drawn by this OpenGL (at most " << largest
                            << " a side): the plain surface is drawn. "
                            << "Lower the grid resolution or the features.");
    return false;
  }
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture->Create2DFromRaw(size[0], size[1], 4, VTK_FLOAT, texels->GetVoidPointer(0));
}

void vtkOpenGLPathFeatureTextures::Activate(bool activate)
{
  if (activate)
  {
    this->GridTexture->Activate();
    this->DataTexture->Activate();
  }
  else
  {
    this->DataTexture->Deactivate();
    this->GridTexture->Deactivate();
  }
}

void vtkOpenGLPathFeatureTextures::SetUniforms(vtkShaderProgram* program)
{
  program->SetUniformi("reliefPathGrid", this->GridTexture->GetTextureUnit());
  program->SetUniformi("reliefPathData", this->DataTexture->GetTextureUnit());
  // the footprint is measured in grid cells, each about a feature wide
  const int* cells = this->Filter->GetResolutionUsed();
  const float size[2] = { static_cast<float>(cells[0]), static_cast<float>(cells[1]) };
  program->SetUniform2f("reliefTextureSize", size);
}

std::string vtkOpenGLPathFeatureTextures::GetSearchDefines()
{
  // the search reaches the deepest cut, which the data's first texel holds
  return "#define RELIEF_PATH_FEATURES\n#define RELIEF_SEARCH reliefSearchPathFeatures\n"
         "#define RELIEF_DEEPEST RELIEF_PATH_TEXEL(0).y\n"
         "#define RELIEF_PATH_DATA_WIDTH_BITS " +
    std::to_string(vtkPathFeatureTextureFilter::DataWidthBits) + "\n";
}

std::string vtkOpenGLPathFeatureTextures::GetSearchSource()
{
  // the hits and the light rays every search shares, and the grid walk's steps
  return std::string(vtkReliefSearch) + vtkReliefGridSearch + vtkReliefPathSearch;
}

std::string vtkOpenGLPathFeatureTextures::GetHitColourCode()
{
  // the footprint's materials, weighted as its normals (reliefFootprintMaterials)
  return "  reliefPathShadeMaterials(ambientColor, diffuseColor, specularColor, specularPower, "
         "ambientIntensity, diffuseIntensity);\n";
}

vtkIdType vtkOpenGLPathFeatureTextures::GetTextureBytes()
{
  return this->UploadedWindow ? this->Filter->GetTextureBytes() : 0;
}

void vtkOpenGLPathFeatureTextures::ReleaseGraphicsResources(vtkWindow* window)
{
  this->GridTexture->ReleaseGraphicsResources(window);
  this->DataTexture->ReleaseGraphicsResources(window);
  this->UploadedWindow = nullptr;
  this->UploadedTime = 0;
}

void vtkOpenGLPathFeatureTextures::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Owner: " << this->Owner << "\n";
  os << indent << "Filter:\n";
  this->Filter->PrintSelf(os, indent.GetNextIndent());
  os << indent << "TextureBytes: " << this->GetTextureBytes() << "\n";
}
