#include "shadelabTriangleIndexBuffer.h"

#include <vtkArrayDispatch.h>
#include <vtkCellArray.h>
#include <vtkDataArrayRange.h>

#include <algorithm>

namespace
{
struct FanIndices
{
  template <typename CellState, typename PointArray>
  void operator()(CellState& state, PointArray* points, std::vector<unsigned int>& indices) const
  {
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const auto* ids = state.GetConnectivity()->GetPointer(0);
    const vtkIdType cells = state.GetNumberOfCells();
    const auto xyz = vtk::DataArrayTupleRange<3>(points);
    // A cell of n >= 3 ids is n - 2 triangles: 3 (ids - 2 cells) indices
    // when every cell has 3 or more (VTK's own estimate), a hint otherwise.
    const auto most = 3 * (static_cast<vtkIdType>(offsets[cells]) - 2 * cells);
    indices.reserve(indices.size() + static_cast<std::size_t>(std::max<vtkIdType>(most, 0)));
    for (vtkIdType c = 0; c < cells; ++c)
    {
      const auto size = offsets[c + 1] - offsets[c];
      if (size < 3)
      {
        continue;
      }
      const auto* cell = ids + offsets[c];
      const auto p1 = xyz[cell[0]];
      for (vtkIdType i = 1; i < size - 1; ++i)
      {
        if (shadelab::IsDrawn(p1, xyz[cell[i]], xyz[cell[i + 1]]))
        {
          indices.push_back(static_cast<unsigned int>(cell[0]));
          indices.push_back(static_cast<unsigned int>(cell[i]));
          indices.push_back(static_cast<unsigned int>(cell[i + 1]));
        }
      }
    }
  }
};

struct PointsWorker
{
  template <typename PointArray>
  void operator()(PointArray* points, vtkCellArray* polys, std::vector<unsigned int>& indices) const
  {
    polys->Visit(FanIndices{}, points, indices);
  }
};
}

namespace shadelab
{
bool AppendTriangleIndices(
  vtkCellArray* polys, vtkDataArray* points, std::vector<unsigned int>& indices)
{
  return vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(
    points, PointsWorker{}, polys, indices);
}
}
