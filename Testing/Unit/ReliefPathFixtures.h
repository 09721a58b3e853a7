// Path-feature scenes for the unit tests: paths and profiles as VTK data, the filter's
// textures as the CPU mirror reads them, and a reference that knows nothing of grids and
// events: the features' definition (the union of each path's straight pieces swept by
// its profile, revolved about their ends, s5.3's priorities and cuts) tested point by
// point, and a ray marched through it in small steps, then bisected.
#ifndef ReliefPathFixtures_h
#define ReliefPathFixtures_h

#include "ReliefCpuMirror.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

namespace ReliefPathFixtures
{
using glm::dvec2;

struct PathSpec
{
  std::vector<dvec2> Points; // straight segments between them
  double Width = 0.05;
  int Profile = 0;
  int Priority = 0;
  double ScaleStart = 1.0;
  double ScaleEnd = 1.0;
};

struct Scene
{
  std::vector<PathSpec> Paths;
  std::vector<std::vector<dvec2>> Profiles; // empty: the filter's default groove
};

inline vtkSmartPointer<vtkPolyData> PathsData(const std::vector<PathSpec>& paths)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkDoubleArray> widths;
  widths->SetName("Width");
  vtkNew<vtkIntArray> profiles;
  profiles->SetName("Profile");
  vtkNew<vtkIntArray> priorities;
  priorities->SetName("Priority");
  vtkNew<vtkDoubleArray> perturbations;
  perturbations->SetName("Perturbation");
  perturbations->SetNumberOfComponents(2);
  for (const PathSpec& path : paths)
  {
    lines->InsertNextCell(static_cast<int>(path.Points.size()));
    for (const dvec2& point : path.Points)
    {
      lines->InsertCellPoint(points->InsertNextPoint(point.x, point.y, 0.0));
    }
    widths->InsertNextValue(path.Width);
    profiles->InsertNextValue(path.Profile);
    priorities->InsertNextValue(path.Priority);
    perturbations->InsertNextTuple2(path.ScaleStart, path.ScaleEnd);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  data->GetCellData()->AddArray(widths);
  data->GetCellData()->AddArray(profiles);
  data->GetCellData()->AddArray(priorities);
  data->GetCellData()->AddArray(perturbations);
  return data;
}

/// The paths, each with the material of the filter's index in `materials` ("Material").
inline vtkSmartPointer<vtkPolyData> PathsData(
  const std::vector<PathSpec>& paths, const std::vector<int>& materials)
{
  vtkSmartPointer<vtkPolyData> data = PathsData(paths);
  vtkNew<vtkIntArray> array;
  array->SetName("Material");
  for (const int material : materials)
  {
    array->InsertNextValue(material);
  }
  data->GetCellData()->AddArray(array);
  return data;
}

inline vtkSmartPointer<vtkPolyData> ProfilesData(const std::vector<std::vector<dvec2>>& profiles)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (const std::vector<dvec2>& profile : profiles)
  {
    lines->InsertNextCell(static_cast<int>(profile.size()));
    for (const dvec2& point : profile)
    {
      lines->InsertCellPoint(points->InsertNextPoint(point.x, point.y, 0.0));
    }
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  return data;
}

/// The default groove, as the filter documents it: a half circle of 8 facets, depth 1.
inline std::vector<dvec2> DefaultGroove()
{
  std::vector<dvec2> profile;
  for (int k = 0; k <= 8; ++k)
  {
    profile.emplace_back(-std::cos(M_PI * k / 8), std::sin(M_PI * k / 8));
  }
  return profile;
}

/// The filter's textures as the mirror reads them.
inline ReliefCpuMirror::PathTextures Textures(vtkPathFeatureTextureFilter* filter)
{
  ReliefCpuMirror::PathTextures textures;
  vtkImageData* grid = filter->GetGridOutput();
  vtkImageData* data = filter->GetDataOutput();
  int dimensions[3];
  grid->GetDimensions(dimensions);
  textures.GridWidth = dimensions[0];
  textures.GridHeight = dimensions[1];
  auto read = [](vtkDataArray* array, std::vector<glm::vec4>& out)
  {
    out.resize(static_cast<size_t>(array->GetNumberOfTuples()));
    for (vtkIdType k = 0; k < array->GetNumberOfTuples(); ++k)
    {
      double value[4];
      array->GetTuple(k, value);
      out[k] = glm::vec4(value[0], value[1], value[2], value[3]);
    }
  };
  read(grid->GetPointData()->GetScalars(), textures.Grid);
  read(data->GetPointData()->GetScalars(), textures.Data);
  return textures;
}

/// The reference: what the features make of a point (u, v, depth), tiles repeating.
class Reference
{
public:
  Reference(const Scene& scene, double base)
    : Features(scene)
    , Base(base)
  {
    if (this->Features.Profiles.empty())
    {
      this->Features.Profiles.push_back(DefaultGroove());
    }
  }

  bool Solid(glm::dvec3 point) const
  {
    bool held = false;
    bool cut = false;
    double best = -1e300;
    for (const PathSpec& path : this->Features.Paths)
    {
      const int kind = this->PathClass(path, point);
      if (kind != 0 && path.Priority >= best)
      {
        cut = path.Priority > best ? kind == 2 : (cut || kind == 2);
        best = path.Priority;
        held = true;
      }
    }
    const double ground = this->Field ? this->Field->Sample(glm::vec2(point.x, point.y)) : 0.0;
    return held ? !cut : point.z >= this->Base + ground;
  }

  /// A relief base (vtkReliefPathOnRelief.glsl): where no feature holds a point, matter is
  /// the field hung from the base plane, not all below it.
  void SetReliefBase(const ReliefCpuMirror::DepthField* field) { this->Field = field; }

  /// The first t in [0, tEnd] where the ray is in matter: steps of `step`, then bisection.
  double Hit(glm::dvec3 origin, glm::dvec3 direction, double tEnd, double step) const
  {
    return this->HitAlong([&](double t) { return origin + t * direction; }, tEnd, step);
  }

  /// The same along any path through (u, v, depth): `at(t)`.
  template <typename PointAt>
  double HitAlong(PointAt at, double tEnd, double step) const
  {
    double previous = 0.0;
    if (this->Solid(at(0.0)))
    {
      return 0.0;
    }
    for (double t = step; t <= tEnd + step; t += step)
    {
      if (this->Solid(at(std::min(t, tEnd))))
      {
        double low = previous;
        double high = std::min(t, tEnd);
        for (int k = 0; k < 40; ++k)
        {
          const double middle = 0.5 * (low + high);
          (this->Solid(at(middle)) ? high : low) = middle;
        }
        return high;
      }
      previous = t;
    }
    return -1.0;
  }

private:
  static bool Inside(const std::vector<dvec2>& profile, double x, double y)
  {
    bool inside = false;
    for (size_t k = 0, previous = profile.size() - 1; k < profile.size(); previous = k++)
    {
      const dvec2& a = profile[k];
      const dvec2& b = profile[previous];
      if ((a.y > y) != (b.y > y) && x < a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y))
      {
        inside = !inside;
      }
    }
    return inside;
  }

  // 0 nothing, 1 added, 2 cut, as the union of the path's pieces (cuts winning)
  int PathClass(const PathSpec& path, glm::dvec3 point) const
  {
    const std::vector<dvec2>& profile = this->Features.Profiles[path.Profile];
    double length = 0.0;
    for (size_t k = 1; k < path.Points.size(); ++k)
    {
      length += glm::length(path.Points[k] - path.Points[k - 1]);
    }
    int result = 0;
    double arc = 0.0;
    for (size_t k = 1; k < path.Points.size(); ++k)
    {
      const dvec2 a = path.Points[k - 1];
      const dvec2 b = path.Points[k];
      const double span = glm::length(b - a);
      const dvec2 axis = (b - a) / span;
      const dvec2 right(axis.y, -axis.x);
      // the copy of the point nearest to the piece
      dvec2 uv(point.x, point.y);
      uv -= glm::round(uv - 0.5 * (a + b));
      const double along = glm::dot(uv - a, axis);
      double across = glm::dot(uv - a, right);
      const double clamped = glm::clamp(along, 0.0, span);
      const double scale = glm::mix(path.ScaleStart, path.ScaleEnd, (arc + clamped) / length);
      if (along < 0.0 || along > span)
      {
        across = (across >= 0.0 ? 1.0 : -1.0) * glm::length(uv - (along < 0.0 ? a : b));
      }
      arc += span;
      if (!(scale > 1e-6))
      {
        continue;
      }
      const double x = across / (0.5 * path.Width * scale);
      const double y = (point.z - this->Base) / scale;
      int kind = 0;
      if (y >= 0.0)
      {
        kind = Inside(profile, x, std::max(y, 1e-6)) ? 2 : 0;
      }
      else
      {
        kind = Inside(profile, x, y) ? 1 : (Inside(profile, x, 1e-6) ? 2 : 0);
      }
      result = kind == 2 ? 2 : std::max(result, kind);
    }
    return result;
  }

  Scene Features;
  double Base;
  const ReliefCpuMirror::DepthField* Field = nullptr;
};
}

#endif
