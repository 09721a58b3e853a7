/**
 * @class   vtkConeStepMapFilter
 * @brief   the relaxed cone map of a relief height field, valid for its bilinear field
 *
 * Builds the map that vtkOpenGLReliefMapper's ConeStep search reads (relaxed cone
 * stepping, Policarpo and Oliveira, GPU Gems 3 ch. 18), made robust for the field the
 * mapper really intersects: the bilinear interpolation of the texel centres (Baboud and Decoret
 * (2006) s3.1), as "Robust Cone Step Mapping" (Bán et al., EGSR 2024) shows the classic,
 * texel-centre generator is not.
 *
 * Coordinates are texels, texel (i, j)'s centre at (i, j); depth d is 0 at the top, 1
 * deepest. Cell (i, j) is the square Q between texel centres i, i + 1 and j, j + 1
 * (repeating at the edges as the texture does); its top T is the least of its four
 * corner depths, the highest point of its patch.
 *
 * Definition. The cone of ratio w (texels per unit depth) of cell (i, j) at a point p of
 * Q is K(p) = { (x, d) : d <= T, |x - p| <= w (T - d) }: apex at the cell's top depth
 * over any point of the cell, so the cone holds whatever point of the cell the search
 * stands over (a nearest-cell lookup returns the cell, not a texel centre).
 *
 * Guarantee (the relaxed cone property). For every p in Q and every ray whose depth
 * grows along it, in any direction and at any slope, the part of the ray that starts
 * over p at a depth of at most T and stays inside K(p) never has a point strictly above
 * the field after a point on or below it. So a search standing over the cell above its
 * top may step to where the ray leaves K(p): if it lands above the field it skipped no
 * intersection; if on or below, the step holds exactly one entry into the field, the
 * first intersection, which bisection brackets.
 *
 * Generation, and why it is right. A ray that is below the field and later above it,
 * inside the cone, passes a highest point m of the field along it before leaving (the
 * least field depth seen so far): there the field's depth along the ray stops falling
 * and starts rising, m lies no farther from p than the exit, and D(m) < T. Hence
 * w = min |m - p| / (T - D(m)) over such ridge points m is a valid ratio. On the
 * bilinear field they are grid vertices, points of the centrelines between them (where
 * the one-sided slopes of the two patches change sign) and points inside twisted
 * patches (where the slope along the ray is zero and the patch curves up along it).
 * Each such feature is kept only if some direction from Q toward it sees the slope turn
 * there, tested with the exact one-sided gradients of the patches; the ratio is bounded
 * from below by the distance from Q over the depth difference, near Q by the slope of
 * the patches next to it, and on smooth fields by how fast the slope along a ray can
 * change (the curvature of the patches and the kinks at the centrelines). Every bound
 * is a lower bound, so every cone is valid; none samples the field. (The classic
 * generator puts the apex at one texel centre and follows rays through texel centres
 * only: it misses the ridges between centres and the rest of the cell, and its cones
 * let rays pass through the field; TestReliefConeStep shows both.)
 *
 * The search is a best-first branch and bound over a least-depth pyramid (as
 * vtkMaximumMipmapFilter's, each node also carrying the range of its patches'
 * gradients), starting from the cell that limited the previous cell's cone: a node is
 * pruned when it holds nothing higher than T, when its bound is no better than the
 * ratio found, or when no direction from Q sees the slope turn inside it. Rows are
 * shared among threads with vtkSMPTools; progress is reported between slices of rows,
 * from the calling thread.
 *
 * Ratios are capped at four times the larger side of the map (a cone reaching four
 * tiles away at depth 1): cells no ridge limits, like the highest ones, get the cap.
 * Stored ratios are shrunk by a relative 1e-5 and rounded down to float, so that the
 * search's float arithmetic cannot step past a cone's edge.
 *
 * Input: vtkReliefTextureFilter's output (depth in the last of four components) or a
 * one-component depth image; anything else gives an error and an empty output. Output:
 * a VTK_FLOAT image of the input's size, scalars "ConeStep", two components per cell
 * (i, j): its top T and its ratio w.
 *
 * On the GPU each cell takes two bytes (EncodeCone): the top rounded up toward the
 * surface to a multiple of 1/255, and the ratio rounded down to one of 255 levels
 * spaced evenly in log2 over the RATIO_OCTAVES octaves below the maximum ratio (4.5%
 * apart), or 0 below them. A higher apex and a narrower cone lie inside the proven
 * cone, so the decoded map keeps the guarantee; the search only takes a few more steps.
 */
#ifndef vtkConeStepMapFilter_h
#define vtkConeStepMapFilter_h

#include "vtkReliefAccelerationFilter.h"
#include "vtkReliefFiltersModule.h" // For export macro

class VTKRELIEFFILTERS_EXPORT vtkConeStepMapFilter : public vtkReliefAccelerationFilter
{
public:
  static vtkConeStepMapFilter* New();
  vtkTypeMacro(vtkConeStepMapFilter, vtkReliefAccelerationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int GetOutputComponents() override { return 2; }

  /// The largest ratio stored for a width x height map: 4 max(width, height).
  static double GetMaximumRatio(int width, int height);

  /// Octaves of ratio below the maximum that the 8-bit ratio codes span.
  enum
  {
    RATIO_OCTAVES = 16
  };

  /**
   * The two bytes a cell's (top, ratio) is uploaded as, both rounded conservatively:
   * code[0] / 255 <= top (strictly below it for top > 0) and
   * maximumRatio * 2^(RATIO_OCTAVES (code[1] - 255) / 254) <= ratio, a relative 1e-5
   * to spare for a GPU's exp2 (code[1] = 0: ratio 0). vtkReliefConeSearch.glsl's
   * reliefConeDecode() reads them back.
   */
  static void EncodeCone(double top, double ratio, double maximumRatio, unsigned char code[2]);

protected:
  vtkConeStepMapFilter();
  ~vtkConeStepMapFilter() override = default;

  const char* GetProductName() override { return "a cone step map"; }
  const char* GetOutputName() override { return "ConeStep"; }
  void Compute(const vtkReliefDepthImage& field, vtkFloatArray* output) override;

private:
  vtkConeStepMapFilter(const vtkConeStepMapFilter&) = delete;
  void operator=(const vtkConeStepMapFilter&) = delete;
};

#endif
