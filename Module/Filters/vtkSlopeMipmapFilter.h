/**
 * @class   vtkSlopeMipmapFilter
 * @brief   a maximum mipmap whose nodes also bound the slopes of the field under them
 *
 * Builds the pyramid that vtkOpenGLReliefMapper's SlopeMipmap search traverses
 * (vtkReliefSlopeSearch.glsl): vtkMaximumMipmapFilter's, in its atlas layout, with, per
 * node, the box of the depth gradients of the bilinear patches under it. A patch's
 * gradient is affine in the cell, so its extremes are at the corners:
 * dD/dx lies between d10 - d00 and d11 - d01, dD/dy between d01 - d00 and d11 - d10, in
 * depth per cell. A parent's box is the union of its children's.
 *
 * Along a ray, the gap between field and ray then changes at a rate bounded by the box,
 * so one node read proves more than "the ray passes over the node's top": that the gap
 * cannot fall in the node, that it cannot fall to 0 before the node's exit (a Lipschitz
 * bound), or that it only falls, so the ray meets the field at most once there.
 *
 * Each node above level 0 also holds the least depths of its four children, coded
 * relative to its own (EncodeChildTops): a search holding a node's texel knows its
 * children's tops without reading them, and passes over the ones the ray clears.
 *
 * Output: one VTK_FLOAT image, scalars "TopAndSlopes", of the atlas size of
 * vtkMaximumMipmapFilter, six components per texel: the least depth, then the least and
 * largest dD/dx, the least and largest dD/dy, then the children's tops coded (0 at level
 * 0). The mapper uploads the boxes in 12-bit logarithmic codes, rounded outward (PackNode).
 */
#ifndef vtkSlopeMipmapFilter_h
#define vtkSlopeMipmapFilter_h

#include "vtkMaximumMipmapFilter.h"
#include "vtkReliefFiltersModule.h" // For export macro

class VTKRELIEFFILTERS_EXPORT vtkSlopeMipmapFilter : public vtkMaximumMipmapFilter
{
public:
  static vtkSlopeMipmapFilter* New();
  vtkTypeMacro(vtkSlopeMipmapFilter, vtkMaximumMipmapFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int GetOutputComponents() override { return 6; }

  /**
   * The least depths of a node's children (slot x + 2 y: the child at offset x along u
   * and y along v; the last node of a row folds its odd third child into offset 1), coded
   * relative to the node's least depth `top`, as the shader decodes them
   * (reliefSlopeChildTops): four 5-bit codes c and a 4-bit exponent e packed in an exact
   * integer, e 2^20 + c0 + 32 c1 + 1024 c2 + 32768 c3; a child's top decodes to
   * top + c 2^-(e + 4), rounded down (toward the top, what the search may assume) with a
   * margin for the GPU's float rounding, on the finest step that holds the largest.
   */
  static float EncodeChildTops(double top, const double childTops[4]);

  /**
   * Two slope bounds [low, high] (depth per cell) packed in one float, as the shader
   * decodes them (reliefSlopeDecode): two 12-bit codes, low * 4096 + high, each a sign
   * and a logarithm of the magnitude, 128 codes per octave from 2^-15 to 2; low is
   * rounded down and high up, by one more code than needed so that the GPU's exp2 cannot
   * round them inward.
   */
  static float EncodeSlopes(double low, double high);

  /**
   * The four floats a node of the output (its six components) is uploaded as: its
   * least depth, its two slope boxes, each packed by EncodeSlopes, and its children's
   * coded tops.
   */
  static void PackNode(const double node[6], float texel[4]);

protected:
  vtkSlopeMipmapFilter();
  ~vtkSlopeMipmapFilter() override = default;

  const char* GetProductName() override { return "a slope mipmap"; }
  const char* GetOutputName() override { return "TopAndSlopes"; }
  void Compute(const vtkReliefDepthImage& field, vtkFloatArray* output) override;

private:
  vtkSlopeMipmapFilter(const vtkSlopeMipmapFilter&) = delete;
  void operator=(const vtkSlopeMipmapFilter&) = delete;
};

#endif
