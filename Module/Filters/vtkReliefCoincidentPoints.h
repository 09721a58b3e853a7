/**
 * vtkReliefCoincidentPoints(mesh, normals, maximumAngle): for each point of `mesh`, the id
 * of one point that stands for every point at its position (within 1e-9 of the bounds'
 * diagonal: the float rounding of exported meshes), so that the copies a texture seam
 * makes count as one. With `normals`, copies whose normals differ by more than
 * `maximumAngle` degrees stay apart: a crease split for its normals is a crease. Empty when
 * a point is not finite. Not wrapped: a helper of the relief filters.
 */
#ifndef vtkReliefCoincidentPoints_h
#define vtkReliefCoincidentPoints_h

#include "vtkType.h"

#include <vector>

class vtkDataArray;
class vtkPolyData;

std::vector<vtkIdType> vtkReliefCoincidentPoints(
  vtkPolyData* mesh, vtkDataArray* normals = nullptr, double maximumAngle = 180.0);

#endif
