/**
 * @class   vtkLocalQuadricFilter
 * @brief   fit a quadric z = a x^2 + b y^2 at every point of a mesh, in its tangent frame
 *
 * Curved relief (Oliveira and Policarpo 2005, "An Efficient Representation for Surface
 * Details") bends the height field along the surface: each point carries a quadric that
 * approximates the surface around it, interpolated across triangles, and rays that come
 * back out of it are silhouette. This filter computes those quadrics.
 *
 * The mesh first goes through vtkReliefTangentFrameFilter (triangulation, normals when
 * the input has none, tangents along increasing u, the texture scale s_x, s_y of
 * Sec. 3.4). At every point p, with unit normal N, the tangent T made orthogonal to it
 * and B = N x T, each neighbour q becomes (x, y, z) = ((q - p).T, (q - p).B, (q - p).N)
 * and a, b minimize sum (a x^2 + b y^2 - z)^2 (Eq. 1-2), a 2x2 system solved directly.
 * Neighbours are the other points of the triangles around p (its 1-ring, as in the
 * paper), or those of the triangles around them too (NeighbourhoodRings 2, steadier on
 * noisy meshes). Points split by the tangent frame filter at creases, and boundary
 * points, fit what lies on their side.
 *
 * Sign convention: z grows along the normal, so a surface curving away from its normal
 * has negative coefficients: a sphere of radius r with outward normals has
 * a = b = -1 / (2 r); its inside, seen with inward normals, +1 / (2 r). a is the
 * curvature term along the texture's u direction, b along v.
 *
 * Where the fit is undetermined (fewer than two neighbours, or neighbours that do not
 * span both x and y, so that the 2x2 system is singular), or the point or its frame is
 * not finite, the point gets a = b = 0 (the tangent plane, flat relief) and is counted
 * in the one-value field array "ReliefQuadricFallbacks".
 *
 * Output: the tangent frame filter's output (points, triangles, normals, tangents,
 * "ReliefTextureScale") plus the point array "ReliefQuadric" (float, two components:
 * a, b). A mesh without texture coordinates or polygons gives the tangent frame
 * filter's error, forwarded as this filter's, and passes through unchanged. Points are
 * fitted in parallel with vtkSMPTools; progress is reported between slices of points.
 */
#ifndef vtkLocalQuadricFilter_h
#define vtkLocalQuadricFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkReliefFiltersModule.h" // For export macro

class VTKRELIEFFILTERS_EXPORT vtkLocalQuadricFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLocalQuadricFilter* New();
  vtkTypeMacro(vtkLocalQuadricFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Name of the two-component point array holding (a, b).
  static const char* QuadricArrayName() { return "ReliefQuadric"; }

  /// Name of the one-value field array counting the points that fell back to a = b = 0.
  static const char* FallbackCountArrayName() { return "ReliefQuadricFallbacks"; }

  ///@{
  /**
   * How far the neighbourhood of a point reaches: 1, the points of its triangles (the
   * paper's choice, default); 2, also the points of their triangles, which averages out
   * noise at the cost of blurring curvature that changes quickly.
   */
  vtkSetClampMacro(NeighbourhoodRings, int, 1, 2);
  vtkGetMacro(NeighbourhoodRings, int);
  ///@}

  /// Points that fell back to a = b = 0 in the last update.
  vtkGetMacro(NumberOfFallbacks, vtkIdType);

protected:
  vtkLocalQuadricFilter();
  ~vtkLocalQuadricFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NeighbourhoodRings = 1;
  vtkIdType NumberOfFallbacks = 0;

private:
  vtkLocalQuadricFilter(const vtkLocalQuadricFilter&) = delete;
  void operator=(const vtkLocalQuadricFilter&) = delete;
};

#endif
