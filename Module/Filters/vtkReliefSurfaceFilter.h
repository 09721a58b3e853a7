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
 * output is then the input, unchanged, and GetHasSurface() is false. Texture coordinates
 * that are not finite (NaN, infinite) are a warning: the mappers draw the triangles
 * around them without relief. So are normals without a direction (zero, not finite),
 * where the surface's own normal stands in, and points that are not finite, whose
 * triangles are left out. Cells that refer to points the mesh does not have (a broken
 * file) are an error and left out.
 */
#ifndef vtkReliefSurfaceFilter_h
#define vtkReliefSurfaceFilter_h

#include "vtkPolyDataAlgorithm.h"
#include "vtkReliefFiltersModule.h"
#include "vtkSmartPointer.h" // for ExtractTriangles

#include <functional> // for LeaveOutCells

class vtkDataArray;

class VTKRELIEFFILTERS_EXPORT vtkReliefSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkReliefSurfaceFilter* New();
  vtkTypeMacro(vtkReliefSurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// True when the last update found texture coordinates and polygons.
  vtkGetMacro(HasSurface, bool);

  /**
   * True when the polygons of `mesh` enclose a volume and face out of it: with coincident
   * points taken as one (texture seams duplicate them), every edge joins exactly two
   * polygons that run along it in opposite directions, and the enclosed signed volume is
   * positive. Degenerate polygons (repeated corners) are left out. Seen from outside such
   * a mesh, back faces are visible only through outlines that relief carves.
   */
  static bool IsClosed(vtkPolyData* mesh);

  /// Whether both texture coordinates of `point` in `tcoords` are finite numbers.
  static bool HasFiniteTextureCoordinates(vtkDataArray* tcoords, vtkIdType point);

  /// Whether the normal of `point` in `normals` has a direction (finite, not zero).
  static bool HasDirection(vtkDataArray* normals, vtkIdType point);

  /// Whether a cell of `mesh` refers to a point id the mesh does not have (a broken file).
  static bool RefersToMissingPoints(vtkPolyData* mesh);

  /// The bounds of the finite points of `mesh`; false (bounds uninitialized) when none is.
  static bool GetFiniteBounds(vtkPolyData* mesh, double bounds[6]);

protected:
  vtkReliefSurfaceFilter();
  ~vtkReliefSurfaceFilter() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /**
   * The triangles of `mesh` (whose cells refer to its own points: see
   * LeaveOutCellsWithMissingPoints) with their point data, or nullptr after reporting why
   * relief cannot be drawn on it (no 2D texture coordinates, no polygons).
   */
  vtkSmartPointer<vtkPolyData> ExtractTriangles(vtkPolyData* mesh);

  /// Names the output's unnamed texture coordinates and normals (copies; the input stays).
  static void NameAttributes(vtkPolyData* output);

  /// One warning when some of the mesh's texture coordinates are not finite.
  void ReportNonFiniteTextureCoordinates(vtkPolyData* mesh);

  /// One warning when some triangles' texture coordinates map no area: no relief there.
  void ReportTextureCoordinatesWithoutArea(vtkPolyData* triangles);
  static bool MapsTextureArea(vtkDataArray* tcoords, const vtkIdType ids[3]);

  /**
   * The mesh, its normals or tangents left out (with one warning) when they do not give
   * three numbers a point; one warning when some normals have no direction (zero, not
   * finite), which the mappers replace by the surface's own.
   */
  vtkSmartPointer<vtkPolyData> WithUsableNormals(vtkPolyData* mesh);

  /// `mesh` without the cells that `leave` picks by their point ids (count, ids), its cell
  /// data kept in step; `left` counts the cells left out.
  static vtkSmartPointer<vtkPolyData> LeaveOutCells(vtkPolyData* mesh,
    const std::function<bool(vtkIdType, const vtkIdType*)>& leave, vtkIdType& left);

  /// The mesh without the cells that refer to points it does not have (with one error);
  /// the mesh itself when there are none.
  vtkSmartPointer<vtkPolyData> LeaveOutCellsWithMissingPoints(vtkPolyData* mesh);

  /// The mesh without the cells that use points that are not finite (with one warning),
  /// those points moved next to a finite one; the mesh itself when all are finite.
  vtkSmartPointer<vtkPolyData> LeaveOutNonFinitePoints(vtkPolyData* mesh);

  bool HasSurface = false;

private:
  vtkReliefSurfaceFilter(const vtkReliefSurfaceFilter&) = delete;
  void operator=(const vtkReliefSurfaceFilter&) = delete;
};

#endif
