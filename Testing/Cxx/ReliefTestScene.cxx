#include "ReliefTestScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkOpenGLReliefMapper.h"
#include "vtkOpenImageIOReader.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSuperquadricSource.h"
#include "vtkTexture.h"
#include "vtkWindowToImageFilter.h"

namespace ReliefTestScene
{
std::string DataFile(const std::string& name)
{
  return std::string(RELIEF_DATA_DIR) + "/" + name;
}

vtkSmartPointer<vtkImageData> ReadImage(const std::string& name)
{
  vtkNew<vtkOpenImageIOReader> reader;
  reader->SetFileName(DataFile(name).c_str());
  reader->Update();
  return reader->GetOutput();
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

vtkSmartPointer<vtkPolyData> Torus()
{
  vtkNew<vtkSuperquadricSource> source;
  source->ToroidalOn();
  source->SetThetaResolution(48);
  source->SetPhiResolution(24);
  source->SetThickness(0.4);
  source->SetSize(0.5);
  source->Update();
  auto torus = vtkSmartPointer<vtkPolyData>::New();
  torus->DeepCopy(source->GetOutput());
  TileTextureCoordinates(torus, 6.0, 2.0);
  return torus;
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

vtkSmartPointer<vtkActor> ReliefActor(vtkOpenGLReliefMapper* mapper, const std::string& colorTexture)
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

namespace ReliefTestScene
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
