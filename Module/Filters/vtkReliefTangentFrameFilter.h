/**
 * @class   vtkReliefTangentFrameFilter
 * @brief   prepare a mesh for tangent-space relief mapping
 *
 * Passes a mesh with texture coordinates through and adds what a relief mapper needs
 * at each point: normals (vtkPolyDataNormals, when the input has none), a tangent
 * along increasing u (the input's own tangents when it has them, else
 * vtkPolyDataTangents), and the texture scale "ReliefTextureScale": the model length
 * of one texture unit along the tangent and along the bitangent cross(normal, tangent),
 * s_x and s_y of Oliveira and Policarpo 2005, Sec. 3.4. s_y is negative where the
 * texture is mirrored. Polygons and strips are triangulated first.
 *
 * A mesh without texture coordinates is an error (map some with
 * vtkTextureMapToPlane, vtkTextureMapToCylinder or vtkTextureMapToSphere); the output
 * is then the input, unchanged.
 */
#ifndef vtkReliefTangentFrameFilter_h
#define vtkReliefTangentFrameFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkReliefFiltersModule.h"

class VTKRELIEFFILTERS_EXPORT vtkReliefTangentFrameFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkReliefTangentFrameFilter* New();
  vtkTypeMacro(vtkReliefTangentFrameFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Name of the two-component point array holding (s_x, s_y).
  static const char* TextureScaleArrayName() { return "ReliefTextureScale"; }

  /**
   * Angle in degrees above which vtkPolyDataNormals splits an edge when normals are
   * computed (default 30, VTK's own default).
   */
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);

  /// True when the last update found texture coordinates and built the frame.
  vtkGetMacro(HasTangentFrame, bool);

protected:
  vtkReliefTangentFrameFilter();
  ~vtkReliefTangentFrameFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double FeatureAngle = 30.0;
  bool HasTangentFrame = false;

private:
  vtkReliefTangentFrameFilter(const vtkReliefTangentFrameFilter&) = delete;
  void operator=(const vtkReliefTangentFrameFilter&) = delete;
};

#endif
