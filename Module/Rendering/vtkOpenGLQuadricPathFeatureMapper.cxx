#include "vtkOpenGLQuadricPathFeatureMapper.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLPathFeatureTextures.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkRenderer.h"

vtkStandardNewMacro(vtkOpenGLQuadricPathFeatureMapper);

vtkOpenGLQuadricPathFeatureMapper::vtkOpenGLQuadricPathFeatureMapper()
{
  this->PathFeatures->SetOwner(this);
}

vtkOpenGLQuadricPathFeatureMapper::~vtkOpenGLQuadricPathFeatureMapper() = default;

void vtkOpenGLQuadricPathFeatureMapper::SetPathsConnection(vtkAlgorithmOutput* output)
{
  this->PathFeatures->GetFilter()->SetPathsConnection(output);
  this->Modified();
}

void vtkOpenGLQuadricPathFeatureMapper::SetPathsData(vtkPolyData* paths)
{
  this->PathFeatures->GetFilter()->SetPathsData(paths);
  this->Modified();
}

void vtkOpenGLQuadricPathFeatureMapper::SetProfilesConnection(vtkAlgorithmOutput* output)
{
  this->PathFeatures->GetFilter()->SetProfilesConnection(output);
  this->Modified();
}

void vtkOpenGLQuadricPathFeatureMapper::SetProfilesData(vtkPolyData* profiles)
{
  this->PathFeatures->GetFilter()->SetProfilesData(profiles);
  this->Modified();
}

vtkPathFeatureTextureFilter* vtkOpenGLQuadricPathFeatureMapper::GetPathFeatureTextureFilter()
{
  return this->PathFeatures->GetFilter();
}

double vtkOpenGLQuadricPathFeatureMapper::GetBaseDepth()
{
  return this->PathFeatures->GetFilter()->GetBaseDepth();
}

bool vtkOpenGLQuadricPathFeatureMapper::UpdateReliefTexture(vtkRenderer* ren)
{
  if (this->GetNumberOfInputConnections(1) > 0 && !this->WarnedReliefBase)
  {
    this->WarnedReliefBase = true;
    vtkWarningMacro("The quadric frame's path features take no relief base (its rays are "
                    "curved): the height map is left out and the base is flat. Draw features "
                    "on a height map with vtkOpenGLPathFeatureMapper.");
  }
  return this->PathFeatures->Update(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()));
}

void vtkOpenGLQuadricPathFeatureMapper::ActivateReliefTextures(bool activate)
{
  this->PathFeatures->Activate(activate);
}

void vtkOpenGLQuadricPathFeatureMapper::SetReliefTextureParameters(vtkShaderProgram* program)
{
  this->PathFeatures->SetUniforms(program);
}

std::string vtkOpenGLQuadricPathFeatureMapper::GetSearchDefines()
{
  return vtkOpenGLPathFeatureTextures::GetSearchDefines();
}

std::string vtkOpenGLQuadricPathFeatureMapper::GetSearchSource()
{
  return vtkOpenGLPathFeatureTextures::GetSearchSource();
}

std::string vtkOpenGLQuadricPathFeatureMapper::GetHitColourCode()
{
  return vtkOpenGLPathFeatureTextures::GetHitColourCode();
}

vtkIdType vtkOpenGLQuadricPathFeatureMapper::GetTextureBytes()
{
  return this->PathFeatures->GetTextureBytes();
}

void vtkOpenGLQuadricPathFeatureMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->PathFeatures->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLQuadricPathFeatureMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "PathFeatures:\n";
  this->PathFeatures->PrintSelf(os, indent.GetNextIndent());
}
