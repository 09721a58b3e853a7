// vtkReliefSurfaceFilter::IsClosed: which meshes enclose a volume and face out of it, so
// that the relief mappers may leave out their back faces.
#include "vtkReliefSurfaceFilter.h"

#include "vtkCellArray.h"
#include "vtkCubeSource.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReverseSense.h"
#include "vtkSphereSource.h"
#include "vtkTexturedSphereSource.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
vtkSmartPointer<vtkPolyData> Copy(vtkPolyData* mesh)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  return copy;
}

vtkSmartPointer<vtkPolyData> Sphere()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(8);
  sphere->Update();
  return Copy(sphere->GetOutput());
}

// The mesh without its cell `removed`.
vtkSmartPointer<vtkPolyData> WithoutCell(vtkPolyData* mesh, vtkIdType removed)
{
  auto result = Copy(mesh);
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdList> ids;
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfPolys(); ++cell)
  {
    if (cell != removed)
    {
      mesh->GetCellPoints(cell, ids);
      polys->InsertNextCell(ids);
    }
  }
  result->SetPolys(polys);
  return result;
}
}

TEST(ReliefSurfaceFilter, ClosedMeshesFacingOutAreClosed)
{
  EXPECT_TRUE(vtkReliefSurfaceFilter::IsClosed(Sphere()));
  // quads, and corners that each face duplicates for its own normals
  vtkNew<vtkCubeSource> cube;
  cube->Update();
  EXPECT_TRUE(vtkReliefSurfaceFilter::IsClosed(cube->GetOutput()));
}

TEST(ReliefSurfaceFilter, TextureSeamsAndPolesDoNotOpenAMesh)
{
  // vtkTexturedSphereSource duplicates the points of its seam and of its poles, one per
  // column, which leaves triangles with two corners at one pole
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(6);
  sphere->Update();
  EXPECT_TRUE(vtkReliefSurfaceFilter::IsClosed(sphere->GetOutput()));
}

TEST(ReliefSurfaceFilter, SeamsOffByRoundingStillClose)
{
  auto sphere = Sphere();
  // the first triangle's first corner becomes a copy of it moved by 1e-12
  vtkNew<vtkIdList> ids;
  sphere->GetPolys()->GetCellAtId(0, ids);
  double point[3];
  sphere->GetPoint(ids->GetId(0), point);
  point[0] += 1e-12;
  ids->SetId(0, sphere->GetPoints()->InsertNextPoint(point));
  sphere->GetPolys()->ReplaceCellAtId(0, ids);
  EXPECT_TRUE(vtkReliefSurfaceFilter::IsClosed(sphere));
}

TEST(ReliefSurfaceFilter, OpenMeshesAreNotClosed)
{
  vtkNew<vtkPlaneSource> plane;
  plane->Update();
  EXPECT_FALSE(vtkReliefSurfaceFilter::IsClosed(plane->GetOutput()));
  EXPECT_FALSE(vtkReliefSurfaceFilter::IsClosed(WithoutCell(Sphere(), 5)));
}

TEST(ReliefSurfaceFilter, InwardOrInconsistentFacesAreNotClosed)
{
  // every face turned in: closed, but its front faces are its inside
  vtkNew<vtkReverseSense> reverse;
  reverse->SetInputData(Sphere());
  reverse->ReverseCellsOn();
  reverse->Update();
  EXPECT_FALSE(vtkReliefSurfaceFilter::IsClosed(reverse->GetOutput()));

  // one face turned: its edges run the same way as its neighbours'
  auto sphere = Sphere();
  vtkNew<vtkIdList> ids;
  sphere->GetPolys()->GetCellAtId(0, ids);
  const vtkIdType first = ids->GetId(0);
  ids->SetId(0, ids->GetId(1));
  ids->SetId(1, first);
  sphere->GetPolys()->ReplaceCellAtId(0, ids);
  EXPECT_FALSE(vtkReliefSurfaceFilter::IsClosed(sphere));
}

TEST(ReliefSurfaceFilter, NonManifoldEdgesAreNotClosed)
{
  // a closed sphere with a fin on one of its edges: that edge joins three triangles
  auto sphere = Sphere();
  vtkNew<vtkIdList> ids;
  sphere->GetCellPoints(0, ids);
  const vtkIdType tip = sphere->GetPoints()->InsertNextPoint(2.0, 2.0, 2.0);
  const vtkIdType fin[3] = { ids->GetId(0), ids->GetId(1), tip };
  sphere->GetPolys()->InsertNextCell(3, fin);
  EXPECT_FALSE(vtkReliefSurfaceFilter::IsClosed(sphere));
}

TEST(ReliefSurfaceFilter, EmptyOrNonFiniteMeshesAreNotClosed)
{
  EXPECT_FALSE(vtkReliefSurfaceFilter::IsClosed(nullptr));
  vtkNew<vtkPolyData> empty;
  EXPECT_FALSE(vtkReliefSurfaceFilter::IsClosed(empty));
  auto sphere = Sphere();
  sphere->GetPoints()->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  EXPECT_FALSE(vtkReliefSurfaceFilter::IsClosed(sphere));
}
