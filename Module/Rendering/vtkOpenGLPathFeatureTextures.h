/**
 * @class   vtkOpenGLPathFeatureTextures
 * @brief   what a path-feature mapper of any frame searches: the paths' grid and data
 *          textures, and the path walk's shader code
 *
 * Owned by vtkOpenGLPathFeatureMapper (the tangent frame) and
 * vtkOpenGLQuadricPathFeatureMapper (the quadric frame), as VTK's mappers own helpers for
 * their GPU data. Its vtkPathFeatureTextureFilter makes the two textures of the
 * path-feature paper (seed 004, s4.2-4.3) from the paths and profiles the mapper is given;
 * they are uploaded as float textures when the filter's output changes, and the shader's
 * search is the path walk (vtkReliefPathSearch.glsl). Errors say what to do, as the
 * owner's (SetOwner): users know the mapper.
 */
#ifndef vtkOpenGLPathFeatureTextures_h
#define vtkOpenGLPathFeatureTextures_h

#include "vtkNew.h"   // For vtkNew
#include "vtkObject.h"
#include "vtkReliefRenderingModule.h" // For export macro
#include "vtkWrappingHints.h"         // For VTK_WRAPEXCLUDE

#include <string> // For the shader code

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkPathFeatureTextureFilter;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class VTK_WRAPEXCLUDE VTKRELIEFRENDERING_EXPORT vtkOpenGLPathFeatureTextures : public vtkObject
{
public:
  static vtkOpenGLPathFeatureTextures* New();
  vtkTypeMacro(vtkOpenGLPathFeatureTextures, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The mapper whose messages these are; its filter's messages become its own too.
  void SetOwner(vtkObject* owner);

  /// The filter that makes the textures from the paths and profiles.
  vtkPathFeatureTextureFilter* GetFilter();

  /**
   * Brings the filter up to date (no paths: an empty set, the plain surface) and uploads
   * its textures into `window` when they changed; false, having said why, where this
   * OpenGL cannot hold them.
   */
  bool Update(vtkOpenGLRenderWindow* window);

  /// Binds the textures to texture units for a draw, or frees the units after it.
  void Activate(bool activate);

  /// The walk's samplers and the grid's size (the footprint is measured in cells).
  void SetUniforms(vtkShaderProgram* program);

  ///@{
  /// The shader code of the search: its defines, its sources, and the lighting's use of
  /// the materials the footprint's rays met.
  static std::string GetSearchDefines();
  static std::string GetSearchSource();
  static std::string GetHitColourCode();
  ///@}

  /// GPU memory of the textures, as last uploaded; 0 before.
  vtkIdType GetTextureBytes();

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkOpenGLPathFeatureTextures();
  ~vtkOpenGLPathFeatureTextures() override;

  /// Uploads `image`'s four float components to `texture` in the window's context.
  bool Upload(vtkTextureObject* texture, vtkImageData* image, vtkOpenGLRenderWindow* window);

  vtkNew<vtkPathFeatureTextureFilter> Filter;
  vtkNew<vtkTextureObject> GridTexture;
  vtkNew<vtkTextureObject> DataTexture;
  vtkObject* Owner = nullptr;
  vtkMTimeType UploadedTime = 0; // of the filter's outputs
  vtkOpenGLRenderWindow* UploadedWindow = nullptr; // compared by address only

private:
  vtkOpenGLPathFeatureTextures(const vtkOpenGLPathFeatureTextures&) = delete;
  void operator=(const vtkOpenGLPathFeatureTextures&) = delete;
};

#endif
