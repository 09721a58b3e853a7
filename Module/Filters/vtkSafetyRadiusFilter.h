/**
 * @class   vtkSafetyRadiusFilter
 * @brief   the safety radius of every cell of a relief height field
 *
 * Builds the map that the SafetyRadius search (vtkReliefSafetySearch.glsl) reads: the
 * robust binary search of Baboud and Decoret, "Rendering geometry with relief textures"
 * (Graphics Interface 2006, s3.4 and s3.5). The height field is the bilinear
 * interpolation of the texel centres; cell (i, j) is the patch between texels i, i + 1
 * and j, j + 1, repeating at the edges as the texture does. A ray goes down into the
 * relief: its depth grows along it. S_n(c) is the square of cells within Chebyshev
 * distance n of cell c, and e the ErrorTolerance.
 *
 * Definition. Cell c has radius n when, for every ray and every point p of it over c
 * (cell borders included) where the ray is on or above the field, the part of the ray
 * from p to where its projection leaves S_n(c) is nowhere above the field once it has
 * been more than e below it. With e = 0 that part meets the field at most once, so a
 * search may jump from p to the square's exit and, if the ray is below the field there,
 * bisect knowing that the crossing is unique (Baboud and Decoret 2006, Fig. 5). The paper asks this
 * of unblocked rays only, those above the field all the way to p; the filter proves it for every
 * ray, which keeps the proof local and costs radius only where a ray would have to be blocked to be
 * safe (valley floors, at e = 0). Radius 0 promises nothing: the search intersects that cell
 * exactly. It is the right value wherever a ray can graze the field and come out again next to the
 * cell (hill tops, ridges, saddles: Baboud and Decoret 2006, Fig. 7), which at e = 0 is most cells
 * of a curved field, since any convexity lets a grazing ray dip in and out; it is never
 * clamped to 1.
 *
 * Error bound. With e > 0 the radii are larger, and a search that trusts them can step
 * over a stretch where the ray is below the field, but only where it is at most e below.
 * The hit it returns is a true intersection, at or after the first one and at or before
 * the first point where the ray is more than e below the field: a feature is missed only
 * where the ray passes through it within e (in depth) of its surface, a silhouette error
 * bounded by e in depth.
 *
 * Algorithm; every radius is at most the largest n with the property. If the property
 * fails for n, some ray is on or above the field at p over c, more than e below it at a
 * later point a and above it at a later point b in S_n(c). With s > 0 the depth the ray
 * gains per texel of run and f the field,
 *   s > (f(a) + e - f(p)) / |pa|                and  s < (f(b) - f(a) - e) / |ab|,
 * and, as f(a) - f(p) and f(b) - f(a) integrate the slope of f along the ray,
 *   s > least slope on [p, a] + e / |pa|        and  s < most slope on [a, b] - e / |ab|.
 * The directions of rays are cut into 16 wedges of 22.5 degrees. Per wedge and per ring
 * of cells around c (Chebyshev distance k), over the cells a ray from c in the wedge can
 * enter (its corridor), the filter takes the least and largest depth, the least and
 * largest slope along the wedge's directions (from the gradients at cell corners, where
 * they are extreme: the gradient of a bilinear patch is affine), and the least and most
 * distance from p (k - 1 to k + 1 cells along the major axis). A pair of rings k_a <= k_b
 * is dangerous when these bounds leave some s; the radius is one less than the first ring
 * k_b of a dangerous pair, 0 when that ring is 0 or 1. Beyond ring 15 rings are taken in
 * runs of 2 (rings 16 to 31), 4, 8 and 16, bounded by precomputed blocks of as many cells
 * a side, each run charged to its first ring: the work per cell grows with the logarithm
 * of the radius past 16. Rounding is always resolved toward danger. The slowest maps are
 * smooth ones where most radii reach MaximumRadius.
 *
 * Input: vtkReliefTextureFilter's output (depth in the last of four components) or a
 * one-component depth image. Output: a VTK_FLOAT image of the input's size whose scalars,
 * "SafetyRadius", hold the radius of cell (i, j) at texel (i, j), in cells (an integer
 * stored as a float). The input must be 2D with point scalars; anything else gives an
 * error and an empty output.
 */
#ifndef vtkSafetyRadiusFilter_h
#define vtkSafetyRadiusFilter_h

#include "vtkReliefAccelerationFilter.h"
#include "vtkReliefFiltersModule.h" // For export macro

class VTKRELIEFFILTERS_EXPORT vtkSafetyRadiusFilter : public vtkReliefAccelerationFilter
{
public:
  static vtkSafetyRadiusFilter* New();
  vtkTypeMacro(vtkSafetyRadiusFilter, vtkReliefAccelerationFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int GetOutputComponents() override { return 1; }

  ///@{
  /**
   * The depth e by which a ray may pass below the field unnoticed (see the class
   * description), as a fraction of the relief's depth. Default 0: the search is exact.
   * Values out of [0, 1] (negative, NaN, more than the whole depth) are clamped, with a
   * warning.
   */
  virtual void SetErrorTolerance(double tolerance);
  vtkGetMacro(ErrorTolerance, double);
  ///@}

  ///@{
  /**
   * The largest radius stored, in cells, at most 255. Default 32. The computation
   * grows with the radii it finds, so a larger cap costs time on smooth maps, where the
   * radius is large almost everywhere; the search gains little from radii beyond a few
   * tens of cells.
   */
  vtkSetClampMacro(MaximumRadius, int, 0, 255);
  vtkGetMacro(MaximumRadius, int);
  ///@}

protected:
  vtkSafetyRadiusFilter();
  ~vtkSafetyRadiusFilter() override = default;

  const char* GetProductName() override { return "safety radii"; }
  const char* GetOutputName() override { return "SafetyRadius"; }
  void Compute(const vtkReliefDepthImage& field, vtkFloatArray* output) override;

  double ErrorTolerance = 0.0;
  int MaximumRadius = 32;

private:
  vtkSafetyRadiusFilter(const vtkSafetyRadiusFilter&) = delete;
  void operator=(const vtkSafetyRadiusFilter&) = delete;
};

#endif
