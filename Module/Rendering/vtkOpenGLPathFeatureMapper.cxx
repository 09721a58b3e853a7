#include "vtkOpenGLPathFeatureMapper.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLPathFeatureTextures.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkOpenGLPathFeatureMapper);

vtkOpenGLPathFeatureMapper::vtkOpenGLPathFeatureMapper()
{
  this->PathFeatures->SetOwner(this);
}

vtkOpenGLPathFeatureMapper::~vtkOpenGLPathFeatureMapper() = default;

void vtkOpenGLPathFeatureMapper::SetPathsConnection(vtkAlgorithmOutput* output)
{
  this->PathFeatures->GetFilter()->SetPathsConnection(output);
  this->Modified();
}

void vtkOpenGLPathFeatureMapper::SetPathsData(vtkPolyData* paths)
{
  this->PathFeatures->GetFilter()->SetPathsData(paths);
  this->Modified();
}

void vtkOpenGLPathFeatureMapper::SetProfilesConnection(vtkAlgorithmOutput* output)
{
  this->PathFeatures->GetFilter()->SetProfilesConnection(output);
  this->Modified();
}

void vtkOpenGLPathFeatureMapper::SetProfilesData(vtkPolyData* profiles)
{
  this->PathFeatures->GetFilter()->SetProfilesData(profiles);
  this->Modified();
}

vtkPathFeatureTextureFilter* vtkOpenGLPathFeatureMapper::GetPathFeatureTextureFilter()
{
  return this->PathFeatures->GetFilter();
}

double vtkOpenGLPathFeatureMapper::GetBaseDepth()
{
  return this->PathFeatures->GetFilter()->GetBaseDepth();
}

bool vtkOpenGLPathFeatureMapper::UpdateReliefTexture(vtkRenderer* ren)
{
  return this->PathFeatures->Update(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()));
}

void vtkOpenGLPathFeatureMapper::ActivateReliefTextures(bool activate)
{
  this->PathFeatures->Activate(activate);
}

void vtkOpenGLPathFeatureMapper::SetReliefTextureParameters(vtkShaderProgram* program)
{
  this->PathFeatures->SetUniforms(program);
}

std::string vtkOpenGLPathFeatureMapper::GetSearchDefines()
{
  return vtkOpenGLPathFeatureTextures::GetSearchDefines();
}

std::string vtkOpenGLPathFeatureMapper::GetSearchSource()
{
  return vtkOpenGLPathFeatureTextures::GetSearchSource();
}

std::string vtkOpenGLPathFeatureMapper::GetHitColourCode()
{
  return vtkOpenGLPathFeatureTextures::GetHitColourCode();
}

vtkIdType vtkOpenGLPathFeatureMapper::GetTextureBytes()
{
  return this->PathFeatures->GetTextureBytes();
}

void vtkOpenGLPathFeatureMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->PathFeatures->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLPathFeatureMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PathFeatures:\n";
  this->PathFeatures->PrintSelf(os, indent.GetNextIndent());
}
