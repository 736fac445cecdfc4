#include "shadelabFaceNormals.h"

#include "shadelabTriangleIndexBuffer.h"
#include "shadelabVec3.h"

#include <vtkArrayDispatch.h>
#include <vtkCellArray.h>
#include <vtkDataArrayRange.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <vector>

namespace
{
struct FaceNormalsWorker
{
  // Each triangle's normal at 3 * i, and whether VTK draws it.
  template <typename PointArray, typename Id>
  void operator()(PointArray* points, const Id* ids, vtkIdType first, vtkIdType count,
    float* normals, char* drawn) const
  {
    const auto xyz = vtk::DataArrayTupleRange<3>(points);
    vtkSMPTools::For(0, count,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          const Id* corner = ids + 3 * (first + i);
          const auto p0 = xyz[corner[0]];
          const auto p1 = xyz[corner[1]];
          const auto p2 = xyz[corner[2]];
          drawn[i] = shadelab::IsDrawn(p0, p1, p2);
          const auto point = [](const auto& p) -> shadelab::Vec3 {
            return { static_cast<double>(p[0]), static_cast<double>(p[1]),
              static_cast<double>(p[2]) };
          };
          shadelab::Vec3 n;
          shadelab::FaceNormal(point(p0), point(p1), point(p2), n);
          for (int c = 0; c < 3; ++c)
          {
            normals[3 * i + c] = static_cast<float>(n[c]);
          }
        }
      });
  }
};

template <typename Id>
void Compute(vtkDataArray* points, const Id* ids, vtkIdType first, vtkIdType count, float* normals,
  char* drawn)
{
  const FaceNormalsWorker worker;
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(
        points, worker, ids, first, count, normals, drawn))
  {
    worker(points, ids, first, count, normals, drawn);
  }
}
}

namespace shadelab
{
vtkIdType ComputeFaceNormals(vtkPolyData* mesh, vtkIdType first, vtkIdType count, float* normals)
{
  vtkCellArray* polys = mesh->GetPolys();
  vtkDataArray* points = mesh->GetPoints()->GetData();
  std::vector<char> drawn(count);
  if (polys->IsStorage64Bit())
  {
    Compute(
      points, polys->GetConnectivityArray64()->GetPointer(0), first, count, normals, drawn.data());
  }
  else
  {
    Compute(
      points, polys->GetConnectivityArray32()->GetPointer(0), first, count, normals, drawn.data());
  }
  vtkIdType written = 0;
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (drawn[i])
    {
      std::copy_n(normals + 3 * i, 3, normals + 3 * written++);
    }
  }
  return written;
}
}
