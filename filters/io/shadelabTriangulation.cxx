#include "shadelabTriangulation.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkContourTriangulator.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>

#include <algorithm>
#include <limits>
#include <vector>

namespace shadelab
{
namespace
{
// True when the polygon visits a vertex twice: a hole joined to the outline
// by a bridge edge that the polygon runs along both ways (LightWave's
// exports), which vtkPolygon's ear cutting does not take.
bool RepeatsAVertex(vtkIdType size, const vtkIdType* ids, std::vector<vtkIdType>& sorted)
{
  sorted.assign(ids, ids + size);
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

// Ear cutting keeps the polygon's orientation and handles concave polygons;
// one with a bridge to a hole goes to vtkContourTriangulator's ear cutting,
// which is made for such polygons (it joins holes that way itself). Where
// both give up (zero area, collinear vertices) a fan keeps the face's
// vertices connected, with degenerate triangles as the face was.
void AddPolygon(vtkIdType size, const vtkIdType* ids, vtkPoints* points, vtkPolygon* polygon,
  vtkIdList* local, std::vector<vtkIdType>& sorted, vtkCellArray* triangles)
{
  if (RepeatsAVertex(size, ids, sorted))
  {
    local->SetNumberOfIds(size);
    std::copy(ids, ids + size, local->GetPointer(0));
    vtkNew<vtkCellArray> bridged; // kept only when the whole polygon was cut
    if (vtkContourTriangulator::TriangulatePolygon(local, points, bridged) &&
      bridged->GetNumberOfCells() > 0)
    {
      triangles->Append(bridged);
      return;
    }
  }
  polygon->GetPointIds()->SetNumberOfIds(size);
  polygon->GetPoints()->SetNumberOfPoints(size);
  for (vtkIdType k = 0; k < size; ++k)
  {
    polygon->GetPointIds()->SetId(k, ids[k]);
    polygon->GetPoints()->SetPoint(k, points->GetPoint(ids[k]));
  }
  if (polygon->Triangulate(local) && local->GetNumberOfIds() >= 3)
  {
    for (vtkIdType t = 0; t + 2 < local->GetNumberOfIds(); t += 3)
    {
      triangles->InsertNextCell(
        { ids[local->GetId(t)], ids[local->GetId(t + 1)], ids[local->GetId(t + 2)] });
    }
    return;
  }
  for (vtkIdType k = 1; k + 1 < size; ++k)
  {
    triangles->InsertNextCell({ ids[0], ids[k], ids[k + 1] });
  }
}

// Every other triangle of a strip runs the other way round; flipping its
// first two vertices gives all of them the orientation of the first.
void AddStrip(vtkIdType size, const vtkIdType* ids, vtkCellArray* triangles)
{
  for (vtkIdType k = 0; k + 2 < size; ++k)
  {
    vtkIdType a = ids[k], b = ids[k + 1];
    const vtkIdType c = ids[k + 2];
    if (k % 2)
    {
      std::swap(a, b);
    }
    if (a != b && b != c && a != c)
    {
      triangles->InsertNextCell({ a, b, c });
    }
  }
}
}

vtkSmartPointer<vtkCellArray> Triangulate(
  vtkPolyData* polygons, vtkPoints* points, std::vector<vtkIdType>& sources)
{
  vtkCellArray* faces = polygons->GetPolys();
  vtkCellArray* strips = polygons->GetStrips();
  const bool hasStrips = strips && strips->GetNumberOfCells() > 0;
  const vtkIdType faceCount = faces ? faces->GetNumberOfCells() : 0;
  if (!hasStrips && faces && faces->IsHomogeneous() == 3)
  {
    return faces; // already triangles: the common case, shared as it is
  }
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  // 32-bit storage where the input's is and the triangles' corners (at
  // most 3 per input corner) still fit in it.
  const auto corners = [](vtkCellArray* cells)
  { return cells ? cells->GetNumberOfConnectivityIds() : 0; };
  const bool narrow =
    (!faces || !faces->IsStorage64Bit()) && (!strips || !strips->IsStorage64Bit());
  if (narrow && 3 * (corners(faces) + corners(strips)) < std::numeric_limits<vtkTypeInt32>::max())
  {
    triangles->Use32BitStorage();
  }
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> local;
  std::vector<vtkIdType> sorted;
  vtkIdType size;
  const vtkIdType* ids;
  const auto addSources = [&](vtkIdType cell)
  { sources.resize(triangles->GetNumberOfCells(), cell); };
  if (faces)
  {
    auto cell = vtk::TakeSmartPointer(faces->NewIterator());
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
    {
      cell->GetCurrentCell(size, ids);
      if (size == 3)
      {
        triangles->InsertNextCell(3, ids);
      }
      else
      {
        AddPolygon(size, ids, points, polygon, local, sorted, triangles);
      }
      addSources(cell->GetCurrentCellId());
    }
  }
  if (hasStrips)
  {
    auto cell = vtk::TakeSmartPointer(strips->NewIterator());
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
    {
      cell->GetCurrentCell(size, ids);
      AddStrip(size, ids, triangles);
      addSources(faceCount + cell->GetCurrentCellId());
    }
  }
  return triangles;
}
}
