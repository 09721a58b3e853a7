#include "ReliefPathScene.h"

#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkPlaneSource.h"
#include "vtkImageData.h"
#include "vtkIntArray.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkOpenGLPathFeatureMapper.h"
#include "vtkOpenGLQuadricPathFeatureMapper.h"
#include "vtkPathFeatureTextureFilter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkTexture.h"

#include <cmath>
#include <utility>
#include <vector>

namespace
{
using Point = std::pair<double, double>;

// Paths under construction: their points and per-path attributes.
class PathBuilder
{
public:
  PathBuilder()
  {
    this->Widths->SetName("Width");
    this->Profiles->SetName("Profile");
    this->Materials->SetName("Material");
    this->Priorities->SetName("Priority");
    this->Perturbations->SetName("Perturbation");
    this->Perturbations->SetNumberOfComponents(2);
    this->Controls->SetName("ControlPoint");
  }

  // a path through `points`, those flagged in `controls` quadratic control points
  void Add(const std::vector<Point>& points, double width, int profile, int material,
    int priority = 0, double scaleStart = 1.0, double scaleEnd = 1.0,
    const std::vector<bool>& controls = {})
  {
    this->Lines->InsertNextCell(static_cast<int>(points.size()));
    for (size_t k = 0; k < points.size(); ++k)
    {
      this->Lines->InsertCellPoint(
        this->Points->InsertNextPoint(points[k].first, points[k].second, 0.0));
      this->Controls->InsertNextValue(k < controls.size() && controls[k] ? 1 : 0);
    }
    this->Widths->InsertNextValue(width);
    this->Profiles->InsertNextValue(profile);
    this->Materials->InsertNextValue(material);
    this->Priorities->InsertNextValue(priority);
    this->Perturbations->InsertNextTuple2(scaleStart, scaleEnd);
  }

  vtkSmartPointer<vtkPolyData> Make()
  {
    auto paths = vtkSmartPointer<vtkPolyData>::New();
    paths->SetPoints(this->Points);
    paths->SetLines(this->Lines);
    paths->GetPointData()->AddArray(this->Controls);
    paths->GetCellData()->AddArray(this->Widths);
    paths->GetCellData()->AddArray(this->Profiles);
    paths->GetCellData()->AddArray(this->Materials);
    paths->GetCellData()->AddArray(this->Priorities);
    paths->GetCellData()->AddArray(this->Perturbations);
    return paths;
  }

private:
  vtkNew<vtkPoints> Points;
  vtkNew<vtkCellArray> Lines;
  vtkNew<vtkIntArray> Controls;
  vtkNew<vtkDoubleArray> Widths;
  vtkNew<vtkIntArray> Profiles;
  vtkNew<vtkIntArray> Materials;
  vtkNew<vtkIntArray> Priorities;
  vtkNew<vtkDoubleArray> Perturbations;
};

// An actor of `mapper` in a steel grey, with the given specular intensity.
vtkSmartPointer<vtkActor> SteelActor(vtkMapper* mapper, double specular)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.72, 0.74, 0.78);
  actor->GetProperty()->SetSpecular(specular);
  actor->GetProperty()->SetSpecularPower(30.0);
  actor->GetProperty()->SetAmbient(0.2);
  return actor;
}

void AddProfile(vtkPoints* points, vtkCellArray* lines, const std::vector<Point>& profile)
{
  lines->InsertNextCell(static_cast<int>(profile.size()));
  for (const Point& point : profile)
  {
    lines->InsertCellPoint(points->InsertNextPoint(point.first, point.second, 0.0));
  }
}
}

namespace ReliefPathScene
{
vtkSmartPointer<vtkPolyData> Profiles()
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  std::vector<Point> round;
  std::vector<Point> bead;
  for (int k = 0; k <= 12; ++k)
  {
    const double angle = M_PI * k / 12;
    round.emplace_back(-std::cos(angle), std::sin(angle));
    bead.emplace_back(-std::cos(angle), -0.5 * std::sin(angle));
  }
  AddProfile(points, lines, round);
  AddProfile(points, lines, { { -1.0, 0.0 }, { 0.0, 1.0 }, { 1.0, 0.0 } });
  AddProfile(points, lines,
    { { -1.0, 0.0 }, { -0.8, 0.2 }, { -0.55, 0.25 }, { 0.55, 0.25 }, { 0.8, 0.2 }, { 1.0, 0.0 } });
  AddProfile(points, lines, bead);
  AddProfile(points, lines, { { -0.5, 0.0 }, { -0.5, 0.15 }, { -1.0, 0.8 }, { 1.0, 0.8 },
                              { 0.5, 0.15 }, { 0.5, 0.0 } });
  auto profiles = vtkSmartPointer<vtkPolyData>::New();
  profiles->SetPoints(points);
  profiles->SetLines(lines);
  return profiles;
}

int AddMaterials(vtkPathFeatureTextureFilter* filter)
{
  const int mortar = filter->AddMaterial(0.62, 0.6, 0.56, 0.05, 5.0);
  filter->AddMaterial(0.25, 0.22, 0.2, 0.0, 1.0);  // the crack's dark inside
  filter->AddMaterial(0.75, 0.75, 0.78, 0.8, 40.0); // the bead's metal
  return mortar;
}

vtkSmartPointer<vtkPolyData> ShowcasePaths(int firstMaterial)
{
  const int mortar = firstMaterial;
  const int crack = firstMaterial + 1;
  const int metal = firstMaterial + 2;
  PathBuilder paths;
  // bricks on u in [0, 0.5]: bed joints every 1/8 of v, continuous (priority 1); head
  // joints between them, staggered, ending on the bed joints
  constexpr int Courses = 8;
  for (int row = 0; row <= Courses; ++row)
  {
    const double v = static_cast<double>(row) / Courses;
    paths.Add({ { 0.0, v }, { 0.5, v } }, 0.022, MORTAR, mortar, 1);
  }
  for (int row = 0; row < Courses; ++row)
  {
    const double low = static_cast<double>(row) / Courses;
    const double high = static_cast<double>(row + 1) / Courses;
    for (double u = row % 2 == 0 ? 0.125 : 0.0; u < 0.5; u += 0.25)
    {
      paths.Add({ { u, low }, { u, high } }, 0.018, MORTAR, mortar);
    }
  }
  // a crack across bricks and joints, narrowing to nothing, and a branch
  paths.Add({ { 0.06, 0.57 }, { 0.14, 0.55 }, { 0.2, 0.61 }, { 0.29, 0.59 }, { 0.36, 0.66 },
              { 0.44, 0.64 } },
    0.012, VEE, crack, 2, 1.0, 0.0);
  paths.Add({ { 0.2, 0.61 }, { 0.23, 0.7 }, { 0.21, 0.78 } }, 0.008, VEE, crack, 2, 1.0, 0.0);
  // on u in [0.5, 1]: a weld bead, a dovetail slot it crosses, an engraved ring
  paths.Add({ { 0.62, 0.06 }, { 0.64, 0.5 }, { 0.62, 0.94 } }, 0.05, BEAD, metal);
  paths.Add({ { 0.55, 0.25 }, { 0.97, 0.25 } }, 0.06, DOVETAIL, -1);
  const double cx = 0.8;
  const double cy = 0.68;
  const double r = 0.13;
  // four quadratic arcs: on-curve points at the axes, control points at the corners
  // (a circle within 1%, as TrueType draws them)
  std::vector<Point> ring;
  std::vector<bool> controls;
  for (int k = 0; k <= 8; ++k)
  {
    const double angle = M_PI / 4 * k;
    const double radius = k % 2 == 0 ? r : r * std::sqrt(2.0);
    ring.emplace_back(cx + radius * std::cos(angle), cy + radius * std::sin(angle));
    controls.push_back(k % 2 == 1);
  }
  paths.Add(ring, 0.02, ROUND, -1, 0, 1.0, 1.0, controls);
  return paths.Make();
}

vtkSmartPointer<vtkOpenGLPathFeatureMapper> ShowcaseMapper(vtkPolyData* surface, double depthScale)
{
  auto mapper = vtkSmartPointer<vtkOpenGLPathFeatureMapper>::New();
  mapper->SetInputData(surface);
  const int first = AddMaterials(mapper->GetPathFeatureTextureFilter());
  mapper->SetPathsData(ShowcasePaths(first));
  mapper->SetProfilesData(Profiles());
  mapper->SetDepthScale(depthScale);
  return mapper;
}

vtkSmartPointer<vtkOpenGLPathFeatureMapper> ShowPathFeatures(
  vtkRenderWindow* window, int width, int height, double angle)
{
  auto renderer = ReliefScene::LitRenderer(window, width, height);
  auto mapper = ShowcaseMapper(ReliefScene::Square(1.0), 0.02);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.66, 0.33, 0.24);
  actor->GetProperty()->SetSpecular(0.1);
  actor->GetProperty()->SetSpecularPower(10.0);
  actor->GetProperty()->SetAmbient(0.2); // what shadows hold stays readable
  renderer->AddActor(actor);
  ReliefScene::ViewSquare(renderer, angle);
  return mapper;
}

vtkSmartPointer<vtkOpenGLPathFeatureMapper> ShowPathFeaturesCloseUp(
  vtkRenderWindow* window, int width, int height)
{
  auto mapper = ShowPathFeatures(window, width, height, 0.0);
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  vtkCamera* camera = renderer->GetActiveCamera();
  // low across the slot, whose lips hide its undercut, toward the bead and the ring
  camera->SetFocalPoint(0.2, -0.2, 0.0);
  camera->SetPosition(0.28, -0.62, 0.1);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(40.0);
  renderer->ResetCameraClippingRange();
  return mapper;
}

vtkSmartPointer<vtkOpenGLPathFeatureMapper> ShowPathFeaturesOnRelief(
  vtkRenderWindow* window, int width, int height, double angle)
{
  auto renderer = ReliefScene::LitRenderer(window, width, height);
  auto mapper = vtkSmartPointer<vtkOpenGLPathFeatureMapper>::New();
  mapper->SetInputData(ReliefScene::Square(1.0));
  mapper->SetHeightMapData(ReliefScene::ReadImage("bricks_height.png"));
  mapper->SetProfilesData(Profiles());
  vtkPathFeatureTextureFilter* filter = mapper->GetPathFeatureTextureFilter();
  const int mortar = AddMaterials(filter);
  const int crack = mortar + 1;
  const int steel = mortar + 2;
  PathBuilder paths;
  // a saw cut 1 deep: through the bricks' faces, hardly into the mortar, 0.95 deep
  paths.Add({ { 0.03, 0.12 }, { 0.97, 0.58 } }, 0.018, VEE, -1);
  paths.Add({ { 0.08, 0.9 }, { 0.3, 0.74 }, { 0.42, 0.77 }, { 0.61, 0.6 } }, 0.014, VEE, crack,
    1, 1.0, 0.0);
  // a steel rod across the wall, standing on the base plane above the mortar
  paths.Add({ { 0.02, 0.33 }, { 0.98, 0.33 } }, 0.02, BEAD, steel);
  mapper->SetPathsData(paths.Make());
  mapper->SetDepthScale(0.03);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(ReliefScene::ReadTexture("bricks_color.png"));
  actor->GetProperty()->SetSpecular(0.1);
  actor->GetProperty()->SetSpecularPower(10.0);
  actor->GetProperty()->SetAmbient(0.2);
  renderer->AddActor(actor);
  ReliefScene::ViewSquare(renderer, angle);
  return mapper;
}

vtkSmartPointer<vtkPolyData> LabelCylinder()
{
  constexpr double Radius = 0.4;
  constexpr double Height = 1.0;
  const double circumference = 2.0 * M_PI * Radius;
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(48, 8);
  plane->Update();
  auto cylinder = vtkSmartPointer<vtkPolyData>::New();
  cylinder->DeepCopy(plane->GetOutput());
  ReliefScene::TileTextureCoordinates(cylinder, 1.0, Height / circumference);
  vtkPoints* points = cylinder->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    const double* flat = points->GetPoint(p); // in [-0.5, 0.5]^2
    const double angle = 2.0 * M_PI * (flat[0] + 0.5);
    points->SetPoint(p, Radius * std::cos(angle), Radius * std::sin(angle), Height * flat[1]);
  }
  cylinder->GetPointData()->SetNormals(nullptr);
  return cylinder;
}

vtkSmartPointer<vtkPolyData> LabelPaths()
{
  PathBuilder paths;
  // letters 0.08 high (0.2 in the world), strokes 0.008 wide, around (0.5, 0.2)
  const double x0 = 0.44;
  const double y0 = 0.16;
  const double h = 0.08;
  auto at = [&](double x, double y) { return Point(x0 + x * h, y0 + y * h); };
  constexpr double Stroke = 0.008;
  paths.Add({ at(0.0, 1.0), at(0.3, 0.0), at(0.6, 1.0) }, Stroke, VEE, -1);      // V
  paths.Add({ at(0.75, 1.0), at(1.35, 1.0) }, Stroke, VEE, -1);                  // T
  paths.Add({ at(1.05, 1.0), at(1.05, 0.0) }, Stroke, VEE, -1);
  paths.Add({ at(1.5, 1.0), at(1.5, 0.0) }, Stroke, VEE, -1);                    // K
  paths.Add({ at(2.05, 1.0), at(1.5, 0.4), at(2.05, 0.0) }, Stroke, VEE, -1);
  // the frame: straight sides, quadratic corners (control points at the box's corners)
  const double left = x0 - 0.02;
  const double right = x0 + 2.05 * h + 0.02;
  const double bottom = y0 - 0.02;
  const double top = y0 + h + 0.02;
  const double r = 0.015;
  paths.Add({ { left + r, bottom }, { right - r, bottom }, { right, bottom },
              { right, bottom + r }, { right, top - r }, { right, top }, { right - r, top },
              { left + r, top }, { left, top }, { left, top - r }, { left, bottom + r },
              { left, bottom }, { left + r, bottom } },
    0.006, ROUND, -1, 0, 1.0, 1.0,
    { false, false, true, false, false, true, false, false, true, false, false, true, false });
  return paths.Make();
}

vtkSmartPointer<vtkOpenGLQuadricPathFeatureMapper> ShowEngravedCylinder(
  vtkRenderWindow* window, int width, int height)
{
  auto renderer = ReliefScene::LitRenderer(window, width, height);
  auto mapper = vtkSmartPointer<vtkOpenGLQuadricPathFeatureMapper>::New();
  mapper->SetInputData(LabelCylinder());
  mapper->SetPathsData(LabelPaths());
  mapper->SetProfilesData(Profiles());
  mapper->SetDepthScale(0.012);
  renderer->AddActor(SteelActor(mapper, 0.5));
  vtkCamera* camera = renderer->GetActiveCamera();
  // u = 0.5 faces -x
  camera->SetFocalPoint(-0.4, 0.0, -0.0);
  camera->SetPosition(-1.6, -0.5, 0.35);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(26.0);
  renderer->ResetCameraClippingRange();
  return mapper;
}

vtkSmartPointer<vtkPolyData> CylinderGrooves()
{
  PathBuilder paths;
  for (int k = 1; k <= 3; ++k)
  {
    paths.Add({ { 0.0, 0.1 * k }, { 1.0, 0.1 * k } }, 0.012, ROUND, -1);
  }
  for (int k = 0; k < 12; ++k)
  {
    const double u = (k + 0.5) / 12.0;
    paths.Add({ { u, 0.03 }, { u, 0.37 } }, 0.02, ROUND, -1);
  }
  return paths.Make();
}

void ShowCurvedPathFeatures(vtkRenderWindow* window, int width, int height, double depthScale)
{
  vtkSmartPointer<vtkPolyData> cylinder = LabelCylinder();
  for (bool quadric : { false, true })
  {
    auto renderer = ReliefScene::LitRenderer(window, width, height);
    renderer->SetViewport(quadric ? 0.5 : 0.0, 0.0, quadric ? 1.0 : 0.5, 1.0);
    vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
    light->SetPosition(-1.0, -2.0, 1.0); // from the camera's left: both outlines lit
    vtkSmartPointer<vtkOpenGLReliefMapper> mapper;
    if (quadric)
    {
      auto curved = vtkSmartPointer<vtkOpenGLQuadricPathFeatureMapper>::New();
      curved->SetPathsData(CylinderGrooves());
      curved->SetProfilesData(Profiles());
      mapper = curved;
    }
    else
    {
      auto flat = vtkSmartPointer<vtkOpenGLPathFeatureMapper>::New();
      flat->SetPathsData(CylinderGrooves());
      flat->SetProfilesData(Profiles());
      mapper = flat;
    }
    mapper->SetInputData(cylinder);
    mapper->SetDepthScale(depthScale);
    renderer->AddActor(SteelActor(mapper, 0.3));
    // u = k / 12 lies at 30 k degrees around the axis: the camera along 195 degrees sees
    // the grooves along it at 105 and 285 degrees on the outlines
    vtkCamera* camera = renderer->GetActiveCamera();
    const double toward = 195.0 * M_PI / 180.0;
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(8.0 * std::cos(toward), 8.0 * std::sin(toward), 0.8);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(9.0);
    renderer->ResetCameraClippingRange();
  }
}
}
