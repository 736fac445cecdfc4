#include "shadelabAssimpScene.h"

#include "shadelabCheckedFile.h"
#include "shadelabMeshReadError.h"
#include "shadelabTextScanner.h"
#include "vtkShadelabFileReader.h"

#include <assimp/material.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
namespace
{
std::string MeshName(const aiMesh& mesh, unsigned index)
{
  const std::string name = mesh.mName.C_Str();
  return "mesh " + std::to_string(index) + (name.empty() ? "" : " " + Quote(name));
}

bool Finite(const aiVector3D& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool Finite(const Rgb& c)
{
  return std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]);
}

// The points and triangles that shadelab makes of the scene's meshes (double
// points, float normals and texture coordinates, 64-bit ids, the VTK copy of
// each): a scene that a hostile file made huge fails here with a message,
// as the own readers refuse counts the memory cannot take.
void CheckMemory(std::uint64_t points, std::uint64_t triangles)
{
  constexpr std::uint64_t pointBytes = 2 * (24 + 12 + 8 + 8), triangleBytes = 2 * (32 + 4);
  const std::uint64_t need = points * pointBytes + triangles * triangleBytes;
  const std::uint64_t available = vtkShadelabFileReader::AvailableMemory();
  if (available > 0 && need > available / 2)
  {
    throw MeshReadError("its " + std::to_string(points) + " vertices and " +
        std::to_string(triangles) + " triangles need " + std::to_string(need >> 20) +
        " MiB, more than the " + std::to_string(available >> 20) + " MiB of memory available",
      vtkErrorCode::UnknownError);
  }
}

// A texture that a material names: an embedded image's encoded bytes, or a
// file beside the mesh (Windows' backslashes read as slashes), repeated,
// clamped or mirrored as the file says; -1 for none.
int MapDiffuseTexture(const aiScene& scene, const aiMaterial& material, const std::string& what,
  const std::string& meshFile, bool allowOutside, AssimpMesh& result)
{
  aiString path;
  aiTextureMapMode modes[2] = { aiTextureMapMode_Wrap, aiTextureMapMode_Wrap };
  if (material.GetTexture(
        aiTextureType_DIFFUSE, 0, &path, nullptr, nullptr, nullptr, nullptr, modes) != AI_SUCCESS ||
    path.length == 0)
  {
    return -1;
  }
  const auto wrap = [](aiTextureMapMode mode)
  {
    return mode == aiTextureMapMode_Clamp || mode == aiTextureMapMode_Decal ? gl::ClampToEdge
      : mode == aiTextureMapMode_Mirror                                     ? gl::MirroredRepeat
                                                                            : gl::Repeat;
  };
  Texture texture;
  texture.WrapS = wrap(modes[0]);
  texture.WrapT = wrap(modes[1]);
  std::string name = path.C_Str();
  if (const aiTexture* embedded = scene.GetEmbeddedTexture(name.c_str()))
  {
    if (embedded->mHeight != 0 || !embedded->pcData)
    {
      // Raw texels rather than an image file: shadelab decodes image files only.
      result.Warnings.push_back(
        what + ": its texture " + Quote(name) + " is raw texels, not an image file; not drawn");
      return -1;
    }
    const auto* bytes = reinterpret_cast<const unsigned char*>(embedded->pcData);
    texture.Bytes.assign(bytes, bytes + embedded->mWidth);
    return AddTexture(result.Textures, std::move(texture));
  }
  if (name[0] == '*')
  {
    throw MeshReadError(what + " names the embedded texture " + Quote(name) +
      ", but the file has " + std::to_string(scene.mNumTextures));
  }
  std::replace(name.begin(), name.end(), '\\', '/');
  try
  {
    texture.Source = ResolveReference(
      meshFile, std::filesystem::path(meshFile).parent_path().string(), name, allowOutside);
  }
  catch (const MeshReadError& e)
  {
    throw MeshReadError(what + ": texture " + Quote(name) + " " + e.what(), e.GetCode());
  }
  return AddTexture(result.Textures, std::move(texture));
}

// A part's material. assimp stands in "DefaultMaterial" where a file has
// none, and keeps the name of one the file names without defining any
// colour: both are a part without a material (index -1), as OBJ's faces
// before any usemtl and its usemtl of a name no library defines, so that the
// program's default material applies to them the same way.
PartMaterial MapMaterial(const aiScene& scene, unsigned index, const std::string& meshFile,
  bool allowOutside, AssimpMesh& result)
{
  PartMaterial part;
  if (index >= scene.mNumMaterials || !scene.mMaterials[index])
  {
    throw MeshReadError("a mesh refers to material " + std::to_string(index) + ", but only " +
      std::to_string(scene.mNumMaterials) + " are defined");
  }
  const aiMaterial& material = *scene.mMaterials[index];
  aiString name;
  if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
    name != aiString(AI_DEFAULT_MATERIAL_NAME))
  {
    part.Name = name.C_Str();
  }
  const std::string what = "material " + std::to_string(index) + " " + Quote(part.Name);
  aiColor3D ka, kd, ks;
  const bool hasKa = material.Get(AI_MATKEY_COLOR_AMBIENT, ka) == AI_SUCCESS;
  const bool hasKd = material.Get(AI_MATKEY_COLOR_DIFFUSE, kd) == AI_SUCCESS;
  const bool hasKs = material.Get(AI_MATKEY_COLOR_SPECULAR, ks) == AI_SUCCESS;
  if (part.Name.empty() || !(hasKa || hasKd || hasKs))
  {
    return part;
  }
  part.Index = static_cast<int>(index);
  Material& m = part.Coefficients;
  m.Name = part.Name;
  m.Ka = { ka.r, ka.g, ka.b };
  m.Kd = { kd.r, kd.g, kd.b };
  ai_real strength = 1, shininess = 0, opacity = 1;
  material.Get(AI_MATKEY_SHININESS_STRENGTH, strength);
  m.Ks = { ks.r * strength, ks.g * strength, ks.b * strength };
  material.Get(AI_MATKEY_SHININESS, shininess);
  m.Ns = shininess;
  // Translucency: the format's opacity (a file's d, a transparency's 1 - Tr).
  material.Get(AI_MATKEY_OPACITY, opacity);
  m.Translucency = opacity;
  if (!Finite(m.Ka) || !Finite(m.Kd) || !Finite(m.Ks) || !std::isfinite(m.Ns) ||
    !std::isfinite(m.Translucency))
  {
    throw MeshReadError(what + " has a non-finite colour or number");
  }
  if (m.Ns < 0)
  {
    throw MeshReadError(what + " has a negative shininess");
  }
  part.KdTexture = MapDiffuseTexture(scene, material, what, meshFile, allowOutside, result);
  part.KaTexture = part.KdTexture;
  return part;
}

// Appends one mesh's triangles, points and attributes to the result.
void AppendMesh(const aiMesh& mesh, unsigned index, bool normals, bool textured, bool colored,
  PolygonMesh& polygons)
{
  const std::string what = MeshName(mesh, index);
  if (!mesh.mVertices || (mesh.mNumFaces > 0 && !mesh.mFaces))
  {
    throw MeshReadError(what + " has no vertex or face array");
  }
  const auto first = static_cast<vtkIdType>(polygons.Points.size() / 3);
  for (unsigned v = 0; v < mesh.mNumVertices; ++v)
  {
    const aiVector3D& p = mesh.mVertices[v];
    if (!Finite(p))
    {
      throw MeshReadError(what + ": vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
    polygons.Points.insert(polygons.Points.end(), { p.x, p.y, p.z });
    if (normals)
    {
      const aiVector3D& n = mesh.mNormals[v];
      polygons.Normals.insert(polygons.Normals.end(), { n.x, n.y, n.z });
    }
    if (textured)
    {
      const aiVector3D* uv = mesh.mTextureCoords[0];
      // A channel of one component is u alone (v 0), as OBJ's "vt u".
      const float s = uv ? uv[v].x : 0, t = uv && mesh.mNumUVComponents[0] > 1 ? uv[v].y : 0;
      if (!std::isfinite(s) || !std::isfinite(t))
      {
        throw MeshReadError(
          what + ": vertex " + std::to_string(v) + " has a non-finite texture coordinate");
      }
      polygons.TextureCoordinates.insert(polygons.TextureCoordinates.end(), { s, t });
    }
    if (colored)
    {
      // A mesh without colours among meshes with them: white, as glTF's.
      const aiColor4D c = mesh.mColors[0] ? mesh.mColors[0][v] : aiColor4D(1, 1, 1, 1);
      if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b) || !std::isfinite(c.a))
      {
        throw MeshReadError(what + ": vertex " + std::to_string(v) + " has a non-finite colour");
      }
      polygons.Colors.insert(polygons.Colors.end(), { c.r, c.g, c.b, c.a });
    }
  }
  for (unsigned f = 0; f < mesh.mNumFaces; ++f)
  {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3 || !face.mIndices)
    {
      throw MeshReadError(what + ": face " + std::to_string(f) + " has " +
        std::to_string(face.mNumIndices) + " vertices after triangulation, not 3");
    }
    for (unsigned k = 0; k < 3; ++k)
    {
      if (face.mIndices[k] >= mesh.mNumVertices)
      {
        throw MeshReadError(what + ": face " + std::to_string(f) + " refers to vertex " +
          std::to_string(face.mIndices[k]) + ", but only " + std::to_string(mesh.mNumVertices) +
          " vertices are defined");
      }
      polygons.FaceIds.push_back(first + static_cast<vtkIdType>(face.mIndices[k]));
    }
    polygons.FaceOffsets.push_back(static_cast<vtkIdType>(polygons.FaceIds.size()));
  }
}
}

AssimpMesh ConvertAssimpScene(
  const aiScene& scene, const std::string& meshFile, bool readNormals, bool allowOutside)
{
  // SortByPType made each mesh one kind of primitive: points and lines
  // (a DXF's polylines, a skeleton's bones) are dropped, as the other
  // readers drop them; "no triangles" comes from MakeTriangleMesh.
  std::vector<unsigned> meshes;
  std::uint64_t points = 0, triangles = 0;
  bool someNormals = false, someLackNormals = false, someUV = false, someLackUV = false,
       someColors = false;
  for (unsigned i = 0; i < scene.mNumMeshes; ++i)
  {
    const aiMesh* mesh = scene.mMeshes[i];
    if (mesh && (mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) && mesh->mNumFaces > 0)
    {
      meshes.push_back(i);
      points += mesh->mNumVertices;
      triangles += mesh->mNumFaces;
      (mesh->mNormals ? someNormals : someLackNormals) = true;
      (mesh->mTextureCoords[0] ? someUV : someLackUV) = true;
      someColors = someColors || mesh->mColors[0];
    }
  }
  CheckMemory(points, triangles);

  AssimpMesh result;
  const bool normals = readNormals && someNormals && !someLackNormals;
  if (readNormals && someNormals && someLackNormals)
  {
    result.Warnings.push_back("some meshes have no normals, so the file's normals are ignored");
  }
  if (someUV && someLackUV)
  {
    result.Warnings.push_back("some meshes have no texture coordinates; their vertices get 0 0");
  }
  PolygonMesh& polygons = result.Mesh;
  polygons.Points.reserve(3 * points);
  polygons.Normals.reserve(normals ? 3 * points : 0);
  polygons.TextureCoordinates.reserve(someUV ? 2 * points : 0);
  polygons.Colors.reserve(someColors ? 4 * points : 0);
  polygons.FaceOffsets.reserve(triangles + 1);
  polygons.FaceIds.reserve(3 * triangles);
  polygons.Parts.reserve(triangles);
  for (unsigned i : meshes)
  {
    const aiMesh& mesh = *scene.mMeshes[i];
    AppendMesh(mesh, i, normals, someUV, someColors, polygons);
    polygons.Parts.insert(
      polygons.Parts.end(), mesh.mNumFaces, static_cast<int>(result.Parts.size()));
    result.Parts.push_back(MapMaterial(scene, mesh.mMaterialIndex, meshFile, allowOutside, result));
  }
  return result;
}
}
