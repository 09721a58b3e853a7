/**
 * vtkReliefCoincidentPoints(mesh): for each point of `mesh`, the id of one point that
 * stands for every point at its position, so that points that texture seams duplicate count
 * as one (within 1e-9 of the bounds' diagonal, float rounding of exported meshes). Empty
 * when a point is not finite. Not wrapped: a helper of the relief filters.
 */
#ifndef vtkReliefCoincidentPoints_h
#define vtkReliefCoincidentPoints_h

#include "vtkType.h"

#include <vector>

class vtkPolyData;

std::vector<vtkIdType> vtkReliefCoincidentPoints(vtkPolyData* mesh);

#endif
