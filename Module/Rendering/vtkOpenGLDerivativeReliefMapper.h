/**
 * @class   vtkOpenGLDerivativeReliefMapper
 * @brief   relief mapping on any mesh with texture coordinates: no tangents needed
 *
 * Derivative-based relief mapping (Tichenor 2012): each fragment builds its
 * texture-space frame from the screen-space derivatives of its view-space position and
 * texture coordinates (dFdx, dFdy), so meshes that carry no tangents, such as PLY scans
 * and OBJ or STL exports, get relief without any per-vertex frame. The mesh is only
 * triangulated (vtkReliefSurfaceFilter); nothing is computed per vertex unless
 * ComputeNormals asks for normals.
 *
 * The frame is the triangle's own affine texture mapping: the gradients of u and v
 * solved exactly from the derivatives, whatever the skew of the texture coordinates
 * (Tichenor's projection on normalized dFdx and dFdy holds only where they are
 * perpendicular). Everything after the frame is vtkOpenGLReliefMapper's: every search
 * method, self-shadowing, true depth, the relief normal rebuilt from the height map.
 *
 * - With point normals (smooth shading) depth is measured along the interpolated
 *   normal, and the texture axes are taken perpendicular to it. The relief normal
 *   follows the smooth normal, which is Tichenor's normal-difference correction
 *   ("Dynamic surface normal calculations"), and the search itself follows it too: where
 *   two faces share their vertex normals, the frame agrees on both sides of their edge
 *   and the texture no longer tears there.
 * - Without normals the frame is the face's: flat shading, and the relief tears at each
 *   edge by an amount that grows with the crease angle and the depth (Tichenor's
 *   "faceted crystal"; Documentation/results.md measures it). ComputeNormalsOn()
 *   gives such a mesh smooth point normals instead, and with them the smooth frame.
 *
 * Where the derivatives hold no mapping (texture coordinates constant or collinear over
 * a triangle) the fragment is shaded plainly, without relief. A mesh without texture
 * coordinates is drawn without relief, with one error, as by vtkOpenGLReliefMapper.
 */
#ifndef vtkOpenGLDerivativeReliefMapper_h
#define vtkOpenGLDerivativeReliefMapper_h

#include "vtkNew.h"                  // For the filters
#include "vtkOpenGLReliefMapper.h"
#include "vtkReliefRenderingModule.h" // For export macro
#include "vtkSmartPointer.h"          // For DrawnSurface

class vtkPolyDataNormals;
class vtkReliefSurfaceFilter;

class VTKRELIEFRENDERING_EXPORT vtkOpenGLDerivativeReliefMapper : public vtkOpenGLReliefMapper
{
public:
  static vtkOpenGLDerivativeReliefMapper* New();
  vtkTypeMacro(vtkOpenGLDerivativeReliefMapper, vtkOpenGLReliefMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// vtkOpenGLReliefMapper's, and the ComputeNormals of a mapper of this frame.
  void CopyReliefSettings(vtkOpenGLReliefMapper* source) override;

  /**
   * The mesh as last rendered: triangulated, with its texture coordinates and normals,
   * if any (computed ones with ComputeNormals); the triangulated mesh before a render.
   */
  vtkPolyData* GetReliefSurface() override;

  ///@{
  /**
   * For a mesh without point normals: off (default), each face's own frame, flat
   * shading and tearing at the edges; on, smooth point normals computed once per change
   * of the mesh (vtkPolyDataNormals, edges never split), the smooth frame and no
   * tearing where faces share points. A mesh's own normals are used either way. The
   * triangles drawn keep their own windings.
   */
  vtkSetMacro(ComputeNormals, bool);
  vtkGetMacro(ComputeNormals, bool);
  vtkBooleanMacro(ComputeNormals, bool);
  ///@}

protected:
  vtkOpenGLDerivativeReliefMapper();
  ~vtkOpenGLDerivativeReliefMapper() override;

  bool UpdateReliefSurface() override;
  void MapFrameAttributes(bool relief) override;
  std::string GetFrameSource() override;
  std::string GetFrameDefines() override;

  /// `surface` with smooth point normals added (NormalsSurface), its cells untouched.
  vtkPolyData* WithComputedNormals(vtkPolyData* surface);

  vtkNew<vtkReliefSurfaceFilter> SurfaceFilter;
  vtkNew<vtkPolyDataNormals> NormalsFilter; // for ComputeNormals
  vtkNew<vtkPolyData> NormalsSurface;       // the surface with the computed normals
  vtkSmartPointer<vtkPolyData> DrawnSurface;
  bool ComputeNormals = false;
  bool HasVertexNormals = false; // the drawn surface has point normals: smooth frame

private:
  vtkOpenGLDerivativeReliefMapper(const vtkOpenGLDerivativeReliefMapper&) = delete;
  void operator=(const vtkOpenGLDerivativeReliefMapper&) = delete;
};

#endif
