#include "shadelabTriangleMesh.h"

#include "shadelabMeshReadError.h"
#include "shadelabTriangulation.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTypeInt32Array.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

namespace shadelab
{
namespace
{
// Frees a parser's array once VTK's has its values: a large mesh is then
// never held twice over.
template <typename Value>
void Release(std::vector<Value>& values)
{
  std::vector<Value>().swap(values);
}

// A parser's values as a VTK array of that type (vtkFloatArray for float...),
// the vector freed.
template <typename Array, typename Value>
vtkSmartPointer<Array> MakeArray(const char* name, int components, std::vector<Value>& values)
{
  auto array = vtkSmartPointer<Array>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size() / components));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  Release(values);
  return array;
}

// The ids in 32 bits, checked as they are copied (one pass); null, and the
// vector kept, where one does not fit.
vtkSmartPointer<vtkTypeInt32Array> Narrowed(std::vector<vtkIdType>& ids)
{
  auto array = vtkSmartPointer<vtkTypeInt32Array>::New();
  array->SetNumberOfValues(static_cast<vtkIdType>(ids.size()));
  vtkTypeInt32* out = array->GetPointer(0);
  for (const vtkIdType id : ids)
  {
    if (id < std::numeric_limits<vtkTypeInt32>::min() ||
      id > std::numeric_limits<vtkTypeInt32>::max())
    {
      return nullptr;
    }
    *out++ = static_cast<vtkTypeInt32>(id);
  }
  Release(ids);
  return array;
}

// A parser's cells, taken over: 32-bit storage (half the memory) where
// every offset and id fits in it, even those out of range (checked later,
// and named in their error as the file has them); 64-bit otherwise. The
// offsets go first, so that the largest vector, the ids, is freed before
// its copy's peer is made (as it was with two passes).
vtkSmartPointer<vtkCellArray> TakeCells(
  std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids)
{
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  // The offsets grow, so the last is the largest.
  if (offsets.back() <= std::numeric_limits<vtkTypeInt32>::max())
  {
    auto offsets32 = MakeArray<vtkTypeInt32Array>(nullptr, 1, offsets);
    if (vtkSmartPointer<vtkTypeInt32Array> ids32 = Narrowed(ids))
    {
      cells->SetData(offsets32, ids32);
      return cells;
    }
    // An id beyond 32 bits (an error, named later): the offsets widened back.
    auto offsets64 = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets64->DeepCopy(offsets32);
    cells->SetData(offsets64, MakeArray<vtkIdTypeArray>(nullptr, 1, ids));
    return cells;
  }
  cells->SetData(
    MakeArray<vtkIdTypeArray>(nullptr, 1, offsets), MakeArray<vtkIdTypeArray>(nullptr, 1, ids));
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

template <typename Value>
void CheckFinite(const Value* values, vtkIdType count, vtkIdType firstNumber)
{
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      throw MeshReadError(
        std::string(NonFinite(values[i])) + " coordinate in vertex " + Number(i / 3, firstNumber));
    }
  }
}

// The points as float where they are (a file's 32-bit coordinates), else
// as double; checked finite.
vtkSmartPointer<vtkDataArray> CheckedPoints(vtkPolyData* polygons, vtkIdType firstNumber)
{
  vtkPoints* points = polygons->GetPoints();
  if (auto* xyz = points ? vtkFloatArray::FastDownCast(points->GetData()) : nullptr)
  {
    CheckFinite(xyz->GetPointer(0), 3 * xyz->GetNumberOfTuples(), firstNumber);
    return xyz;
  }
  vtkSmartPointer<vtkDoubleArray> xyz =
    points ? vtkDoubleArray::FastDownCast(points->GetData()) : nullptr;
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
  CheckFinite(xyz->GetPointer(0), 3 * xyz->GetNumberOfTuples(), firstNumber);
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

// A point attribute that goes along: the float array of that name with
// `components` per point, its values finite; null where there is none.
vtkSmartPointer<vtkFloatArray> PointAttribute(vtkPolyData* polygons, const char* name,
  int components, const char* what, vtkIdType pointCount, vtkIdType firstNumber)
{
  auto* array = vtkFloatArray::SafeDownCast(polygons->GetPointData()->GetArray(name));
  if (!array || array->GetNumberOfComponents() != components ||
    array->GetNumberOfTuples() != pointCount)
  {
    return nullptr;
  }
  const float* values = array->GetPointer(0);
  for (vtkIdType i = 0; i < components * pointCount; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      throw MeshReadError(std::string(NonFinite(values[i])) + " " + what + " in vertex " +
        Number(i / components, firstNumber));
    }
  }
  return array;
}

// The points' file vertices where they go along: an id array of one value
// per point, each a point's number; null otherwise.
vtkSmartPointer<vtkIdTypeArray> FileVertices(vtkPolyData* polygons, vtkIdType pointCount)
{
  auto* array =
    vtkIdTypeArray::SafeDownCast(polygons->GetPointData()->GetArray(FileVertexArrayName));
  if (!array || array->GetNumberOfComponents() != 1 || array->GetNumberOfTuples() != pointCount)
  {
    return nullptr;
  }
  const vtkIdType* values = array->GetPointer(0);
  const bool inRange = std::all_of(
    values, values + pointCount, [pointCount](vtkIdType v) { return v >= 0 && v < pointCount; });
  return inRange ? array : nullptr;
}

// Each cell's size and ids, read in place from either storage (an
// iterator would copy every 32-bit cell into a list first).
struct CellCheck
{
  template <typename CellState>
  void operator()(
    CellState& state, const char* kind, vtkIdType pointCount, vtkIdType firstNumber) const
  {
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const auto* ids = state.GetConnectivity()->GetPointer(0);
    const vtkIdType cells = state.GetNumberOfCells();
    for (vtkIdType c = 0; c < cells; ++c)
    {
      const auto name = [&] { return std::string(kind) + " " + Number(c, firstNumber); };
      const vtkIdType size = offsets[c + 1] - offsets[c];
      if (size < 3)
      {
        throw MeshReadError(
          name() + " has " + std::to_string(size) + " vertices, at least 3 are needed");
      }
      for (auto k = offsets[c]; k < offsets[c + 1]; ++k)
      {
        if (ids[k] < 0 || ids[k] >= pointCount)
        {
          throw MeshReadError(name() + " refers to vertex " + Number(ids[k], firstNumber) +
            ", but only " + std::to_string(pointCount) + " vertices are defined");
        }
      }
    }
  }
};

void CheckCells(vtkCellArray* cells, const char* kind, vtkIdType pointCount, vtkIdType firstNumber)
{
  if (cells)
  {
    cells->Visit(CellCheck{}, kind, pointCount, firstNumber);
  }
}

// The part of each triangle from that of its face or strip; null where the
// polygons have no int array of parts, one per cell.
vtkSmartPointer<vtkIntArray> TriangleParts(
  vtkPolyData* polygons, const std::vector<vtkIdType>& sources)
{
  vtkSmartPointer<vtkIntArray> parts =
    vtkIntArray::SafeDownCast(polygons->GetCellData()->GetArray(PartArrayName));
  const vtkIdType cells = (polygons->GetPolys() ? polygons->GetPolys()->GetNumberOfCells() : 0) +
    (polygons->GetStrips() ? polygons->GetStrips()->GetNumberOfCells() : 0);
  if (!parts || parts->GetNumberOfComponents() != 1 || parts->GetNumberOfTuples() != cells)
  {
    return nullptr;
  }
  if (sources.empty())
  {
    return parts; // one triangle per face
  }
  auto result = vtkSmartPointer<vtkIntArray>::New();
  result->SetName(PartArrayName);
  result->SetNumberOfValues(static_cast<vtkIdType>(sources.size()));
  for (std::size_t t = 0; t < sources.size(); ++t)
  {
    result->SetValue(static_cast<vtkIdType>(t), parts->GetValue(sources[t]));
  }
  return result;
}
}

vtkSmartPointer<vtkPolyData> ToPolyData(PolygonMesh&& mesh)
{
  vtkNew<vtkPoints> points;
  if (mesh.FloatPoints)
  {
    points->SetData(MakeArray<vtkFloatArray>(nullptr, 3, mesh.Points));
  }
  else
  {
    points->SetData(MakeArray<vtkDoubleArray>(nullptr, 3, mesh.Points));
  }

  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  if (!mesh.Normals.empty())
  {
    data->GetPointData()->SetNormals(MakeArray<vtkFloatArray>("Normals", 3, mesh.Normals));
  }
  if (!mesh.Colors.empty())
  {
    data->GetPointData()->AddArray(MakeArray<vtkFloatArray>(ColorsArrayName, 4, mesh.Colors));
  }
  if (!mesh.TextureCoordinates.empty())
  {
    data->GetPointData()->SetTCoords(
      MakeArray<vtkFloatArray>(TextureCoordinatesArrayName, 2, mesh.TextureCoordinates));
  }
  if (!mesh.FileVertices.empty())
  {
    data->GetPointData()->AddArray(
      MakeArray<vtkIdTypeArray>(FileVertexArrayName, 1, mesh.FileVertices));
  }
  data->SetPolys(TakeCells(mesh.FaceOffsets, mesh.FaceIds));
  data->SetStrips(TakeCells(mesh.StripOffsets, mesh.StripIds));
  if (!mesh.Parts.empty())
  {
    data->GetCellData()->AddArray(MakeArray<vtkIntArray>(PartArrayName, 1, mesh.Parts));
  }
  return data;
}

void MakeTriangleMesh(vtkPolyData* polygons, vtkPolyData* triangles, vtkIdType firstNumber)
{
  vtkSmartPointer<vtkDataArray> xyz = CheckedPoints(polygons, firstNumber);
  const vtkIdType pointCount = xyz->GetNumberOfTuples();
  vtkSmartPointer<vtkFloatArray> normals = FloatNormals(polygons, pointCount, firstNumber);
  vtkSmartPointer<vtkFloatArray> colors =
    PointAttribute(polygons, ColorsArrayName, 4, "colour", pointCount, firstNumber);
  vtkSmartPointer<vtkFloatArray> textureCoordinates = PointAttribute(
    polygons, TextureCoordinatesArrayName, 2, "texture coordinate", pointCount, firstNumber);
  vtkSmartPointer<vtkIdTypeArray> fileVertices = FileVertices(polygons, pointCount);
  CheckCells(polygons->GetPolys(), "face", pointCount, firstNumber);
  CheckCells(polygons->GetStrips(), "triangle strip", pointCount, firstNumber);

  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  std::vector<vtkIdType> sources;
  vtkSmartPointer<vtkCellArray> cells = Triangulate(polygons, points, sources);
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
  if (colors)
  {
    triangles->GetPointData()->AddArray(colors);
  }
  if (textureCoordinates)
  {
    triangles->GetPointData()->SetTCoords(textureCoordinates);
  }
  if (fileVertices)
  {
    triangles->GetPointData()->AddArray(fileVertices);
  }
  if (vtkSmartPointer<vtkIntArray> parts = TriangleParts(polygons, sources))
  {
    triangles->GetCellData()->AddArray(parts);
  }
}
}
