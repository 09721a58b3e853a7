/**
 * @class   vtkMaximumMipmapFilter
 * @brief   the maximum mipmap (least-depth pyramid) of a relief height field
 *
 * Builds the pyramid that vtkOpenGLReliefMapper's MaximumMipmap search traverses
 * (Tevs, Ihrke and Seidel, "Maximum mipmaps for fast, accurate, and scalable dynamic
 * height field rendering", I3D 2008). The height field is the bilinear interpolation of
 * the texel centres, so its pieces are the cells between four centres; cell (i, j) lies
 * between texels i, i + 1 and j, j + 1, repeating at the edges as the texture does. A
 * bilinear patch is highest at a corner, so level 0 holds, per cell, the least of its
 * four corner depths: exactly the highest point of the patch, in the relief convention
 * where depth 0 is the top (hence a maximum mipmap of heights).
 *
 * Level L has OpenGL's mipmap size, max(1, n >> L) for n texels, so non-power-of-two
 * maps need no padding: node i of level L covers cells [i 2^L, (i + 1) 2^L), except
 * the last node of a row, which covers every cell to the edge (up to 2^(L+1) - 1).
 * Its value is the least over those cells.
 *
 * Input: vtkReliefTextureFilter's output (depth in the last of four components) or a
 * one-component depth image. Output: one VTK_FLOAT image, scalars "MinimumDepth",
 * holding every level in an atlas: level 0 (the input's size) at the left, levels 1 and
 * up stacked from the bottom in one column to its right. GetLevelPlacement() says where
 * each level lies.
 */
#ifndef vtkMaximumMipmapFilter_h
#define vtkMaximumMipmapFilter_h

#include "vtkReliefAccelerationFilter.h"
#include "vtkReliefFiltersModule.h" // For export macro

#include <functional> // For ReduceLevels

class VTKRELIEFFILTERS_EXPORT vtkMaximumMipmapFilter : public vtkReliefAccelerationFilter
{
public:
  static vtkMaximumMipmapFilter* New();
  vtkTypeMacro(vtkMaximumMipmapFilter, vtkReliefAccelerationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void GetOutputSize(int width, int height, int size[2]) override;
  int GetOutputComponents() override { return 1; }

  /// Number of levels above level 0 for a width x height map: floor(log2(max)).
  static int GetTopLevel(int width, int height);

  /**
   * Where level `level` of the pyramid of a width x height map lies in the atlas: its
   * lower-left texel (origin) and size. False for a level that does not exist.
   */
  static bool GetLevelPlacement(int width, int height, int level, int origin[2], int size[2]);

  /// Nodes along an axis of `size` cells at `level`: GL's mipmap size max(1, size >> level).
  static int GetLevelSize(int size, int level);

  /**
   * The children of node `node` (along an axis of `size` cells) at the level below
   * `level`: [first, last]. The last node of a row also takes the odd child at its end.
   */
  static void GetChildRange(int node, int size, int level, int& first, int& last);

  /// Size of the atlas holding the whole pyramid of a width x height map.
  static void GetAtlasSize(int width, int height, int size[2]);

protected:
  vtkMaximumMipmapFilter();
  ~vtkMaximumMipmapFilter() override = default;

  const char* GetProductName() override { return "a maximum mipmap"; }
  const char* GetOutputName() override { return "MinimumDepth"; }
  void Compute(const vtkReliefDepthImage& field, vtkFloatArray* output) override;

  /**
   * Fills levels 1 and up of the atlas `values` of a width x height map, `components`
   * floats a texel, from level 0: each node starts as its first child, combine(node,
   * child, slot) takes in each child (slot x + 2 y: its offset from the first child along
   * each axis, at most 1, the last node's odd third child folded into 1), and then
   * finish(node), when given, completes the node.
   */
  static void ReduceLevels(int width, int height, int components, float* values,
    const std::function<void(float* node, const float* child, int slot)>& combine,
    const std::function<void(float* node)>& finish = nullptr);

private:
  vtkMaximumMipmapFilter(const vtkMaximumMipmapFilter&) = delete;
  void operator=(const vtkMaximumMipmapFilter&) = delete;
};

#endif
