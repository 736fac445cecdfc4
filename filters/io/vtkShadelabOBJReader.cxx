#include "vtkShadelabOBJReader.h"

#include "shadelabCheckedFile.h"
#include "shadelabMeshReadError.h"
#include "shadelabMtlParser.h"
#include "shadelabObjVertices.h"
#include "shadelabPartMaterials.h"
#include "shadelabTextScanner.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkShadelabOBJReader);

namespace
{
using shadelab::Quote;
using shadelab::TextScanner;

using shadelab::ObjNoIndex;

struct ObjData
{
  shadelab::ObjCorners Corners; // v, vt, vn and the faces' corners
  std::vector<vtkIdType> FaceOffsets{ 0 };
  bool SomeCornersHaveTexture = false;
  bool SomeCornersLackTexture = false;
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

// One corner: v, v/vt, v//vn or v/vt/vn.
void ReadCorner(std::string_view token, ObjData& obj, const TextScanner& scanner)
{
  const char* p = token.data();
  const char* end = p + token.size();
  const auto malformed = [&] { scanner.Fail("malformed face vertex " + Quote(token)); };
  long long vertex = 0, texture = 0, normal = 0;
  bool hasTexture = false, hasNormal = false;
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
      hasTexture = true;
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
  obj.Corners.VertexIds.push_back(
    Resolve(vertex, obj.Corners.Vertices.size() / 3, "vertex", "vertices", scanner));
  obj.Corners.TextureIds.push_back(hasTexture
      ? Resolve(texture, obj.Corners.TextureCoordinates.size() / 2, "texture coordinate",
          "texture coordinates", scanner)
      : ObjNoIndex);
  obj.Corners.NormalIds.push_back(hasNormal
      ? Resolve(normal, obj.Corners.Normals.size() / 3, "normal", "normals", scanner)
      : ObjNoIndex);
  (hasTexture ? obj.SomeCornersHaveTexture : obj.SomeCornersLackTexture) = true;
  (hasNormal ? obj.SomeCornersHaveNormals : obj.SomeCornersLackNormals) = true;
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

// vt u [v [w]]: v is 0 where the file leaves it out, w (depth) is ignored.
void ReadTextureCoordinate(TextScanner& scanner, ObjData& obj)
{
  double values[3] = { scanner.ReadDouble("texture coordinate"), 0, 0 };
  int count = 1;
  for (auto token = scanner.NextToken(); !AtStatementEnd(token); token = scanner.NextToken())
  {
    if (count == 3)
    {
      scanner.Fail("unexpected " + Quote(token) + " after a texture coordinate");
    }
    if (!shadelab::ParseNumber(token, values[count++]))
    {
      scanner.Fail("malformed texture coordinate " + Quote(token));
    }
  }
  if (!std::isfinite(values[0]) || !std::isfinite(values[1]))
  {
    scanner.Fail("non-finite texture coordinate");
  }
  obj.Corners.TextureCoordinates.insert(obj.Corners.TextureCoordinates.end(),
    { static_cast<float>(values[0]), static_cast<float>(values[1]) });
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
        obj.Corners.Vertices.push_back(scanner.ReadDouble("vertex coordinate"));
      }
      // w, or (the common extension) r g b: the colour kept, anything else read and dropped.
      double extra[3];
      int extras = 0;
      for (auto token = scanner.NextToken(); !AtStatementEnd(token); token = scanner.NextToken())
      {
        double& value = extra[std::min(extras++, 2)];
        if (!shadelab::ParseNumber(token, value))
        {
          scanner.Fail("malformed number " + Quote(token) + " after a vertex");
        }
      }
      if (extras == 3)
      {
        obj.Corners.Colors.insert(obj.Corners.Colors.end(),
          { static_cast<float>(extra[0]), static_cast<float>(extra[1]),
            static_cast<float>(extra[2]), 1.0f });
      }
    }
    else if (keyword == "vt")
    {
      ReadTextureCoordinate(scanner, obj);
    }
    else if (keyword == "vn")
    {
      for (int c = 0; c < 3; ++c)
      {
        obj.Corners.Normals.push_back(static_cast<float>(scanner.ReadDouble("normal component")));
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
      const std::size_t first = obj.Corners.VertexIds.size();
      for (auto token = scanner.NextToken(); !AtStatementEnd(token); token = scanner.NextToken())
      {
        ReadCorner(token, obj, scanner);
      }
      const std::size_t corners = obj.Corners.VertexIds.size() - first;
      if (corners < 3)
      {
        scanner.Fail("face has " + std::to_string(corners) + " vertices, at least 3 are needed");
      }
      obj.FaceOffsets.push_back(static_cast<vtkIdType>(obj.Corners.VertexIds.size()));
      obj.FaceParts.push_back(obj.Part);
    }
  }
  if (obj.MaterialNames.empty())
  {
    obj.FaceParts.clear();
  }
  return obj;
}

// A map of an MTL material as a texture of the mesh: its file resolved
// against the MTL's folder, repeated (or clamped) and bilinear, as OBJ's
// images are drawn; -1 without a map.
int MapTexture(const shadelab::MtlMap& map, std::vector<shadelab::Texture>& textures)
{
  if (map.File.empty())
  {
    return -1;
  }
  shadelab::Texture texture;
  texture.Source = map.File;
  texture.WrapS = texture.WrapT = map.Clamp ? shadelab::gl::ClampToEdge : shadelab::gl::Repeat;
  return shadelab::AddTexture(textures, std::move(texture));
}

// Each part's material: its name's first definition in the libraries'
// materials (in their order), or none; with the textures of its maps.
std::vector<shadelab::PartMaterial> PartMaterials(const std::vector<std::string>& names,
  const std::vector<shadelab::MtlMaterial>& library, std::vector<shadelab::Texture>& textures)
{
  std::vector<shadelab::PartMaterial> parts;
  for (const std::string& name : names)
  {
    shadelab::PartMaterial part;
    part.Name = name;
    for (std::size_t m = 0; m < library.size() && !name.empty(); ++m)
    {
      if (library[m].Coefficients.Name == name)
      {
        part.Index = static_cast<int>(m);
        part.Coefficients = library[m].Coefficients;
        part.KdTexture = MapTexture(library[m].KdMap, textures);
        part.KaTexture = MapTexture(library[m].KaMap, textures);
        part.NormalTexture = MapTexture(library[m].NormalMap, textures);
        part.NormalScale = library[m].NormalMap.Scale;
        part.NormalFromBump = library[m].NormalFromBump;
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
  const bool texture = obj.SomeCornersHaveTexture;
  if (texture && obj.SomeCornersLackTexture)
  {
    vtkWarningMacro(<< "some faces have no vt texture coordinates; their vertices get 0 0");
  }
  const bool normals =
    this->ReadNormals && obj.SomeCornersHaveNormals && !obj.SomeCornersLackNormals;
  if (this->ReadNormals && obj.SomeCornersHaveNormals && obj.SomeCornersLackNormals)
  {
    vtkWarningMacro(<< "some faces have no vn normals, so the file's normals are ignored");
  }
  if (!obj.Corners.Colors.empty() &&
    3 * obj.Corners.Colors.size() != 4 * obj.Corners.Vertices.size())
  {
    vtkWarningMacro(<< "some vertices have no r g b colour, so the file's colours are ignored");
    obj.Corners.Colors.clear();
  }
  shadelab::PolygonMesh mesh;
  shadelab::SplitVertices(obj.Corners, texture, normals, mesh);
  mesh.FaceOffsets = std::move(obj.FaceOffsets);
  mesh.FaceIds = std::move(obj.Corners.VertexIds);
  mesh.Parts = std::move(obj.FaceParts);
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(std::move(mesh)), triangles, 1);
  if (!obj.MaterialNames.empty())
  {
    std::vector<shadelab::Texture> textures;
    shadelab::AddPartMaterials(
      PartMaterials(obj.MaterialNames, this->ReadLibraries(fileName, obj.Libraries), textures),
      triangles);
    shadelab::AddTextures(textures, triangles);
  }
}

std::vector<shadelab::MtlMaterial> vtkShadelabOBJReader::ReadLibraries(
  const char* fileName, const std::vector<std::string>& libraries)
{
  std::vector<shadelab::MtlMaterial> materials;
  const std::filesystem::path folder = std::filesystem::path(fileName).parent_path();
  for (const std::string& library : libraries)
  {
    std::filesystem::path path;
    std::string text;
    try
    {
      path = shadelab::ResolveReference(
        fileName, folder.string(), library, this->AllowOutsideReferences);
      text = ReadFileBytes(path.c_str());
    }
    catch (const shadelab::MeshReadError& e)
    {
      // OBJ files from the web often come without their MTL: drawn anyway.
      vtkWarningMacro(<< "material library " << shadelab::Quote(library) << ": " << e.what()
                      << "; its materials are the default");
      continue;
    }
    shadelab::MtlLibrary parsed;
    try
    {
      parsed = shadelab::ParseMtl(text);
    }
    catch (const shadelab::MeshReadError& e)
    {
      throw shadelab::MeshReadError(
        "material library " + shadelab::Quote(library) + " " + e.what());
    }
    for (const std::string& warning : parsed.Warnings)
    {
      vtkWarningMacro(<< "material library " << shadelab::Quote(library) << " " << warning);
    }
    for (shadelab::MtlMaterial& m : parsed.Materials)
    {
      // Map files are named relative to the MTL's folder, and lie in the
      // mesh's, like the library.
      for (shadelab::MtlMap* map : { &m.KdMap, &m.KaMap, &m.NormalMap })
      {
        if (!map->File.empty())
        {
          try
          {
            map->File = shadelab::ResolveReference(
              fileName, path.parent_path().string(), map->File, this->AllowOutsideReferences);
          }
          catch (const shadelab::MeshReadError& e)
          {
            throw shadelab::MeshReadError("material library " + shadelab::Quote(library) +
                ": map " + shadelab::Quote(map->File) + " " + e.what(),
              e.GetCode());
          }
        }
      }
      materials.push_back(std::move(m));
    }
  }
  return materials;
}
