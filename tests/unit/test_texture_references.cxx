// Texture coordinates and texture references from the files: OBJ's vt (and
// the points a seam splits), MTL's map_Kd and map_Ka with their options, glTF's
// baseColorTexture with its image and sampler, in the field data that
// shadelabPartMaterials.h names; the real textured files of tests/data/meshes
// (spot with its texture, Khronos' BoxTextured) and bad input.
#include "mesh_reader_fixture.h"
#include "shadelabMeshReadError.h"
#include "shadelabMtlParser.h"
#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"

#include <vtkBase64Utilities.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtkUnsignedCharArray.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace shadelab::test;
using Json = nlohmann::json;

std::string FileBytes(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

// A point's texture coordinates.
std::pair<double, double> St(vtkPolyData* mesh, vtkIdType point)
{
  const double* st = mesh->GetPointData()->GetTCoords()->GetTuple2(point);
  return { st[0], st[1] };
}

// Field data int array `name` as a vector; empty where it is missing.
std::vector<int> Ints(vtkPolyData* mesh, const char* name)
{
  std::vector<int> values;
  if (auto* array = vtkIntArray::SafeDownCast(mesh->GetFieldData()->GetArray(name)))
  {
    values.assign(array->GetPointer(0), array->GetPointer(0) + array->GetNumberOfValues());
  }
  return values;
}

std::vector<std::string> Sources(vtkPolyData* mesh)
{
  std::vector<std::string> sources;
  if (auto* array = vtkStringArray::SafeDownCast(
        mesh->GetFieldData()->GetAbstractArray(shadelab::TextureSourcesArrayName)))
  {
    for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
    {
      sources.push_back(array->GetValue(i));
    }
  }
  return sources;
}

std::vector<vtkIdType> FileVertices(vtkPolyData* mesh)
{
  auto* array =
    vtkIdTypeArray::SafeDownCast(mesh->GetPointData()->GetArray(shadelab::FileVertexArrayName));
  return array ? std::vector<vtkIdType>(
                   array->GetPointer(0), array->GetPointer(0) + array->GetNumberOfValues())
               : std::vector<vtkIdType>{};
}

// ---------------------------------------------------------------------------
// OBJ vt

// Two triangles over one edge whose second vertex has another vt in the
// second triangle: a seam. The vertex becomes two points.
TEST_F(MeshReaders, ObjVertexUsedWithTwoTextureCoordinatesIsSplit)
{
  const ReadResult result = Read(this->Write("seam.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
    "vt 0 0\nvt 0.5 0\nvt 0 1\nvt 1 1 0.25\nvt 0.75\n"
    "f 1/1 2/2 3/3\nf 2/5 4/4 3/3\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  EXPECT_TRUE(result.Warnings.empty());
  ASSERT_EQ(result.Mesh->GetNumberOfPoints(), 5);
  ASSERT_NE(result.Mesh->GetPointData()->GetTCoords(), nullptr);
  EXPECT_STREQ(
    result.Mesh->GetPointData()->GetTCoords()->GetName(), shadelab::TextureCoordinatesArrayName);
  const auto triangles = Triangles(result.Mesh);
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_EQ(triangles[0], (std::array<vtkIdType, 3>{ 0, 1, 2 }));
  EXPECT_EQ(triangles[1], (std::array<vtkIdType, 3>{ 4, 3, 2 }));
  EXPECT_EQ(St(result.Mesh, 1), std::make_pair(0.5, 0.0));
  EXPECT_EQ(St(result.Mesh, 3), std::make_pair(1.0, 1.0));  // w is ignored
  EXPECT_EQ(St(result.Mesh, 4), std::make_pair(0.75, 0.0)); // vt u alone: v 0
  EXPECT_EQ(FileVertices(result.Mesh), (std::vector<vtkIdType>{ 0, 1, 2, 3, 1 }));
}

// vt and vn split together: one point per (v, vt, vn); a vertex used with
// the same pair everywhere stays one point, and no FileVertex is needed.
TEST_F(MeshReaders, ObjTextureCoordinatesAndNormalsSplitTogether)
{
  const std::string faces = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
                            "vn 0 0 -1\n";
  const ReadResult split = Read(this->Write(
    "both.obj", faces + "f 1/1/1 2/2/1 3/3/1\nf 1/1/2 3/3/2 2/1/2\nf 1/1/1 3/3/1 2/2/1\n"));
  ASSERT_TRUE(split.Ok) << split.Error;
  ExpectTriangleMesh(split.Mesh);
  // Vertex 2 with (vt 2, vn 1), (vt 1, vn 2): two points; 1 and 3 each with
  // both normals: two each.
  EXPECT_EQ(split.Mesh->GetNumberOfPoints(), 6);
  EXPECT_EQ(FileVertices(split.Mesh), (std::vector<vtkIdType>{ 0, 1, 2, 0, 2, 1 }));
  const auto triangles = Triangles(split.Mesh);
  EXPECT_EQ(triangles[1], (std::array<vtkIdType, 3>{ 3, 4, 5 }));
  EXPECT_EQ(triangles[2], (std::array<vtkIdType, 3>{ 0, 2, 1 }));
  EXPECT_EQ(St(split.Mesh, 5), std::make_pair(0.0, 0.0));
  EXPECT_EQ(split.Mesh->GetPointData()->GetNormals()->GetTuple3(5)[2], -1.0);

  const ReadResult same =
    Read(this->Write("same.obj", faces + "f 1/1/1 2/2/1 3/3/1\nf 3/3/1 2/2/1 1/1/1\n"));
  ASSERT_TRUE(same.Ok) << same.Error;
  EXPECT_EQ(same.Mesh->GetNumberOfPoints(), 3);
  EXPECT_TRUE(FileVertices(same.Mesh).empty());
}

TEST_F(MeshReaders, ObjCornersWithoutTextureCoordinatesGetZeroWithAWarning)
{
  const ReadResult result = Read(this->Write(
    "some.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.5 0.5\nf 1/1 2/1 3/1\nf 2 4 3\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  ASSERT_EQ(result.Warnings.size(), 1u);
  EXPECT_NE(result.Warnings[0].find("no vt texture coordinates"), std::string::npos)
    << result.Warnings[0];
  // Vertices 2 and 3 are used with and without vt: a point for each.
  EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 6);
  EXPECT_EQ(St(result.Mesh, 1), std::make_pair(0.5, 0.5));
  EXPECT_EQ(St(result.Mesh, 3), std::make_pair(0.0, 0.0)); // vertex 4, only without
  EXPECT_EQ(St(result.Mesh, 4), std::make_pair(0.0, 0.0)); // vertex 2 without
}

TEST_F(MeshReaders, BadObjTextureCoordinates)
{
  const std::string square = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  this->ExpectError("vt-missing.obj", square + "vt\n", { "line 4", "missing texture coordinate" });
  this->ExpectError(
    "vt-malformed.obj", square + "vt 0 x\n", { "line 4", "malformed texture coordinate 'x'" });
  this->ExpectError("vt-long.obj", square + "vt 0 0 0 0\n", { "line 4", "unexpected '0'" });
  this->ExpectError("vt-nan.obj", square + "vt nan 0\n", { "line 4", "non-finite" });
  this->ExpectError("vt-range.obj", square + "vt 0 0\nf 1/1 2/2 3/1\n",
    { "line 5", "texture coordinate 2", "only 1" });
  this->ExpectError(
    "vt-zero.obj", square + "vt 0 0\nf 1/0 2/1 3/1\n", { "line 5", "texture coordinate 0" });
}

// ---------------------------------------------------------------------------
// MTL maps

TEST_F(MeshReaders, MtlMapsWithOptions)
{
  const shadelab::MtlLibrary library = shadelab::ParseMtl(
    "newmtl a\nmap_Kd wood.png\nmap_Ka -clamp on -s 2 2 1 textures\\wood grain.png # c\n"
    "newmtl b\nmap_Kd -o 0.5 -blendu off -clamp off -mm 0 1 -t 1 b.png\nmap_Ks ignored.png\n");
  ASSERT_EQ(library.Materials.size(), 2u);
  const shadelab::MtlMaterial& a = library.Materials[0];
  EXPECT_EQ(a.KdMap.File, "wood.png");
  EXPECT_FALSE(a.KdMap.Clamp);
  EXPECT_EQ(a.KaMap.File, "textures/wood grain.png");
  EXPECT_TRUE(a.KaMap.Clamp);
  const shadelab::MtlMaterial& b = library.Materials[1];
  EXPECT_EQ(b.KdMap.File, "b.png");
  EXPECT_FALSE(b.KdMap.Clamp);
  EXPECT_EQ(b.KaMap.File, "");
  EXPECT_EQ(library.Warnings,
    (std::vector<std::string>{ "line 3: map_Ka option -s is not supported, ignored",
      "line 5: map_Kd option -o is not supported, ignored",
      "line 5: map_Kd option -blendu is not supported, ignored",
      "line 5: map_Kd option -mm is not supported, ignored",
      "line 5: map_Kd option -t is not supported, ignored" }));

  const std::vector<std::pair<std::string, std::string>> mistakes{
    { "map_Kd a.png\n", "line 1: map_Kd before any newmtl" },
    { "newmtl a\nmap_Kd\n", "line 2: map_Kd without a file name" },
    { "newmtl a\nmap_Ka -clamp on # no file\n", "line 2: map_Ka without a file name" },
    { "newmtl a\nmap_Kd -clamp\n", "line 2: map_Kd option -clamp without its value" },
    { "newmtl a\nmap_Kd -clamp yes a.png\n", "line 2: malformed map_Kd -clamp 'yes' (on or off)" },
    { "newmtl a\nmap_Kd -zoom 2 a.png\n", "line 2: unknown map_Kd option '-zoom'" },
    { "newmtl a\nmap_Kd -mm 1\n", "line 2: map_Kd option -mm without its value" },
  };
  ExpectMtlErrors(mistakes);
}

// The maps become the parts' textures: files resolved against the MTL's
// folder (which need not exist yet), one texture per distinct file and
// sampling, -clamp on as CLAMP_TO_EDGE; options skipped are warnings.
TEST_F(MeshReaders, ObjMaterialMapsBecomeThePartsTextures)
{
  fs::create_directories(this->Dir / "materials");
  this->Write("materials/lib.mtl",
    "newmtl wood\nKd 0.5 0.5 0.5\nmap_Kd ../textures/wood.png\nmap_Ka ../textures/wood.png\n"
    "newmtl edge\nmap_Kd -clamp on -s 2 2 edge.png\n"
    "newmtl again\nmap_Ka ../textures/wood.png\n"
    "newmtl plain\nKd 1 0 0\n");
  const ReadResult result = Read(this->Write("parts.obj",
    "mtllib materials/lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
    "usemtl plain\nf 1 2 3\nusemtl wood\nf 1 2 3\nusemtl edge\nf 1 2 3\n"
    "usemtl again\nf 1 2 3\nusemtl unknown\nf 1 2 3\n"));
  ASSERT_TRUE(result.Ok) << result.Error;
  ASSERT_EQ(result.Warnings.size(), 1u);
  EXPECT_NE(result.Warnings[0].find("material library 'materials/lib.mtl' line 6: map_Kd option "
                                    "-s is not supported"),
    std::string::npos)
    << result.Warnings[0];
  EXPECT_EQ(Sources(result.Mesh),
    (std::vector<std::string>{
      (this->Dir / "textures/wood.png").string(), (this->Dir / "materials/edge.png").string() }));
  EXPECT_EQ(
    Ints(result.Mesh, shadelab::PartKdTextureArrayName), (std::vector<int>{ -1, 0, 1, -1, -1 }));
  EXPECT_EQ(
    Ints(result.Mesh, shadelab::PartKaTextureArrayName), (std::vector<int>{ -1, 0, -1, 0, -1 }));
  using shadelab::gl::ClampToEdge, shadelab::gl::Linear, shadelab::gl::Repeat;
  EXPECT_EQ(
    Ints(result.Mesh, shadelab::TextureWrapSArrayName), (std::vector<int>{ Repeat, ClampToEdge }));
  EXPECT_EQ(
    Ints(result.Mesh, shadelab::TextureWrapTArrayName), (std::vector<int>{ Repeat, ClampToEdge }));
  EXPECT_EQ(
    Ints(result.Mesh, shadelab::TextureMagFilterArrayName), (std::vector<int>{ Linear, Linear }));
  EXPECT_EQ(
    Ints(result.Mesh, shadelab::TextureMinFilterArrayName), (std::vector<int>{ Linear, Linear }));
  EXPECT_EQ(result.Mesh->GetFieldData()->GetArray("TextureBytes0"), nullptr); // files, not bytes

  // Materials without maps: part arrays of -1, no texture arrays at all.
  this->Write("plain.mtl", "newmtl plain\nKd 1 0 0\n");
  const ReadResult plain = Read(this->Write(
    "plain.obj", "mtllib plain.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl plain\nf 1 2 3\n"));
  ASSERT_TRUE(plain.Ok) << plain.Error;
  EXPECT_EQ(Ints(plain.Mesh, shadelab::PartKdTextureArrayName), (std::vector<int>{ -1 }));
  EXPECT_EQ(
    plain.Mesh->GetFieldData()->GetAbstractArray(shadelab::TextureSourcesArrayName), nullptr);
}

TEST_F(MeshReaders, BadMtlMapIsAnErrorNamingTheLibraryAndLine)
{
  this->Write("bad.mtl", "newmtl a\nmap_Kd -clamp maybe a.png\n");
  this->ExpectError("bad.obj", "mtllib bad.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n",
    { "material library 'bad.mtl'", "line 2", "-clamp 'maybe'" });
}

// ---------------------------------------------------------------------------
// The real textured files

// teapot.obj has vt per patch, split where patches meet (3,864 distinct
// v/vt pairs on its 3,241 vertices, counted from the file);
// teapot-textured.obj is the same mesh with a library whose material maps
// teapot-texture.png.
TEST_F(MeshReaders, TheTeapotsTextureCoordinatesAndTexture)
{
  for (const char* name : { "teapot.obj", "teapot-textured.obj" })
  {
    SCOPED_TRACE(name);
    const ReadResult result = Read(TestMeshes / name);
    ASSERT_TRUE(result.Ok) << result.Error;
    EXPECT_TRUE(result.Warnings.empty());
    ExpectTriangleMesh(result.Mesh);
    EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 3864);
    const std::vector<vtkIdType> fileVertices = FileVertices(result.Mesh);
    ASSERT_EQ(fileVertices.size(), 3864u);
    // The first face, "f 1/1 2/2 13/13", and vt 1, 2 and 13 of the file.
    const auto first = Triangles(result.Mesh)[0];
    EXPECT_EQ(fileVertices[first[0]], 0);
    EXPECT_EQ(fileVertices[first[1]], 1);
    EXPECT_EQ(fileVertices[first[2]], 12);
    EXPECT_EQ(St(result.Mesh, first[0]), (std::pair<double, double>(0.0f, 1.0f)));
    EXPECT_EQ(St(result.Mesh, first[1]), (std::pair<double, double>(0.1f, 1.0f)));
    EXPECT_EQ(St(result.Mesh, first[2]), (std::pair<double, double>(0.1f, 0.9f)));
  }
  const ReadResult textured = Read(TestMeshes / "teapot-textured.obj");
  ASSERT_TRUE(textured.Ok) << textured.Error;
  EXPECT_EQ(Sources(textured.Mesh),
    (std::vector<std::string>{ (TestMeshes / "teapot-texture.png").lexically_normal().string() }));
  EXPECT_EQ(Ints(textured.Mesh, shadelab::PartKdTextureArrayName), (std::vector<int>{ 0 }));
  EXPECT_EQ(Ints(textured.Mesh, shadelab::PartKaTextureArrayName), (std::vector<int>{ 0 }));
  EXPECT_EQ(Ints(textured.Mesh, shadelab::PartKsTextureArrayName), (std::vector<int>{ -1 }));
  EXPECT_EQ(Ints(textured.Mesh, shadelab::TextureWrapSArrayName),
    (std::vector<int>{ shadelab::gl::Repeat }));
}

// Khronos' BoxTextured, as Debian's assimp-testmodels hold it.
const fs::path BoxTextured = DebianModels / "glTF2";

// BoxTextured: one dielectric material whose baseColorTexture is
// CesiumLogoFlat.png, sampled LINEAR and NEAREST_MIPMAP_LINEAR; a file
// beside the .gltf, the bytes of a bufferView in the .glb.
TEST_F(MeshReaders, BoxTexturedsTextureInBothForms)
{
  const std::string png = FileBytes(BoxTextured / "BoxTextured-glTF/CesiumLogoFlat.png");
  for (const char* name :
    { "BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb" })
  {
    SCOPED_TRACE(name);
    const ReadResult result = Read(BoxTextured / name);
    ASSERT_TRUE(result.Ok) << result.Error;
    EXPECT_TRUE(result.Warnings.empty());
    ExpectTriangleMesh(result.Mesh);
    ASSERT_EQ(result.Mesh->GetNumberOfPoints(), 24);
    const bool binary = fs::path(name).extension() == ".glb";
    EXPECT_EQ(Sources(result.Mesh),
      (std::vector<std::string>{
        binary ? "" : (BoxTextured / "BoxTextured-glTF/CesiumLogoFlat.png").string() }));
    auto* bytes =
      vtkUnsignedCharArray::SafeDownCast(result.Mesh->GetFieldData()->GetArray("TextureBytes0"));
    ASSERT_EQ(bytes != nullptr, binary);
    if (binary)
    {
      EXPECT_EQ(std::string(
                  reinterpret_cast<const char*>(bytes->GetPointer(0)), bytes->GetNumberOfValues()),
        png);
    }
    EXPECT_EQ(Ints(result.Mesh, shadelab::PartKdTextureArrayName), (std::vector<int>{ 0 }));
    EXPECT_EQ(Ints(result.Mesh, shadelab::PartKaTextureArrayName), (std::vector<int>{ 0 }));
    // Metallic 0: the texture does not colour ks.
    EXPECT_EQ(Ints(result.Mesh, shadelab::PartKsTextureArrayName), (std::vector<int>{ -1 }));
    // The .gltf's sampler: MIRRORED_REPEAT along s, CLAMP_TO_EDGE along t;
    // the .glb's (an older export): REPEAT both ways.
    EXPECT_EQ(Ints(result.Mesh, shadelab::TextureWrapSArrayName),
      (std::vector<int>{ binary ? 10497 : 33648 }));
    EXPECT_EQ(Ints(result.Mesh, shadelab::TextureWrapTArrayName),
      (std::vector<int>{ binary ? 10497 : 33071 }));
    EXPECT_EQ(Ints(result.Mesh, shadelab::TextureMagFilterArrayName), (std::vector<int>{ 9729 }));
    EXPECT_EQ(Ints(result.Mesh, shadelab::TextureMinFilterArrayName), (std::vector<int>{ 9986 }));
    // TEXCOORD_0's first two elements, (6, 0) and (5, 0), with t turned over.
    EXPECT_EQ(St(result.Mesh, 0), std::make_pair(6.0, 1.0));
    EXPECT_EQ(St(result.Mesh, 1), std::make_pair(5.0, 1.0));
  }
}

// ---------------------------------------------------------------------------
// glTF textures built here from BoxTextured

class GltfTextures : public MeshReaders
{
protected:
  void SetUp() override
  {
    MeshReaders::SetUp();
    for (const char* file : { "BoxTextured0.bin", "CesiumLogoFlat.png" })
    {
      fs::copy_file(BoxTextured / "BoxTextured-glTF" / file, this->Dir / file);
    }
  }

  // BoxTextured.gltf changed by `edit`, read from the test's folder.
  ReadResult ReadEdited(const std::function<void(Json&)>& edit)
  {
    Json doc = Json::parse(FileBytes(BoxTextured / "BoxTextured-glTF/BoxTextured.gltf"));
    edit(doc);
    return Read(this->Write("edited.gltf", doc.dump()));
  }

  void ExpectEditError(
    const std::function<void(Json&)>& edit, std::initializer_list<const char*> keyWords)
  {
    Json doc = Json::parse(FileBytes(BoxTextured / "BoxTextured-glTF/BoxTextured.gltf"));
    edit(doc);
    this->ExpectError("bad.gltf", doc.dump(), keyWords);
  }
};

// baseColorTexture colours a metal's ks by the metal's part of it, m B
// (shadelabGLTFMaterial.h): part 0 metallic 0.5 with B (0.5, 0.25, 1), part
// 1 the same but a dielectric (m = 0), whose ks has no texture.
TEST_F(GltfTextures, AMetalsBaseColourTextureColoursItsKs)
{
  const ReadResult result = this->ReadEdited(
    [](Json& doc)
    {
      Json& pbr = doc["materials"][0]["pbrMetallicRoughness"];
      pbr["baseColorFactor"] = { 0.5, 0.25, 1, 1 };
      pbr["metallicFactor"] = 0.5;
      doc["materials"].push_back(doc["materials"][0]);
      doc["materials"][1]["pbrMetallicRoughness"]["metallicFactor"] = 0;
      doc["meshes"][0]["primitives"].push_back(doc["meshes"][0]["primitives"][0]);
      doc["meshes"][0]["primitives"][1]["material"] = 1;
    });
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(Ints(result.Mesh, shadelab::PartKdTextureArrayName), (std::vector<int>{ 0, 0 }));
  EXPECT_EQ(Ints(result.Mesh, shadelab::PartKsTextureArrayName), (std::vector<int>{ 0, -1 }));
  vtkDataArray* scale =
    result.Mesh->GetFieldData()->GetArray(shadelab::PartKsTextureScaleArrayName);
  ASSERT_NE(scale, nullptr);
  ASSERT_EQ(scale->GetNumberOfTuples(), 2);
  ASSERT_EQ(scale->GetNumberOfComponents(), 3);
  const double* metal = scale->GetTuple3(0);
  EXPECT_EQ(std::vector<double>(metal, metal + 3), (std::vector<double>{ 0.25, 0.125, 0.5 }));
  const double* dielectric = scale->GetTuple3(1);
  EXPECT_EQ(std::vector<double>(dielectric, dielectric + 3), (std::vector<double>{ 0, 0, 0 }));
}

TEST_F(GltfTextures, SamplerDefaultsDataUrisAndSharedTextures)
{
  // No sampler: REPEAT, and LINEAR where glTF leaves the filters open.
  const ReadResult plain = this->ReadEdited([](Json& doc) { doc["textures"][0].erase("sampler"); });
  ASSERT_TRUE(plain.Ok) << plain.Error;
  EXPECT_EQ(Ints(plain.Mesh, shadelab::TextureWrapSArrayName), (std::vector<int>{ 10497 }));
  EXPECT_EQ(Ints(plain.Mesh, shadelab::TextureMinFilterArrayName), (std::vector<int>{ 9729 }));

  // The image as a data URI: embedded, its bytes decoded; a second
  // material using the same texture shares it.
  const std::string png = FileBytes(this->Dir / "CesiumLogoFlat.png");
  const ReadResult embedded = this->ReadEdited(
    [&](Json& doc)
    {
      std::string base64(png.size() * 4 / 3 + 4, '\0');
      base64.resize(vtkBase64Utilities::Encode(reinterpret_cast<const unsigned char*>(png.data()),
        png.size(), reinterpret_cast<unsigned char*>(base64.data())));
      doc["images"][0]["uri"] = "data:image/png;base64," + base64;
      doc["samplers"][0] = { { "wrapS", 33071 }, { "wrapT", 33648 }, { "magFilter", 9728 } };
      doc["materials"].push_back(doc["materials"][0]);
      doc["meshes"][0]["primitives"].push_back(doc["meshes"][0]["primitives"][0]);
      doc["meshes"][0]["primitives"][1]["material"] = 1;
    });
  ASSERT_TRUE(embedded.Ok) << embedded.Error;
  EXPECT_EQ(Sources(embedded.Mesh), (std::vector<std::string>{ "" }));
  auto* bytes =
    vtkUnsignedCharArray::SafeDownCast(embedded.Mesh->GetFieldData()->GetArray("TextureBytes0"));
  ASSERT_NE(bytes, nullptr);
  EXPECT_EQ(
    std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)), bytes->GetNumberOfValues()),
    png);
  EXPECT_EQ(Ints(embedded.Mesh, shadelab::PartKdTextureArrayName), (std::vector<int>{ 0, 0 }));
  EXPECT_EQ(Ints(embedded.Mesh, shadelab::TextureWrapSArrayName), (std::vector<int>{ 33071 }));
  EXPECT_EQ(Ints(embedded.Mesh, shadelab::TextureWrapTArrayName), (std::vector<int>{ 33648 }));
  EXPECT_EQ(Ints(embedded.Mesh, shadelab::TextureMagFilterArrayName), (std::vector<int>{ 9728 }));
  // A sampler without filters: LINEAR for both.
  EXPECT_EQ(Ints(embedded.Mesh, shadelab::TextureMinFilterArrayName), (std::vector<int>{ 9729 }));
}

// What is not drawn is a warning: another texture coordinate set, a
// texture whose image an extension gives.
TEST_F(GltfTextures, TexturesNotDrawnAreWarnings)
{
  const ReadResult second = this->ReadEdited([](Json& doc)
    { doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["texCoord"] = 1; });
  ASSERT_TRUE(second.Ok) << second.Error;
  ASSERT_EQ(second.Warnings.size(), 1u);
  EXPECT_NE(
    second.Warnings[0].find("material 0 baseColorTexture uses TEXCOORD_1"), std::string::npos)
    << second.Warnings[0];
  EXPECT_EQ(Ints(second.Mesh, shadelab::PartKdTextureArrayName), (std::vector<int>{ -1 }));
  EXPECT_TRUE(Sources(second.Mesh).empty());

  const ReadResult sourceless =
    this->ReadEdited([](Json& doc) { doc["textures"][0].erase("source"); });
  ASSERT_TRUE(sourceless.Ok) << sourceless.Error;
  ASSERT_EQ(sourceless.Warnings.size(), 1u);
  EXPECT_NE(sourceless.Warnings[0].find("texture 0 has no source"), std::string::npos);
}

// KHR_texture_transform on the base colour texture, in extensionsRequired
// too: the primitive's coordinates mapped as the extension says (scale,
// then the rotation, then the offset, in glTF's u and v, v down the image),
// and its texCoord overriding the textureInfo's.
TEST_F(GltfTextures, TextureTransformMapsTheCoordinates)
{
  const auto transform = [](const Json& extension)
  {
    return [extension](Json& doc)
    {
      doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
        { "KHR_texture_transform", extension }
      };
      doc["extensionsUsed"] = { "KHR_texture_transform" };
      doc["extensionsRequired"] = { "KHR_texture_transform" };
    };
  };
  const ReadResult plain = this->ReadEdited([](Json&) {});
  const ReadResult moved = this->ReadEdited(transform(
    { { "offset", { 0.5, 0.25 } }, { "rotation", std::acos(-1.0) / 2 }, { "scale", { 2, 4 } } }));
  ASSERT_TRUE(plain.Ok) << plain.Error;
  ASSERT_TRUE(moved.Ok) << moved.Error;
  EXPECT_TRUE(moved.Warnings.empty());
  vtkDataArray* before = plain.Mesh->GetPointData()->GetTCoords();
  vtkDataArray* after = moved.Mesh->GetPointData()->GetTCoords();
  ASSERT_NE(after, nullptr);
  ASSERT_EQ(after->GetNumberOfTuples(), before->GetNumberOfTuples());
  for (vtkIdType p = 0; p < before->GetNumberOfTuples(); ++p)
  {
    // t is 1 - v; a quarter turn counter-clockwise takes (u, v) to (v, -u).
    const double u = before->GetComponent(p, 0), v = 1 - before->GetComponent(p, 1);
    EXPECT_NEAR(after->GetComponent(p, 0), 4 * v + 0.5, 1e-6) << "point " << p;
    EXPECT_NEAR(after->GetComponent(p, 1), 1 - (-2 * u + 0.25), 1e-6) << "point " << p;
  }

  const ReadResult second = this->ReadEdited(transform({ { "texCoord", 1 } }));
  ASSERT_TRUE(second.Ok) << second.Error;
  ASSERT_EQ(second.Warnings.size(), 1u);
  EXPECT_NE(
    second.Warnings[0].find("material 0 baseColorTexture uses TEXCOORD_1"), std::string::npos);
  this->ExpectEditError(transform({ { "scale", { 1, "x" } } }),
    { "material 0 baseColorTexture KHR_texture_transform" });
}

TEST_F(GltfTextures, BadTextureReferences)
{
  this->ExpectEditError([](Json& doc)
    { doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] = 3; },
    { "material 0 baseColorTexture refers to textures[3]" });
  this->ExpectEditError([](Json& doc)
    { doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = 0; },
    { "material 0 baseColorTexture is not an object" });
  this->ExpectEditError(
    [](Json& doc) { doc["textures"][0]["source"] = 1; }, { "texture 0 refers to images[1]" });
  this->ExpectEditError(
    [](Json& doc) { doc["textures"][0]["sampler"] = 2; }, { "texture 0 refers to samplers[2]" });
  this->ExpectEditError([](Json& doc) { doc["samplers"][0]["wrapS"] = 10496; },
    { "sampler 0.wrapS is 10496", "not define" });
  this->ExpectEditError([](Json& doc) { doc["samplers"][0]["minFilter"] = -1; }, { "minFilter" });
  this->ExpectEditError(
    [](Json& doc) {
      doc["images"][0] = { { "bufferView", 7 } };
    },
    { "image 0 refers to bufferViews[7]" });
  this->ExpectEditError(
    [](Json& doc)
    {
      doc["bufferViews"].push_back(
        { { "buffer", 0 }, { "byteOffset", 800 }, { "byteLength", 41 } });
      doc["images"][0] = { { "bufferView", 3 }, { "mimeType", "image/png" } };
    },
    { "bufferView 3's byteOffset 800 and byteLength 41 go past the end of buffer 0, which has "
      "840" });
  this->ExpectEditError([](Json& doc) { doc["images"][0]["uri"] = "data:image/png;base64,iVBO!"; },
    { "image 0", "malformed base64" });
  this->ExpectEditError(
    [](Json& doc) { doc["images"][0]["uri"] = "data:image/png,raw"; }, { "image 0", "not base64" });
}
}
