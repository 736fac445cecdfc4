// vtkShadelabFlatTriangles: every triangle a provoking (last) point of its
// own at its last vertex's position, carrying the face normal that the
// exploded mesh (every triangle three points) carries, bit for bit; the
// corners' colours and texture coordinates; copies counted; unused points
// left out.
#include "exploded_flat_mesh.h"
#include "shadelabShaderSource.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabFlatTriangles.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using namespace shadelab;

vtkSmartPointer<vtkPolyData> Read(const std::string& name)
{
  vtkNew<vtkShadelabMeshReader> reader;
  reader->SetFileName((fs::path(SHADELAB_TEST_MESHES) / name).c_str());
  EXPECT_TRUE(reader->GetExecutive()->Update()) << name;
  return reader->GetOutput();
}

// mesh with its points in `type`, its cells' ids in 32 or 64 bits, a point
// that no triangle uses (far off, so that it would show in the bounds), and
// colours and texture coordinates that differ from point to point.
vtkSmartPointer<vtkPolyData> WithUnusedPointAndArrays(vtkPolyData* mesh, int type, bool ids32)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(type);
  points->SetNumberOfPoints(mesh->GetNumberOfPoints() + 1);
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, mesh->GetPoint(i));
  }
  points->SetPoint(mesh->GetNumberOfPoints(), 100, -100, 100);
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName(ColorsArrayName);
  colors->SetNumberOfComponents(4);
  auto coordinates = vtkSmartPointer<vtkFloatArray>::New();
  coordinates->SetName(TextureCoordinatesArrayName);
  coordinates->SetNumberOfComponents(2);
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    colors->InsertNextTuple4(i % 251, (i / 251) % 256, i % 7, 255);
    coordinates->InsertNextTuple2(0.001 * static_cast<double>(i), 1.0 / (1.0 + i));
  }
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(points);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->DeepCopy(mesh->GetPolys());
  EXPECT_TRUE(ids32 ? polys->ConvertTo32BitStorage() : polys->ConvertTo64BitStorage());
  out->SetPolys(polys);
  out->GetPointData()->AddArray(colors);
  out->GetPointData()->AddArray(coordinates);
  return out;
}

std::vector<double> Tuple(vtkDataArray* array, vtkIdType i)
{
  std::vector<double> t(array->GetNumberOfComponents());
  array->GetTuple(i, t.data());
  return t;
}

void ExpectProvokingPointsOfTheirOwn(vtkPolyData* mesh)
{
  SCOPED_TRACE(std::string(mesh->GetPoints()->GetData()->GetDataTypeAsString()) +
    (mesh->GetPolys()->IsStorage64Bit() ? " points, 64-bit ids" : " points, 32-bit ids"));
  vtkNew<vtkShadelabFlatTriangles> flat;
  flat->SetInputData(mesh);
  ASSERT_TRUE(flat->GetExecutive()->Update());
  vtkPolyData* out = flat->GetOutput();
  const vtkSmartPointer<vtkPolyData> exploded = ExplodedFlatMesh(mesh);
  const vtkIdType triangles = mesh->GetNumberOfPolys();
  ASSERT_EQ(out->GetNumberOfPolys(), triangles);
  EXPECT_EQ(out->GetPoints()->GetDataType(), mesh->GetPoints()->GetDataType());

  vtkDataArray* normals = out->GetPointData()->GetArray(FaceNormalArrayName);
  vtkDataArray* explodedNormals = exploded->GetPointData()->GetArray(FaceNormalArrayName);
  ASSERT_NE(normals, nullptr);
  ASSERT_EQ(normals->GetDataType(), VTK_FLOAT);
  std::set<vtkIdType> provoking;
  std::set<vtkIdType> lastVertices;
  std::set<vtkIdType> usedVertices;
  vtkNew<vtkIdList> in, drawn;
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    mesh->GetPolys()->GetCellAtId(t, in);
    out->GetPolys()->GetCellAtId(t, drawn);
    ASSERT_EQ(drawn->GetNumberOfIds(), 3);
    EXPECT_TRUE(provoking.insert(drawn->GetId(2)).second) << "triangle " << t;
    lastVertices.insert(in->GetId(2));
    for (int k = 0; k < 3; ++k)
    {
      usedVertices.insert(in->GetId(k));
      // Bit-equal positions (the point type is kept), colours and texture
      // coordinates at every corner, the cell's order of corners kept.
      EXPECT_EQ(Tuple(out->GetPoints()->GetData(), drawn->GetId(k)),
        Tuple(mesh->GetPoints()->GetData(), in->GetId(k)))
        << "triangle " << t << " corner " << k;
      for (const char* name : { ColorsArrayName, TextureCoordinatesArrayName })
      {
        EXPECT_EQ(Tuple(out->GetPointData()->GetArray(name), drawn->GetId(k)),
          Tuple(mesh->GetPointData()->GetArray(name), in->GetId(k)))
          << name << " triangle " << t << " corner " << k;
      }
    }
    // The face normal, bit for bit the exploded mesh's (which computes it in
    // double from the same positions and casts it to float).
    EXPECT_EQ(Tuple(normals, drawn->GetId(2)), Tuple(explodedNormals, 3 * t)) << "triangle " << t;
  }
  // The greedy walk copies a vertex once for each triangle after the first
  // that ends at it; the used points are all kept, the unused one is not.
  const vtkIdType copies = triangles - static_cast<vtkIdType>(lastVertices.size());
  EXPECT_EQ(flat->GetNumberOfCopies(), copies);
  EXPECT_EQ(out->GetNumberOfPoints(), static_cast<vtkIdType>(usedVertices.size()) + copies);
  EXPECT_LT(usedVertices.size(), static_cast<size_t>(mesh->GetNumberOfPoints()));
  double bounds[6], explodedBounds[6];
  out->GetBounds(bounds);
  exploded->GetBounds(explodedBounds);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(bounds[i], explodedBounds[i]);
  }
  // Far fewer points than the exploded mesh's 3T: a closed mesh has about
  // half as many vertices as triangles, so about T/2 copies and 1.5T points.
  EXPECT_LT(out->GetNumberOfPoints(), 2 * triangles);
}

TEST(FlatTriangles, ProvokingPointsOfTheirOwnWhateverThePointAndIdTypes)
{
  const vtkSmartPointer<vtkPolyData> bunny = Read("stanford-bunny.obj");
  ASSERT_GT(bunny->GetNumberOfPolys(), 60000);
  ExpectProvokingPointsOfTheirOwn(WithUnusedPointAndArrays(bunny, VTK_FLOAT, false));
  ExpectProvokingPointsOfTheirOwn(WithUnusedPointAndArrays(bunny, VTK_DOUBLE, true));
}

TEST(FlatTriangles, RejectsCellsOtherThanTrianglesAndPointsNotThere)
{
  vtkShadelabOutputWindow::Install();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  for (int i = 0; i < 6; ++i)
  {
    points->InsertNextPoint(i, i % 2, 0);
  }
  mesh->SetPoints(points);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType quad[4] = { 0, 1, 2, 3 }, line[2] = { 4, 5 };
  polys->InsertNextCell(4, quad); // 6 ids in 2 cells, as two triangles would have
  polys->InsertNextCell(2, line);
  mesh->SetPolys(polys);
  vtkNew<vtkShadelabFlatTriangles> flat;
  flat->SetInputData(mesh);
  EXPECT_FALSE(flat->GetExecutive()->Update());

  // Triangles, but one names a point past the last.
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType first[3] = { 0, 1, 2 }, past[3] = { 3, 4, 6 };
  triangles->InsertNextCell(3, first);
  triangles->InsertNextCell(3, past);
  mesh->SetPolys(triangles);
  flat->Modified();
  EXPECT_FALSE(flat->GetExecutive()->Update());
  triangles->ReplaceCellAtId(1, 3, first);
  triangles->Modified();
  flat->Modified();
  EXPECT_TRUE(flat->GetExecutive()->Update());
}
}
