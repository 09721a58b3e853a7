#include "vtkOpenGLPathFeatureMapper.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefForwardMessages.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include "vtkReliefGridSearch.h"
#include "vtkReliefPathSearch.h"
#include "vtkReliefSearch.h"

#include <string>

vtkStandardNewMacro(vtkOpenGLPathFeatureMapper);

vtkOpenGLPathFeatureMapper::vtkOpenGLPathFeatureMapper()
{
  vtkReliefForwardMessages(this->PathFeatureTextureFilter, this);
}

vtkOpenGLPathFeatureMapper::~vtkOpenGLPathFeatureMapper() = default;

void vtkOpenGLPathFeatureMapper::SetPathsConnection(vtkAlgorithmOutput* output)
{
  this->PathFeatureTextureFilter->SetPathsConnection(output);
  this->Modified();
}

void vtkOpenGLPathFeatureMapper::SetPathsData(vtkPolyData* paths)
{
  this->PathFeatureTextureFilter->SetPathsData(paths);
  this->Modified();
}

void vtkOpenGLPathFeatureMapper::SetProfilesConnection(vtkAlgorithmOutput* output)
{
  this->PathFeatureTextureFilter->SetProfilesConnection(output);
  this->Modified();
}

void vtkOpenGLPathFeatureMapper::SetProfilesData(vtkPolyData* profiles)
{
  this->PathFeatureTextureFilter->SetProfilesData(profiles);
  this->Modified();
}

vtkPathFeatureTextureFilter* vtkOpenGLPathFeatureMapper::GetPathFeatureTextureFilter()
{
  return this->PathFeatureTextureFilter;
}

double vtkOpenGLPathFeatureMapper::GetBaseDepth()
{
  return this->PathFeatureTextureFilter->GetBaseDepth();
}

bool vtkOpenGLPathFeatureMapper::UpdateReliefTexture(vtkRenderer* ren)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  vtkPathFeatureTextureFilter* filter = this->PathFeatureTextureFilter;
  if (filter->GetNumberOfInputConnections(0) == 0)
  {
    // no paths: an empty set, the plain surface
    vtkNew<vtkPolyData> none;
    filter->SetPathsData(none);
  }
  filter->Update();
  vtkImageData* grid = filter->GetGridOutput();
  vtkImageData* data = filter->GetDataOutput();
  const vtkMTimeType made = std::max(grid->GetMTime(), data->GetMTime());
  if (made == this->UploadedTime && window == this->UploadedWindow)
  {
    return true;
  }
  if (!this->Upload(this->GridTexture, grid, window) || !this->Upload(this->DataTexture, data, window))
  {
    return false;
  }
  this->UploadedTime = made;
  this->UploadedWindow = window;
  return true;
}

bool vtkOpenGLPathFeatureMapper::Upload(
  vtkTextureObject* texture, vtkImageData* image, vtkOpenGLRenderWindow* window)
{
  auto* texels = vtkFloatArray::SafeDownCast(image->GetPointData()->GetScalars());
  int size[3];
  image->GetDimensions(size);
  texture->SetContext(window);
  const int largest = texture->GetMaximumTextureSize(window);
  if (!texels || texels->GetNumberOfComponents() != 4 || size[0] > largest || size[1] > largest)
  {
    vtkErrorMacro("The path features' " << (texture == this->GridTexture ? "grid" : "data")
                                        << " texture (" << size[0] << " x " << size[1]
                                        << ") cannot be drawn by this OpenGL (at most "
                                        << largest << " a side): the plain surface is drawn. "
                                        << "Lower the grid resolution or the features.");
    return false;
  }
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture->Create2DFromRaw(size[0], size[1], 4, VTK_FLOAT, texels->GetVoidPointer(0));
}

void vtkOpenGLPathFeatureMapper::ActivateReliefTextures(bool activate)
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

void vtkOpenGLPathFeatureMapper::SetReliefTextureParameters(vtkShaderProgram* program)
{
  program->SetUniformi("reliefPathGrid", this->GridTexture->GetTextureUnit());
  program->SetUniformi("reliefPathData", this->DataTexture->GetTextureUnit());
  // the footprint is measured in grid cells, each about a feature wide
  const int* cells = this->PathFeatureTextureFilter->GetResolutionUsed();
  const float size[2] = { static_cast<float>(cells[0]), static_cast<float>(cells[1]) };
  program->SetUniform2f("reliefTextureSize", size);
}

std::string vtkOpenGLPathFeatureMapper::GetSearchDefines()
{
  return "#define RELIEF_PATH_FEATURES\n#define RELIEF_SEARCH reliefSearchPathFeatures\n"
         "#define RELIEF_PATH_DATA_WIDTH_BITS " +
    std::to_string(vtkPathFeatureTextureFilter::DataWidthBits) + "\n";
}

std::string vtkOpenGLPathFeatureMapper::GetSearchSource()
{
  // the hits and the light rays every search shares, and the grid walk's steps
  return std::string(vtkReliefSearch) + vtkReliefGridSearch + vtkReliefPathSearch;
}

std::string vtkOpenGLPathFeatureMapper::GetHitColourCode()
{
  // the footprint's materials, weighted as its normals (reliefFootprintMaterials)
  return "  reliefPathShadeMaterials(ambientColor, diffuseColor, specularColor, specularPower, "
         "ambientIntensity, diffuseIntensity);\n";
}

vtkIdType vtkOpenGLPathFeatureMapper::GetTextureBytes()
{
  return this->UploadedWindow ? this->PathFeatureTextureFilter->GetTextureBytes() : 0;
}

void vtkOpenGLPathFeatureMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->GridTexture->ReleaseGraphicsResources(window);
  this->DataTexture->ReleaseGraphicsResources(window);
  this->UploadedWindow = nullptr;
  this->UploadedTime = 0;
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLPathFeatureMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PathFeatureTextureFilter:\n";
  this->PathFeatureTextureFilter->PrintSelf(os, indent.GetNextIndent());
  os << indent << "TextureBytes: " << this->GetTextureBytes() << "\n";
}
