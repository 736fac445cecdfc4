#include "shadelabVertexTangents.h"

#include "shadelabTriangleMesh.h"
#include "shadelabVec3.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace shadelab
{
namespace
{
// A triangle's corner: its point, the angle there and the triangle's unit
// tangent and handedness.
struct Corner
{
  vtkIdType Point;
  double Angle;
  Vec3 T;
  double W;
};

double AngleAt(const Vec3& p, const Vec3& a, const Vec3& b)
{
  const Vec3 u = normalize(a - p), v = normalize(b - p);
  return std::acos(std::clamp(dot(u, v), -1.0, 1.0));
}

// The corners of triangle (i, j, k), none where its tangent is undefined.
void AddCorners(vtkPoints* points, vtkDataArray* st, vtkIdType i, vtkIdType j, vtkIdType k,
  std::vector<Corner>& corners)
{
  Vec3 p[3];
  points->GetPoint(i, p[0].data());
  points->GetPoint(j, p[1].data());
  points->GetPoint(k, p[2].data());
  const Vec3 e1 = p[1] - p[0], e2 = p[2] - p[0];
  const double du1 = st->GetComponent(j, 0) - st->GetComponent(i, 0);
  const double dv1 = st->GetComponent(j, 1) - st->GetComponent(i, 1);
  const double du2 = st->GetComponent(k, 0) - st->GetComponent(i, 0);
  const double dv2 = st->GetComponent(k, 1) - st->GetComponent(i, 1);
  const double det = du1 * dv2 - du2 * dv1;
  if (det == 0 || !std::isfinite(det))
  {
    return;
  }
  const Vec3 T = (1 / det) * (dv2 * e1 - dv1 * e2);
  const Vec3 B = (1 / det) * (du1 * e2 - du2 * e1);
  const double len = length(T);
  if (!(len > 0) || !std::isfinite(len))
  {
    return;
  }
  const double w = dot(cross(cross(e1, e2), T), B) < 0 ? -1 : 1;
  const vtkIdType ids[3] = { i, j, k };
  for (int c = 0; c < 3; ++c)
  {
    corners.push_back({ ids[c], AngleAt(p[c], p[(c + 1) % 3], p[(c + 2) % 3]), (1 / len) * T, w });
  }
}
}

vtkSmartPointer<vtkFloatArray> VertexTangents(vtkPolyData* mesh)
{
  vtkPoints* points = mesh->GetPoints();
  vtkDataArray* st = mesh->GetPointData()->GetArray(TextureCoordinatesArrayName);
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  const vtkIdType n = points ? points->GetNumberOfPoints() : 0;
  std::vector<Corner> corners;
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); st && polys->GetNextCell(count, ids);)
  {
    for (vtkIdType c = 1; c + 1 < count; ++c)
    {
      AddCorners(points, st, ids[0], ids[c], ids[c + 1], corners);
    }
  }
  std::vector<double> handedness(n, 0);
  for (const Corner& c : corners)
  {
    handedness[c.Point] += c.W * c.Angle;
  }
  // Each point's key: its position, normal and handedness; the sums by key.
  using Key = std::array<double, 7>;
  std::vector<Key> keys(n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    Key& key = keys[p];
    points->GetPoint(p, key.data());
    if (normals)
    {
      normals->GetTuple(p, key.data() + 3);
    }
    key[6] = handedness[p] < 0 ? -1 : 1;
  }
  std::map<Key, Vec3> sums;
  for (const Corner& c : corners)
  {
    const Key& key = keys[c.Point];
    if (c.W == key[6])
    {
      Vec3& sum = sums[key];
      sum = sum + c.Angle * c.T;
    }
  }
  auto tangents = vtkSmartPointer<vtkFloatArray>::New();
  tangents->SetName(TangentsArrayName);
  tangents->SetNumberOfComponents(4);
  tangents->SetNumberOfTuples(n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    const auto sum = sums.find(keys[p]);
    const Vec3 t = sum == sums.end() ? Vec3{ 0, 0, 0 } : normalize(sum->second);
    const float tuple[4] = { static_cast<float>(t[0]), static_cast<float>(t[1]),
      static_cast<float>(t[2]), static_cast<float>(keys[p][6]) };
    tangents->SetTypedTuple(p, tuple);
  }
  return tangents;
}
}
