/**
 * @class   vtkReliefDepthImage
 * @brief   the depth field an acceleration filter reads, taken from its input image
 *
 * Acceleration filters (vtkMaximumMipmapFilter and the like) accept either the output of
 * vtkReliefTextureFilter (four components, depth in the last) or a one-component depth
 * image (0 at the surface, 1 deepest). This helper checks the input, says what is wrong
 * with it, and copies its depths into a tiling field of floats. Not wrapped.
 */
#ifndef vtkReliefDepthImage_h
#define vtkReliefDepthImage_h

#include "vtkReliefFiltersModule.h" // For export macro

#include <string>
#include <vector>

class vtkImageData;

class VTKRELIEFFILTERS_EXPORT vtkReliefDepthImage
{
public:
  int Width = 0;
  int Height = 0;
  std::vector<float> Depths; // row j = 0 first, as in VTK images

  /// Copies the depths of `image`; false, with the reason in `error`, if it has none.
  bool Read(vtkImageData* image, std::string& error);

  /// Depth of texel (i, j), indices repeating with the texture.
  float At(int i, int j) const
  {
    i %= this->Width;
    j %= this->Height;
    i += i < 0 ? this->Width : 0;
    j += j < 0 ? this->Height : 0;
    return this->Depths[static_cast<size_t>(j) * this->Width + i];
  }

  /// The bilinear field between texel centres (what GL_LINEAR returns, in double) at
  /// texture coordinate (u, v), repeating; u and v must be finite.
  double Interpolate(double u, double v) const;
};

#endif
