#include "vtkShadelabOBJReader.h"

#include "shadelabMeshReadError.h"
#include "shadelabMtlParser.h"
#include "shadelabTextScanner.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <vector>

vtkStandardNewMacro(vtkShadelabOBJReader);

namespace
{
using shadelab::Quote;
using shadelab::TextScanner;

constexpr vtkIdType NoNormal = -1;

struct ObjData
{
  std::vector<double> Vertices; // x y z per v
  std::vector<float> Normals;   // x y z per vn
  std::vector<vtkIdType> FaceOffsets{ 0 };
  std::vector<vtkIdType> VertexIds; // 0-based, per corner
  std::vector<vtkIdType> NormalIds; // 0-based or NoNormal, per corner
  bool SomeCornersHaveNormals = false;
  bool SomeCornersLackNormals = false;
  // usemtl: each face's part, one part per material name in the order of
  // first use ("" for faces before the first usemtl); empty without usemtl.
  std::vector<int> FaceParts;
  std::vector<std::string> MaterialNames;
  int Part = 0;                       // the part of the faces read now
  std::vector<std::string> Libraries; // mtllib's files, as written
};

// A 1-based or negative (relative) OBJ index as a 0-based one.
vtkIdType Resolve(long long index, std::size_t defined, const char* kind, const char* kinds,
  const TextScanner& scanner)
{
  if (index == 0)
  {
    scanner.Fail(std::string("face refers to ") + kind + " 0 (OBJ counts from 1)");
  }
  const long long count = static_cast<long long>(defined);
  const long long resolved = index > 0 ? index - 1 : count + index;
  if (resolved < 0 || resolved >= count)
  {
    scanner.Fail(std::string("face refers to ") + kind + " " + std::to_string(index) +
      ", but only " + std::to_string(count) + " " + kinds + " are defined");
  }
  return static_cast<vtkIdType>(resolved);
}

// One corner: v, v/vt, v//vn or v/vt/vn. The vt index must be a number but
// is otherwise ignored, as texture coordinates are.
void ReadCorner(std::string_view token, ObjData& obj, const TextScanner& scanner)
{
  const char* p = token.data();
  const char* end = p + token.size();
  const auto malformed = [&] { scanner.Fail("malformed face vertex " + Quote(token)); };
  long long vertex = 0, texture = 0, normal = 0;
  bool hasNormal = false;
  auto result = std::from_chars(p, end, vertex);
  if (result.ec != std::errc())
  {
    malformed();
  }
  p = result.ptr;
  if (p != end)
  {
    if (*p++ != '/' || p == end)
    {
      malformed();
    }
    if (*p != '/')
    {
      result = std::from_chars(p, end, texture);
      if (result.ec != std::errc())
      {
        malformed();
      }
      p = result.ptr;
    }
    if (p != end)
    {
      if (*p++ != '/')
      {
        malformed();
      }
      result = std::from_chars(p, end, normal);
      if (result.ec != std::errc() || result.ptr != end)
      {
        malformed();
      }
      hasNormal = true;
    }
  }
  obj.VertexIds.push_back(Resolve(vertex, obj.Vertices.size() / 3, "vertex", "vertices", scanner));
  if (hasNormal)
  {
    obj.NormalIds.push_back(Resolve(normal, obj.Normals.size() / 3, "normal", "normals", scanner));
    obj.SomeCornersHaveNormals = true;
  }
  else
  {
    obj.NormalIds.push_back(NoNormal);
    obj.SomeCornersLackNormals = true;
  }
}

// usemtl NAME: the faces that follow are the part of that material.
void UseMaterial(const std::string& name, ObjData& obj)
{
  if (obj.MaterialNames.empty() && !obj.FaceParts.empty())
  {
    obj.MaterialNames.push_back(""); // the faces read so far: part 0, without a material
  }
  std::size_t part = 0;
  while (part < obj.MaterialNames.size() && obj.MaterialNames[part] != name)
  {
    ++part;
  }
  if (part == obj.MaterialNames.size())
  {
    obj.MaterialNames.push_back(name);
  }
  obj.Part = static_cast<int>(part);
}

// A statement's end: the line's end or a comment.
bool AtStatementEnd(std::string_view token)
{
  return token.empty() || token[0] == '#';
}

ObjData Parse(std::string_view text)
{
  ObjData obj;
  TextScanner scanner(text);
  while (scanner.NextLine())
  {
    const std::string_view keyword = scanner.NextToken();
    if (keyword == "v")
    {
      for (int c = 0; c < 3; ++c)
      {
        obj.Vertices.push_back(scanner.ReadDouble("vertex coordinate"));
      }
      double extra;
      for (auto token = scanner.NextToken(); !AtStatementEnd(token); token = scanner.NextToken())
      {
        if (!shadelab::ParseNumber(token, extra))
        {
          scanner.Fail("malformed number " + Quote(token) + " after a vertex");
        }
      }
    }
    else if (keyword == "vn")
    {
      for (int c = 0; c < 3; ++c)
      {
        obj.Normals.push_back(static_cast<float>(scanner.ReadDouble("normal component")));
      }
      const auto token = scanner.NextToken();
      if (!AtStatementEnd(token))
      {
        scanner.Fail("unexpected " + Quote(token) + " after a normal");
      }
    }
    else if (keyword == "mtllib")
    {
      for (auto name = scanner.NextToken(); !AtStatementEnd(name); name = scanner.NextToken())
      {
        obj.Libraries.emplace_back(name);
      }
    }
    else if (keyword == "usemtl")
    {
      const auto name = scanner.NextToken();
      if (AtStatementEnd(name))
      {
        scanner.Fail("usemtl without a material name");
      }
      UseMaterial(std::string(name), obj);
    }
    else if (keyword == "f")
    {
      const std::size_t first = obj.VertexIds.size();
      for (auto token = scanner.NextToken(); !AtStatementEnd(token); token = scanner.NextToken())
      {
        ReadCorner(token, obj, scanner);
      }
      const std::size_t corners = obj.VertexIds.size() - first;
      if (corners < 3)
      {
        scanner.Fail("face has " + std::to_string(corners) + " vertices, at least 3 are needed");
      }
      obj.FaceOffsets.push_back(static_cast<vtkIdType>(obj.VertexIds.size()));
      obj.FaceParts.push_back(obj.Part);
    }
  }
  if (obj.MaterialNames.empty())
  {
    obj.FaceParts.clear();
  }
  return obj;
}

// Every corner has a normal: one point per distinct (v, vn) pair, point i
// keeping vertex i with the normal of its first use.
void SplitByNormal(ObjData& obj, shadelab::PolygonMesh& mesh)
{
  const std::size_t vertexCount = obj.Vertices.size() / 3;
  const std::uint64_t normalCount = obj.Normals.size() / 3;
  std::vector<vtkIdType> pointNormal(vertexCount, NoNormal);
  // Key v * normalCount + vn is unique per pair; both counts are bounded by
  // the file's size, so it cannot overflow.
  std::unordered_map<std::uint64_t, vtkIdType> splitPoints;
  mesh.Points = std::move(obj.Vertices);
  for (std::size_t c = 0; c < obj.VertexIds.size(); ++c)
  {
    const vtkIdType v = obj.VertexIds[c];
    const vtkIdType n = obj.NormalIds[c];
    if (pointNormal[v] == NoNormal)
    {
      pointNormal[v] = n;
    }
    else if (pointNormal[v] != n)
    {
      const auto [it, added] = splitPoints.try_emplace(
        static_cast<std::uint64_t>(v) * normalCount + static_cast<std::uint64_t>(n),
        static_cast<vtkIdType>(pointNormal.size()));
      if (added)
      {
        mesh.Points.insert(mesh.Points.end(),
          { mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] });
        pointNormal.push_back(n);
      }
      obj.VertexIds[c] = it->second;
    }
  }
  mesh.Normals.reserve(3 * pointNormal.size());
  for (const vtkIdType n : pointNormal)
  {
    for (int k = 0; k < 3; ++k)
    {
      mesh.Normals.push_back(n == NoNormal ? 0.0f : obj.Normals[3 * n + k]);
    }
  }
}

// Each part's material: its name's first definition in the libraries'
// materials (in their order), or none.
std::vector<shadelab::PartMaterial> PartMaterials(
  const std::vector<std::string>& names, const std::vector<shadelab::Material>& library)
{
  std::vector<shadelab::PartMaterial> parts;
  for (const std::string& name : names)
  {
    shadelab::PartMaterial part;
    part.Name = name;
    for (std::size_t m = 0; m < library.size() && !name.empty(); ++m)
    {
      if (library[m].Name == name)
      {
        part.Index = static_cast<int>(m);
        part.Coefficients = library[m];
        break;
      }
    }
    parts.push_back(part);
  }
  return parts;
}
}

void vtkShadelabOBJReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  ObjData obj = Parse(ReadFileBytes(fileName));
  shadelab::PolygonMesh mesh;
  if (!this->ReadNormals)
  {
    mesh.Points = std::move(obj.Vertices);
  }
  else if (obj.SomeCornersHaveNormals && !obj.SomeCornersLackNormals)
  {
    SplitByNormal(obj, mesh);
  }
  else
  {
    if (obj.SomeCornersHaveNormals)
    {
      vtkWarningMacro(<< "some faces have no vn normals, so the file's normals are ignored");
    }
    mesh.Points = std::move(obj.Vertices);
  }
  mesh.FaceOffsets = std::move(obj.FaceOffsets);
  mesh.FaceIds = std::move(obj.VertexIds);
  mesh.Parts = std::move(obj.FaceParts);
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(mesh), triangles, 1);
  if (!obj.MaterialNames.empty())
  {
    shadelab::AddPartMaterials(
      PartMaterials(obj.MaterialNames, this->ReadLibraries(fileName, obj.Libraries)), triangles);
  }
}

std::vector<shadelab::Material> vtkShadelabOBJReader::ReadLibraries(
  const char* fileName, const std::vector<std::string>& libraries)
{
  std::vector<shadelab::Material> materials;
  const std::filesystem::path folder = std::filesystem::path(fileName).parent_path();
  for (const std::string& library : libraries)
  {
    std::string text;
    try
    {
      text = ReadFileBytes((folder / library).c_str());
    }
    catch (const shadelab::MeshReadError& e)
    {
      // OBJ files from the web often come without their MTL: drawn anyway.
      vtkWarningMacro(<< "material library " << shadelab::Quote(library) << ": " << e.what()
                      << "; its materials are the default");
      continue;
    }
    try
    {
      for (shadelab::Material& m : shadelab::ParseMtl(text))
      {
        materials.push_back(std::move(m));
      }
    }
    catch (const shadelab::MeshReadError& e)
    {
      throw shadelab::MeshReadError(
        "material library " + shadelab::Quote(library) + " " + e.what());
    }
  }
  return materials;
}
