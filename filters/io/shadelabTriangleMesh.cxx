#include "shadelabTriangleMesh.h"

#include "shadelabMeshReadError.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolygon.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace shadelab
{
namespace
{
vtkSmartPointer<vtkCellArray> MakeCells(
  const std::vector<vtkIdType>& offsets, const std::vector<vtkIdType>& ids)
{
  vtkNew<vtkIdTypeArray> offsetArray;
  offsetArray->SetNumberOfValues(static_cast<vtkIdType>(offsets.size()));
  std::copy(offsets.begin(), offsets.end(), offsetArray->GetPointer(0));
  vtkNew<vtkIdTypeArray> idArray;
  idArray->SetNumberOfValues(static_cast<vtkIdType>(ids.size()));
  std::copy(ids.begin(), ids.end(), idArray->GetPointer(0));
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsetArray, idArray);
  return cells;
}

std::string Number(vtkIdType index, vtkIdType firstNumber)
{
  return std::to_string(index + firstNumber);
}

const char* NonFinite(double value)
{
  return std::isnan(value) ? "NaN" : "infinite";
}

vtkSmartPointer<vtkDoubleArray> DoublePoints(vtkPolyData* polygons, vtkIdType firstNumber)
{
  vtkPoints* points = polygons->GetPoints();
  vtkSmartPointer<vtkDoubleArray> xyz =
    points ? vtkDoubleArray::SafeDownCast(points->GetData()) : nullptr;
  if (!xyz)
  {
    const vtkIdType count = points ? points->GetNumberOfPoints() : 0;
    xyz = vtkSmartPointer<vtkDoubleArray>::New();
    xyz->SetNumberOfComponents(3);
    xyz->SetNumberOfTuples(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      xyz->SetTuple(i, points->GetPoint(i));
    }
  }
  const double* values = xyz->GetPointer(0);
  for (vtkIdType i = 0; i < 3 * xyz->GetNumberOfTuples(); ++i)
  {
    if (!std::isfinite(values[i]))
    {
      throw MeshReadError(
        std::string(NonFinite(values[i])) + " coordinate in vertex " + Number(i / 3, firstNumber));
    }
  }
  return xyz;
}

vtkSmartPointer<vtkFloatArray> FloatNormals(
  vtkPolyData* polygons, vtkIdType pointCount, vtkIdType firstNumber)
{
  vtkDataArray* normals = polygons->GetPointData()->GetNormals();
  if (!normals)
  {
    return nullptr;
  }
  if (normals->GetNumberOfComponents() != 3 || normals->GetNumberOfTuples() != pointCount)
  {
    throw MeshReadError("the normals are " + std::to_string(normals->GetNumberOfTuples()) +
      " tuples of " + std::to_string(normals->GetNumberOfComponents()) +
      " components, not one 3-vector for each of the " + std::to_string(pointCount) + " vertices");
  }
  auto floats = vtkSmartPointer<vtkFloatArray>::New();
  floats->SetName("Normals");
  floats->SetNumberOfComponents(3);
  floats->SetNumberOfTuples(pointCount);
  for (vtkIdType i = 0; i < pointCount; ++i)
  {
    const double* n = normals->GetTuple3(i);
    for (int c = 0; c < 3; ++c)
    {
      if (!std::isfinite(n[c]))
      {
        throw MeshReadError(
          std::string(NonFinite(n[c])) + " normal in vertex " + Number(i, firstNumber));
      }
    }
    floats->SetTuple3(i, n[0], n[1], n[2]);
  }
  return floats;
}

void CheckCells(vtkCellArray* cells, const char* kind, vtkIdType pointCount, vtkIdType firstNumber)
{
  if (!cells)
  {
    return;
  }
  auto cell = vtk::TakeSmartPointer(cells->NewIterator());
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    cell->GetCurrentCell(size, ids);
    const auto name = [&]
    { return std::string(kind) + " " + Number(cell->GetCurrentCellId(), firstNumber); };
    if (size < 3)
    {
      throw MeshReadError(
        name() + " has " + std::to_string(size) + " vertices, at least 3 are needed");
    }
    for (vtkIdType k = 0; k < size; ++k)
    {
      if (ids[k] < 0 || ids[k] >= pointCount)
      {
        throw MeshReadError(name() + " refers to vertex " + Number(ids[k], firstNumber) +
          ", but only " + std::to_string(pointCount) + " vertices are defined");
      }
    }
  }
}

// Ear cutting keeps the polygon's orientation and handles concave polygons;
// where it gives up (zero area, repeated or collinear vertices) a fan keeps
// the face's vertices connected, with degenerate triangles as the face was.
void AddPolygon(vtkIdType size, const vtkIdType* ids, vtkPoints* points, vtkPolygon* polygon,
  vtkIdList* local, vtkCellArray* triangles)
{
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

vtkSmartPointer<vtkCellArray> Triangulate(vtkPolyData* polygons, vtkPoints* points)
{
  vtkCellArray* faces = polygons->GetPolys();
  vtkCellArray* strips = polygons->GetStrips();
  const bool hasStrips = strips && strips->GetNumberOfCells() > 0;
  if (!hasStrips && faces && faces->IsHomogeneous() == 3)
  {
    return faces; // already triangles: the common case, shared as it is
  }
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  vtkNew<vtkPolygon> polygon;
  vtkNew<vtkIdList> local;
  vtkIdType size;
  const vtkIdType* ids;
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
        AddPolygon(size, ids, points, polygon, local, triangles);
      }
    }
  }
  if (hasStrips)
  {
    auto cell = vtk::TakeSmartPointer(strips->NewIterator());
    for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
    {
      cell->GetCurrentCell(size, ids);
      AddStrip(size, ids, triangles);
    }
  }
  return triangles;
}
}

vtkSmartPointer<vtkPolyData> ToPolyData(const PolygonMesh& mesh)
{
  vtkNew<vtkDoubleArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(static_cast<vtkIdType>(mesh.Points.size() / 3));
  std::copy(mesh.Points.begin(), mesh.Points.end(), xyz->GetPointer(0));
  vtkNew<vtkPoints> points;
  points->SetData(xyz);

  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  if (!mesh.Normals.empty())
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    normals->SetNumberOfTuples(static_cast<vtkIdType>(mesh.Normals.size() / 3));
    std::copy(mesh.Normals.begin(), mesh.Normals.end(), normals->GetPointer(0));
    data->GetPointData()->SetNormals(normals);
  }
  data->SetPolys(MakeCells(mesh.FaceOffsets, mesh.FaceIds));
  data->SetStrips(MakeCells(mesh.StripOffsets, mesh.StripIds));
  return data;
}

void MakeTriangleMesh(vtkPolyData* polygons, vtkPolyData* triangles, vtkIdType firstNumber)
{
  vtkSmartPointer<vtkDoubleArray> xyz = DoublePoints(polygons, firstNumber);
  const vtkIdType pointCount = xyz->GetNumberOfTuples();
  vtkSmartPointer<vtkFloatArray> normals = FloatNormals(polygons, pointCount, firstNumber);
  CheckCells(polygons->GetPolys(), "face", pointCount, firstNumber);
  CheckCells(polygons->GetStrips(), "triangle strip", pointCount, firstNumber);

  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  vtkSmartPointer<vtkCellArray> cells = Triangulate(polygons, points);
  if (cells->GetNumberOfCells() == 0)
  {
    throw MeshReadError("no triangles");
  }
  triangles->Initialize();
  triangles->SetPoints(points);
  triangles->SetPolys(cells);
  if (normals)
  {
    triangles->GetPointData()->SetNormals(normals);
  }
}
}
