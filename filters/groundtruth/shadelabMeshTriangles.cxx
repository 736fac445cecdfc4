#include "shadelabMeshTriangles.h"

#include <vtkCellArray.h>
#include <vtkPolyData.h>

namespace shadelab
{
std::vector<Vec3> PointsOf(vtkPolyData* mesh)
{
  std::vector<Vec3> points(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    mesh->GetPoint(i, points[i].data());
  }
  return points;
}

std::vector<TriangleCorners> TrianglesOf(vtkPolyData* mesh)
{
  std::vector<TriangleCorners> triangles;
  triangles.reserve(mesh->GetNumberOfPolys());
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    triangles.push_back(
      n == 3 ? TriangleCorners{ ids[0], ids[1], ids[2] } : TriangleCorners{ 0, 0, 0 });
  }
  return triangles;
}
}
