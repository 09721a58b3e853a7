#include "vtkReliefCoincidentPoints.h"

#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticPointLocator.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace
{
// Whether the normals of points a and b are at most `cosine` apart (both without a
// direction count as alike).
bool Alike(vtkDataArray* normals, vtkIdType a, vtkIdType b, double cosine)
{
  double na[3], nb[3];
  normals->GetTuple(a, na);
  normals->GetTuple(b, nb);
  const double la = vtkMath::Norm(na);
  const double lb = vtkMath::Norm(nb);
  if (!(la > 0.0) || !(lb > 0.0) || !std::isfinite(la) || !std::isfinite(lb))
  {
    return !(la > 0.0 && std::isfinite(la)) && !(lb > 0.0 && std::isfinite(lb));
  }
  return vtkMath::Dot(na, nb) >= cosine * la * lb;
}
}

std::vector<vtkIdType> vtkReliefCoincidentPoints(
  vtkPolyData* mesh, vtkDataArray* normals, double maximumAngle)
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
  // Each point goes to the lowest id within the tolerance, that one to its own, and so on:
  // the same groups whatever the threads do (VTK 9.1's threaded MergePoints picks its
  // stand-ins in whatever order its threads run, and a mesh's closedness changed from run
  // to run with it).
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(mesh);
  locator->BuildLocator();
  const double tolerance = 1e-9 * mesh->GetLength();
  vtkSMPThreadLocalObject<vtkIdList> nearby;
  vtkSMPTools::For(0, count, [&](vtkIdType begin, vtkIdType end) {
    vtkIdList* found = nearby.Local();
    for (vtkIdType id = begin; id < end; ++id)
    {
      double point[3];
      mesh->GetPoint(id, point); // the thread-safe form
      locator->FindPointsWithinRadius(tolerance, point, found);
      vtkIdType lowest = id;
      for (vtkIdType k = 0; k < found->GetNumberOfIds(); ++k)
      {
        lowest = std::min(lowest, found->GetId(k));
      }
      merged[id] = lowest;
    }
  });
  for (vtkIdType id = 0; id < count; ++id)
  {
    merged[id] = merged[merged[id]]; // lower ids are final already
  }
  if (!normals || normals->GetNumberOfTuples() < count || maximumAngle >= 180.0)
  {
    return merged;
  }
  // within each group at one position, the copies whose normals differ stand apart: each
  // point goes to the first of its group (in id order) that stands for itself and is alike
  const double cosine = std::cos(vtkMath::RadiansFromDegrees(maximumAngle));
  std::unordered_map<vtkIdType, std::vector<vtkIdType>> standIns; // per position
  std::vector<vtkIdType> split(merged.size());
  for (vtkIdType id = 0; id < count; ++id)
  {
    std::vector<vtkIdType>& candidates = standIns[merged[id]];
    split[id] = id;
    for (vtkIdType candidate : candidates)
    {
      if (Alike(normals, id, candidate, cosine))
      {
        split[id] = candidate;
        break;
      }
    }
    if (split[id] == id)
    {
      candidates.push_back(id);
    }
  }
  return split;
}
