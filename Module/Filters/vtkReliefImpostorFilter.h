/**
 * @class   vtkReliefImpostorFilter
 * @brief   capture a mesh as 1 or 6 height fields over its bounding box (a relief impostor)
 *
 * vtkReliefImpostorFilter turns any surface mesh into the textures of a relief impostor
 * (Baboud and Decoret 2006, s4): height fields that replace the object, searched by the
 * relief mappers' methods. Each view looks into the mesh's bounding box (padded by
 * Padding) from one of its faces: one view (NumberOfViews 1) from its +z face, six from
 * all of them (+x, -x, +y, -y, +z, -z, in that order). A view's field runs across the
 * whole box: depth 0 on the face, 1 on the opposite face.
 *
 * A view's rays are parallel (Projection ORTHOGRAPHIC) or, in reverse perspective
 * (REVERSE_PERSPECTIVE, s4 and Fig. 9), converge on an apex beyond the opposite face,
 * ApexDistance box depths from the face, so that the rays lean inward and see the sides
 * of what stands on the far face (the facades an orthogonal view loses). The frustum is
 * chosen to hold the box: its far end is the far face, its near end, on the plane of the
 * view's face, as much larger as the apex makes it (the rays from its margin enter the box
 * through its sides); the renderer clips it to the box (s4.1). Either way a
 * view maps world points to its unit cube (u, v, depth) by a projective map, so that
 * straight rays stay straight: the homogeneous 4x4 matrix of view k (row major, world to
 * (u w, v w, depth w, w)) is tuple k of the field data array "ViewProjections" of both
 * outputs.
 *
 * Output 0, the depths: a DepthResolution^2 x NumberOfViews image (slice k is view k),
 * VTK_FLOAT scalars "Depth" in [0, 1], the depth of the first surface along each texel's
 * ray; exactly 1 where the ray meets nothing (an empty column). Output 1, the colours: a
 * ColourResolution^2 x NumberOfViews image (s4.3: resolutions independent) with unsigned
 * char RGBA scalars "Colour" (alpha 255 where the ray met the mesh, 0 elsewhere) and
 * VTK_FLOAT "Normals", the mesh's normal there in world coordinates (its point normals
 * interpolated where it has them, its triangles' otherwise). Texel (i, j) of a slice lies
 * at ((i + 0.5) / N, (j + 0.5) / N) of the face: point spacing 1 / N, origin half a texel.
 *
 * Colour comes from the mesh's point scalars (unsigned char RGB or RGBA as they are, any
 * other through a lookup table over their range), else from a colour image on input 1
 * read at the mesh's texture coordinates, else white, with a warning.
 *
 * The capture is exact at each texel's centre: the mesh's triangles are projected into
 * each view and rasterized with a depth test, threaded over rows (vtkSMPTools), with
 * progress events. A depth texel whose centre no triangle covers, but that a triangle
 * reaches into, takes that triangle's least depth within the texel: a sheet seen edge on,
 * or anything thinner than a texel, falls between centres and would leave the view
 * empty, and an impostor keeps only what every view holds. UnseenSurfaceFraction tells
 * how much of the mesh's area no view saw: the share of 65536 points spread over the
 * surface by area that lie behind every view's
 * field (deeper than the field at the four texels around them, by more than a thousandth
 * of the depth); it is also the field data value "UnseenSurfaceFraction" of output 0.
 *
 * Bad input gives an error and empty outputs (no triangles, an ApexDistance of 1 or
 * less), or a warning and a capture that still works: a mesh flat along an axis (its box
 * is thickened to a hundredth of its largest side), no colour.
 */

#ifndef vtkReliefImpostorFilter_h
#define vtkReliefImpostorFilter_h

#include "vtkReliefFiltersModule.h" // For export macro
#include "vtkReliefWholeImagesAlgorithm.h"

#include <memory> // For std::unique_ptr

class vtkImageData;
class vtkPolyData;

class VTKRELIEFFILTERS_EXPORT vtkReliefImpostorFilter : public vtkReliefWholeImagesAlgorithm
{
public:
  static vtkReliefImpostorFilter* New();
  vtkTypeMacro(vtkReliefImpostorFilter, vtkReliefWholeImagesAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Projections
  {
    ORTHOGRAPHIC = 0,       ///< parallel rays
    REVERSE_PERSPECTIVE = 1 ///< rays converging beyond the far face (s4, Fig. 9)
  };

  /// The largest resolution accepted: 16384 texels a side, the largest texture any GL
  /// implementation VTK supports offers (GL_MAX_TEXTURE_SIZE is at least 1024).
  static constexpr int MaximumResolution = 16384;
  /// The surface points UnseenSurfaceFraction is judged on.
  static constexpr int CoverageSamples = 65536;

  ///@{
  /// The mesh (port 0) and an optional colour image read at its texture coordinates (port 1).
  void SetInputData(vtkPolyData* mesh);
  void SetColourTextureConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(1, output);
  }
  void SetColourTextureData(vtkImageData* image);
  ///@}

  ///@{
  /// The outputs: the depths (port 0) and the colours with normals (port 1).
  vtkImageData* GetDepthOutput();
  vtkImageData* GetColourOutput();
  ///@}

  ///@{
  /// 1 (the +z face) or 6 (every face). Default 6; other values are taken as the nearer.
  void SetNumberOfViews(int views);
  vtkGetMacro(NumberOfViews, int);
  ///@}

  ///@{
  /// ORTHOGRAPHIC (default) or REVERSE_PERSPECTIVE.
  vtkSetClampMacro(Projection, int, ORTHOGRAPHIC, REVERSE_PERSPECTIVE);
  vtkGetMacro(Projection, int);
  void SetProjectionToOrthographic() { this->SetProjection(ORTHOGRAPHIC); }
  void SetProjectionToReversePerspective() { this->SetProjection(REVERSE_PERSPECTIVE); }
  ///@}

  ///@{
  /**
   * Reverse perspective: how far the apex lies from the face, in box depths (along the
   * view). Must be over 1, beyond the far face; default 2: the frustum's near end is
   * twice the box's face, whose texels see the middle half of each texture's side, and
   * the rays lean in by up to a quarter of the box's side per box depth.
   */
  vtkSetMacro(ApexDistance, double);
  vtkGetMacro(ApexDistance, double);
  ///@}

  ///@{
  /// Texels a side of the depth and colour slices (s4.3). Defaults 256 and 512; values
  /// outside [1, MaximumResolution] are an error.
  vtkSetMacro(DepthResolution, int);
  vtkGetMacro(DepthResolution, int);
  vtkSetMacro(ColourResolution, int);
  vtkGetMacro(ColourResolution, int);
  ///@}

  ///@{
  /// How far the box reaches beyond the mesh's bounds, as a share of its diagonal, so that
  /// no surface lies exactly on a face. Default 0.01, clamped to [0, 1].
  vtkSetClampMacro(Padding, double, 0.0, 1.0);
  vtkGetMacro(Padding, double);
  ///@}

  /// The box the last update captured: xmin, xmax, ymin, ymax, zmin, zmax.
  vtkGetVector6Macro(Box, double);

  /**
   * The box of a mesh with these bounds: padded by `padding` of their diagonal, and
   * thickened to a hundredth of its largest side along an axis where it is thinner. The
   * bits 1, 2, 4 of the result tell which of x, y, z were thickened.
   */
  static int PadBounds(const double bounds[6], double padding, double box[6]);

  ///@{
  /**
   * A depth of the depth output as 16 bits, as vtkOpenGLReliefImpostorMapper holds it: an
   * empty column (depth 1) is 65535 and any surface at most 65534, so that a surface on
   * the far face stays apart from emptiness. DecodeDepth gives the depth it stands for.
   */
  static unsigned short EncodeDepth(float depth);
  static float DecodeDepth(unsigned short code) { return code / 65535.0f; }
  ///@}

  /// The share of the mesh's area the last update's views did not see (0 to 1).
  vtkGetMacro(UnseenSurfaceFraction, double);

  /**
   * The homogeneous projection of view `view` of the last update, world to
   * (u w, v w, depth w, w), row major; false where there is no such view.
   */
  bool GetViewProjection(int view, double matrix[16]);

protected:
  vtkReliefImpostorFilter();
  ~vtkReliefImpostorFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(
    vtkInformation* request, vtkInformationVector** inputs, vtkInformationVector* outputs) override;

  int NumberOfViews = 6;
  int Projection = ORTHOGRAPHIC;
  double ApexDistance = 2.0;
  int DepthResolution = 256;
  int ColourResolution = 512;
  double Padding = 0.01;
  double Box[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  double UnseenSurfaceFraction = 0.0;

private:
  vtkReliefImpostorFilter(const vtkReliefImpostorFilter&) = delete;
  void operator=(const vtkReliefImpostorFilter&) = delete;

  /// An error, and false, where the settings cannot make a capture.
  bool CheckSettings();
  /// Box: the mesh's bounds, padded, and thickened where flat (with a warning).
  void ChooseBox(const double bounds[6]);
  /// The views' projections, from Box.
  void MakeProjections();

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
