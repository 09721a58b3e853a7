/**
 * @class   vtkOpenGLQuadricPathFeatureMapper
 * @brief   path-based surface detail on curved meshes, carving their outlines
 *
 * The path features of vtkOpenGLPathFeatureMapper (grooves, engravings, cracks, ridges:
 * the path-feature paper, seed 004) on the quadric frame of vtkOpenGLQuadricReliefMapper
 * (Oliveira and Policarpo 2005): below a quadric that follows the surface around each
 * fragment the view ray's depth is quadratic along it, and the path walk follows it as
 * the paper tracks the surface's curvature (s4.1, s5.1), each grid cell's stretch of the
 * ray straight within 1/256 of DepthScale. A ray that comes back out of the quadric without
 * meeting matter passes the outline: a groove that crosses the silhouette notches it.
 *
 * Paths, profiles, materials and antialiasing as for vtkOpenGLPathFeatureMapper; the
 * quadrics, the hull and the faces that carry relief as for vtkOpenGLQuadricReliefMapper,
 * whose search method does not apply. Region sampling takes a pixel's rays as straight,
 * so on the curved frame the pixels a feature reaches are supersampled.
 */
#ifndef vtkOpenGLQuadricPathFeatureMapper_h
#define vtkOpenGLQuadricPathFeatureMapper_h

#include "vtkNew.h" // For vtkNew
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkReliefRenderingModule.h" // For export macro

class vtkAlgorithmOutput;
class vtkOpenGLPathFeatureTextures;
class vtkPathFeatureTextureFilter;

class VTKRELIEFRENDERING_EXPORT vtkOpenGLQuadricPathFeatureMapper
  : public vtkOpenGLQuadricReliefMapper
{
public:
  static vtkOpenGLQuadricPathFeatureMapper* New();
  vtkTypeMacro(vtkOpenGLQuadricPathFeatureMapper, vtkOpenGLQuadricReliefMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The paths and the profiles (see vtkPathFeatureTextureFilter).
  void SetPathsConnection(vtkAlgorithmOutput* output);
  void SetPathsData(vtkPolyData* paths);
  void SetProfilesConnection(vtkAlgorithmOutput* output);
  void SetProfilesData(vtkPolyData* profiles);
  ///@}

  /// The filter that makes the textures: its grid resolution, default width, materials.
  vtkPathFeatureTextureFilter* GetPathFeatureTextureFilter();

  /// The depth of the base surface below the quadric, in units of DepthScale, as drawn.
  double GetBaseDepth();

  /// GPU memory of the grid and data textures, as last uploaded.
  vtkIdType GetTextureBytes() override;

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkOpenGLQuadricPathFeatureMapper();
  ~vtkOpenGLQuadricPathFeatureMapper() override;

  bool UpdateReliefTexture(vtkRenderer* ren) override;
  void UpdateAcceleration(vtkRenderer*) override {}
  void ActivateReliefTextures(bool activate) override;
  void SetReliefTextureParameters(vtkShaderProgram* program) override;
  std::string GetSearchDefines() override;
  std::string GetSearchSource() override;
  std::string GetHitColourCode() override;

  vtkNew<vtkOpenGLPathFeatureTextures> PathFeatures;
  bool WarnedReliefBase = false; // a height map was given, which this frame leaves out

private:
  vtkOpenGLQuadricPathFeatureMapper(const vtkOpenGLQuadricPathFeatureMapper&) = delete;
  void operator=(const vtkOpenGLQuadricPathFeatureMapper&) = delete;
};

#endif
