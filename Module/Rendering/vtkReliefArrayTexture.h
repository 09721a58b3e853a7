/**
 * @class   vtkReliefArrayTexture
 * @brief   a 2D array texture (GL_TEXTURE_2D_ARRAY): one layer per view of an impostor
 *
 * vtkTextureObject makes 1D, 2D, 3D and cube textures; an impostor's views are layers of
 * one array texture, each filtered on its own (a 3D texture would blend neighbouring
 * views) and read with textureGather. Activation and release are vtkTextureObject's; the
 * filters and wrapping are set here, once, at creation: vtkTextureObject's own parameter
 * upload asserts on array targets in VTK 9.2 (IsBound knows none), so AutoParameters is
 * off and its Set*Filter and SetWrap* settings are not used.
 */
#ifndef vtkReliefArrayTexture_h
#define vtkReliefArrayTexture_h

#include "vtkReliefRenderingModule.h" // For export macro
#include "vtkTextureObject.h"
#include "vtkWrappingHints.h" // For VTK_WRAPEXCLUDE

class VTK_WRAPEXCLUDE VTKRELIEFRENDERING_EXPORT vtkReliefArrayTexture : public vtkTextureObject
{
public:
  static vtkReliefArrayTexture* New();
  vtkTypeMacro(vtkReliefArrayTexture, vtkTextureObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// How a texture is read: texel by texel, bilinearly, or trilinearly across its mipmaps.
  enum Filtering
  {
    NEAREST,
    LINEAR,
    MIPMAPPED
  };

  /**
   * Makes the texture: `layers` layers of width x height texels from `data` (layer by
   * layer, rows from the bottom), held as `internalFormat` (GL_R16, GL_RGBA8, ...), given
   * as `format` and `type` (GL_RED and GL_UNSIGNED_SHORT, ...), with `bytesPerTexel` on
   * the GPU for GetBytes() (0 for a compressed `internalFormat`, which the GL compresses
   * and whose sizes it reports), read with `filtering` (MIPMAPPED makes the mipmaps) and
   * clamped at its edges. The context must be set (SetContext) and current. False where
   * GL refused.
   */
  bool Create2DArrayFromRaw(unsigned int width, unsigned int height, unsigned int layers,
    unsigned int internalFormat, unsigned int format, unsigned int type, int bytesPerTexel,
    const void* data, int filtering);

  /// GPU bytes of the texture as last made, its mipmaps included; 0 when released.
  vtkIdType GetBytes() const { return this->Handle ? this->Bytes : 0; }

protected:
  vtkReliefArrayTexture();
  ~vtkReliefArrayTexture() override = default;

  vtkIdType Bytes = 0;

private:
  vtkReliefArrayTexture(const vtkReliefArrayTexture&) = delete;
  void operator=(const vtkReliefArrayTexture&) = delete;
};

#endif
