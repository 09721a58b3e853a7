// The meshes the impostor's unit tests capture (TestReliefImpostorFilter,
// TestReliefImpostorFrame): a sphere, and a cube standing on a ground.
#ifndef ReliefImpostorMeshes_h
#define ReliefImpostorMeshes_h

#include "vtkAppendPolyData.h"
#include "vtkCubeSource.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"

namespace ReliefImpostorMeshes
{
/// A sphere about the origin, `resolution` facets around and from pole to pole.
inline vtkSmartPointer<vtkPolyData> Sphere(double radius, int resolution)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(resolution);
  sphere->SetPhiResolution(resolution);
  sphere->Update();
  return sphere->GetOutput();
}

/// A unit cube standing on a 4 x 4 ground (z = 0), its walls at x, y = +-0.5.
inline vtkSmartPointer<vtkPolyData> CubeOnGround()
{
  vtkNew<vtkCubeSource> cube;
  cube->SetCenter(0.0, 0.0, 0.5);
  vtkNew<vtkPlaneSource> ground;
  ground->SetOrigin(-2.0, -2.0, 0.0);
  ground->SetPoint1(2.0, -2.0, 0.0);
  ground->SetPoint2(-2.0, 2.0, 0.0);
  ground->SetResolution(8, 8);
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(cube->GetOutputPort());
  both->AddInputConnection(ground->GetOutputPort());
  both->Update();
  return both->GetOutput();
}
}

#endif
