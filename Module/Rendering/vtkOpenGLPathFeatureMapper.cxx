#include "vtkOpenGLPathFeatureMapper.h"

#include "vtkObjectFactory.h"
#include "vtkOpenGLPathFeatureTextures.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkReliefPathOnRelief.h"
#include "vtkReliefPathSearch.h"
#include "vtkReliefSearchMethod.h"
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
  if (!this->PathFeatures->Update(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow())))
  {
    return false;
  }
  // a height map, where one is given, is the base the features cut into; one that cannot
  // be drawn (said why, once) leaves the base flat
  const bool reliefBase =
    this->GetNumberOfInputConnections(1) > 0 && this->Superclass::UpdateReliefTexture(ren);
  if (reliefBase != this->DrawingReliefBase)
  {
    this->DrawingReliefBase = reliefBase;
    this->ShaderOptionsTime.Modified();
  }
  return true;
}

void vtkOpenGLPathFeatureMapper::UpdateAcceleration(vtkRenderer* ren)
{
  if (this->DrawingReliefBase)
  {
    this->Superclass::UpdateAcceleration(ren);
  }
}

void vtkOpenGLPathFeatureMapper::ActivateReliefTextures(bool activate)
{
  this->PathFeatures->Activate(activate);
  if (this->DrawingReliefBase)
  {
    this->Superclass::ActivateReliefTextures(activate);
  }
}

void vtkOpenGLPathFeatureMapper::SetReliefTextureParameters(vtkShaderProgram* program)
{
  this->PathFeatures->SetUniforms(program);
  if (this->DrawingReliefBase)
  {
    // after the features': the field's texel size is the one its searches and footprint read
    this->Superclass::SetReliefTextureParameters(program);
  }
}

std::string vtkOpenGLPathFeatureMapper::GetSearchDefines()
{
  std::string defines = vtkOpenGLPathFeatureTextures::GetSearchDefines();
  if (this->DrawingReliefBase)
  {
    // the features' search on the field, which the search method searches, reaching its
    // depth 1 below the base plane
    defines += std::string("#define RELIEF_PATH_RELIEF_BASE\n"
                           "#define RELIEF_PATH_BASE_SEARCH ") +
      this->GetActiveSearch().Function +
      "\n#undef RELIEF_SEARCH\n#define RELIEF_SEARCH reliefSearchPathFeaturesOnRelief\n"
      "#undef RELIEF_DEEPEST\n"
      "#define RELIEF_DEEPEST max(RELIEF_PATH_TEXEL(0).y, RELIEF_PATH_TEXEL(0).x + 1.0)\n";
  }
  return defines;
}

std::string vtkOpenGLPathFeatureMapper::GetSearchSource()
{
  if (this->DrawingReliefBase)
  {
    return this->Superclass::GetSearchSource() + vtkReliefPathSearch + vtkReliefPathOnRelief;
  }
  return vtkOpenGLPathFeatureTextures::GetSearchSource();
}

std::string vtkOpenGLPathFeatureMapper::GetHitColourCode()
{
  return vtkOpenGLPathFeatureTextures::GetHitColourCode();
}

vtkIdType vtkOpenGLPathFeatureMapper::GetTextureBytes()
{
  return this->PathFeatures->GetTextureBytes() +
    (this->DrawingReliefBase ? this->Superclass::GetTextureBytes() : 0);
}

void vtkOpenGLPathFeatureMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  this->PathFeatures->ReleaseGraphicsResources(window);
  this->Superclass::ReleaseGraphicsResources(window);
}

void vtkOpenGLPathFeatureMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DrawingReliefBase: " << this->DrawingReliefBase << "\n";
  os << indent << "PathFeatures:\n";
  this->PathFeatures->PrintSelf(os, indent.GetNextIndent());
}
