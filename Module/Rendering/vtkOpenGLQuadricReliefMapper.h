/**
 * @class   vtkOpenGLQuadricReliefMapper
 * @brief   relief mapping on curved surfaces, with correct silhouettes
 *
 * Oliveira and Policarpo 2005, "An Efficient Representation for Surface Details": the
 * height field is laid below a quadric that follows the surface around each fragment,
 * z = a x^2 + b y^2 in its tangent frame, interpolated from per-point coefficients
 * (vtkLocalQuadricFilter). The straight view ray's depth below that quadric is
 * quadratic along it (Eq. 7, the approximate distance; SetDistanceModeToExact() for
 * Eq. 6); the search follows it from the
 * polygon to depth 1 or until it comes back out of the quadric (s3.3), and a ray that
 * comes back out without meeting the relief is silhouette: the fragment is discarded,
 * and the relief carves the object's outline. Texture coordinates advance with the
 * texture scale s_x, s_y (Eq. 8-9); the hit's true depth is written (s3.5); the lit
 * normal combines the relief's slope and the quadric's at the hit.
 *
 * Outlines: the polygons of a coarse mesh sag inside the curved surface, and no fragment
 * exists outside them. The mapper draws a hull instead, each point lifted along its
 * normal by vtkLocalQuadricFilter's lift (how far the quadric surface rises above the
 * triangles around it) less the relief's clearance (how far below the surface the height
 * map's highest texel lies), so that the hull encloses the relief; a geometry shader gives
 * each fragment its height above the quadric surface (the interpolated lift less the
 * surface's rise over the triangle), and its view ray starts where it first meets the
 * quadric (A t^2 + B t = height), back toward the viewer from a polygon below it; a ray
 * that passes above the quadric is discarded. So the relief, not the tessellation,
 * decides the silhouette.
 *
 * Everything else is vtkOpenGLReliefMapper's. The quadrics are the input's point array
 * "ReliefQuadric" when it has a usable one (two components, one tuple a point), and the
 * lifts its "ReliefQuadricLift" or, without one, computed from those quadrics
 * (vtkLocalQuadricFilter::NewHullLifts); otherwise the mapper computes both once
 * per change of the mesh, with one warning if the input's quadric array was unusable.
 * NaN coefficients are taken as a plane.
 *
 * Search methods: Linear, LinearBinary and Secant sample the ray wherever it goes, so
 * they follow the curved ray exactly as the straight one; so does Automatic, the
 * default, with steps of half a texel or of its screen tolerance (no cone map).
 * ExactDDA, SafetyRadius, ConeStep and MaximumMipmap walk cells, radii, cones or pyramid
 * nodes along a straight line in texture space, assuming depth linear along it; below a
 * quadric it is not, so they are not offered: they fall back to LinearBinary with one
 * warning.
 * Self-shadowing follows the light from the hit in the tangent plane of the fragment
 * (flat), an approximation on curved surfaces. Shadows with other actors come through
 * VTK's shadow-map passes (vtkShadowMapBakerPass, vtkShadowMapPass): the baker runs
 * this mapper's shader, so the shadow map holds the carved outline (s3.5).
 *
 * The actor's default properties carve outlines: past a carved outline the ray must show
 * what lies behind the shape, not the relief on the inside of its far side, and the
 * mapper decides which faces carry relief (see SetTwoSidedRelief()). Back faces of a
 * closed mesh seen from outside are left out; on other meshes a back fragment whose ray,
 * followed back toward the viewer below the quadric, comes back out of it before depth 1
 * came in through the curved surface close by, where the front faces answer for it, and
 * is discarded (vtkReliefQuadricFrame.glsl, reliefQuadricBehindOutline).
 */
#ifndef vtkOpenGLQuadricReliefMapper_h
#define vtkOpenGLQuadricReliefMapper_h

#include "vtkNew.h" // For vtkNew
#include "vtkOpenGLReliefMapper.h"
#include "vtkPolyData.h" // For vtkNew<vtkPolyData>
#include "vtkReliefRenderingModule.h" // For export macro

class vtkLocalQuadricFilter;

class VTKRELIEFRENDERING_EXPORT vtkOpenGLQuadricReliefMapper : public vtkOpenGLReliefMapper
{
public:
  static vtkOpenGLQuadricReliefMapper* New();
  vtkTypeMacro(vtkOpenGLQuadricReliefMapper, vtkOpenGLReliefMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// vtkOpenGLReliefMapper's, and the DistanceMode and quadric filter's neighbourhood of
  /// a mapper of this frame.
  void CopyReliefSettings(vtkOpenGLReliefMapper* source) override;
  vtkMTimeType GetReliefSettingsMTime() override;
  ///@}

  /// The filter that computes the quadrics when the input has none, to configure it.
  vtkLocalQuadricFilter* GetLocalQuadricFilter();

  /// The mesh as rendered: with the input's quadrics or those computed.
  vtkPolyData* GetReliefSurface() override;

  enum DistanceModes
  {
    APPROXIMATE = 0, ///< Eq. 7: the depth below the quadric along the normal (default)
    EXACT = 1        ///< Eq. 6 where the quadric bends away from the viewer both ways
  };

  ///@{
  /**
   * How the ray's depth below the quadric is measured. APPROXIMATE (default): along
   * the fragment's normal, Eq. 7, everywhere. EXACT: from the ray point along the
   * direction perpendicular to the ray in the plane of the ray and the normal, Eq. 6,
   * where both principal curvatures bend away from the viewer (a < 0 and b < 0), and
   * Eq. 7 elsewhere, as Oliveira and Policarpo (2005) do (s3.1-3.2; the paper finds it about half
   * as fast). Changing it rebuilds the shader.
   */
  virtual void SetDistanceMode(int mode);
  vtkGetMacro(DistanceMode, int);
  void SetDistanceModeToApproximate() { this->SetDistanceMode(APPROXIMATE); }
  void SetDistanceModeToExact() { this->SetDistanceMode(EXACT); }
  const char* GetDistanceModeAsString();
  ///@}

protected:
  vtkOpenGLQuadricReliefMapper();
  ~vtkOpenGLQuadricReliefMapper() override;

  bool UpdateReliefSurface() override;
  void MapFrameAttributes(bool relief) override;
  /// The hull's clearance: how far below the surface the relief's top lies.
  void SetMapperShaderParameters(
    vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor) override;
  /// VTK's templates, with a triangle geometry shader where VTK has none (the hull).
  void GetShaderTemplate(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor) override;
  /// Only the methods that follow curved rays, Automatic as fixed steps of its tolerance.
  const vtkReliefSearchMethod* DescribeSearch(int method) override;
  const char* GetUnsupportedSearchReason() override;
  std::string GetFrameSource() override;
  std::string GetFrameDefines() override;

  /// True when the input carries usable quadrics; warns once per mesh when it carries
  /// unusable ones.
  bool HasUsableQuadrics(vtkPolyData* mesh);

  /// Gives the framed input's own quadrics their hull's lifts where it has none.
  bool UpdateHullLifts();

  vtkLocalQuadricFilter* QuadricFilter;
  vtkNew<vtkPolyData> LiftedSurface; // the framed input with the lifts of its quadrics
  vtkPolyData* LiftedFrom = nullptr;
  vtkMTimeType LiftedTime = 0;
  int DistanceMode = APPROXIMATE;
  bool ComputesQuadrics = true; // the input had no usable quadrics at the last render
  vtkMTimeType WarnedQuadricsTime = 0;

private:
  vtkOpenGLQuadricReliefMapper(const vtkOpenGLQuadricReliefMapper&) = delete;
  void operator=(const vtkOpenGLQuadricReliefMapper&) = delete;
};

#endif
