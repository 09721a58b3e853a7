#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkAppendPolyData.h"
#include "vtkCamera.h"
#include "vtkCubeSource.h"
#include "vtkElevationFilter.h"
#include "vtkCameraPass.h"
#include "vtkFloatArray.h"
#include "vtkGenericDataObjectReader.h"
#include "vtkGeometryFilter.h"
#include "vtkImageData.h"
#include "vtkImageResize.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkOBJReader.h"
#include "vtkOpenGLDerivativeReliefMapper.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkOpenGLReliefImpostorMapper.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkReliefSearchMethod.h"
#include "vtkOpenImageIOReader.h"
#include "vtkPlaneSource.h"
#include "vtkPLYReader.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkReliefDisplacementFilter.h"
#include "vtkRenderer.h"
#include "vtkRendererCollection.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderWindow.h"
#include "vtkSequencePass.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkSphereSource.h"
#include "vtkSTLReader.h"
#include "vtkSuperquadricSource.h"
#include "vtkTexture.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTriangleFilter.h"
#include "vtkTexturedSphereSource.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <random>

namespace ReliefScene
{
namespace
{
std::string& DataDirectory()
{
  static std::string directory = RELIEF_DATA_DIR;
  return directory;
}
}

void SetDataDirectory(const std::string& directory)
{
  DataDirectory() = directory;
}

std::string DataFile(const std::string& name)
{
  return !name.empty() && name[0] == '/' ? name : DataDirectory() + "/" + name;
}

vtkSmartPointer<vtkImageData> ReadImage(const std::string& name)
{
  vtkNew<vtkOpenImageIOReader> reader;
  reader->SetFileName(DataFile(name).c_str());
  reader->Update();
  return reader->GetOutput();
}

// Reads a surface with the VTK reader its extension calls for. A legacy .vtk file of
// another dataset type (unstructured grid, ...) is reduced to its outer surface.
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& fileName, std::string& error)
{
  const std::string extension =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(fileName));
  vtkSmartPointer<vtkAlgorithm> reader;
  if (extension == ".vtp")
  {
    auto xmlReader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xmlReader->SetFileName(fileName.c_str());
    reader = xmlReader;
  }
  else if (extension == ".vtk")
  {
    auto legacyReader = vtkSmartPointer<vtkGenericDataObjectReader>::New();
    legacyReader->SetFileName(fileName.c_str());
    legacyReader->Update();
    vtkDataObject* data = legacyReader->GetOutput();
    if (vtkDataSet::SafeDownCast(data) && !vtkPolyData::SafeDownCast(data))
    {
      auto surface = vtkSmartPointer<vtkGeometryFilter>::New();
      surface->SetInputConnection(legacyReader->GetOutputPort());
      reader = surface;
    }
    else
    {
      reader = legacyReader;
    }
  }
  else if (extension == ".ply")
  {
    auto plyReader = vtkSmartPointer<vtkPLYReader>::New();
    plyReader->SetFileName(fileName.c_str());
    reader = plyReader;
  }
  else if (extension == ".obj")
  {
    auto objReader = vtkSmartPointer<vtkOBJReader>::New();
    objReader->SetFileName(fileName.c_str());
    reader = objReader;
  }
  else if (extension == ".stl")
  {
    auto stlReader = vtkSmartPointer<vtkSTLReader>::New();
    stlReader->SetFileName(fileName.c_str());
    reader = stlReader;
  }
  else
  {
    error = "mesh '" + fileName + "': unknown extension '" + extension +
      "'; use .vtp, .vtk, .ply, .obj or .stl";
    return nullptr;
  }
  reader->Update();
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!mesh || mesh->GetNumberOfPoints() == 0)
  {
    error = "could not read a mesh from '" + fileName + "'";
    return nullptr;
  }
  if (mesh->GetNumberOfPolys() + mesh->GetNumberOfStrips() == 0)
  {
    error = "mesh '" + fileName + "' has no polygons to carry relief";
    return nullptr;
  }
  return mesh;
}

vtkSmartPointer<vtkTexture> ReadTexture(const std::string& name)
{
  auto texture = vtkSmartPointer<vtkTexture>::New();
  texture->SetInputData(ReadImage(name));
  texture->InterpolateOn();
  texture->MipmapOn();
  texture->RepeatOn();
  return texture;
}

void TileTextureCoordinates(vtkPolyData* surface, double uTiles, double vTiles)
{
  vtkDataArray* tcoords = surface->GetPointData()->GetTCoords();
  for (vtkIdType i = 0; i < tcoords->GetNumberOfTuples(); ++i)
  {
    tcoords->SetTuple2(
      i, tcoords->GetComponent(i, 0) * uTiles, tcoords->GetComponent(i, 1) * vTiles);
  }
  tcoords->Modified();
}

vtkSmartPointer<vtkPolyData> Square(double tiles)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-0.5, -0.5, 0.0);
  plane->SetPoint1(0.5, -0.5, 0.0);
  plane->SetPoint2(-0.5, 0.5, 0.0);
  plane->Update();
  auto square = vtkSmartPointer<vtkPolyData>::New();
  square->DeepCopy(plane->GetOutput());
  TileTextureCoordinates(square, tiles, tiles);
  return square;
}

vtkSmartPointer<vtkPolyData> Torus(int resolution)
{
  vtkNew<vtkSuperquadricSource> source;
  source->ToroidalOn();
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(resolution / 2);
  source->SetThickness(0.4);
  source->SetSize(0.5);
  source->Update();
  auto torus = vtkSmartPointer<vtkPolyData>::New();
  torus->DeepCopy(source->GetOutput());
  TileTextureCoordinates(torus, 6.0, 2.0);
  return torus;
}

vtkSmartPointer<vtkPolyData> Sphere(int resolution)
{
  vtkNew<vtkTexturedSphereSource> source;
  source->SetRadius(0.5);
  source->SetThetaResolution(resolution);
  source->SetPhiResolution(resolution / 2);
  source->Update();
  auto sphere = vtkSmartPointer<vtkPolyData>::New();
  sphere->DeepCopy(source->GetOutput());
  TileTextureCoordinates(sphere, 4.0, 2.0);
  return sphere;
}

vtkSmartPointer<vtkPolyData> ImpostorObject(int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(0.5);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution / 2);
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(0.3, 0.3, 0.3);
  cube->SetXLength(0.6);
  cube->SetYLength(0.6);
  cube->SetZLength(0.6);
  vtkNew<vtkSuperquadricSource> ring;
  ring->ToroidalOn();
  ring->SetThetaResolution(resolution);
  ring->SetPhiResolution(resolution / 2);
  ring->SetThickness(0.25);
  ring->SetSize(0.75);
  ring->SetScale(1.0, 1.0, 1.0);
  vtkNew<vtkTransform> tilt;
  tilt->RotateX(90.0 - 25.0); // the source's ring lies in y = 0
  vtkNew<vtkTransformPolyDataFilter> tilted;
  tilted->SetInputConnection(ring->GetOutputPort());
  tilted->SetTransform(tilt);
  vtkNew<vtkAppendPolyData> parts;
  parts->AddInputConnection(sphere->GetOutputPort());
  parts->AddInputConnection(cube->GetOutputPort());
  parts->AddInputConnection(tilted->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(parts->GetOutputPort());
  vtkNew<vtkElevationFilter> elevation;
  elevation->SetInputConnection(triangles->GetOutputPort());
  elevation->SetLowPoint(0.0, 0.0, -0.6);
  elevation->SetHighPoint(0.0, 0.0, 0.6);
  elevation->Update();
  auto object = vtkSmartPointer<vtkPolyData>::New();
  object->DeepCopy(elevation->GetOutput());
  return object;
}

vtkSmartPointer<vtkActor> MeshActor(vtkPolyData* mesh)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

vtkSmartPointer<vtkActor> ImpostorActor(vtkPolyData* mesh)
{
  vtkNew<vtkOpenGLReliefImpostorMapper> mapper;
  mapper->SetInputData(mesh);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

double AddField(vtkRenderer* renderer, vtkMapper* mapper, int count, double spacing)
{
  const int side = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count))));
  const double half = 0.5 * (side - 1) * spacing;
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < count; ++k)
  {
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->SetPosition((k % side) * spacing - half, (k / side) * spacing - half, 0.0);
    actor->RotateZ(360.0 * unit(generator));
    actor->GetProperty()->SetColor(0.6 + 0.4 * unit(generator), 0.6 + 0.4 * unit(generator),
      0.6 + 0.4 * unit(generator));
    renderer->AddActor(actor);
  }
  return half + 0.5 * spacing;
}

void ViewField(vtkRenderer* renderer, double half, double distance)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, distance * half, 0.0); // LitRenderer's light over its shoulder
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->Elevation(40.0);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(30.0);
  renderer->ResetCameraClippingRange();
}

void ShowImpostorBesideMesh(vtkRenderWindow* window, int width, int height)
{
  vtkSmartPointer<vtkPolyData> object = ImpostorObject(96);
  auto left = LitRenderer(window, width, height);
  left->SetViewport(0.0, 0.0, 0.5, 1.0);
  left->AddActor(MeshActor(object));
  vtkNew<vtkRenderer> right;
  right->SetViewport(0.5, 0.0, 1.0, 1.0);
  right->SetBackground(left->GetBackground());
  right->AutomaticLightCreationOff();
  right->SetLightCollection(left->GetLights());
  right->SetActiveCamera(left->GetActiveCamera());
  right->AddActor(ImpostorActor(object));
  window->AddRenderer(right);
  vtkCamera* camera = left->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 4.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->Elevation(35.0);
  camera->Azimuth(30.0);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(30.0);
  left->ResetCameraClippingRange(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
}

void ShowImpostorShadows(vtkRenderWindow* window, int width, int height)
{
  vtkSmartPointer<vtkPolyData> object = ImpostorObject(96);
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  vtkCamera* camera = nullptr;
  for (int half = 0; half < 2; ++half)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(0.1, 0.12, 0.16);
    renderer->SetViewport(0.5 * half, 0.0, 0.5 * half + 0.5, 1.0);
    AddSpotlight(renderer);
    vtkNew<vtkPlaneSource> floor;
    floor->SetOrigin(-1.6, -1.6, -0.9);
    floor->SetPoint1(1.6, -1.6, -0.9);
    floor->SetPoint2(-1.6, 1.6, -0.9);
    vtkNew<vtkPolyDataMapper> floorMapper;
    floorMapper->SetInputConnection(floor->GetOutputPort());
    vtkNew<vtkActor> floorActor;
    floorActor->SetMapper(floorMapper);
    renderer->AddActor(floorActor);
    renderer->AddActor(half == 0 ? MeshActor(object) : ImpostorActor(object));
    UseShadowMaps(renderer);
    if (camera)
    {
      renderer->SetActiveCamera(camera);
    }
    else
    {
      camera = renderer->GetActiveCamera();
      camera->SetPosition(0.0, -3.5, 2.5);
      camera->SetFocalPoint(0.0, 0.0, -0.4);
      camera->SetViewUp(0.0, 0.0, 1.0);
      renderer->ResetCamera();
      camera->Zoom(1.3);
    }
    window->AddRenderer(renderer);
  }
}

void ShowImpostorField(vtkRenderWindow* window, int width, int height, int count)
{
  auto renderer = LitRenderer(window, width, height);
  vtkNew<vtkOpenGLReliefImpostorMapper> mapper;
  mapper->SetInputData(ImpostorObject(96));
  const double half = AddField(renderer, mapper, count, 2.5);
  ViewField(renderer, half, 1.9);
}

vtkSmartPointer<vtkPolyData> Cylinder(int resolution, double sweep)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(std::max(1, static_cast<int>(std::lround(resolution * sweep / 360.0))),
    resolution);
  plane->Update();
  auto cylinder = vtkSmartPointer<vtkPolyData>::New();
  cylinder->DeepCopy(plane->GetOutput());
  TileTextureCoordinates(cylinder, 4.0 * sweep / 360.0, 5.0);
  vtkPoints* points = cylinder->GetPoints();
  for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
  {
    const double* flat = points->GetPoint(p); // in [-0.5, 0.5]^2
    const double angle = vtkMath::RadiansFromDegrees(sweep) * (flat[0] + 0.5);
    points->SetPoint(p, 0.4 * std::cos(angle), 0.4 * std::sin(angle), 3.0 * flat[1]);
  }
  cylinder->GetPointData()->SetNormals(nullptr); // the plane's: recomputed where needed
  return cylinder;
}

vtkSmartPointer<vtkOpenGLReliefMapper> ReliefMapper(
  vtkPolyData* surface, const std::string& heightMap, double depthScale)
{
  auto mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
  mapper->SetInputData(surface);
  mapper->SetHeightMapData(ReadImage(heightMap));
  mapper->SetDepthScale(depthScale);
  return mapper;
}

void SetStones(vtkOpenGLReliefMapper* mapper, vtkPolyData* surface, double depthScale)
{
  mapper->SetInputData(surface);
  mapper->SetHeightMapData(ReadImage("stones_height.png"));
  mapper->SetDepthScale(depthScale);
  mapper->SetSearchMethodToLinearBinary();
  mapper->SetLinearSteps(32);
  mapper->SetBinarySteps(6);
}

vtkSmartPointer<vtkPolyData> DisplacedMesh(
  vtkPolyData* surface, vtkImageData* relief, double depthScale, double edgeTexels)
{
  vtkNew<vtkReliefDisplacementFilter> displacement;
  displacement->SetInputData(surface);
  displacement->SetReliefData(relief);
  displacement->SetDepthScale(depthScale);
  displacement->SetMaximumEdgeTexels(edgeTexels);
  displacement->SetMaximumNumberOfTriangles(vtkIdType(1) << 24);
  displacement->Update();
  return displacement->GetOutput();
}

vtkSmartPointer<vtkActor> ReliefActor(vtkMapper* mapper, const std::string& colorTexture)
{
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  if (!colorTexture.empty())
  {
    actor->SetTexture(ReadTexture(colorTexture));
  }
  actor->GetProperty()->SetAmbient(0.15);
  actor->GetProperty()->SetDiffuse(0.85);
  actor->GetProperty()->SetSpecular(0.2);
  actor->GetProperty()->SetSpecularPower(30.0);
  return actor;
}

vtkSmartPointer<vtkRenderer> LitRenderer(vtkRenderWindow* window, int width, int height)
{
  auto renderer = vtkSmartPointer<vtkRenderer>::New();
  renderer->SetBackground(0.1, 0.12, 0.16);
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(-1.0, 1.0, 1.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->PositionalOff();
  renderer->AddLight(light);
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  window->AddRenderer(renderer);
  return renderer;
}

void ViewSquare(vtkRenderer* renderer, double angle)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 0.0, 1.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->Elevation(-angle);
  camera->OrthogonalizeViewUp();
  camera->SetViewAngle(45.0);
  renderer->ResetCamera();
  camera->Dolly(1.3);
  renderer->ResetCameraClippingRange();
}
}

namespace ReliefScene
{
std::vector<unsigned char> Pixels(vtkRenderWindow* window)
{
  vtkNew<vtkWindowToImageFilter> capture;
  capture->SetInput(window);
  capture->SetInputBufferTypeToRGB();
  capture->ReadFrontBufferOff();
  capture->Update();
  vtkDataArray* scalars = capture->GetOutput()->GetPointData()->GetScalars();
  const auto* first = static_cast<unsigned char*>(scalars->GetVoidPointer(0));
  return std::vector<unsigned char>(first, first + scalars->GetDataSize());
}
}

namespace
{
// One half of the window: a floor, a spotlight from above, the sphere drawn by `mapper`,
// rendered through the shadow-map passes.
void ShowShadowHalf(vtkRenderWindow* window, vtkOpenGLReliefMapper* mapper, vtkPolyData* sphere,
  double left)
{
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.1, 0.12, 0.16);
  renderer->SetViewport(left, 0.0, left + 0.5, 1.0);
  ReliefScene::AddSpotlight(renderer);

  vtkNew<vtkPlaneSource> floor;
  floor->SetOrigin(-1.5, -1.5, -0.6);
  floor->SetPoint1(1.5, -1.5, -0.6);
  floor->SetPoint2(-1.5, 1.5, -0.6);
  vtkNew<vtkPolyDataMapper> floorMapper;
  floorMapper->SetInputConnection(floor->GetOutputPort());
  vtkNew<vtkActor> floorActor;
  floorActor->SetMapper(floorMapper);
  renderer->AddActor(floorActor);

  ReliefScene::SetStones(mapper, sphere, 0.1);
  vtkNew<vtkActor> sphereActor;
  sphereActor->SetMapper(mapper);
  renderer->AddActor(sphereActor);

  ReliefScene::UseShadowMaps(renderer);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -3.0, 2.5);
  camera->SetFocalPoint(0.0, 0.0, -0.3);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  camera->Zoom(1.3);
  window->AddRenderer(renderer);
}

}

namespace ReliefScene
{
vtkSmartPointer<vtkOpenGLReliefMapper> ShowBricks(vtkRenderWindow* window, int width, int height,
  double angle, double tiles, double depthScale)
{
  auto renderer = LitRenderer(window, width, height);
  auto mapper = ReliefMapper(Square(tiles), "bricks_height.png", depthScale);
  renderer->AddActor(ReliefActor(mapper, "bricks_color.png"));
  ViewSquare(renderer, angle);
  return mapper;
}

int SearchMethodNamed(const std::string& name)
{
  const vtkReliefSearchMethod* method = vtkReliefSearchMethod::Find(name);
  return method ? method->Id : -1;
}

vtkSmartPointer<vtkImageData> HeightImage(
  int width, int height, const std::function<float(int, int)>& heightAt)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_FLOAT, 1);
  auto* heights = static_cast<float*>(image->GetScalarPointer());
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      heights[j * width + i] = heightAt(i, j);
    }
  }
  return image;
}

vtkSmartPointer<vtkImageData> ThinFeatures()
{
  return HeightImage(64, 64, [](int i, int j) {
    const bool wall = i % 16 == 8 || (j == 40 && i >= 16 && i < 48);
    const bool spike = i % 16 == 0 && j % 8 == 4;
    return wall || spike ? 1.0f : 0.2f;
  });
}

vtkSmartPointer<vtkOpenGLReliefMapper> ShowThinFeatures(
  vtkRenderWindow* window, int width, int height, double angle, int method)
{
  auto renderer = LitRenderer(window, width, height);
  auto mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
  mapper->SetInputData(Square(1.0));
  mapper->SetHeightMapData(ThinFeatures());
  mapper->SetDepthScale(0.05);
  mapper->SetSearchMethod(method);
  renderer->AddActor(ReliefActor(mapper, ""));
  ViewSquare(renderer, angle);
  // a grazing view shrinks the square: come closer
  renderer->GetActiveCamera()->Dolly(1.0 + angle / 80.0);
  renderer->ResetCameraClippingRange();
  return mapper;
}

const std::vector<int>& SearchMethods()
{
  static const std::vector<int> methods = [] {
    std::vector<int> ids;
    for (int id = 0; id < vtkReliefSearchMethod::GetNumberOfMethods(); ++id)
    {
      ids.push_back(id);
    }
    return ids;
  }();
  return methods;
}

void ShowSearchMethods(vtkRenderWindow* window, int width, int height)
{
  const std::vector<int>& methods = SearchMethods();
  const double columns = static_cast<double>(methods.size());
  for (int row = 0; row < 2; ++row)
  {
    for (size_t column = 0; column < methods.size(); ++column)
    {
      ShowThinFeatures(window, width, height, row == 0 ? 80.0 : 45.0, methods[column]);
      vtkRendererCollection* renderers = window->GetRenderers();
      vtkRenderer::SafeDownCast(renderers->GetItemAsObject(renderers->GetNumberOfItems() - 1))
        ->SetViewport(column / columns, row / 2.0, (column + 1) / columns, (row + 1) / 2.0);
    }
  }
}

vtkSmartPointer<vtkOpenGLReliefMapper> ShowTorus(vtkRenderWindow* window, int width, int height)
{
  auto renderer = LitRenderer(window, width, height);
  auto mapper = ReliefMapper(Torus(48), "stones_height.png", 0.03);
  renderer->AddActor(ReliefActor(mapper, "stones_color.png"));
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, -1.0, 0.8);
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  camera->Dolly(1.4);
  renderer->ResetCameraClippingRange();
  return mapper;
}

void ShowSelfShadowing(vtkRenderWindow* window, int width, int height)
{
  for (bool shadows : { true, false })
  {
    auto renderer = LitRenderer(window, width, height);
    renderer->SetViewport(shadows ? 0.0 : 0.5, 0.0, shadows ? 0.5 : 1.0, 1.0);
    vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
    light->SetPosition(-1.0, 0.4, 0.35); // low, so shadows are long
    auto mapper = ReliefMapper(Square(1.0), "rivets_height.png", 0.08);
    mapper->SetSelfShadowing(shadows);
    mapper->SetLinearSteps(32);
    renderer->AddActor(ReliefActor(mapper, ""));
    ViewSquare(renderer, 20.0);
  }
}

void ShowInterpenetration(vtkRenderWindow* window, int width, int height)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(0.0, 0.0, -0.12);
  sphere->SetRadius(0.15);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(48);
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  for (bool correction : { true, false })
  {
    auto renderer = LitRenderer(window, width, height);
    renderer->SetViewport(correction ? 0.0 : 0.5, 0.0, correction ? 0.5 : 1.0, 1.0);
    auto mapper = ReliefMapper(Square(1.0), "bricks_height.png", 0.15);
    mapper->SetDepthCorrection(correction);
    mapper->SetLinearSteps(24);
    renderer->AddActor(ReliefActor(mapper, "bricks_color.png"));
    vtkNew<vtkActor> ball;
    ball->SetMapper(sphereMapper);
    ball->GetProperty()->SetColor(0.3, 0.6, 0.95);
    renderer->AddActor(ball);
    ViewSquare(renderer, 50.0);
  }
}

void ShowPlainBesideRelief(vtkRenderWindow* window, int width, int height)
{
  auto square = Square(2.0);
  for (bool relief : { false, true })
  {
    auto renderer = LitRenderer(window, width, height);
    renderer->SetViewport(relief ? 0.5 : 0.0, 0.0, relief ? 1.0 : 0.5, 1.0);
    vtkSmartPointer<vtkMapper> mapper;
    if (relief)
    {
      mapper = ReliefMapper(square, "bricks_height.png", 0.04);
    }
    else
    {
      auto plain = vtkSmartPointer<vtkPolyDataMapper>::New();
      plain->SetInputData(square);
      mapper = plain;
    }
    renderer->AddActor(ReliefActor(mapper, "bricks_color.png"));
    ViewSquare(renderer, 50.0);
  }
}

void ShowQuadricSilhouettes(vtkRenderWindow* window, int width, int height)
{
  auto torus = Torus(48);
  for (bool quadric : { false, true })
  {
    auto renderer = LitRenderer(window, width, height);
    renderer->SetViewport(quadric ? 0.5 : 0.0, 0.0, quadric ? 1.0 : 0.5, 1.0);
    vtkLight* light = vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0));
    light->SetPosition(-1.0, -1.0, 1.0);
    vtkSmartPointer<vtkOpenGLReliefMapper> mapper;
    if (quadric)
    {
      mapper = vtkSmartPointer<vtkOpenGLQuadricReliefMapper>::New();
    }
    else
    {
      mapper = vtkSmartPointer<vtkOpenGLReliefMapper>::New();
    }
    SetStones(mapper, torus, 0.05);
    renderer->AddActor(ReliefActor(mapper, "stones_color.png"));
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetFocalPoint(0.3, 0.0, 0.25);
    camera->SetPosition(0.3, -2.0, 0.6);
    camera->SetViewUp(0.0, 0.0, 1.0);
    camera->SetViewAngle(20.0);
    renderer->ResetCameraClippingRange();
  }
}

vtkSmartPointer<vtkOpenGLReliefMapper> ShowDerivativeMesh(vtkRenderWindow* window, int width,
  int height, const std::string& mesh, bool normals, double left, double right)
{
  std::string error;
  vtkSmartPointer<vtkPolyData> surface = ReadMesh(DataFile(mesh), error);
  if (!surface)
  {
    vtkGenericWarningMacro(<< error);
    return nullptr;
  }
  if (!normals)
  {
    auto stripped = vtkSmartPointer<vtkPolyData>::New();
    stripped->ShallowCopy(surface);
    stripped->GetPointData()->SetNormals(nullptr);
    surface = stripped;
  }
  auto renderer = LitRenderer(window, width, height);
  renderer->SetViewport(left, 0.0, right, 1.0);
  vtkLight::SafeDownCast(renderer->GetLights()->GetItemAsObject(0))->SetPosition(-1.0, -1.0, 1.0);
  auto mapper = vtkSmartPointer<vtkOpenGLDerivativeReliefMapper>::New();
  SetStones(mapper, surface, 0.02);
  renderer->AddActor(ReliefActor(mapper, "stones_color.png"));
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, -1.0, 0.6);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();
  camera->Dolly(1.3);
  renderer->ResetCameraClippingRange();
  return mapper;
}

void ShowDerivativeFrames(vtkRenderWindow* window, int width, int height)
{
  ShowDerivativeMesh(window, width, height, "torus.obj", true, 0.0, 1.0 / 3.0);
  ShowDerivativeMesh(window, width, height, "torus.obj", false, 1.0 / 3.0, 2.0 / 3.0);
  ShowDerivativeMesh(window, width, height, "icosahedron.ply", false, 2.0 / 3.0, 1.0);
}

void AddSpotlight(vtkRenderer* renderer)
{
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetPosition(0.0, -0.3, 3.0);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->PositionalOn();
  light->SetConeAngle(40.0);
  renderer->AddLight(light);
}

void UseShadowMaps(vtkRenderer* renderer)
{
  vtkNew<vtkShadowMapPass> shadows;
  vtkNew<vtkRenderPassCollection> passes;
  passes->AddItem(shadows->GetShadowMapBakerPass());
  passes->AddItem(shadows);
  vtkNew<vtkSequencePass> sequence;
  sequence->SetPasses(passes);
  vtkNew<vtkCameraPass> cameraPass;
  cameraPass->SetDelegatePass(sequence);
  renderer->SetPass(cameraPass);
}

void ShowQuadricShadows(vtkRenderWindow* window, int width, int height)
{
  window->SetSize(width, height);
  window->SetMultiSamples(0);
  auto sphere = Sphere(48);
  ShowShadowHalf(window, vtkSmartPointer<vtkOpenGLReliefMapper>::New(), sphere, 0.0);
  ShowShadowHalf(window, vtkSmartPointer<vtkOpenGLQuadricReliefMapper>::New(), sphere, 0.5);
}

vtkSmartPointer<vtkImageData> ResizedImage(vtkImageData* image, int size)
{
  vtkNew<vtkImageResize> resize;
  resize->SetInputData(image);
  resize->SetOutputDimensions(size, size, 1);
  resize->Update();
  return resize->GetOutput();
}

vtkSmartPointer<vtkImageData> ResizedHeightMap(const std::string& name, int size)
{
  return ResizedImage(ReadImage(name), size);
}

Lineup::Lineup(vtkRenderWindow* window, vtkRenderer* renderer,
  const std::vector<vtkSmartPointer<vtkActor>>& actors)
  : Window(window)
  , Renderer(renderer)
  , Actors(actors)
{
  renderer->RemoveAllViewProps();
  for (vtkActor* actor : actors)
  {
    renderer->AddActor(actor);
  }
}

void Lineup::Show(vtkActor* shown)
{
  for (vtkActor* actor : this->Actors)
  {
    actor->SetVisibility(actor == shown);
  }
}

ReliefMetrics::Capture Lineup::Capture(vtkActor* shown)
{
  this->Show(shown);
  this->Window->Render();
  return ReliefScene::Capture(this->Window, this->Renderer);
}

std::vector<double> Lineup::InterleavedMilliseconds(
  const std::vector<vtkActor*>& timed, int rounds, int frames)
{
  std::vector<std::vector<double>> milliseconds(timed.size());
  for (int round = 0; round < rounds; ++round)
  {
    for (size_t a = 0; a < timed.size(); ++a)
    {
      this->Show(timed[a]);
      const std::vector<double> times = FrameMilliseconds(this->Window, 2, frames);
      milliseconds[a].insert(milliseconds[a].end(), times.begin(), times.end());
    }
  }
  std::vector<double> medians;
  for (const std::vector<double>& times : milliseconds)
  {
    medians.push_back(Median(times));
  }
  return medians;
}

std::vector<double> FrameMilliseconds(vtkRenderWindow* window, int warmup, int frames)
{
  for (int i = 0; i < warmup; ++i)
  {
    window->Render();
  }
  window->WaitForCompletion();
  std::vector<double> milliseconds;
  for (int i = 0; i < frames; ++i)
  {
    const auto start = std::chrono::steady_clock::now();
    window->Render();
    window->WaitForCompletion();
    const std::chrono::duration<double, std::milli> elapsed =
      std::chrono::steady_clock::now() - start;
    milliseconds.push_back(elapsed.count());
  }
  return milliseconds;
}

double Median(std::vector<double> values)
{
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

ReliefMetrics::Capture Capture(vtkRenderWindow* window, vtkRenderer* renderer)
{
  ReliefMetrics::Capture capture;
  capture.Width = window->GetSize()[0];
  capture.Height = window->GetSize()[1];
  const std::vector<unsigned char> pixels = Pixels(window);
  capture.Rgb.reserve(pixels.size());
  for (unsigned char value : pixels)
  {
    capture.Rgb.push_back(value / 255.0f);
  }
  std::vector<float> window01(static_cast<size_t>(capture.Width) * capture.Height);
  window->GetZbufferData(0, 0, capture.Width - 1, capture.Height - 1, window01.data());
  vtkCamera* camera = renderer->GetActiveCamera();
  double range[2];
  camera->GetClippingRange(range);
  const double near = range[0];
  const double far = range[1];
  capture.EyeDepth.reserve(window01.size());
  for (float depth : window01)
  {
    if (depth >= 1.0f)
    {
      capture.EyeDepth.push_back(std::numeric_limits<float>::infinity());
    }
    else if (camera->GetParallelProjection())
    {
      capture.EyeDepth.push_back(static_cast<float>(near + depth * (far - near)));
    }
    else
    {
      // the inverse of the perspective depth mapping, window depth in [0, 1]
      const double ndc = 2.0 * depth - 1.0;
      capture.EyeDepth.push_back(
        static_cast<float>(2.0 * near * far / (far + near - ndc * (far - near))));
    }
  }
  return capture;
}

SampleStatistics SampleCounts(
  vtkRenderWindow* window, vtkRenderer* renderer, vtkOpenGLReliefMapper* mapper)
{
  mapper->SetDisplayModeToSampleCount();
  window->Render();
  const ReliefMetrics::Capture capture = Capture(window, renderer);
  mapper->SetDisplayModeToShaded();
  double sum = 0.0;
  size_t covered = 0;
  SampleStatistics statistics;
  for (size_t pixel = 0; pixel < capture.EyeDepth.size(); ++pixel)
  {
    if (capture.Covers(pixel))
    {
      const int samples = static_cast<int>(std::lround(255.0f * capture.Rgb[3 * pixel]));
      sum += samples;
      statistics.Maximum = std::max(statistics.Maximum, samples);
      ++covered;
    }
  }
  statistics.Mean = covered ? sum / covered : 0.0;
  statistics.Coverage = static_cast<double>(covered) / capture.EyeDepth.size();
  return statistics;
}

double MedianFrameMilliseconds(vtkRenderWindow* window, int warmup, int frames)
{
  return Median(FrameMilliseconds(window, warmup, frames));
}
}
