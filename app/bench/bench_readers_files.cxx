#include "bench/bench_readers_files.h"

#include "core/output_file.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

namespace shadelab::bench_readers
{
namespace
{
std::vector<std::uint32_t> TriangleIds(vtkPolyData* mesh)
{
  std::vector<std::uint32_t> ids;
  ids.reserve(3 * mesh->GetNumberOfPolys());
  auto cell = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cell->GoToFirstCell(); !cell->IsDoneWithTraversal(); cell->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* corners;
    cell->GetCurrentCell(size, corners);
    for (vtkIdType k = 0; k < size; ++k)
    {
      ids.push_back(static_cast<std::uint32_t>(corners[k]));
    }
  }
  return ids;
}

template <typename T>
void Append(std::string& bytes, const std::vector<T>& values)
{
  const std::size_t at = bytes.size();
  bytes.resize(at + values.size() * sizeof(T));
  std::memcpy(bytes.data() + at, values.data(), values.size() * sizeof(T)); // little-endian hosts
}

std::vector<float> Floats(vtkDataArray* array)
{
  std::vector<float> values(3 * array->GetNumberOfTuples());
  for (vtkIdType i = 0; i < array->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      values[3 * i + c] = static_cast<float>(array->GetComponent(i, c));
    }
  }
  return values;
}

void Pad(std::string& bytes, char with)
{
  bytes.resize((bytes.size() + 3) / 4 * 4, with);
}

void PutUInt32(std::string& bytes, std::uint32_t value)
{
  bytes.append(reinterpret_cast<const char*>(&value), sizeof value);
}
}

std::string WriteOff(vtkPolyData* mesh, const std::string& path)
{
  std::string text = "OFF\n" + std::to_string(mesh->GetNumberOfPoints()) + " " +
    std::to_string(mesh->GetNumberOfPolys()) + " 0\n";
  char line[128];
  double p[3];
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    mesh->GetPoint(i, p);
    text.append(line, std::snprintf(line, sizeof line, "%.9g %.9g %.9g\n", p[0], p[1], p[2]));
  }
  const std::vector<std::uint32_t> ids = TriangleIds(mesh);
  for (std::size_t t = 0; t < ids.size(); t += 3)
  {
    text.append(
      line, std::snprintf(line, sizeof line, "3 %u %u %u\n", ids[t], ids[t + 1], ids[t + 2]));
  }
  return WriteFile(path + ".off", text);
}

std::string WriteGltf(vtkPolyData* mesh, const std::string& path, bool binary)
{
  const std::vector<float> positions = Floats(mesh->GetPoints()->GetData());
  const std::vector<float> normals = Floats(mesh->GetPointData()->GetNormals());
  const std::vector<std::uint32_t> ids = TriangleIds(mesh);
  std::vector<float> low(3, std::numeric_limits<float>::max());
  std::vector<float> high(3, std::numeric_limits<float>::lowest());
  for (std::size_t i = 0; i < positions.size(); ++i)
  {
    low[i % 3] = std::min(low[i % 3], positions[i]);
    high[i % 3] = std::max(high[i % 3], positions[i]);
  }
  std::string buffer;
  Append(buffer, positions);
  Append(buffer, normals);
  Append(buffer, ids);
  const std::size_t vertexBytes = positions.size() * sizeof(float);
  const auto count = static_cast<std::size_t>(mesh->GetNumberOfPoints());

  using Json = nlohmann::json;
  Json document = { { "asset",
                      { { "version", "2.0" }, { "generator", "shadelab-bench-readers" } } },
    { "scene", 0 }, { "scenes", { { { "nodes", { 0 } } } } }, { "nodes", { { { "mesh", 0 } } } },
    { "meshes",
      { { { "primitives",
        { { { "attributes", { { "POSITION", 0 }, { "NORMAL", 1 } } }, { "indices", 2 } } } } } } },
    { "accessors",
      { { { "bufferView", 0 }, { "componentType", 5126 }, { "count", count }, { "type", "VEC3" },
          { "min", low }, { "max", high } },
        { { "bufferView", 1 }, { "componentType", 5126 }, { "count", count }, { "type", "VEC3" } },
        { { "bufferView", 2 }, { "componentType", 5125 }, { "count", ids.size() },
          { "type", "SCALAR" } } } },
    { "bufferViews",
      { { { "buffer", 0 }, { "byteOffset", 0 }, { "byteLength", vertexBytes },
          { "target", 34962 } },
        { { "buffer", 0 }, { "byteOffset", vertexBytes }, { "byteLength", vertexBytes },
          { "target", 34962 } },
        { { "buffer", 0 }, { "byteOffset", 2 * vertexBytes },
          { "byteLength", ids.size() * sizeof(std::uint32_t) }, { "target", 34963 } } } },
    { "buffers", { { { "byteLength", buffer.size() } } } } };
  if (!binary)
  {
    const std::string bin = path + ".bin";
    document["buffers"][0]["uri"] = bin.substr(bin.find_last_of('/') + 1);
    const std::string error = WriteFile(bin, buffer);
    return error.empty() ? WriteFile(path + ".gltf", document.dump()) : error;
  }
  std::string json = document.dump();
  Pad(json, ' ');
  Pad(buffer, '\0');
  std::string glb;
  PutUInt32(glb, 0x46546C67); // "glTF"
  PutUInt32(glb, 2);
  PutUInt32(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + buffer.size()));
  PutUInt32(glb, static_cast<std::uint32_t>(json.size()));
  PutUInt32(glb, 0x4E4F534A); // "JSON"
  glb += json;
  PutUInt32(glb, static_cast<std::uint32_t>(buffer.size()));
  PutUInt32(glb, 0x004E4942); // "BIN"
  glb += buffer;
  return WriteFile(path + ".glb", glb);
}
}
