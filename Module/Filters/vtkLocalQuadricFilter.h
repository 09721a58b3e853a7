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
 * The polygons of a coarse mesh sag inside the curved surface their quadrics describe,
 * and no fragment exists outside them: vtkOpenGLQuadricReliefMapper draws a hull
 * lifted off each point along its normal, far enough that the hull encloses the
 * quadric surface over every triangle around it. Over the edge from p to q that surface
 * stands -s (1 - s) Q above the chord (s in [0, 1], Q the mean of both ends' quadrics
 * a x^2 + b y^2 evaluated on q - p); over a triangle, with barycentric coordinates l,
 * sum l_i l_j w_ij with w_ij = -Q_ij, at most max(w) / 3: a point's lift is the
 * greatest of these over its triangles, shared by the copies of a point at one
 * position; 0 on a crease (copies whose normals part), where lifting the copies apart
 * would open a crack.
 *
 * Output: the tangent frame filter's output (points, triangles, normals, tangents,
 * "ReliefTextureScale") plus the point arrays "ReliefQuadric" (float, two components:
 * a, b) and "ReliefQuadricLift" (float, the hull's lift, model units, 0 or more). A mesh
 * without texture coordinates or polygons gives the tangent frame
 * filter's error, forwarded as this filter's, and passes through unchanged. Points are
 * fitted in parallel with vtkSMPTools; progress is reported between slices of points.
 */
#ifndef vtkLocalQuadricFilter_h
#define vtkLocalQuadricFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkReliefFiltersModule.h" // For export macro
#include "vtkWrappingHints.h"       // For VTK_NEWINSTANCE

class vtkFloatArray;

class VTKRELIEFFILTERS_EXPORT vtkLocalQuadricFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLocalQuadricFilter* New();
  vtkTypeMacro(vtkLocalQuadricFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Name of the two-component point array holding (a, b).
  static const char* QuadricArrayName() { return "ReliefQuadric"; }

  /// Name of the point array holding the hull's lift along the normal, model units.
  static const char* HullLiftArrayName() { return "ReliefQuadricLift"; }

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

  /**
   * The hull's lifts (HullLiftArrayName()) of a triangle mesh that carries quadrics
   * (QuadricArrayName()), point normals and tangents, one tuple a point, as this filter's
   * output does; null when it lacks one of them. For quadrics computed otherwise.
   */
  VTK_NEWINSTANCE static vtkFloatArray* NewHullLifts(vtkPolyData* framed);

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
