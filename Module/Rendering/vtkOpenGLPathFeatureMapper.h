/**
 * @class   vtkOpenGLPathFeatureMapper
 * @brief   draws path-based surface detail (grooves, engravings, cracks, ridges) on any mesh
 *          with normals and texture coordinates
 *
 * The path-feature paper (seed 004): features are paths in texture space swept by
 * profiles, held as vectors (vtkPathFeatureTextureFilter's grid and data textures) rather
 * than as a height map, so they stay sharp at every distance and cost kilobytes. Each
 * fragment walks its view ray through the grid and finds, by CSG over the features of
 * each cell it reaches, where the ray first enters matter (vtkReliefPathSearch.glsl): cuts
 * below the base surface, additions above it, overhangs, crossings, revolved ends. The
 * hit is lit with the facet's normal and the feature's material (or the actor's
 * property), shadowed by a second walk toward each light, and its true depth written,
 * so other actors and shadow maps meet the grooves where they are.
 *
 * Port 0 takes the mesh (point texture coordinates required; normals and tangents
 * computed when missing): the tangent frame of vtkOpenGLReliefMapper, whose settings
 * (DepthScale, SelfShadowing, FootprintShading, DepthCorrection, DisplayMode,
 * TwoSidedRelief) apply as there. The paths go to SetPathsConnection() or SetPathsData(),
 * the profiles, optionally, to SetProfilesConnection() or SetProfilesData(): see
 * vtkPathFeatureTextureFilter for the data, and GetPathFeatureTextureFilter() for its
 * settings and materials. The base surface lies GetBaseDepth() x DepthScale below the
 * polygons, so that what protrudes reaches them. Without paths the plain surface is drawn.
 *
 * The base may itself be a relief: give a height map (SetHeightMapConnection() or
 * SetHeightMapData(), read as vtkOpenGLReliefMapper reads it, but lit by its gradient: a
 * normal map given with it is not read) and the features cut into it
 * (vtkReliefPathOnRelief.glsl, beyond the paper): the field hangs from the base plane,
 * its depth 1 a DepthScale below it, and is searched by the superclass's SearchMethod;
 * what the features add stands on the plane, what they cut is cut from the field too;
 * one true depth for both. The actor's texture colours what has no material of its own.
 * Without a height map the base is flat and SearchMethod does not apply: the path search
 * is the only one.
 * On curved meshes vtkOpenGLQuadricPathFeatureMapper lets the features carve the outline.
 */
#ifndef vtkOpenGLPathFeatureMapper_h
#define vtkOpenGLPathFeatureMapper_h

#include "vtkNew.h" // For vtkNew
#include "vtkOpenGLReliefMapper.h"
#include "vtkReliefRenderingModule.h" // For export macro

class vtkAlgorithmOutput;
class vtkOpenGLPathFeatureTextures;
class vtkPathFeatureTextureFilter;

class VTKRELIEFRENDERING_EXPORT vtkOpenGLPathFeatureMapper : public vtkOpenGLReliefMapper
{
public:
  static vtkOpenGLPathFeatureMapper* New();
  vtkTypeMacro(vtkOpenGLPathFeatureMapper, vtkOpenGLReliefMapper);
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

  /// The depth of the base surface below the polygons, in units of DepthScale, as drawn.
  double GetBaseDepth();

  /// GPU memory of the grid and data textures, as last uploaded, and of the relief base's.
  vtkIdType GetTextureBytes() override;

  /// Whether the last render drew the features on a relief base (a usable height map).
  vtkGetMacro(DrawingReliefBase, bool);

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkOpenGLPathFeatureMapper();
  ~vtkOpenGLPathFeatureMapper() override;

  bool UpdateReliefTexture(vtkRenderer* ren) override;
  void UpdateAcceleration(vtkRenderer* ren) override;
  void ActivateReliefTextures(bool activate) override;
  void SetReliefTextureParameters(vtkShaderProgram* program) override;
  std::string GetSearchDefines() override;
  std::string GetSearchSource() override;
  std::string GetHitColourCode() override;

  vtkNew<vtkOpenGLPathFeatureTextures> PathFeatures;
  bool DrawingReliefBase = false; // a height map given and usable, as of the last render

private:
  vtkOpenGLPathFeatureMapper(const vtkOpenGLPathFeatureMapper&) = delete;
  void operator=(const vtkOpenGLPathFeatureMapper&) = delete;
};

#endif
