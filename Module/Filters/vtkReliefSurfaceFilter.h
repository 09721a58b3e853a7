/**
 * @class   vtkReliefSurfaceFilter
 * @brief   the polygons of a mesh, ready for a relief mapper
 *
 * Passes the polygons of a mesh with texture coordinates through, triangulated (strips
 * and polygons become triangles; vertices and lines are left out), with the texture
 * coordinates and normals the mesh has named, since a mapper binds them to shader inputs
 * by name. Nothing is computed: a mesh without normals stays without them. This is what
 * vtkOpenGLDerivativeReliefMapper draws, its frame coming from screen-space derivatives;
 * vtkReliefTangentFrameFilter adds the tangent frame the other mappers need.
 *
 * A mesh without texture coordinates is an error (map some with vtkTextureMapToPlane,
 * vtkTextureMapToCylinder or vtkTextureMapToSphere), as is one without polygons; the
 * output is then the input, unchanged, and GetHasSurface() is false.
 */
#ifndef vtkReliefSurfaceFilter_h
#define vtkReliefSurfaceFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkReliefFiltersModule.h"
#include "vtkSmartPointer.h" // for ExtractTriangles

class VTKRELIEFFILTERS_EXPORT vtkReliefSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkReliefSurfaceFilter* New();
  vtkTypeMacro(vtkReliefSurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// True when the last update found texture coordinates and polygons.
  vtkGetMacro(HasSurface, bool);

protected:
  vtkReliefSurfaceFilter();
  ~vtkReliefSurfaceFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The input's triangles with their point data, or nullptr after reporting why relief
   * cannot be drawn on it (no 2D texture coordinates, no polygons).
   */
  vtkSmartPointer<vtkPolyData> ExtractTriangles(vtkPolyData* input);

  /// Names the output's unnamed texture coordinates and normals (copies; the input stays).
  static void NameAttributes(vtkPolyData* output);

  bool HasSurface = false;

private:
  vtkReliefSurfaceFilter(const vtkReliefSurfaceFilter&) = delete;
  void operator=(const vtkReliefSurfaceFilter&) = delete;
};

#endif
