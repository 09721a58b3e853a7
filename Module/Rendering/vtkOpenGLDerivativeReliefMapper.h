/**
 * @class   vtkOpenGLDerivativeReliefMapper
 * @brief   relief mapping on any mesh with texture coordinates: no tangents needed
 *
 * Derivative-based relief mapping (seed 003, Hoffman 2012): each fragment builds its
 * texture-space frame from the screen-space derivatives of its view-space position and
 * texture coordinates (dFdx, dFdy), so meshes that carry no tangents, such as PLY scans
 * and OBJ or STL exports, get relief without any per-vertex frame. Nothing is computed
 * per vertex: the mesh is only triangulated (vtkReliefSurfaceFilter).
 *
 * The frame is the triangle's own affine texture mapping: the gradients of u and v
 * solved exactly from the derivatives, whatever the skew of the texture coordinates
 * (the seed's projection on normalized dFdx and dFdy holds only where they are
 * perpendicular). Everything after the frame is vtkOpenGLReliefMapper's: every search
 * method, self-shadowing, true depth, the relief normal rebuilt from the height map.
 *
 * - With point normals (smooth shading) depth is measured along the interpolated
 *   normal, and the texture axes are taken perpendicular to it. The relief normal
 *   follows the smooth normal, which is the seed's normal-difference correction
 *   ("Dynamic surface normal calculations"), and the search itself follows it too: where
 *   two faces share their vertex normals, the frame agrees on both sides of their edge
 *   and the texture no longer tears there.
 * - Without normals the frame is the face's: flat shading, and the relief tears at each
 *   edge by an amount that grows with the crease angle and the depth (the seed's
 *   "faceted crystal"; Documentation/results.md measures it). ComputeNormalsOn()
 *   gives such a mesh smooth point normals instead, and with them the smooth frame.
 *
 * Where the derivatives hold no mapping (texture coordinates constant or collinear over
 * a triangle) the fragment is shaded plainly, without relief. A mesh without texture
 * coordinates is drawn without relief, with one error, as by vtkOpenGLReliefMapper.
 */
#ifndef vtkOpenGLDerivativeReliefMapper_h
#define vtkOpenGLDerivativeReliefMapper_h

#include "vtkOpenGLReliefMapper.h"
#include "vtkReliefRenderingModule.h" // For export macro

class vtkPolyDataNormals;
class vtkReliefSurfaceFilter;

class VTKRELIEFRENDERING_EXPORT vtkOpenGLDerivativeReliefMapper : public vtkOpenGLReliefMapper
{
public:
  static vtkOpenGLDerivativeReliefMapper* New();
  vtkTypeMacro(vtkOpenGLDerivativeReliefMapper, vtkOpenGLReliefMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The mesh as rendered: triangulated, with its texture coordinates and normals, if any.
  vtkPolyData* GetReliefSurface() override;

  ///@{
  /**
   * For a mesh without point normals: off (default), each face's own frame, flat
   * shading and tearing at the edges; on, smooth point normals computed once per change
   * of the mesh (vtkPolyDataNormals, edges never split), the smooth frame and no
   * tearing where faces share points. A mesh's own normals are used either way.
   * Changing it rebuilds the shader.
   */
  void SetComputeNormals(bool compute);
  vtkGetMacro(ComputeNormals, bool);
  vtkBooleanMacro(ComputeNormals, bool);
  ///@}

protected:
  vtkOpenGLDerivativeReliefMapper();
  ~vtkOpenGLDerivativeReliefMapper() override;

  bool UpdateReliefSurface() override;
  void MapReliefAttributes(bool relief) override;
  std::string GetFrameDefines() override;

  vtkNew<vtkReliefSurfaceFilter> Surface;
  vtkNew<vtkPolyDataNormals> Normals; // for ComputeNormals
  bool ComputeNormals = false;
  bool VertexNormals = false; // the surface has point normals: smooth frame

private:
  vtkOpenGLDerivativeReliefMapper(const vtkOpenGLDerivativeReliefMapper&) = delete;
  void operator=(const vtkOpenGLDerivativeReliefMapper&) = delete;
};

#endif
