#include "shadelabFileVertices.h"

#include "shadelabTriangleMesh.h"

#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <cstdint>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace shadelab::normals
{
std::string FileVertices::Read(vtkPolyData* input)
{
  this->Weld.clear();
  this->Corners.clear();
  vtkAbstractArray* array = input->GetPointData()->GetAbstractArray(FileVertexArrayName);
  if (!array)
  {
    return "";
  }
  const vtkIdType points = input->GetNumberOfPoints();
  auto* ids = vtkIdTypeArray::SafeDownCast(array);
  if (!ids || ids->GetNumberOfComponents() != 1 || ids->GetNumberOfTuples() != points)
  {
    return std::string(FileVertexArrayName) + " is not one id per point";
  }
  std::vector<Id> first(points, -1);
  this->Weld.resize(points);
  for (vtkIdType p = 0; p < points; ++p)
  {
    const vtkIdType vertex = ids->GetValue(p);
    if (vertex < 0 || vertex >= points)
    {
      this->Weld.clear();
      return std::string(FileVertexArrayName) + " of point " + std::to_string(p) + " is " +
        std::to_string(vertex) + ", not a point's number";
    }
    if (first[vertex] < 0)
    {
      first[vertex] = static_cast<Id>(p);
    }
    this->Weld[p] = first[vertex];
  }
  return "";
}

void FileVertices::Welded(Id* triangles, vtkIdType count)
{
  this->Corners.assign(triangles, triangles + count);
  for (vtkIdType k = 0; k < count; ++k)
  {
    triangles[k] = this->Weld[triangles[k]];
  }
}

void FileVertices::FollowOrientation(const Id* oriented)
{
  for (std::size_t f = 0; f < this->Corners.size(); f += 3)
  {
    if (this->Weld[this->Corners[f + 1]] != oriented[f + 1])
    {
      std::swap(this->Corners[f + 1], this->Corners[f + 2]);
    }
  }
}

void FileVertices::Unweld(const Id* cornerPoint, vtkIdType points,
  vtkSmartPointer<vtkFloatArray>& normals, std::vector<Id>& corners,
  std::vector<vtkIdType>& source) const
{
  // The welded point whose normal each output point takes.
  std::vector<vtkIdType> normalOf(this->Weld.begin(), this->Weld.end());
  source.resize(points);
  std::iota(source.begin(), source.end(), 0);
  corners.resize(this->Corners.size());
  std::vector<bool> used(points, false);
  // Both ids are OpenMesh's ints: one 64-bit key per (input point, welded point).
  std::unordered_map<std::uint64_t, Id> copies;
  for (std::size_t k = 0; k < this->Corners.size(); ++k)
  {
    const Id p = this->Corners[k];
    const Id welded = cornerPoint[k];
    if (!used[p])
    {
      used[p] = true;
      normalOf[p] = welded;
    }
    if (normalOf[p] == welded)
    {
      corners[k] = p;
      continue;
    }
    const std::uint64_t key =
      static_cast<std::uint64_t>(p) << 32 | static_cast<std::uint32_t>(welded);
    const auto [copy, added] = copies.try_emplace(key, static_cast<Id>(source.size()));
    if (added)
    {
      source.push_back(p);
      normalOf.push_back(welded);
    }
    corners[k] = copy->second;
  }
  auto unwelded = vtkSmartPointer<vtkFloatArray>::New();
  unwelded->SetName(normals->GetName());
  unwelded->SetNumberOfComponents(3);
  unwelded->SetNumberOfTuples(static_cast<vtkIdType>(normalOf.size()));
  for (std::size_t i = 0; i < normalOf.size(); ++i)
  {
    unwelded->SetTypedTuple(static_cast<vtkIdType>(i), normals->GetPointer(3 * normalOf[i]));
  }
  normals = unwelded;
}
}
