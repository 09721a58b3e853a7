/**
 * @class   vtkReliefTangentFrameFilter
 * @brief   prepare a mesh for tangent-space relief mapping
 *
 * vtkReliefSurfaceFilter's triangles, with what a tangent-space relief mapper needs
 * at each point: normals (vtkPolyDataNormals, when the input has none), a tangent
 * along increasing u (the input's own tangents when it has them, else
 * vtkPolyDataTangents), and the texture scale "ReliefTextureScale": the model length
 * of one texture unit along the tangent and along the bitangent cross(normal, tangent),
 * s_x and s_y of Oliveira and Policarpo 2005, Sec. 3.4. s_y is negative where the
 * texture is mirrored.
 *
 * A mesh without texture coordinates or polygons is an error, as for
 * vtkReliefSurfaceFilter; the output is then the input, unchanged, and GetHasSurface()
 * is false.
 */
#ifndef vtkReliefTangentFrameFilter_h
#define vtkReliefTangentFrameFilter_h

#include "vtkReliefFiltersModule.h"
#include "vtkReliefSurfaceFilter.h"

class VTKRELIEFFILTERS_EXPORT vtkReliefTangentFrameFilter : public vtkReliefSurfaceFilter
{
public:
  static vtkReliefTangentFrameFilter* New();
  vtkTypeMacro(vtkReliefTangentFrameFilter, vtkReliefSurfaceFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Name of the two-component point array holding (s_x, s_y).
  static const char* TextureScaleArrayName() { return "ReliefTextureScale"; }

  /**
   * Angle in degrees above which vtkPolyDataNormals splits an edge when normals are
   * computed (default 30, VTK's own default). Values out of [0, 180] are clamped and NaN
   * is refused, with a warning.
   */
  virtual void SetFeatureAngle(double degrees);
  vtkGetMacro(FeatureAngle, double);

protected:
  vtkReliefTangentFrameFilter();
  ~vtkReliefTangentFrameFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double FeatureAngle = 30.0;

private:
  vtkReliefTangentFrameFilter(const vtkReliefTangentFrameFilter&) = delete;
  void operator=(const vtkReliefTangentFrameFilter&) = delete;
};

#endif
