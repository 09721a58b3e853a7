/**
 * @class   vtkOpenGLReliefTextures
 * @brief   the relief mappers' textures: encoding, upload and the acceleration cache
 *
 * Owned by vtkOpenGLReliefMapper, as VTK's mappers own helpers for their GPU data. It
 * holds what the relief shader reads: the 16-bit depth texture with its mipmaps (the
 * searches read it, and the shading rebuilds the relief normal from it), a normal map's
 * (nx, ny) when one was given with the heights, and the acceleration image of the search
 * method (vtkReliefSearchMethod: the filter that makes it, its encoding, its uniforms),
 * precomputed or built here, each uploaded once per change. Errors say what to do, once
 * per change of what they are about, as the owner's (SetOwner): users know the mapper.
 */
#ifndef vtkOpenGLReliefTextures_h
#define vtkOpenGLReliefTextures_h

#include "vtkNew.h" // For the textures
#include "vtkObject.h"
#include "vtkReliefRenderingModule.h" // For export macro
#include "vtkSmartPointer.h"          // For AccelerationFilter
#include "vtkWrappingHints.h"         // For VTK_WRAPEXCLUDE

class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkReliefAccelerationFilter;
class vtkReliefSearchMethod;
class vtkShaderProgram;
class vtkTextureObject;
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
   * Uploads vtkReliefTextureFilter's output `relief` (its depths; with inputNormals its
   * normals too) unless it is already. False when it cannot be drawn: too large for this
   * OpenGL, or the upload failed (reported).
   */
  bool UploadRelief(vtkOpenGLRenderWindow* window, vtkImageData* relief, bool inputNormals);
  /// Whether the uploaded relief carries a normal map's texture (RELIEF_INPUT_NORMALS).
  bool GetInputNormals() const { return this->InputNormals; }

  /**
   * Brings the acceleration image `method` reads up to date on the GPU: `precomputed`
   * when given, checked against what the method's filter makes of `relief`, or else
   * built by that filter (SafetyRadiusTolerance given to vtkSafetyRadiusFilter) and
   * cached against the relief and the setting. False when there is none to use.
   */
  bool UpdateAcceleration(vtkOpenGLRenderWindow* window, const vtkReliefSearchMethod& method,
    vtkImageData* relief, vtkImageData* precomputed, double safetyRadiusTolerance);

  ///@{
  /// Binds the textures `method` reads to texture units for a render, and frees them.
  void Activate(const vtkReliefSearchMethod& method);
  void Deactivate(const vtkReliefSearchMethod& method);
  ///@}

  /// The textures' uniforms, and those of `method`'s acceleration image.
  void SetShaderParameters(vtkShaderProgram* program, const vtkReliefSearchMethod& method);

  /// GPU bytes of the textures `method` reads, as last uploaded.
  vtkIdType GetTextureBytes(const vtkReliefSearchMethod& method) const;

  void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkOpenGLReliefTextures();
  ~vtkOpenGLReliefTextures() override;

  vtkImageData* BuildAcceleration(const vtkReliefSearchMethod& method, vtkImageData* relief,
    double safetyRadiusTolerance);
  bool CheckAcceleration(
    const vtkReliefSearchMethod& method, vtkImageData* relief, vtkImageData* acceleration);
  bool UploadAcceleration(vtkOpenGLRenderWindow* window, const vtkReliefSearchMethod& method,
    vtkImageData* acceleration);

  /// Who reports: the owner, or the helper itself without one.
  vtkObject* GetReporter() { return this->Owner ? this->Owner : this; }

  vtkObject* Owner = nullptr;
  vtkNew<vtkTextureObject> DepthTexture;  // 16-bit depth: searched, and shaded from
  vtkNew<vtkTextureObject> NormalTexture; // (nx, ny) of an input normal map, if one is used
  vtkNew<vtkTextureObject> AccelerationTexture; // what the search method reads besides
  bool InputNormals = false; // NormalTexture holds the normals the shading reads
  int ReliefSize[2] = { 0, 0 };
  vtkIdType DepthTextureBytes = 0;
  vtkIdType NormalTextureBytes = 0;
  vtkIdType AccelerationTextureBytes = 0;
  vtkTimeStamp ReliefUploadTime;
  vtkTimeStamp OversizeReportTime; // when a too large height map was last reported
  vtkSmartPointer<vtkReliefAccelerationFilter> AccelerationFilter; // builds the image
  int AccelerationFilterMethod = -1; // the method AccelerationFilter was made for
  vtkImageData* UploadedAcceleration = nullptr; // compared by address only
  int AccelerationMethod = -1; // the method AccelerationTexture was built for
  vtkTimeStamp AccelerationUploadTime;
  bool AccelerationUsable = false;

private:
  vtkOpenGLReliefTextures(const vtkOpenGLReliefTextures&) = delete;
  void operator=(const vtkOpenGLReliefTextures&) = delete;
};

#endif
