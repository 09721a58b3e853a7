// vtkOpenGLQuadricReliefMapper on the shapes of Oliveira and Policarpo (2005), in one distance mode
// (the argument: Approximate or Exact): a sphere, a cylinder, the inside of a torus's ring
// (negative Gaussian curvature, the saddles of Fig. 14) and an open piece of cylinder (a mesh with
// boundaries, where the relief simply ends with the mesh, seen so that its inside shows beside its
// outer side). Stones on each, seen so that outlines cross the relief, with the actors' default
// properties. Regression images, one per mode.
#include "ReliefScene.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkOpenGLQuadricReliefMapper.h"
#include "vtkPolyData.h"
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
  renderer->AddActor(ReliefScene::ReliefActor(mapper, "stones_color.png"));
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
    { ReliefScene::Sphere(32), { 0.0, 2.6, 0.9 }, { 0.0, 0.0, 0.0 }, 30.0 },
    { ReliefScene::Cylinder(32), { 0.5, 3.4, 1.2 }, { 0.0, 0.0, 0.0 }, 30.0 },
    { ReliefScene::Torus(48), { 0.25, 1.6, 0.15 }, { 0.0, 0.0, 0.0 }, 35.0 },
    // the open piece: its inside (left) past the top rim, its outer side and outline (right)
    { ReliefScene::Cylinder(32, 150.0), { -0.8, -2.2, 2.4 }, { 0.0, 0.25, 0.9 }, 35.0 },
  };
  vtkNew<vtkRenderWindow> window;
  Show(window, views[0], mode, 0.0, 0.5);
  Show(window, views[1], mode, 0.5, 0.5);
  Show(window, views[2], mode, 0.0, 0.0);
  Show(window, views[3], mode, 0.5, 0.0);
  window->Render();
  return !vtkRegressionTestImage(window);
}
