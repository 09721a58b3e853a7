#include "vtkPathFeatureTextureFilter.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkPathFeatureTextureFilter);

namespace
{
using glm::dvec2;

// How far a curve's straight pieces may stray from it, in half widths of its feature.
constexpr double CurveTolerance = 0.02;

struct Profile
{
  std::vector<dvec2> Points; // (across in half widths, depth below the base)
  double Extent = 0.0;       // the most |x|: how far across the feature reaches
  double Top = 0.0;          // the least y: its highest point (negative protrudes)
  double Bottom = 0.0;       // the most y: its deepest
  bool Centred = false;      // at every depth its inside is one interval centred on x = 0
};

struct Material
{
  double Colour[3];
  double Specular;
  double SpecularPower;
};

struct Path
{
  double HalfWidth = 0.0;
  int Profile = 0;
  int Material = -1;
  int Priority = 0;
  double ScaleStart = 1.0;
  double ScaleEnd = 1.0;
  double Length = 0.0;
  bool Closed = false;
  int ElementCount = 0;
  vtkIdType Cell = 0; // the input's line
};

// A path's segment as read: a line, or a quadratic curve through its control point.
struct Segment
{
  dvec2 Start;
  dvec2 Control; // quadratic only
  dvec2 End;
  bool Quadratic = false;
};

// What the grid lists and the shader intersects: a straight piece of a path.
struct Element
{
  dvec2 Start;
  dvec2 End;
  int Path = 0;
  double ArcStart = 0.0;
  double ArcEnd = 0.0;
  bool StartsPath = false; // an open path's first element
  bool EndsPath = false;   // its last
  int Index = 0;           // in its path
};

// The round-bottomed groove of depth 1 used where no profile is given.
Profile DefaultProfile()
{
  Profile profile;
  constexpr int Facets = 8;
  for (int k = 0; k <= Facets; ++k)
  {
    const double angle = M_PI * k / Facets;
    profile.Points.emplace_back(-std::cos(angle), std::sin(angle));
  }
  return profile;
}

// Whether the profile, closed from its last point to its first, holds at every depth
// one interval centred on x = 0, or nothing (even-odd, as the shader reads it), to 1e-9
// of its size. Between two depths of its points the interval's ends move linearly, so two
// depths within each such band tell; bands thinner than that are left out (a point at
// sin(pi) = 1.2e-16 for 0).
bool IsCentred(const Profile& profile)
{
  const double tolerance =
    1e-9 * std::max({ 1.0, profile.Extent, profile.Bottom - profile.Top });
  std::vector<double> depths;
  for (const dvec2& point : profile.Points)
  {
    depths.push_back(point.y);
  }
  std::sort(depths.begin(), depths.end());
  std::vector<double> levels;
  for (const double depth : depths)
  {
    if (levels.empty() || depth - levels.back() > tolerance)
    {
      levels.push_back(depth);
    }
  }
  const size_t n = profile.Points.size();
  std::vector<double> crossings;
  for (size_t band = 0; band + 1 < levels.size(); ++band)
  {
    for (const double share : { 0.25, 0.75 })
    {
      const double y = glm::mix(levels[band], levels[band + 1], share);
      crossings.clear();
      for (size_t k = 0; k < n; ++k)
      {
        const dvec2& a = profile.Points[(k + n - 1) % n];
        const dvec2& b = profile.Points[k];
        if ((a.y > y) != (b.y > y))
        {
          crossings.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
        }
      }
      if (crossings.size() != 2 || std::abs(crossings[0] + crossings[1]) > tolerance)
      {
        return false;
      }
    }
  }
  return true;
}

void MeasureProfile(Profile& profile)
{
  profile.Extent = 0.0;
  profile.Top = 0.0;
  profile.Bottom = 0.0;
  for (const dvec2& point : profile.Points)
  {
    profile.Extent = std::max(profile.Extent, std::abs(point.x));
    profile.Top = std::min(profile.Top, point.y);
    profile.Bottom = std::max(profile.Bottom, point.y);
  }
  profile.Centred = IsCentred(profile);
}

dvec2 QuadraticAt(const Segment& segment, double s)
{
  return (1 - s) * (1 - s) * segment.Start + 2 * s * (1 - s) * segment.Control +
    s * s * segment.End;
}

// The segment as straight elements, none longer than MaximumElementLength; a curve in
// pieces whose chords stray at most `tolerance` from it (a quadratic's chord over a
// parameter step h strays |p0 - 2c + p2| h^2 / 4).
void AppendElements(const Segment& segment, double tolerance, std::vector<Element>& out)
{
  std::vector<dvec2> points{ segment.Start };
  if (segment.Quadratic)
  {
    const double bend = glm::length(segment.Start - 2.0 * segment.Control + segment.End);
    const int pieces =
      std::max(1, static_cast<int>(std::ceil(std::sqrt(bend / (4.0 * tolerance)))));
    for (int k = 1; k <= pieces; ++k)
    {
      points.push_back(QuadraticAt(segment, static_cast<double>(k) / pieces));
    }
  }
  else
  {
    points.push_back(segment.End);
  }
  for (size_t k = 1; k < points.size(); ++k)
  {
    const double length = glm::length(points[k] - points[k - 1]);
    const int pieces = std::max(
      1, static_cast<int>(std::ceil(length / vtkPathFeatureTextureFilter::MaximumElementLength)));
    for (int piece = 0; piece < pieces; ++piece)
    {
      Element element;
      element.Start = glm::mix(points[k - 1], points[k], static_cast<double>(piece) / pieces);
      element.End = glm::mix(points[k - 1], points[k], static_cast<double>(piece + 1) / pieces);
      out.push_back(element);
    }
  }
}

double DistanceToSegment(dvec2 point, dvec2 a, dvec2 b)
{
  const dvec2 ab = b - a;
  const double span = glm::dot(ab, ab);
  const double s = span > 0.0 ? glm::clamp(glm::dot(point - a, ab) / span, 0.0, 1.0) : 0.0;
  return glm::length(point - (a + s * ab));
}

double Cross(dvec2 a, dvec2 b)
{
  return a.x * b.y - a.y * b.x;
}

bool SegmentsCross(dvec2 a, dvec2 b, dvec2 c, dvec2 d)
{
  const double d1 = Cross(b - a, c - a);
  const double d2 = Cross(b - a, d - a);
  const double d3 = Cross(d - c, a - c);
  const double d4 = Cross(d - c, b - c);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 &&
    d4 != 0;
}

// The array `name` of `data` if it has `components` components, else null (its default
// applies).
vtkDataArray* ArrayWithComponents(vtkFieldData* data, const char* name, int components)
{
  vtkDataArray* array = data ? data->GetArray(name) : nullptr;
  return array && array->GetNumberOfComponents() == components ? array : nullptr;
}
}

namespace
{
// What the paths held that could not be drawn as given.
struct PathReport
{
  vtkIdType BadWidths = 0;
  vtkIdType WideWidths = 0;
  vtkIdType ZeroLengthSegments = 0;
  vtkIdType DegeneratePaths = 0;
  vtkIdType UnknownProfiles = 0;
  vtkIdType UnknownMaterials = 0;
  vtkIdType BadScales = 0;
};

}

struct vtkPathFeatureTextureFilter::Internals
{
  std::vector<Material> Materials;
  std::vector<Profile> Profiles;
  std::vector<Path> Paths;
  std::vector<Element> Elements;
  PathReport Report;
  vtkIdType TextureBytes = 0;
};

vtkPathFeatureTextureFilter::vtkPathFeatureTextureFilter()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2);
}

vtkPathFeatureTextureFilter::~vtkPathFeatureTextureFilter() = default;

void vtkPathFeatureTextureFilter::SetPathsData(vtkPolyData* paths)
{
  this->SetInputDataInternal(0, reinterpret_cast<vtkDataObject*>(paths));
}

void vtkPathFeatureTextureFilter::SetProfilesData(vtkPolyData* profiles)
{
  this->SetInputDataInternal(1, reinterpret_cast<vtkDataObject*>(profiles));
}

vtkImageData* vtkPathFeatureTextureFilter::GetGridOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(0));
}

vtkImageData* vtkPathFeatureTextureFilter::GetDataOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

int vtkPathFeatureTextureFilter::AddMaterial(
  double red, double green, double blue, double specular, double specularPower)
{
  Material material{ { red, green, blue }, specular, specularPower };
  for (double& channel : material.Colour)
  {
    channel = std::isfinite(channel) ? glm::clamp(channel, 0.0, 1.0) : 0.0;
  }
  material.Specular = std::isfinite(specular) ? std::max(specular, 0.0) : 0.0;
  material.SpecularPower = std::isfinite(specularPower) ? std::max(specularPower, 0.0) : 1.0;
  this->Internal->Materials.push_back(material);
  this->Modified();
  return static_cast<int>(this->Internal->Materials.size()) - 1;
}

void vtkPathFeatureTextureFilter::RemoveAllMaterials()
{
  if (!this->Internal->Materials.empty())
  {
    this->Internal->Materials.clear();
    this->Modified();
  }
}

int vtkPathFeatureTextureFilter::GetNumberOfMaterials()
{
  return static_cast<int>(this->Internal->Materials.size());
}

vtkIdType vtkPathFeatureTextureFilter::GetTextureBytes()
{
  return this->Internal->TextureBytes;
}

int vtkPathFeatureTextureFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

namespace
{
// Reads the profiles of port 1 (or the default), each checked.
std::vector<Profile> ReadProfiles(
  vtkPolyData* input, std::vector<vtkIdType>& tooShort, std::vector<vtkIdType>& tooLong)
{
  std::vector<Profile> profiles;
  if (!input || input->GetNumberOfLines() == 0)
  {
    profiles.push_back(DefaultProfile());
    MeasureProfile(profiles.back());
    return profiles;
  }
  auto lines = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    lines->GetCurrentCell(size, ids);
    Profile profile;
    for (vtkIdType k = 0; k < size; ++k)
    {
      double point[3];
      input->GetPoint(ids[k], point);
      if (std::isfinite(point[0]) && std::isfinite(point[1]))
      {
        profile.Points.emplace_back(point[0], point[1]);
      }
    }
    if (profile.Points.size() < 2)
    {
      tooShort.push_back(static_cast<vtkIdType>(profiles.size()));
      profile = DefaultProfile();
    }
    const size_t most = vtkPathFeatureTextureFilter::MaximumProfilePoints;
    if (profile.Points.size() > most)
    {
      // evenly chosen points, both ends kept
      tooLong.push_back(static_cast<vtkIdType>(profiles.size()));
      std::vector<dvec2> kept;
      for (size_t k = 0; k < most; ++k)
      {
        kept.push_back(profile.Points[k * (profile.Points.size() - 1) / (most - 1)]);
      }
      profile.Points = kept;
    }
    MeasureProfile(profile);
    profiles.push_back(profile);
  }
  return profiles;
}
}

namespace
{
// The attributes of path `cell` from the cell data, checked; false to leave it out.
bool ReadPathAttributes(vtkPolyData* input, vtkIdType cell, double defaultWidth, int profileCount,
  int materialCount, Path& path, PathReport& report)
{
  vtkCellData* cellData = input->GetCellData();
  vtkDataArray* widths = ArrayWithComponents(cellData, "Width", 1);
  vtkDataArray* profiles = ArrayWithComponents(cellData, "Profile", 1);
  vtkDataArray* materials = ArrayWithComponents(cellData, "Material", 1);
  vtkDataArray* priorities = ArrayWithComponents(cellData, "Priority", 1);
  vtkDataArray* perturbations = ArrayWithComponents(cellData, "Perturbation", 2);
  const double width = widths ? widths->GetTuple1(cell) : defaultWidth;
  if (!(width > 0.0) || !std::isfinite(width))
  {
    report.BadWidths += 1;
    return false;
  }
  if (width > 1.0)
  {
    report.WideWidths += 1;
  }
  path.Cell = cell;
  path.HalfWidth = 0.5 * std::min(width, 1.0);
  const double profile = profiles ? profiles->GetTuple1(cell) : 0.0;
  path.Profile = static_cast<int>(std::lround(profile));
  if (!(profile >= 0.0) || path.Profile >= profileCount)
  {
    report.UnknownProfiles += 1;
    path.Profile = 0;
  }
  const double material = materials ? materials->GetTuple1(cell) : -1.0;
  path.Material = static_cast<int>(std::lround(material));
  if (!(material >= -1.0) || path.Material >= materialCount)
  {
    report.UnknownMaterials += 1;
    path.Material = -1;
  }
  const double priority = priorities ? priorities->GetTuple1(cell) : 0.0;
  path.Priority = std::isfinite(priority)
    ? static_cast<int>(std::lround(glm::clamp(priority, -65536.0, 65536.0)))
    : 0;
  if (perturbations)
  {
    double scales[2];
    perturbations->GetTuple(cell, scales);
    for (double& scale : scales)
    {
      if (!(scale >= 0.0) || !std::isfinite(scale))
      {
        report.BadScales += 1;
        scale = 1.0;
      }
    }
    path.ScaleStart = scales[0];
    path.ScaleEnd = scales[1];
  }
  return true;
}

// The path's segments from its points, control points making quadratic ones.
std::vector<Segment> ReadSegments(vtkPolyData* input, vtkIdType size, const vtkIdType* ids,
  vtkDataArray* controls, PathReport& report)
{
  std::vector<dvec2> points;
  std::vector<bool> isControl;
  vtkIdType repeated = 0;
  for (vtkIdType k = 0; k < size; ++k)
  {
    double point[3];
    input->GetPoint(ids[k], point);
    const dvec2 uv(point[0], point[1]);
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y))
    {
      continue;
    }
    if (!points.empty() && uv == points.back())
    {
      repeated += 1;
      continue;
    }
    points.push_back(uv);
    isControl.push_back(controls && controls->GetTuple1(ids[k]) != 0.0);
  }
  std::vector<Segment> segments;
  if (points.size() < 2)
  {
    return segments; // the whole path is reported instead
  }
  report.ZeroLengthSegments += repeated;
  // a path starts and ends on itself
  isControl.front() = false;
  isControl.back() = false;
  dvec2 current = points[0];
  for (size_t k = 1; k < points.size(); ++k)
  {
    Segment segment;
    segment.Start = current;
    if (!isControl[k])
    {
      segment.End = points[k];
    }
    else
    {
      segment.Control = points[k];
      segment.End = isControl[k + 1] ? 0.5 * (points[k] + points[k + 1]) : points[k + 1];
      k += isControl[k + 1] ? 0 : 1;
      // a control point on the chord makes a line
      const dvec2 chord = segment.End - segment.Start;
      segment.Quadratic =
        std::abs(Cross(segment.Control - segment.Start, chord)) > 1e-9 * glm::dot(chord, chord);
    }
    current = segment.End;
    if (segment.End == segment.Start)
    {
      report.ZeroLengthSegments += 1;
      continue;
    }
    segments.push_back(segment);
  }
  return segments;
}

// Reads every path of port 0 into `paths` and `elements`.
void ReadPaths(vtkPolyData* input, double defaultWidth, int profileCount, int materialCount,
  std::vector<Path>& paths, std::vector<Element>& elements, PathReport& report)
{
  paths.clear();
  elements.clear();
  if (!input || input->GetNumberOfLines() == 0)
  {
    return;
  }
  vtkDataArray* controls = ArrayWithComponents(input->GetPointData(), "ControlPoint", 1);
  // cell data counts vertices first, then lines
  vtkIdType cell = input->GetNumberOfVerts();
  auto lines = vtk::TakeSmartPointer(input->GetLines()->NewIterator());
  for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    lines->GetCurrentCell(size, ids);
    Path path;
    if (!ReadPathAttributes(input, cell, defaultWidth, profileCount, materialCount, path, report))
    {
      continue;
    }
    std::vector<Segment> segments = ReadSegments(input, size, ids, controls, report);
    if (segments.empty())
    {
      report.DegeneratePaths += 1;
      continue;
    }
    path.Closed = segments.size() > 1 && segments.front().Start == segments.back().End;
    // the path's first tile: the texture repeats, and so does its grid
    const dvec2 tile = glm::floor(segments.front().Start);
    const int pathIndex = static_cast<int>(paths.size());
    const size_t first = elements.size();
    for (Segment& segment : segments)
    {
      segment.Start -= tile;
      segment.Control -= tile;
      segment.End -= tile;
      AppendElements(segment, CurveTolerance * path.HalfWidth, elements);
    }
    double arc = 0.0;
    for (size_t k = first; k < elements.size(); ++k)
    {
      Element& element = elements[k];
      element.Path = pathIndex;
      element.Index = static_cast<int>(k - first);
      element.ArcStart = arc;
      arc += glm::length(element.End - element.Start);
      element.ArcEnd = arc;
    }
    elements[first].StartsPath = !path.Closed;
    elements.back().EndsPath = !path.Closed;
    path.Length = arc;
    path.ElementCount = static_cast<int>(elements.size() - first);
    paths.push_back(path);
  }
}

// The scale of a path's profile at arc length `arc` (s5.5).
double ScaleAt(const Path& path, double arc)
{
  return path.Length > 0.0 ? glm::mix(path.ScaleStart, path.ScaleEnd, arc / path.Length)
                           : path.ScaleStart;
}

// How far from its centre line an element's feature reaches, in tiles.
double ElementRadius(const Element& element, const Path& path, const Profile& profile)
{
  const double scale = std::max(ScaleAt(path, element.ArcStart), ScaleAt(path, element.ArcEnd));
  return path.HalfWidth * profile.Extent * scale;
}

// Where a path turns (not exactly straight on), the shader revolves the profile about the
// joint beyond the previous element's end and before the next one's start; one of the two
// holds all the other does where the profile is centred (then, within the revolved
// profile's reach of the joint, an element's straight part holds at the same depth all
// its revolved end holds), does not both cut and add, keeps one scale along its path, and
// the element whose end stays revolved runs on at least that reach from the joint: that
// one alone is revolved (the other ends at the plane across the joint, as at an exact
// join), so that rays pass one revolved end there, not two. 1: the previous element's end
// is not revolved; 2: the next one's start; 0: both are.
int RevolvedOnce(
  const Element& previous, const Element& next, const Path& path, const Profile& profile)
{
  if (!profile.Centred || (profile.Top < 0.0 && profile.Bottom > 0.0) ||
    path.ScaleStart != path.ScaleEnd)
  {
    return 0;
  }
  const double reach = ElementRadius(previous, path, profile); // one scale along the path
  if (glm::length(previous.End - previous.Start) >= reach)
  {
    return 2;
  }
  return glm::length(next.End - next.Start) >= reach ? 1 : 0;
}

// The grid cells (wrapped, row-major) within reach of `element`.
std::vector<int> CellsOf(const Element& element, double radius, const int resolution[2])
{
  const dvec2 size(resolution[0], resolution[1]);
  const dvec2 low = glm::min(element.Start, element.End);
  const dvec2 high = glm::max(element.Start, element.End);
  const glm::ivec2 first(glm::floor((low - radius) * size));
  const glm::ivec2 last(glm::floor((high + radius) * size));
  const double halfDiagonal = 0.5 * glm::length(1.0 / size);
  std::vector<int> cells;
  for (int j = first.y; j <= last.y; ++j)
  {
    for (int i = first.x; i <= last.x; ++i)
    {
      const dvec2 centre = (dvec2(i, j) + 0.5) / size;
      if (DistanceToSegment(centre, element.Start, element.End) <= radius + halfDiagonal)
      {
        const int wrappedI = ((i % resolution[0]) + resolution[0]) % resolution[0];
        const int wrappedJ = ((j % resolution[1]) + resolution[1]) % resolution[1];
        cells.push_back(wrappedJ * resolution[0] + wrappedI);
      }
    }
  }
  // a feature wider than the tile reaches a cell more than once
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return cells;
}

bool ElementsCross(const Element& a, const Element& b)
{
  return SegmentsCross(a.Start, a.End, b.Start, b.End);
}
}

int vtkPathFeatureTextureFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputs, vtkInformationVector* outputs)
{
  Internals& internal = *this->Internal;
  std::vector<vtkIdType> tooShort;
  std::vector<vtkIdType> tooLong;
  internal.Profiles = ReadProfiles(vtkPolyData::GetData(inputs[1]), tooShort, tooLong);
  if (!tooShort.empty())
  {
    vtkErrorMacro(<< tooShort.size() << " profile(s), the first number " << tooShort.front()
                  << ", have fewer than two points: the default groove is drawn instead."
                     " Give each profile polyline two points or more.");
  }
  if (!tooLong.empty())
  {
    vtkWarningMacro(<< tooLong.size() << " profile(s), the first number " << tooLong.front()
                    << ", have more than " << MaximumProfilePoints
                    << " points: " << MaximumProfilePoints
                    << " of them, evenly chosen, are drawn. Simplify the profile.");
  }
  internal.Report = PathReport();
  ReadPaths(vtkPolyData::GetData(inputs[0]), this->DefaultWidth,
    static_cast<int>(internal.Profiles.size()), static_cast<int>(internal.Materials.size()),
    internal.Paths, internal.Elements, internal.Report);
  this->ReportPaths();
  this->NumberOfElements = static_cast<vtkIdType>(internal.Elements.size());
  this->UpdateProgress(0.2);
  this->MeasureDepths();
  this->ChooseResolution();
  std::vector<int> offsets;
  std::vector<int> lists = this->ListCells(offsets);
  this->UpdateProgress(0.8);
  this->WriteTextures(
    offsets, lists, vtkImageData::GetData(outputs, 0), vtkImageData::GetData(outputs, 1));
  this->UpdateProgress(1.0);
  return 1;
}

void vtkPathFeatureTextureFilter::ReportPaths()
{
  const PathReport& report = this->Internal->Report;
  if (report.BadWidths > 0)
  {
    vtkWarningMacro(<< report.BadWidths
                    << " path(s) with a zero, negative or non-finite \"Width\" are left out."
                       " Give every path a width above 0, in texture units.");
  }
  if (report.WideWidths > 0)
  {
    vtkWarningMacro(<< report.WideWidths
                    << " path(s) wider than a texture tile are drawn one tile wide.");
  }
  if (report.ZeroLengthSegments > 0)
  {
    vtkWarningMacro(<< report.ZeroLengthSegments
                    << " zero-length segment(s) (a point repeated) are left out, the rest of "
                       "their paths drawn. Remove repeated points.");
  }
  if (report.DegeneratePaths > 0)
  {
    vtkWarningMacro(<< report.DegeneratePaths
                    << " path(s) of fewer than two distinct points are left out: a path "
                       "needs a length.");
  }
  if (report.UnknownProfiles > 0)
  {
    vtkWarningMacro(<< report.UnknownProfiles << " path(s) name a profile out of the "
                    << this->Internal->Profiles.size()
                    << " given: they are drawn with profile 0. Number profiles from 0.");
  }
  if (report.UnknownMaterials > 0)
  {
    vtkWarningMacro(<< report.UnknownMaterials << " path(s) name a material out of the "
                    << this->Internal->Materials.size()
                    << " added (AddMaterial): they take the actor's property (-1).");
  }
  if (report.BadScales > 0)
  {
    vtkWarningMacro(<< report.BadScales
                    << " negative or non-finite \"Perturbation\" scale(s) are taken as 1.");
  }
}

void vtkPathFeatureTextureFilter::MeasureDepths()
{
  const Internals& internal = *this->Internal;
  double base = 0.0;
  for (const Path& path : internal.Paths)
  {
    const double scale = std::max(path.ScaleStart, path.ScaleEnd);
    base = std::max(base, -internal.Profiles[path.Profile].Top * scale);
  }
  double deepest = base;
  for (const Path& path : internal.Paths)
  {
    const double scale = std::max(path.ScaleStart, path.ScaleEnd);
    deepest = std::max(deepest, base + internal.Profiles[path.Profile].Bottom * scale);
  }
  this->BaseDepth = base;
  this->MaximumDepth = deepest;
}

void vtkPathFeatureTextureFilter::ChooseResolution()
{
  const Internals& internal = *this->Internal;
  // a cell about as wide as the mean feature, weighted by length (s6, Fig. 14)
  double lengths = 0.0;
  double widths = 0.0;
  for (const Path& path : internal.Paths)
  {
    const double scale = 0.5 * (path.ScaleStart + path.ScaleEnd);
    lengths += path.Length;
    widths += path.Length * 2.0 * path.HalfWidth * internal.Profiles[path.Profile].Extent * scale;
  }
  const double meanWidth = lengths > 0.0 ? widths / lengths : 1.0;
  const int automatic = meanWidth > 0.0 ? static_cast<int>(glm::clamp(std::round(1.0 / meanWidth),
                                            1.0, static_cast<double>(MaximumAutomaticResolution)))
                                        : 1;
  for (int axis = 0; axis < 2; ++axis)
  {
    this->ResolutionUsed[axis] =
      this->GridResolution[axis] > 0 ? this->GridResolution[axis] : automatic;
  }
}

std::vector<int> vtkPathFeatureTextureFilter::ListCells(std::vector<int>& offsets)
{
  const Internals& internal = *this->Internal;
  const std::vector<Element>& elements = internal.Elements;
  std::vector<std::vector<int>> reached(elements.size());
  vtkSMPTools::For(0, static_cast<vtkIdType>(elements.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const Element& element = elements[e];
        const Path& path = internal.Paths[element.Path];
        reached[e] = CellsOf(element, ElementRadius(element, path, internal.Profiles[path.Profile]),
          this->ResolutionUsed);
      }
    });
  // counting sort by cell: each list in element order, the whole linear in its size
  const int cellCount = this->ResolutionUsed[0] * this->ResolutionUsed[1];
  offsets.assign(static_cast<size_t>(cellCount) + 1, 0);
  for (const std::vector<int>& cells : reached)
  {
    for (int cell : cells)
    {
      offsets[cell + 1] += 1;
    }
  }
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  std::vector<int> lists(offsets.back());
  std::vector<int> filled(offsets.begin(), offsets.end() - 1);
  for (size_t e = 0; e < reached.size(); ++e)
  {
    for (int cell : reached[e])
    {
      lists[filled[cell]++] = static_cast<int>(e);
    }
  }
  return lists;
}

std::vector<int> vtkPathFeatureTextureFilter::Joins() const
{
  const Internals& internal = *this->Internal;
  const std::vector<Element>& elements = internal.Elements;
  const double smooth = std::cos(SmoothJointDegrees * M_PI / 180.0);
  const double exact = std::cos(ExactJointRadians);
  std::vector<int> joins(elements.size(), 0);
  for (size_t e = 1; e < elements.size(); ++e)
  {
    const Element& previous = elements[e - 1];
    const Element& element = elements[e];
    if (previous.Path != element.Path)
    {
      continue;
    }
    const double turn = glm::dot(glm::normalize(previous.End - previous.Start),
      glm::normalize(element.End - element.Start));
    if (turn >= smooth)
    {
      joins[e - 1] |= turn >= exact ? 2 + 8 : 2;
      joins[e] |= turn >= exact ? 1 + 4 : 1;
    }
    if (turn < exact)
    {
      const Path& path = internal.Paths[element.Path];
      const int once = RevolvedOnce(previous, element, path, internal.Profiles[path.Profile]);
      joins[e - 1] |= once == 1 ? 8 : 0;
      joins[e] |= once == 2 ? 4 : 0;
    }
  }
  return joins;
}

int vtkPathFeatureTextureFilter::ClassifyCell(
  const int* begin, const int* end, int cell, std::vector<int>& selfCrossing)
{
  const Internals& internal = *this->Internal;
  if (begin == end)
  {
    return 0;
  }
  const dvec2 size(this->ResolutionUsed[0], this->ResolutionUsed[1]);
  const dvec2 centre =
    (dvec2(cell % this->ResolutionUsed[0], cell / this->ResolutionUsed[0]) + 0.5) / size;
  const double halfDiagonal = 0.5 * glm::length(1.0 / size);
  int kind = 1;
  for (const int* a = begin; a != end; ++a)
  {
    const Element& first = internal.Elements[*a];
    const Path& path = internal.Paths[first.Path];
    const double reach = ElementRadius(first, path, internal.Profiles[path.Profile]) + halfDiagonal;
    // an end within reach: its cap meets the cell (positions compared within a tile)
    auto near = [&](dvec2 point)
    {
      const dvec2 offset = point - centre;
      return glm::length(offset - glm::round(offset)) <= reach;
    };
    if ((first.StartsPath && near(first.Start)) || (first.EndsPath && near(first.End)))
    {
      kind = 2;
    }
    for (const int* b = a + 1; b != end; ++b)
    {
      const Element& second = internal.Elements[*b];
      if (second.Path != first.Path)
      {
        kind = 2;
        continue;
      }
      const int apart = std::abs(second.Index - first.Index);
      const bool neighbours = apart == 1 || (path.Closed && apart == path.ElementCount - 1);
      if (!neighbours)
      {
        kind = 2; // the path comes back near itself
        if (ElementsCross(first, second))
        {
          selfCrossing.push_back(first.Path);
        }
      }
    }
  }
  return kind;
}

void vtkPathFeatureTextureFilter::WriteTextures(const std::vector<int>& offsets,
  const std::vector<int>& lists, vtkImageData* grid, vtkImageData* data)
{
  Internals& internal = *this->Internal;
  const int cellCount = this->ResolutionUsed[0] * this->ResolutionUsed[1];
  // where each record starts (the class description's layout)
  int cursor = 1;
  std::vector<int> profileTexels;
  for (const Profile& profile : internal.Profiles)
  {
    profileTexels.push_back(cursor);
    cursor += 1 + static_cast<int>(profile.Points.size() + 1) / 2;
  }
  std::vector<int> materialTexels;
  for (size_t m = 0; m < internal.Materials.size(); ++m)
  {
    materialTexels.push_back(cursor);
    cursor += 2;
  }
  std::vector<int> pathTexels;
  for (size_t p = 0; p < internal.Paths.size(); ++p)
  {
    pathTexels.push_back(cursor);
    cursor += 2;
  }
  std::vector<int> elementTexels;
  for (size_t e = 0; e < internal.Elements.size(); ++e)
  {
    elementTexels.push_back(cursor);
    cursor += 2;
  }
  std::vector<int> listTexels(cellCount);
  std::vector<int> counts(cellCount);
  this->MaximumCellCount = 0;
  int overfull = 0;
  for (int cell = 0; cell < cellCount; ++cell)
  {
    const int count = offsets[cell + 1] - offsets[cell];
    this->MaximumCellCount = std::max(this->MaximumCellCount, count);
    overfull += count > CellCapacity ? 1 : 0;
    counts[cell] = std::min(count, static_cast<int>(CellCapacity));
    listTexels[cell] = cursor;
    cursor += (counts[cell] + 3) / 4;
  }
  if (overfull > 0)
  {
    // elements spread over cells as the area they cover: a grid finer by the square root
    // of the excess brings the busiest cell within the capacity where features are apart
    const double finer = std::sqrt(static_cast<double>(this->MaximumCellCount) / CellCapacity);
    vtkErrorMacro(<< overfull << " grid cell(s) are crossed by more than the " << CellCapacity
                  << " elements a cell can hold (up to " << this->MaximumCellCount
                  << "): the first " << CellCapacity << " of each are drawn. Set GridResolution to "
                  << static_cast<int>(std::ceil(this->ResolutionUsed[0] * finer)) << " "
                  << static_cast<int>(std::ceil(this->ResolutionUsed[1] * finer))
                  << " or more (now " << this->ResolutionUsed[0] << " " << this->ResolutionUsed[1]
                  << "), or split the features that meet there.");
  }

  const int width = std::min(cursor, static_cast<int>(DataWidth));
  const int rows = (cursor + DataWidth - 1) / DataWidth;
  vtkNew<vtkFloatArray> texels;
  texels->SetName("PathFeatureData");
  texels->SetNumberOfComponents(4);
  texels->SetNumberOfTuples(static_cast<vtkIdType>(width) * rows);
  texels->Fill(0.0);
  auto write = [&](int texel, double a, double b, double c, double d)
  {
    const double values[4] = { a, b, c, d };
    texels->SetTuple(texel, values);
  };
  write(0, this->BaseDepth, this->MaximumDepth, this->ResolutionUsed[0], this->ResolutionUsed[1]);
  for (size_t p = 0; p < internal.Profiles.size(); ++p)
  {
    const std::vector<dvec2>& points = internal.Profiles[p].Points;
    const Profile& profile = internal.Profiles[p];
    write(profileTexels[p], static_cast<double>(points.size()), profile.Extent, profile.Top,
      profile.Bottom);
    for (size_t k = 0; k < points.size(); k += 2)
    {
      const dvec2 second = k + 1 < points.size() ? points[k + 1] : dvec2(0.0);
      write(profileTexels[p] + 1 + static_cast<int>(k / 2), points[k].x, points[k].y, second.x,
        second.y);
    }
  }
  for (size_t m = 0; m < internal.Materials.size(); ++m)
  {
    const Material& material = internal.Materials[m];
    write(materialTexels[m], material.Colour[0], material.Colour[1], material.Colour[2],
      material.Specular);
    write(materialTexels[m] + 1, material.SpecularPower, 0, 0, 0);
  }
  for (size_t p = 0; p < internal.Paths.size(); ++p)
  {
    const Path& path = internal.Paths[p];
    write(pathTexels[p], path.HalfWidth, profileTexels[path.Profile],
      path.Material >= 0 ? materialTexels[path.Material] : -1.0, path.Priority);
    write(pathTexels[p] + 1, path.ScaleStart, path.ScaleEnd, path.Length,
      internal.Profiles[path.Profile].Centred ? 0 : 1);
  }
  const std::vector<int> joins = this->Joins();
  for (size_t e = 0; e < internal.Elements.size(); ++e)
  {
    const Element& element = internal.Elements[e];
    write(elementTexels[e], element.Start.x, element.Start.y, element.End.x, element.End.y);
    write(elementTexels[e] + 1, pathTexels[element.Path], element.ArcStart, element.ArcEnd,
      joins[e]);
  }

  vtkNew<vtkFloatArray> cells;
  cells->SetName("PathFeatureGrid");
  cells->SetNumberOfComponents(4);
  cells->SetNumberOfTuples(cellCount);
  std::vector<int> selfCrossing;
  for (int cell = 0; cell < cellCount; ++cell)
  {
    const int* begin = lists.data() + offsets[cell];
    const int* end = begin + counts[cell];
    double top = this->BaseDepth;
    for (const int* e = begin; e != end; ++e)
    {
      const Element& element = internal.Elements[*e];
      const Path& path = internal.Paths[element.Path];
      const double scale = std::max(ScaleAt(path, element.ArcStart), ScaleAt(path, element.ArcEnd));
      top = std::min(top, this->BaseDepth + internal.Profiles[path.Profile].Top * scale);
      const int slot = static_cast<int>(e - begin);
      double entry[4];
      texels->GetTuple(listTexels[cell] + slot / 4, entry);
      entry[slot % 4] = elementTexels[*e];
      texels->SetTuple(listTexels[cell] + slot / 4, entry);
    }
    for (int slot = counts[cell]; slot % 4 != 0; ++slot)
    {
      double entry[4];
      texels->GetTuple(listTexels[cell] + slot / 4, entry);
      entry[slot % 4] = -1.0;
      texels->SetTuple(listTexels[cell] + slot / 4, entry);
    }
    const double values[4] = { static_cast<double>(listTexels[cell]),
      static_cast<double>(counts[cell]), top,
      static_cast<double>(this->ClassifyCell(begin, end, cell, selfCrossing)) };
    cells->SetTuple(cell, values);
  }
  std::sort(selfCrossing.begin(), selfCrossing.end());
  selfCrossing.erase(std::unique(selfCrossing.begin(), selfCrossing.end()), selfCrossing.end());
  if (!selfCrossing.empty())
  {
    vtkWarningMacro(<< selfCrossing.size()
                    << " path(s) cross themselves, the first the input's line "
                    << internal.Paths[selfCrossing.front()].Cell
                    << ": each is drawn as the union of its parts, as where two paths cross.");
  }

  grid->Initialize();
  grid->SetDimensions(this->ResolutionUsed[0], this->ResolutionUsed[1], 1);
  grid->SetSpacing(1.0 / this->ResolutionUsed[0], 1.0 / this->ResolutionUsed[1], 1.0);
  grid->SetOrigin(0.5 / this->ResolutionUsed[0], 0.5 / this->ResolutionUsed[1], 0.0);
  grid->GetPointData()->SetScalars(cells);
  data->Initialize();
  data->SetDimensions(width, rows, 1);
  data->GetPointData()->SetScalars(texels);
  internal.TextureBytes =
    16 * (static_cast<vtkIdType>(cellCount) + static_cast<vtkIdType>(width) * rows);
}

void vtkPathFeatureTextureFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "GridResolution: " << this->GridResolution[0] << " " << this->GridResolution[1]
     << "\n";
  os << indent << "ResolutionUsed: " << this->ResolutionUsed[0] << " " << this->ResolutionUsed[1]
     << "\n";
  os << indent << "DefaultWidth: " << this->DefaultWidth << "\n";
  os << indent << "NumberOfMaterials: " << this->Internal->Materials.size() << "\n";
  os << indent << "BaseDepth: " << this->BaseDepth << "\n";
  os << indent << "MaximumDepth: " << this->MaximumDepth << "\n";
  os << indent << "NumberOfElements: " << this->NumberOfElements << "\n";
  os << indent << "MaximumCellCount: " << this->MaximumCellCount << "\n";
  os << indent << "TextureBytes: " << this->Internal->TextureBytes << "\n";
}
