#include "exploded_flat_mesh.h"

#include "shadelabShaderSource.h"
#include "shadelabTriangleMesh.h"

#include <array>
#include <utility>
#include <vector>

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace shadelab
{
vtkSmartPointer<vtkPolyData> ExplodedFlatMesh(vtkPolyData* mesh)
{
  vtkCellArray* polys = mesh->GetPolys();
  const vtkIdType triangles = polys->GetNumberOfCells();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(3 * triangles);
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName(FaceNormalArrayName);
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(3 * triangles);
  std::vector<std::pair<vtkDataArray*, vtkSmartPointer<vtkDataArray>>> carried;
  for (const char* name : { ColorsArrayName, TextureCoordinatesArrayName })
  {
    if (vtkDataArray* array = mesh->GetPointData()->GetArray(name))
    {
      vtkSmartPointer<vtkDataArray> corners;
      corners.TakeReference(array->NewInstance());
      corners->SetName(name);
      corners->SetNumberOfComponents(array->GetNumberOfComponents());
      corners->SetNumberOfTuples(3 * triangles);
      carried.emplace_back(array, corners);
    }
  }
  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  vtkIdType next = 0;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids); next += 3)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      mesh->GetPoint(ids[k], p[k]);
      points->SetPoint(next + k, p[k]);
      for (auto& [array, corners] : carried)
      {
        corners->SetTuple(next + k, ids[k], array);
      }
    }
    double e1[3], e2[3], n[3];
    vtkMath::Subtract(p[1], p[0], e1);
    vtkMath::Subtract(p[2], p[0], e2);
    vtkMath::Cross(e1, e2, n);
    vtkMath::Normalize(n);
    const std::array<float, 3> face = { static_cast<float>(n[0]), static_cast<float>(n[1]),
      static_cast<float>(n[2]) };
    for (int k = 0; k < 3; ++k)
    {
      normals->SetTypedTuple(next + k, face.data());
    }
  }
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(triangles + 1);
  connectivity->SetNumberOfValues(3 * triangles);
  for (vtkIdType i = 0; i <= triangles; ++i)
  {
    offsets->SetValue(i, 3 * i);
  }
  for (vtkIdType i = 0; i < 3 * triangles; ++i)
  {
    connectivity->SetValue(i, i);
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  auto exploded = vtkSmartPointer<vtkPolyData>::New();
  exploded->SetPoints(points);
  exploded->SetPolys(cells);
  exploded->GetPointData()->AddArray(normals);
  for (auto& [array, corners] : carried)
  {
    exploded->GetPointData()->AddArray(corners);
  }
  return exploded;
}
}
