// vtkOpenGLQuadricReliefMapper on the shapes of seed 000, in one distance mode (the
// argument: Approximate or Exact): a sphere, a cylinder, the inside of a torus's ring
// (negative Gaussian curvature, the saddles of Fig. 14) and an open piece of cylinder
// (a mesh with boundaries, where the relief simply ends with the mesh). Stones on each,
// seen so that outlines cross the relief. Regression images, one per mode.
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"

#include <cstring>
#include <iostream>

namespace
{
struct View
{
  vtkSmartPointer<vtkPolyData> Shape;
  bool Closed; // cull back faces: past the outline lies what is behind the shape
  double Position[3];
  double FocalPoint[3];
  double ViewAngle;
};

void Show(vtkRenderWindow* window, const View& view, int mode, double left, double bottom)
{
  auto renderer = ReliefScene::LitRenderer(window, 600, 600);
  renderer->SetViewport(left, bottom, left + 0.5, bottom + 0.5);
  vtkNew<vtkOpenGLQuadricReliefMapper> mapper;
  mapper->SetDistanceMode(mode);
  ReliefScene::SetStones(mapper, view.Shape, 0.06);
  auto actor = ReliefScene::ReliefActor(mapper, "stones_color.png");
  actor->GetProperty()->SetBackfaceCulling(view.Closed);
  renderer->AddActor(actor);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(view.Position);
  camera->SetFocalPoint(view.FocalPoint);
  camera->SetViewUp(0.0, 0.0, 1.0);
  camera->SetViewAngle(view.ViewAngle);
  renderer->ResetCameraClippingRange();
}
}

int TestReliefQuadricShapes(int argc, char* argv[])
{
  int mode = vtkOpenGLQuadricReliefMapper::APPROXIMATE;
  for (int i = 1; i < argc; ++i)
  {
    mode = std::strcmp(argv[i], "Exact") == 0 ? vtkOpenGLQuadricReliefMapper::EXACT : mode;
  }
  // the torus lies in the x-z plane (axis y): looking along y into its hole shows the
  // inner, saddle-shaped side of the ring
  const View views[] = {
    { ReliefScene::Sphere(32), true, { 0.0, 2.6, 0.9 }, { 0.0, 0.0, 0.0 }, 30.0 },
    { ReliefScene::Cylinder(32), true, { 0.5, 3.4, 1.2 }, { 0.0, 0.0, 0.0 }, 30.0 },
    { ReliefScene::Torus(48), true, { 0.25, 1.6, 0.15 }, { 0.0, 0.0, 0.0 }, 35.0 },
    // the open piece from outside, its top rim and both side edges in view
    { ReliefScene::Cylinder(32, 150.0), false, { 0.9, 2.6, 2.6 }, { 0.0, 0.3, 1.0 }, 35.0 },
  };
  vtkNew<vtkRenderWindow> window;
  Show(window, views[0], mode, 0.0, 0.5);
  Show(window, views[1], mode, 0.5, 0.5);
  Show(window, views[2], mode, 0.0, 0.0);
  Show(window, views[3], mode, 0.5, 0.0);
  window->Render();
  return !vtkRegressionTestImage(window);
}
