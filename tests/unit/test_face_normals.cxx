// Flat shading's face normals: ComputeFaceNormals against shadelab::FaceNormal
// (the oracle's) cast to float, bit for bit, for float and double points and
// 32- and 64-bit cells, whole or slice by slice, leaving out the triangles
// that VTK does not draw (two corners at one position); and the refusal of
// a mesh whose cells are not all triangles (gl_PrimitiveID would then name
// the wrong triangle's normal).
#include "headless/headless_renderer.h"
#include "shadelabFaceNormals.h"
#include "shadelabVec3.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using namespace shadelab;

// The bunny with its points in `type` and its cells in 32 or 64 bits, and
// five more triangles: two that VTK does not draw (a repeated point id; two
// points at one position), a degenerate one it draws (collinear corners), a
// sliver, and one so
// large that its cross product overflows a double (in float points, its
// corners are infinite).
vtkSmartPointer<vtkPolyData> BunnyAndHardTriangles(int type, bool ids32)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName((fs::path(SHADELAB_TEST_MESHES) / "teapot-fine.ply").c_str());
  EXPECT_TRUE(reader->GetExecutive()->Update());
  vtkPolyData* bunny = reader->GetOutput();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(type);
  for (vtkIdType i = 0; i < bunny->GetNumberOfPoints(); ++i)
  {
    points->InsertNextPoint(bunny->GetPoint(i));
  }
  const vtkIdType a = points->InsertNextPoint(0, 0, 0);
  const vtkIdType twin = points->InsertNextPoint(0, 0, 0);
  const vtkIdType between = points->InsertNextPoint(0.5, 0.5e-7, 0);
  const vtkIdType b = points->InsertNextPoint(1, 1e-7, 0);
  const vtkIdType c = points->InsertNextPoint(2, 0, 1e-7);
  const vtkIdType far = points->InsertNextPoint(-1e160, -1e160, 0);
  const vtkIdType far2 = points->InsertNextPoint(1e160, 0, 1e160);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  if (ids32)
  {
    cells->ConvertTo32BitStorage();
  }
  else
  {
    cells->ConvertTo64BitStorage();
  }
  vtkCellArray* polys = bunny->GetPolys();
  for (vtkIdType t = 0; t < polys->GetNumberOfCells(); ++t)
  {
    vtkIdType n;
    const vtkIdType* ids;
    polys->GetCellAtId(t, n, ids);
    cells->InsertNextCell(n, ids);
  }
  for (const auto& ids : std::vector<std::vector<vtkIdType>>{
         { a, b, b }, { twin, c, a }, { a, between, b }, { a, b, c }, { a, far, far2 } })
  {
    cells->InsertNextCell(3, ids.data());
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(cells);
  return mesh;
}

// The normals of the triangles that VTK draws, each from FaceNormal.
std::vector<float> Expected(vtkPolyData* mesh)
{
  std::vector<float> expected;
  vtkCellArray* polys = mesh->GetPolys();
  for (vtkIdType t = 0; t < polys->GetNumberOfCells(); ++t)
  {
    vtkIdType n;
    const vtkIdType* ids;
    polys->GetCellAtId(t, n, ids);
    Vec3 p[3], normal;
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k].data());
    }
    if (p[0] == p[1] || p[0] == p[2] || p[1] == p[2])
    {
      continue;
    }
    FaceNormal(p[0], p[1], p[2], normal);
    for (double x : normal)
    {
      expected.push_back(static_cast<float>(x));
    }
  }
  return expected;
}

TEST(FaceNormals, AreTheOraclesCastToFloatForTheDrawnTrianglesWholeOrBySlices)
{
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    for (bool ids32 : { true, false })
    {
      const vtkSmartPointer<vtkPolyData> mesh = BunnyAndHardTriangles(type, ids32);
      const std::vector<float> expected = Expected(mesh);
      const vtkIdType triangles = mesh->GetNumberOfPolys();
      // Every bunny triangle is drawn; of the hard ones, the two with a
      // point twice are not; the collinear and the overflowing one have no
      // direction, the sliver a unit normal.
      ASSERT_EQ(expected.size(), 3U * (triangles - 2));
      const float* last = expected.data() + expected.size() - 9;
      EXPECT_EQ(std::vector<float>(last, last + 3), std::vector<float>(3, 0.0f));
      EXPECT_NEAR(last[3] * last[3] + last[4] * last[4] + last[5] * last[5], 1.0, 1e-6);
      EXPECT_EQ(std::vector<float>(last + 6, last + 9), std::vector<float>(3, 0.0f));

      std::vector<float> whole(3 * triangles, -7.0f);
      EXPECT_EQ(ComputeFaceNormals(mesh, 0, triangles, whole.data()), triangles - 2);
      EXPECT_EQ(std::memcmp(whole.data(), expected.data(), expected.size() * sizeof(float)), 0)
        << "points " << type << ", 32-bit ids " << ids32;

      std::vector<float> sliced(3 * triangles, -7.0f);
      const vtkIdType slice = 1000;
      vtkIdType written = 0;
      for (vtkIdType first = 0; first < triangles; first += slice)
      {
        written += ComputeFaceNormals(
          mesh, first, std::min(slice, triangles - first), sliced.data() + 3 * written);
      }
      EXPECT_EQ(written, triangles - 2);
      EXPECT_EQ(std::memcmp(sliced.data(), expected.data(), expected.size() * sizeof(float)), 0);
    }
  }
}

TEST(FaceNormals, FlatRefusesCellsOtherThanTriangles)
{
  HeadlessRenderer renderer;
  ASSERT_EQ(renderer.Start(64, 48), "");
  auto points = vtkSmartPointer<vtkPoints>::New();
  const double corners[4][3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } };
  for (const double* p : corners)
  {
    points->InsertNextPoint(p);
  }
  auto quad = vtkSmartPointer<vtkPolyData>::New();
  quad->SetPoints(points);
  quad->SetPolys(vtkSmartPointer<vtkCellArray>::New());
  const vtkIdType ids[4] = { 0, 1, 2, 3 };
  quad->GetPolys()->InsertNextCell(4, ids);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(quad);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  renderer.GetRenderer()->AddActor(actor);
  renderer.GetRenderer()->ResetCamera();
  vtkNew<vtkShadelabShading> shading;
  ASSERT_TRUE(shading->SetShadingRuleByName("flat"));
  shading->AddPointLight(0, 0, 5);
  shading->Attach(actor, renderer.GetRenderer());
  renderer.Render();
  EXPECT_NE(renderer.GetError().find("flat shading draws triangles only"), std::string::npos)
    << renderer.GetError();
}
}
