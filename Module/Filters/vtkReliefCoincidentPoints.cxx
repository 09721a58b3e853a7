#include "vtkReliefCoincidentPoints.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStaticPointLocator.h"

#include <cmath>

std::vector<vtkIdType> vtkReliefCoincidentPoints(vtkPolyData* mesh)
{
  const vtkIdType count = mesh->GetNumberOfPoints();
  for (vtkIdType id = 0; id < count; ++id)
  {
    const double* point = mesh->GetPoint(id);
    if (!std::isfinite(point[0]) || !std::isfinite(point[1]) || !std::isfinite(point[2]))
    {
      return {};
    }
  }
  std::vector<vtkIdType> merged(static_cast<size_t>(count));
  if (count == 0)
  {
    return merged;
  }
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(mesh);
  locator->BuildLocator();
  locator->MergePoints(1e-9 * mesh->GetLength(), merged.data());
  return merged;
}
