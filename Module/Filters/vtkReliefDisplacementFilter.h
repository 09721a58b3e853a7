/**
 * @class   vtkReliefDisplacementFilter
 * @brief   the relief as real geometry: a mesh subdivided and displaced by its depth image
 *
 * What a relief mapper draws, built as triangles for VTK's stock vtkPolyDataMapper: the
 * ground truth every search method is measured against, and the dense displaced mesh a
 * VTK user would otherwise render (vtkWarpScalar on a subdivided mesh).
 *
 * Input 0 is the coarse mesh the mapper draws: triangles (polygons and strips are
 * triangulated) with 2D texture coordinates, and normals (computed as
 * vtkReliefTangentFrameFilter computes them, feature angle 30 degrees, when it has none).
 * Input 1 is the relief: vtkReliefTextureFilter's output or a one-component depth image
 * (0 at the surface, 1 deepest), tiling with the texture coordinates as the mapper's.
 *
 * The mesh is subdivided (vtkLinearSubdivisionFilter, normals and texture coordinates
 * interpolated linearly as the rasteriser interpolates them) until every edge spans at
 * most MaximumEdgeTexels texels of the relief image, then every point moves inward along
 * its interpolated unit normal by DepthScale times the bilinear depth at its texture
 * coordinate (the field between texel centres, Baboud and Decoret 2006, s3.1, exactly what the
 * mapper searches). Normals are recomputed on the displaced mesh; texture coordinates are kept, so
 * the colour texture maps as on the relief.
 *
 * Subdivision multiplies triangles by 4 per level: MaximumNumberOfTriangles caps the
 * level, with a warning naming the edge length reached. A mesh without texture
 * coordinates, or a relief image without depths, is an error; the output is then the
 * input mesh, unchanged.
 */
#ifndef vtkReliefDisplacementFilter_h
#define vtkReliefDisplacementFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkReliefFiltersModule.h" // For export macro

class vtkImageData;

class VTKRELIEFFILTERS_EXPORT vtkReliefDisplacementFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkReliefDisplacementFilter* New();
  vtkTypeMacro(vtkReliefDisplacementFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The relief image on input port 1 (see the class description).
  ///@{
  void SetReliefConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetReliefData(vtkImageData* image);
  ///@}

  /**
   * Model length of depth 1, as the mapper's DepthScale (default 0.05). A negative value
   * becomes 0 and one that is not finite is refused (the depth stays), with a warning.
   */
  virtual void SetDepthScale(double depthScale);
  vtkGetMacro(DepthScale, double);

  /**
   * Longest edge allowed, in texels of the relief image (default 0.5: the ground truth;
   * infinite: no subdivision). Values below 1e-3 become 1e-3 and NaN is refused, with a
   * warning.
   */
  virtual void SetMaximumEdgeTexels(double texels);
  vtkGetMacro(MaximumEdgeTexels, double);

  /// Most triangles the subdivision may make (default 2^23).
  vtkSetClampMacro(MaximumNumberOfTriangles, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(MaximumNumberOfTriangles, vtkIdType);

  /// After an update: the subdivision levels used and the longest edge they left, in
  /// texels (before displacement).
  ///@{
  vtkGetMacro(SubdivisionLevels, int);
  vtkGetMacro(LongestEdgeTexels, double);
  ///@}

protected:
  vtkReliefDisplacementFilter();
  ~vtkReliefDisplacementFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double DepthScale = 0.05;
  double MaximumEdgeTexels = 0.5;
  vtkIdType MaximumNumberOfTriangles = vtkIdType(1) << 23;
  int SubdivisionLevels = 0;
  double LongestEdgeTexels = 0.0;

private:
  vtkReliefDisplacementFilter(const vtkReliefDisplacementFilter&) = delete;
  void operator=(const vtkReliefDisplacementFilter&) = delete;
};

#endif
