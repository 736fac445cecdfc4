#include "vtkShadelabGLTFReader.h"

#include "shadelabGLTFAccessor.h"
#include "shadelabGLTFDocument.h"
#include "shadelabGLTFMaterial.h"
#include "shadelabGLTFScene.h"
#include "shadelabGLTFTexture.h"
#include "shadelabMeshReadError.h"
#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkShadelabGLTFReader);

namespace
{
using namespace shadelab::gltf;
using shadelab::MeshReadError;

const AccessorUse PositionUse = { "POSITION", 3, 3, false, false, Quantization::Integers };
const AccessorUse NormalUse = { "NORMAL", 3, 3, false, false, Quantization::SignedNormalized };
const AccessorUse TextureCoordinatesUse = { "TEXCOORD_0", 2, 2, true, false,
  Quantization::Integers };
const AccessorUse ColorUse = { "COLOR_0", 3, 4, true };

// glTF's primitive modes.
enum Mode : std::uint64_t
{
  LineStrip = 3, // 0 .. 3: points and lines
  Triangles = 4,
  TriangleStrip = 5,
  TriangleFan = 6
};

// A node may draw a mesh that other nodes draw too, so a small file can ask
// for any number of copies of its largest mesh. What the scene's triangle
// primitives will take is counted from the accessors' counts before anything
// is built (the accessors checked as reading them checks).
struct SceneSize
{
  std::uint64_t Points = 0;
  std::uint64_t Corners = 0;     // of the scene's faces and strips
  std::uint64_t FileCorners = 0; // of its meshes, each counted once
};

// See the class's description.
constexpr std::uint64_t MaxInstancedCorners = 3 * (std::uint64_t(4) << 20);

SceneSize MeasureScene(const Document& document, const std::vector<MeshInstance>& instances)
{
  SceneSize size;
  std::vector<bool> counted(document.Root.contains("meshes") ? document.Root["meshes"].size() : 0);
  for (const MeshInstance& instance : instances)
  {
    const std::string meshName = "mesh " + std::to_string(instance.Mesh);
    const Json& primitives =
      List(Item(document.Root, "meshes", instance.Mesh, meshName), "primitives");
    std::uint64_t meshCorners = 0;
    for (std::size_t p = 0; p < primitives.size(); ++p)
    {
      const Json& primitive = primitives[p];
      const std::string where = meshName + " primitive " + std::to_string(p);
      if (!primitive.is_object() || !primitive.contains("attributes") ||
        !primitive["attributes"].contains("POSITION") ||
        Unsigned(primitive, "mode", where, Triangles) <= LineStrip)
      {
        continue; // nothing to draw, or an error that reading it reports
      }
      const std::uint64_t points =
        CountOf(document, Unsigned(primitive["attributes"], "POSITION", where), PositionUse, where);
      size.Points += points;
      meshCorners += primitive.contains("indices")
        ? CountOf(document, Unsigned(primitive, "indices", where), IndicesUse, where)
        : points;
    }
    size.Corners += meshCorners;
    if (instance.Mesh < counted.size() && !counted[instance.Mesh])
    {
      counted[instance.Mesh] = true;
      size.FileCorners += meshCorners;
    }
  }
  return size;
}

// A scene that needs more than half of the memory there is fails before it
// is built rather than meet the OOM killer (points with their attributes
// and corners held twice on the way to vtkPolyData); and instancing, which
// costs the file nothing, may not take a scene past MaxInstancedCorners
// unless its meshes hold that many themselves.
void CheckSize(const SceneSize& size)
{
  constexpr double pointBytes = 128, cornerBytes = 24;
  const double needed =
    pointBytes * static_cast<double>(size.Points) + cornerBytes * static_cast<double>(size.Corners);
  const double available = static_cast<double>(vtkShadelabFileReader::AvailableMemory());
  if (available > 0 && needed > available / 2)
  {
    throw MeshReadError("the scene's meshes need about " +
        std::to_string(static_cast<long long>(needed / (1 << 20))) + " MiB, more than the " +
        std::to_string(static_cast<long long>(available / (1 << 20))) +
        " MiB of memory available allow",
      vtkErrorCode::UnknownError);
  }
  if (size.Corners > std::max(size.FileCorners, MaxInstancedCorners))
  {
    throw MeshReadError("its nodes draw its meshes' " + std::to_string(size.FileCorners / 3) +
        " triangles as " + std::to_string(size.Corners / 3) + " (about " +
        std::to_string(size.Corners / std::max<std::uint64_t>(size.FileCorners, 1)) +
        " times); instances may make at most " + std::to_string(MaxInstancedCorners / 3) +
        " triangles",
      vtkErrorCode::UnknownError);
  }
}

// The drawn primitives of the scene, gathered into one PolygonMesh: points
// and their attributes one primitive after the other, faces (triangles and
// fans) and strips with the part of each.
class MeshBuilder
{
public:
  explicit MeshBuilder(const Document& document)
    : Doc(document)
  {
  }

  void AddMesh(const MeshInstance& instance)
  {
    const std::string meshName = "mesh " + std::to_string(instance.Mesh);
    const Json& mesh = Item(this->Doc.Root, "meshes", instance.Mesh, meshName);
    const Json& primitives = List(mesh, "primitives");
    if (primitives.empty())
    {
      Fail(meshName + " has no primitives");
    }
    for (std::size_t p = 0; p < primitives.size(); ++p)
    {
      const std::string where = meshName + " primitive " + std::to_string(p);
      if (!primitives[p].is_object())
      {
        Fail(where + " is not an object");
      }
      this->AddPrimitive(primitives[p], instance.World, where);
    }
  }

  /** Room for the whole scene at once: one copy of each array, however many primitives. */
  void Reserve(const SceneSize& size)
  {
    this->Mesh.Points.reserve(3 * size.Points);
    this->Mesh.FaceIds.reserve(size.Corners);
    this->Mesh.FaceOffsets.reserve(size.Corners / 3 + 1);
    this->FaceParts.reserve(size.Corners / 3);
  }

  /** The mesh, with the attributes that only some primitives have completed. */
  shadelab::PolygonMesh& Finish()
  {
    const std::size_t points = this->Mesh.Points.size() / 3;
    Complete(this->Mesh.Colors, 4 * points, 1.0f);
    Complete(this->Mesh.TextureCoordinates, 2 * points, 0.0f);
    if (this->SomeLackNormals)
    {
      this->Mesh.Normals.clear();
    }
    this->Mesh.Parts = this->FaceParts;
    this->Mesh.Parts.insert(
      this->Mesh.Parts.end(), this->StripParts.begin(), this->StripParts.end());
    return this->Mesh;
  }

  std::vector<shadelab::PartMaterial> Materials; // per part
  std::vector<shadelab::Texture> Textures;       // the parts' textures
  std::vector<std::string> Warnings;             // textures not drawn
  std::size_t Skipped = 0;
  bool SomeLackNormals = false;
  bool SomeHaveNormals = false;

private:
  // Fills `values` up to `size` with `value`: the vertices of primitives
  // that lack the attribute.
  static void Complete(std::vector<float>& values, std::size_t size, float value)
  {
    if (!values.empty())
    {
      values.resize(size, value);
    }
  }

  FloatValues Attribute(const Json& attributes, const char* name, const AccessorUse& use,
    std::uint64_t count, const std::string& where)
  {
    FloatValues values = ReadFloats(this->Doc, Unsigned(attributes, name, where), use, where);
    if (values.Count != count)
    {
      Fail(where + ": " + name + " has " + std::to_string(values.Count) + " elements, POSITION " +
        std::to_string(count));
    }
    return values;
  }

  void AddPrimitive(const Json& primitive, const Matrix& world, const std::string& where)
  {
    const std::uint64_t mode = Unsigned(primitive, "mode", where, Triangles);
    if (mode <= LineStrip)
    {
      ++this->Skipped;
      return;
    }
    if (mode > TriangleFan)
    {
      Fail(where + ": mode " + std::to_string(mode) + " is not a glTF primitive mode");
    }
    if (!primitive.contains("attributes") || !primitive["attributes"].is_object())
    {
      Fail(where + " has no attributes");
    }
    const Json& attributes = primitive["attributes"];
    if (!attributes.contains("POSITION"))
    {
      Fail(where + " has no POSITION");
    }
    const FloatValues positions =
      ReadFloats(this->Doc, Unsigned(attributes, "POSITION", where), PositionUse, where);
    const std::uint64_t count = positions.Count;
    const std::vector<std::uint32_t> indices = this->Indices(primitive, count, where);
    const WorldTransform transform(world);
    this->AddFaces(static_cast<Mode>(mode), indices, transform.Mirrors(), where);
    const std::size_t first = this->Mesh.Points.size() / 3;
    for (std::uint64_t v = 0; v < count; ++v)
    {
      transform.Point(&positions.Values[3 * v], this->Mesh.Points);
    }
    if (attributes.contains("NORMAL"))
    {
      const FloatValues normals = Attribute(attributes, "NORMAL", NormalUse, count, where);
      this->Mesh.Normals.resize(3 * first, 0.0f); // primitives before without: dropped in Finish
      for (std::uint64_t v = 0; v < count; ++v)
      {
        transform.Normal(&normals.Values[3 * v], this->Mesh.Normals);
      }
      this->SomeHaveNormals = true;
    }
    else
    {
      this->SomeLackNormals = true;
    }
    if (attributes.contains("COLOR_0"))
    {
      const FloatValues colors = Attribute(attributes, "COLOR_0", ColorUse, count, where);
      this->Mesh.Colors.resize(4 * first, 1.0f);
      for (std::uint64_t v = 0; v < count; ++v)
      {
        const float* c = &colors.Values[colors.Components * v];
        this->Mesh.Colors.insert(
          this->Mesh.Colors.end(), { c[0], c[1], c[2], colors.Components == 4 ? c[3] : 1.0f });
      }
    }
    if (attributes.contains("TEXCOORD_0"))
    {
      const FloatValues uv =
        Attribute(attributes, "TEXCOORD_0", TextureCoordinatesUse, count, where);
      this->Mesh.TextureCoordinates.resize(2 * first, 0.0f);
      for (std::uint64_t v = 0; v < count; ++v)
      {
        this->Mesh.TextureCoordinates.insert(
          this->Mesh.TextureCoordinates.end(), { uv.Values[2 * v], 1.0f - uv.Values[2 * v + 1] });
      }
    }
    const UvTransform uvMap = this->AddMaterial(primitive, where);
    if (attributes.contains("TEXCOORD_0"))
    {
      MapTextureCoordinates(uvMap, &this->Mesh.TextureCoordinates[2 * first], count);
    }
  }

  // The primitive's indices (all of its vertices in order without an
  // indices accessor), each checked against the vertex count.
  std::vector<std::uint32_t> Indices(
    const Json& primitive, std::uint64_t count, const std::string& where) const
  {
    if (!primitive.contains("indices"))
    {
      std::vector<std::uint32_t> indices(count);
      std::iota(indices.begin(), indices.end(), std::uint32_t{ 0 });
      return indices;
    }
    std::vector<std::uint32_t> indices =
      ReadIndices(this->Doc, Unsigned(primitive, "indices", where), where);
    for (std::size_t k = 0; k < indices.size(); ++k)
    {
      if (indices[k] >= count)
      {
        Fail(where + ": index " + std::to_string(k) + " is " + std::to_string(indices[k]) +
          ", but POSITION has " + std::to_string(count) + " elements");
      }
    }
    return indices;
  }

  // The triangles of `indices` as faces, or one strip, offset by the points
  // before this primitive; turned round when the transform mirrors.
  void AddFaces(
    Mode mode, const std::vector<std::uint32_t>& indices, bool turn, const std::string& where)
  {
    const std::size_t n = indices.size();
    if (n < 3 || (mode == Triangles && n % 3 != 0))
    {
      Fail(where + " has " + std::to_string(n) + " vertices, which make no whole triangles");
    }
    const int part = static_cast<int>(this->Materials.size());
    const vtkIdType base = static_cast<vtkIdType>(this->Mesh.Points.size() / 3);
    const auto id = [&](std::size_t k) { return base + static_cast<vtkIdType>(indices[k]); };
    const auto addTriangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
    {
      this->Mesh.FaceIds.insert(this->Mesh.FaceIds.end(), { a, turn ? c : b, turn ? b : c });
      this->Mesh.FaceOffsets.push_back(static_cast<vtkIdType>(this->Mesh.FaceIds.size()));
      this->FaceParts.push_back(part);
    };
    if (mode == Triangles)
    {
      for (std::size_t k = 0; k < n; k += 3)
      {
        addTriangle(id(k), id(k + 1), id(k + 2));
      }
    }
    else if (mode == TriangleFan)
    {
      for (std::size_t k = 1; k + 1 < n; ++k)
      {
        addTriangle(id(0), id(k), id(k + 1));
      }
    }
    else
    {
      // A strip that starts with its first index twice runs the other way
      // round: its first triangle is degenerate (and dropped), and every
      // following one swaps its orientation.
      if (turn)
      {
        this->Mesh.StripIds.push_back(id(0));
      }
      for (std::size_t k = 0; k < n; ++k)
      {
        this->Mesh.StripIds.push_back(id(k));
      }
      this->Mesh.StripOffsets.push_back(static_cast<vtkIdType>(this->Mesh.StripIds.size()));
      this->StripParts.push_back(part);
    }
  }

  // The primitive's part and its material; the map of its texture
  // coordinates (KHR_texture_transform).
  UvTransform AddMaterial(const Json& primitive, const std::string& where)
  {
    UvTransform transform;
    if (!primitive.contains("material"))
    {
      this->Materials.emplace_back();
      return transform;
    }
    const std::uint64_t index = Unsigned(primitive, "material", where);
    const Json& material = Item(this->Doc.Root, "materials", index, where);
    const std::string name = "material " + std::to_string(index);
    const shadelab::Material m = LectureMaterial(material, name);
    std::string warning;
    // glTF's ka is its kd (shadelabGLTFMaterial.h), so is their texture.
    const int texture =
      BaseColorTexture(this->Doc, material, name, this->Textures, warning, transform);
    std::string normalWarning;
    double normalScale = 1;
    const int normals = NormalTexture(this->Doc, material, name, this->Textures, normalWarning,
      transform, texture >= 0, normalScale);
    for (const std::string& w : { warning, normalWarning })
    {
      if (!w.empty() &&
        std::find(this->Warnings.begin(), this->Warnings.end(), w) == this->Warnings.end())
      {
        this->Warnings.push_back(w);
      }
    }
    // In ks it multiplies the metal's part (KsTextureScale): none for a dielectric.
    const shadelab::Rgb ksScale = KsTextureScale(material, name);
    const bool ksTextured = texture >= 0 && ksScale != shadelab::Rgb{};
    this->Materials.push_back(
      { m.Name, static_cast<int>(index), m, texture, texture, ksTextured ? texture : -1,
        ksTextured ? ksScale : shadelab::Rgb{}, normals, normalScale, false });
    return transform;
  }

  const Document& Doc;
  shadelab::PolygonMesh Mesh;
  std::vector<int> FaceParts;
  std::vector<int> StripParts;
};
}

void vtkShadelabGLTFReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  const Document document = Load(fileName, ReadFileBytes(fileName), this->AllowOutsideReferences);
  const std::vector<MeshInstance> instances = SceneMeshes(document.Root);
  const SceneSize size = MeasureScene(document, instances);
  CheckSize(size);
  MeshBuilder builder(document);
  builder.Reserve(size);
  for (const MeshInstance& instance : instances)
  {
    builder.AddMesh(instance);
  }
  if (builder.Skipped > 0)
  {
    vtkWarningMacro(<< "skipped " << builder.Skipped
                    << " primitives of points or lines: shadelab draws triangles");
  }
  if (builder.SomeHaveNormals && builder.SomeLackNormals)
  {
    vtkWarningMacro(<< "some primitives have no NORMAL, so the file's normals are ignored");
  }
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(std::move(builder.Finish())), triangles);

  for (const std::string& warning : builder.Warnings)
  {
    vtkWarningMacro(<< warning);
  }
  shadelab::AddPartMaterials(builder.Materials, triangles);
  shadelab::AddTextures(builder.Textures, triangles);
}
