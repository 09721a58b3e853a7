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
 * Each node above level 0 also holds the least depths of its sixteen grandchildren
 * (EncodeGrandchildTops), coded relative to its own: a search holding a node's texel
 * knows its children's and grandchildren's tops without reading them, passes over the
 * ones the ray clears and goes down through a child without reading it.
 *
 * Output: one VTK_FLOAT image, scalars "TopAndSlopes", of the atlas size of
 * vtkMaximumMipmapFilter, eight components per texel: the least depth, then the least and
 * largest dD/dx, the least and largest dD/dy, then the grandchildren's tops coded in three
 * words (0 at level 0). The mapper uploads a node as four 32-bit integers (PackNode).
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

  int GetOutputComponents() override { return 8; }

  /**
   * A node's top as the search decodes it: rounded down to a multiple of 2^-20.
   */
  static double DecodedTop(double top);

  /**
   * The least depths of a node's grandchildren, slot x + 4 y (the grandchild at offset x
   * along u and y along v from the first; the last node of a row folds its grandchildren
   * past the fourth into offset 3, and a single child's third child also into offset 1,
   * which the child's top is read from; a level-1 node's slots hold its cells, each over
   * two slots a side), coded relative to the node's decoded top (DecodedTop) as the shader
   * decodes them (reliefSlopeGrandchildTop): 4-bit codes c on one step 2^-(e + 4), e the
   * one of 0 to 15 that rounds the sixteen least in all (a finer step holds the low tops
   * closer and clamps the high ones to code 15), each rounded down with a margin of a
   * 1024th of a step for the GPU's rounding of the step.
   * `words`: e and codes 0 to 4, codes 5 to 10 and codes 11 to 15, 4 bits each, in three
   * exact integers.
   */
  static void EncodeGrandchildTops(double top, const double grandchildTops[16], float words[3]);

  /**
   * Two slope bounds [low, high] (depth per cell) packed in 20 bits, as the shader decodes
   * them (reliefSlopeDecode): two 10-bit codes, low + 1024 high, each a sign and a
   * logarithm of the magnitude, 30 codes per octave from 2^-15 to 4; low is rounded down
   * and high up, by one more code than needed so that the GPU's exp2 cannot round them
   * inward.
   */
  static unsigned int EncodeSlopes(double low, double high);

  /**
   * The four 32-bit integers a node of the output (its eight components) is uploaded as
   * (RGBA32UI), bit 0 lowest: x = decoded top * 2^20 (bits 0-19), the grandchildren's
   * exponent (20-23) and codes 14 and 15 (24-31); y = the dD/dx bounds (EncodeSlopes,
   * 0-19) and codes 8 to 10; z = the dD/dy bounds and codes 11 to 13; w = codes 0 to 7.
   */
  static void PackNode(const double node[8], unsigned int texel[4]);

protected:
  vtkSlopeMipmapFilter();
  ~vtkSlopeMipmapFilter() override = default;

  const char* GetProductName() override { return "a slope mipmap"; }
  const char* GetOutputName() override { return "TopAndSlopes"; }
  void Compute(const vtkReliefDepthImage& field, vtkFloatArray* output) override;

  // Components 5 to 7 of every node above level 0, from the levels' tops.
  void EncodeGrandchildren(int width, int height, float* values);

private:
  vtkSlopeMipmapFilter(const vtkSlopeMipmapFilter&) = delete;
  void operator=(const vtkSlopeMipmapFilter&) = delete;
};

#endif
