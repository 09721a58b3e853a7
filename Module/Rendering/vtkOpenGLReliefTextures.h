/**
 * @class   vtkOpenGLReliefTextures
 * @brief   the relief mappers' textures: encoding, upload, acceleration images, sharing
 *
 * Owned by vtkOpenGLReliefMapper, as VTK's mappers own helpers for their GPU data. It
 * gives the mapper what the relief shader reads: the 16-bit depth texture at full
 * resolution (the searches read it, and the shading takes the relief normal from it), a
 * normal map's (nx, ny) when one was given with the heights, and the acceleration image
 * of the search method (vtkReliefSearchMethod: the filter that makes it, its encoding,
 * its uniforms), precomputed or built here.
 *
 * What the scene shares is made once: the helpers of all mappers drawing in one window
 * whose height map is the same data (the same image, unmodified since) with the same
 * vtkReliefTextureFilter settings share one relief texture, computed and uploaded by the
 * first, and one acceleration image a method (and setting, or precomputed image). Each
 * is released with the last helper that holds it (ReleaseGraphicsResources, or a change
 * of height map), so a multiblock dataset or many instances of one relief cost one copy.
 * Errors say what to do, once per shared texture, as the owner's (SetOwner): users know
 * the mapper.
 */
#ifndef vtkOpenGLReliefTextures_h
#define vtkOpenGLReliefTextures_h

#include "vtkObject.h"
#include "vtkReliefRenderingModule.h" // For export macro
#include "vtkWrappingHints.h"         // For VTK_WRAPEXCLUDE

#include <memory> // For the shared textures

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkReliefSearchMethod;
class vtkReliefTextureFilter;
class vtkShaderProgram;
class vtkWindow;

class VTK_WRAPEXCLUDE VTKRELIEFRENDERING_EXPORT vtkOpenGLReliefTextures : public vtkObject
{
public:
  static vtkOpenGLReliefTextures* New();
  vtkTypeMacro(vtkOpenGLReliefTextures, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The mapper whose messages these are; not counted: the mapper owns the helper.
  void SetOwner(vtkObject* owner) { this->Owner = owner; }

  /**
   * The relief texture that `settings` (a vtkReliefTextureFilter, read and not run) makes
   * of `heights`, on the GPU of `window`: shared when another helper there has it, made
   * and uploaded otherwise. nullptr when it cannot be drawn: the filter failed, it is too
   * large for this OpenGL, or the upload failed (each reported once).
   */
  vtkImageData* UpdateRelief(
    vtkOpenGLRenderWindow* window, vtkImageData* heights, vtkReliefTextureFilter* settings);
  /// Whether the relief carries a normal map's texture (RELIEF_INPUT_NORMALS).
  bool GetInputNormals() const;

  /**
   * Brings the acceleration image `method` reads of the relief (UpdateRelief) up to date
   * on the GPU: `precomputed` when given, checked against what the method's filter makes
   * of the relief, or else built by that filter (SafetyRadiusTolerance given to
   * vtkSafetyRadiusFilter). False when there is none to use.
   */
  bool UpdateAcceleration(vtkOpenGLRenderWindow* window, const vtkReliefSearchMethod& method,
    vtkImageData* precomputed, double safetyRadiusTolerance);

  ///@{
  /// Binds the textures `method` reads to texture units for a render, and frees them.
  void Activate(const vtkReliefSearchMethod& method);
  void Deactivate(const vtkReliefSearchMethod& method);
  ///@}

  /// The textures' uniforms, and those of `method`'s acceleration image.
  void SetShaderParameters(vtkShaderProgram* program, const vtkReliefSearchMethod& method);

  /// GPU bytes of the textures `method` reads, shared or not, as last uploaded.
  vtkIdType GetTextureBytes(const vtkReliefSearchMethod& method) const;

  /// GPU bytes of all the relief textures in `window`, each shared one counted once.
  static vtkIdType GetTextureBytesInUse(vtkWindow* window);

  /// Lets go of the shared textures; the last helper to hold one releases it.
  void ReleaseGraphicsResources(vtkWindow* window);

  ///@{
  /// What helpers share, defined with the registry that finds it.
  struct SharedRelief;
  struct SharedAcceleration;
  ///@}

protected:
  vtkOpenGLReliefTextures();
  ~vtkOpenGLReliefTextures() override;

  /// Who reports: the owner, or the helper itself without one.
  vtkObject* GetReporter() { return this->Owner ? this->Owner : this; }

  vtkObject* Owner = nullptr;
  std::shared_ptr<SharedRelief> Relief;             // as UpdateRelief last gave it
  std::shared_ptr<SharedAcceleration> Acceleration; // as UpdateAcceleration last gave it

private:
  vtkOpenGLReliefTextures(const vtkOpenGLReliefTextures&) = delete;
  void operator=(const vtkOpenGLReliefTextures&) = delete;
};

#endif
