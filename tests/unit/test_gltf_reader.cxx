// The glTF reader: Khronos' BoxTextured in its three forms (from Debian's
// assimp-testmodels), documents built here (node transforms, strips and
// fans, attributes, parts and materials, the three ways of storing
// buffers), and bad input of every kind.
#include "gltf_document_builder.h"
#include "mesh_reader_fixture.h"
#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabGLTFReader.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>

#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <set>

namespace
{
using namespace shadelab::test;

constexpr double Pi = 3.14159265358979323846;

// accessors[a].sparse: `count` elements, `indices` (UNSIGNED_BYTE) and
// `values` (floats) in views of their own.
void MakeSparse(Gltf& gltf, int a, std::size_t count, const std::vector<std::uint8_t>& indices,
  const std::vector<float>& values)
{
  std::string i, v;
  for (const std::uint8_t index : indices)
  {
    Put(i, index);
  }
  for (const float value : values)
  {
    Put(v, value);
  }
  gltf.Doc["accessors"][a]["sparse"] = { { "count", count },
    { "indices", { { "bufferView", gltf.View(i) }, { "componentType", UnsignedByte } } },
    { "values", { { "bufferView", gltf.View(v) } } } };
}

std::array<double, 3> Point(vtkPolyData* mesh, vtkIdType i)
{
  std::array<double, 3> p;
  mesh->GetPoint(i, p.data());
  return p;
}

std::array<double, 3> Tuple3(vtkDataArray* array, vtkIdType i)
{
  std::array<double, 3> t;
  array->GetTuple(i, t.data());
  return t;
}

void ExpectNear(const std::array<double, 3>& actual, const std::array<double, 3>& expected,
  double tolerance = 1e-12)
{
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(actual[k], expected[k], tolerance) << "component " << k;
  }
}

// Each triangle's area normal points the way of its vertices' normals:
// winding and normal transform agree (front faces stay in front).
void ExpectWindingAgreesWithNormals(vtkPolyData* mesh)
{
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  for (const auto& triangle : Triangles(mesh))
  {
    const auto area = AreaNormal(mesh, triangle);
    for (const vtkIdType v : triangle)
    {
      const auto n = Tuple3(normals, v);
      EXPECT_GT(vtkMath::Dot(area.data(), n.data()), 0.0) << "vertex " << v;
    }
  }
}

std::vector<int> Parts(vtkPolyData* mesh)
{
  auto* parts = vtkIntArray::SafeDownCast(mesh->GetCellData()->GetArray(shadelab::PartArrayName));
  EXPECT_NE(parts, nullptr);
  std::vector<int> values;
  for (vtkIdType i = 0; parts && i < parts->GetNumberOfValues(); ++i)
  {
    values.push_back(parts->GetValue(i));
  }
  return values;
}

std::vector<std::string> MaterialNames(vtkPolyData* mesh)
{
  auto* names = vtkStringArray::SafeDownCast(
    mesh->GetFieldData()->GetAbstractArray(shadelab::PartMaterialsArrayName));
  EXPECT_NE(names, nullptr);
  std::vector<std::string> values;
  for (vtkIdType i = 0; names && i < names->GetNumberOfValues(); ++i)
  {
    values.push_back(names->GetValue(i));
  }
  return values;
}

std::vector<int> MaterialIndices(vtkPolyData* mesh)
{
  auto* indices = vtkIntArray::SafeDownCast(
    mesh->GetFieldData()->GetArray(shadelab::PartMaterialIndicesArrayName));
  EXPECT_NE(indices, nullptr);
  std::vector<int> values;
  for (vtkIdType i = 0; indices && i < indices->GetNumberOfValues(); ++i)
  {
    values.push_back(indices->GetValue(i));
  }
  return values;
}

// (point, normal) pairs, rounded to floats: what two writers of one mesh share.
std::set<std::array<float, 6>> PointsWithNormals(vtkPolyData* mesh)
{
  std::set<std::array<float, 6>> pairs;
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    const auto p = Point(mesh, i);
    const auto n = Tuple3(normals, i);
    pairs.insert({ static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]),
      static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]) });
  }
  return pairs;
}

// ---------------------------------------------------------------------------
// The real files

// Khronos' BoxTextured as Debian's assimp-testmodels hold it: the document
// with its buffer and image as files, as data URIs, and as GLB.
const fs::path BoxTextured = DebianModels / "glTF2";
const char* const BoxTexturedForms[] = { "BoxTextured-glTF/BoxTextured.gltf",
  "BoxTextured-glTF-Embedded/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb" };

TEST_F(MeshReaders, KhronosBoxIsTurnedByItsParentNodesMatrix)
{
  // The buffer's first vertex is (-0.5, -0.5, 0.5) with normal (0, 0, 1);
  // the parent's matrix (columns x, -z, y) turns +Y up into +Z up:
  // (x, y, z) -> (x, z, -y).
  const ReadResult result = Read(BoxTextured / BoxTexturedForms[0]);
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 24);
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 12);
  ExpectNear(Point(result.Mesh, 0), { -0.5, 0.5, 0.5 });
  ExpectNear(Tuple3(result.Mesh->GetPointData()->GetNormals(), 0), { 0, 1, 0 });
  ExpectWindingAgreesWithNormals(result.Mesh);
  EXPECT_EQ(Parts(result.Mesh), std::vector<int>(12, 0));
  EXPECT_EQ(MaterialNames(result.Mesh), std::vector<std::string>{ "Texture" });
  EXPECT_EQ(MaterialIndices(result.Mesh), std::vector<int>{ 0 });
}

TEST_F(MeshReaders, TheBoxAsFilesDataUrisAndGlbIsOneMesh)
{
  const ReadResult files = Read(BoxTextured / BoxTexturedForms[0]);
  ASSERT_TRUE(files.Ok) << files.Error;
  for (const char* name : { BoxTexturedForms[1], BoxTexturedForms[2] })
  {
    SCOPED_TRACE(name);
    const ReadResult result = Read(BoxTextured / name);
    ASSERT_TRUE(result.Ok) << result.Error;
    EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 12);
    EXPECT_EQ(PointsWithNormals(result.Mesh), PointsWithNormals(files.Mesh));
    ExpectWindingAgreesWithNormals(result.Mesh);
    EXPECT_EQ(MaterialNames(result.Mesh), MaterialNames(files.Mesh));
  }
}

// One mesh on two nodes, the second moved by 1 along x; positions and
// normals interleaved in one bufferView (byteStride 24); `scenes` without
// `scene`; CRLF line ends: as Khronos' SimpleMeshes sample is made.
TEST_F(MeshReaders, AMeshOnTwoNodesIsDrawnOncePerNode)
{
  Gltf gltf;
  std::string interleaved;
  const float triangle[3][6] = { { 0, 0, 0, 0, 0, 1 }, { 1, 0, 0, 0, 0, 1 }, { 0, 1, 0, 0, 0, 1 } };
  for (const auto& vertex : triangle)
  {
    for (const float x : vertex)
    {
      Put(interleaved, x);
    }
  }
  const int view = gltf.View(interleaved, 24);
  const int position = gltf.Accessor(view, Float, 3, "VEC3");
  const int normal = gltf.Accessor(view, Float, 3, "VEC3");
  gltf.Doc["accessors"][normal]["byteOffset"] = 12;
  Json primitive = Primitive(position);
  primitive["attributes"]["NORMAL"] = normal;
  const int mesh = gltf.Mesh({ primitive });
  const int first = gltf.Node({ { "mesh", mesh } });
  const int second = gltf.Node({ { "mesh", mesh }, { "translation", { 1, 0, 0 } } });
  gltf.Doc["scenes"] = Json::array({ { { "nodes", { first, second } } } });
  std::string text;
  for (const char c : gltf.DataUri())
  {
    text += c == '\n' ? std::string("\r\n") : std::string(1, c);
  }
  const ReadResult result = Read(this->Write("simple-meshes.gltf", text));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  ASSERT_EQ(result.Mesh->GetNumberOfPoints(), 6);
  for (vtkIdType i = 0; i < 3; ++i)
  {
    const auto first = Point(result.Mesh, i);
    ExpectNear(Point(result.Mesh, i + 3), { first[0] + 1, first[1], first[2] });
    ExpectNear(Tuple3(result.Mesh->GetPointData()->GetNormals(), i), { 0, 0, 1 });
  }
  ExpectWindingAgreesWithNormals(result.Mesh);
  EXPECT_EQ(Parts(result.Mesh), (std::vector<int>{ 0, 1 }));
  EXPECT_EQ(MaterialNames(result.Mesh), (std::vector<std::string>{ "", "" }));
  EXPECT_EQ(MaterialIndices(result.Mesh), (std::vector<int>{ -1, -1 }));
}

// ---------------------------------------------------------------------------
// Documents built here

TEST_F(MeshReaders, GltfBufferAsFileDataUriOrGlbChunkGivesTheSameMesh)
{
  const Gltf gltf = SquareDocument();
  this->Write("square.bin", gltf.Buffer);
  this->Write("my square.bin", gltf.Buffer);
  for (const fs::path& path : { this->Write("file.gltf", gltf.Text("square.bin")),
         this->Write("escaped.gltf", gltf.Text("my%20square.bin")),
         this->Write("embedded.gltf", gltf.DataUri()), this->Write("binary.GLB", gltf.Glb()) })
  {
    SCOPED_TRACE(path.filename().string());
    const ReadResult result = Read(path);
    ASSERT_TRUE(result.Ok) << result.Error;
    ExpectTriangleMesh(result.Mesh);
    ASSERT_EQ(result.Mesh->GetNumberOfPoints(), 4);
    EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 2);
    ExpectNear(Point(result.Mesh, 2), { 1, 1, 0 });
    EXPECT_EQ(result.Mesh->GetPointData()->GetNumberOfArrays(), 0);
  }
}

// Sparse accessors (core glTF 2.0; morph targets use them): their elements
// replace the base's, or the zeros of an accessor without a bufferView.
TEST_F(MeshReaders, GltfSparseAccessorsReplaceTheirBasesElements)
{
  Gltf patched = SquareDocument();
  std::string wrong; // the square with corner 2 at 5 5 5, put right by the sparse element
  for (const float value : { 0, 0, 0, 1, 0, 0, 5, 5, 5, 0, 1, 0 })
  {
    Put(wrong, value);
  }
  patched.Doc["accessors"][0]["bufferView"] = patched.View(wrong);
  MakeSparse(patched, 0, 1, { 2 }, { 1, 1, 0 });
  Gltf zeros = SquareDocument();
  zeros.Doc["accessors"][0].erase("bufferView");
  MakeSparse(zeros, 0, 3, { 1, 2, 3 }, { 1, 0, 0, 1, 1, 0, 0, 1, 0 });
  const std::vector<std::pair<std::string, const Gltf*>> cases{ { "patched", &patched },
    { "zeros", &zeros } };
  for (const auto& [name, gltf] : cases)
  {
    SCOPED_TRACE(name);
    const ReadResult result = Read(this->Write(name + ".glb", gltf->Glb()));
    ASSERT_TRUE(result.Ok) << result.Error;
    ASSERT_EQ(result.Mesh->GetNumberOfPoints(), 4);
    for (vtkIdType i = 0; i < 4; ++i)
    {
      ExpectNear(Point(result.Mesh, i), { Square[3 * i], Square[3 * i + 1], Square[3 * i + 2] });
    }
  }
}

TEST_F(MeshReaders, GltfNodeTranslationRotationScaleAndChildNodeCompose)
{
  // Parent: translate (10, 0, 0), turn 90 degrees about +z, scale (2, 1, 1);
  // child: translate (1, 0, 0). A point p goes to T R S (p + (1, 0, 0)):
  // (x, y, z) -> (10 - y, 2 (x + 1), z).
  const double s = std::sin(Pi / 4);
  Gltf gltf;
  const int normal = gltf.Vec3({ 0, 0, 1, 0, 0, 1, 0.6f, 0.8f, 0, 0.6f, 0.8f, 0 });
  Json primitive = Primitive(gltf.Vec3(Square), gltf.Indices({ 0, 1, 2, 0, 2, 3 }));
  primitive["attributes"]["NORMAL"] = normal;
  const int child =
    gltf.Node({ { "mesh", gltf.Mesh({ primitive }) }, { "translation", { 1, 0, 0 } } });
  const Json parent = { { "children", { child } }, { "translation", { 10, 0, 0 } },
    { "rotation", { 0, 0, s, s } }, { "scale", { 2, 1, 1 } } };
  gltf.Scene({ gltf.Node(parent) });

  const ReadResult result = Read(this->Write("trs.glb", gltf.Glb()));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectNear(Point(result.Mesh, 0), { 10, 2, 0 });
  ExpectNear(Point(result.Mesh, 1), { 10, 4, 0 });
  ExpectNear(Point(result.Mesh, 2), { 9, 4, 0 });
  ExpectNear(Point(result.Mesh, 3), { 9, 2, 0 });
  // Normals by the inverse transpose: (nx, ny, nz) -> (-ny, nx / 2, nz),
  // renormalised; (0.6, 0.8, 0) -> (-0.8, 0.3, 0) / |.|.
  vtkDataArray* normals = result.Mesh->GetPointData()->GetNormals();
  ExpectNear(Tuple3(normals, 0), { 0, 0, 1 }, 1e-7);
  const double length = std::hypot(0.8, 0.3);
  ExpectNear(Tuple3(normals, 2), { -0.8 / length, 0.3 / length, 0 }, 1e-7);

  // The same transforms as matrices (column-major) give the same mesh.
  Gltf matrices = gltf;
  matrices.Doc["nodes"][1] = { { "children", { child } },
    { "matrix", { 0, 2, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0, 10, 0, 0, 1 } } };
  matrices.Doc["nodes"][0].erase("translation");
  matrices.Doc["nodes"][0]["matrix"] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 1 };
  const ReadResult same = Read(this->Write("matrix.glb", matrices.Glb()));
  ASSERT_TRUE(same.Ok) << same.Error;
  for (vtkIdType i = 0; i < 4; ++i)
  {
    ExpectNear(Point(same.Mesh, i), Point(result.Mesh, i));
    ExpectNear(Tuple3(same.Mesh->GetPointData()->GetNormals(), i), Tuple3(normals, i), 1e-7);
  }
}

TEST_F(MeshReaders, GltfStripsAndFansBecomeTrianglesFacingTheirNormals)
{
  // One mesh: the square as a strip (0 1 3 2), as a fan (0 1 2 3) and as
  // triangles, each a primitive of its own, on a plain node and on one that
  // mirrors x (determinant < 0: glTF turns the triangles round).
  for (const double mirror : { 1.0, -1.0 })
  {
    SCOPED_TRACE(mirror);
    Gltf gltf;
    const int position = gltf.Vec3(Square);
    const int normal = gltf.Vec3({ 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1 });
    std::vector<Json> primitives = { Primitive(position, gltf.Indices({ 0, 1, 3, 2 }), 5),
      Primitive(position, gltf.Indices({ 0, 1, 2, 3 }), 6),
      Primitive(position, gltf.Indices({ 0, 1, 2, 0, 2, 3 }), 4) };
    for (Json& primitive : primitives)
    {
      primitive["attributes"]["NORMAL"] = normal;
    }
    gltf.Scene({ gltf.Node({ { "mesh", gltf.Mesh(primitives) }, { "scale", { mirror, 1, 1 } } }) });

    const ReadResult result = Read(this->Write("modes.gltf", gltf.DataUri()));
    ASSERT_TRUE(result.Ok) << result.Error;
    ExpectTriangleMesh(result.Mesh);
    EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 6);
    ExpectWindingAgreesWithNormals(result.Mesh);
    // Each primitive gives two triangles covering the square once.
    const std::vector<int> parts = Parts(result.Mesh);
    const auto triangles = Triangles(result.Mesh);
    ASSERT_EQ(parts.size(), triangles.size());
    std::map<int, double> area;
    for (std::size_t t = 0; t < triangles.size(); ++t)
    {
      const auto n = AreaNormal(result.Mesh, triangles[t]);
      area[parts[t]] += 0.5 * std::abs(n[2]);
      EXPECT_GT(n[2], 0.0) << "mirrored or not, the square faces +z, the way of its normals";
    }
    EXPECT_EQ(area, (std::map<int, double>{ { 0, 1.0 }, { 1, 1.0 }, { 2, 1.0 } }));
  }
}

TEST_F(MeshReaders, GltfColoursTextureCoordinatesAndTheirDefaults)
{
  // Primitive 0: float RGBA colours and float texture coordinates; primitive
  // 1: normalized UNSIGNED_BYTE RGB and UNSIGNED_SHORT texture coordinates;
  // primitive 2: neither (white, 0 0).
  Gltf gltf;
  const int position = gltf.Vec3({ 0, 0, 0, 1, 0, 0, 0, 1, 0 });
  Json a = Primitive(position);
  a["attributes"]["COLOR_0"] =
    gltf.Values(std::vector<float>{ 1, 0, 0, 0.5f, 0, 1, 0, 1, 0, 0, 1, 1 }, Float, "VEC4", 4);
  a["attributes"]["TEXCOORD_0"] =
    gltf.Values(std::vector<float>{ 0, 0, 1, 0, 0, 0.25f }, Float, "VEC2", 2);
  Json b = Primitive(position);
  b["attributes"]["COLOR_0"] = gltf.Values(
    std::vector<std::uint8_t>{ 255, 0, 0, 0, 51, 0, 0, 0, 255 }, UnsignedByte, "VEC3", 3, true);
  b["attributes"]["TEXCOORD_0"] = gltf.Values(
    std::vector<std::uint16_t>{ 0, 65535, 65535, 0, 0, 0 }, UnsignedShort, "VEC2", 2, true);
  const Json c = Primitive(position);
  gltf.Scene({ gltf.Node({ { "mesh", gltf.Mesh({ a, b, c }) } }) });

  const ReadResult result = Read(this->Write("attributes.glb", gltf.Glb()));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  vtkDataArray* colors = result.Mesh->GetPointData()->GetArray(shadelab::ColorsArrayName);
  vtkDataArray* uv = result.Mesh->GetPointData()->GetTCoords();
  ASSERT_TRUE(colors && uv);
  const auto rgba = [&](vtkIdType i)
  {
    std::array<double, 4> t;
    colors->GetTuple(i, t.data());
    return t;
  };
  EXPECT_EQ(rgba(0), (std::array<double, 4>{ 1, 0, 0, 0.5 }));
  EXPECT_NEAR(rgba(4)[1], 0.2, 1e-7);
  EXPECT_EQ(rgba(4)[3], 1.0);
  EXPECT_EQ(rgba(7), (std::array<double, 4>{ 1, 1, 1, 1 }));
  // glTF counts v from the top, VTK t from the bottom: t = 1 - v.
  EXPECT_EQ(uv->GetComponent(0, 1), 1.0);
  EXPECT_EQ(uv->GetComponent(2, 1), 0.75);
  EXPECT_EQ(uv->GetComponent(3, 1), 0.0);
  EXPECT_EQ(uv->GetComponent(4, 0), 1.0);
  EXPECT_EQ(uv->GetComponent(8, 0), 0.0);
  EXPECT_EQ(uv->GetComponent(8, 1), 0.0);
}

TEST_F(MeshReaders, GltfPartsCarryTheirMaterials)
{
  Gltf gltf;
  const int position = gltf.Vec3(Square);
  Json red = Primitive(position, gltf.Indices({ 0, 1, 2 }));
  red["material"] = 1;
  Json blue = Primitive(position, gltf.Indices({ 0, 2, 3 }));
  blue["material"] = 0;
  gltf.Doc["materials"] = { { { "name", "blue" },
                              { "pbrMetallicRoughness",
                                { { "baseColorFactor", { 0.2, 0.4, 1, 1 } },
                                  { "metallicFactor", 0.25 }, { "roughnessFactor", 0.5 } } } },
    { { "name", "red" } } };
  gltf.Scene({ gltf.Node({ { "mesh", gltf.Mesh({ red, blue, Primitive(position) }) } }) });
  gltf.Doc["meshes"][0]["primitives"][2]["indices"] = gltf.Indices({ 1, 2, 3 });

  const ReadResult result = Read(this->Write("materials.gltf", gltf.DataUri()));
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(Parts(result.Mesh), (std::vector<int>{ 0, 1, 2 }));
  EXPECT_EQ(MaterialNames(result.Mesh), (std::vector<std::string>{ "red", "blue", "" }));
  EXPECT_EQ(MaterialIndices(result.Mesh), (std::vector<int>{ 1, 0, -1 }));
  // The lecture's coefficients (shadelabGLTFMaterial.h): red has the
  // specification's defaults (white, metallic 1, roughness 1); blue
  // kd = B (1 - m), ka = kd, ks = 0.04 (1 - m) + B m, ns = 2/r^4 - 2.
  const std::vector<std::array<double, 3>> ka{ { 0, 0, 0 }, { 0.15, 0.3, 0.75 }, { 0, 0, 0 } },
    kd = ka, ks{ { 1, 1, 1 }, { 0.08, 0.13, 0.28 }, { 0, 0, 0 } };
  const std::vector<double> ns{ 0, 30, 0 };
  vtkFieldData* field = result.Mesh->GetFieldData();
  for (vtkIdType part = 0; part < 3; ++part)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_FLOAT_EQ(
        field->GetArray(shadelab::PartKaArrayName)->GetComponent(part, c), ka[part][c]);
      EXPECT_FLOAT_EQ(
        field->GetArray(shadelab::PartKdArrayName)->GetComponent(part, c), kd[part][c]);
      EXPECT_FLOAT_EQ(
        field->GetArray(shadelab::PartKsArrayName)->GetComponent(part, c), ks[part][c]);
    }
    EXPECT_FLOAT_EQ(field->GetArray(shadelab::PartNsArrayName)->GetComponent(part, 0), ns[part]);
  }
}

// a by alphaMode (shadelabGLTFMaterial.h): OPAQUE (the default) ignores
// the alpha, BLEND takes it, MASK cuts at alphaCutoff (default 0.5).
TEST_F(MeshReaders, GltfOpacityFollowsAlphaMode)
{
  const std::vector<std::pair<Json, double>> cases{
    { Json::object(), 1 },
    { { { "alphaMode", "OPAQUE" } }, 1 },
    { { { "alphaMode", "BLEND" } }, 0.25 },
    { { { "alphaMode", "MASK" } }, 0 },
    { { { "alphaMode", "MASK" }, { "alphaCutoff", 0.2 } }, 1 },
  };
  Gltf gltf;
  const int position = gltf.Vec3(Square);
  Json materials = Json::array(), primitives = Json::array();
  for (std::size_t k = 0; k < cases.size(); ++k)
  {
    Json material = cases[k].first;
    material["pbrMetallicRoughness"] = { { "baseColorFactor", { 1, 1, 1, 0.25 } } };
    materials.push_back(material);
    Json primitive = Primitive(position, gltf.Indices({ 0, 1, 2 }));
    primitive["material"] = static_cast<int>(k);
    primitives.push_back(primitive);
  }
  gltf.Doc["materials"] = materials;
  gltf.Scene({ gltf.Node({ { "mesh", gltf.Mesh(primitives) } }) });
  const ReadResult result = Read(this->Write("alpha.gltf", gltf.DataUri()));
  ASSERT_TRUE(result.Ok) << result.Error;
  vtkDataArray* a = result.Mesh->GetFieldData()->GetArray(shadelab::PartTranslucencyArrayName);
  ASSERT_NE(a, nullptr);
  for (std::size_t k = 0; k < cases.size(); ++k)
  {
    EXPECT_EQ(a->GetComponent(static_cast<vtkIdType>(k), 0), cases[k].second) << cases[k].first;
  }
  gltf.Doc["materials"][0]["alphaMode"] = "HALF";
  const ReadResult bad = Read(this->Write("bad-alpha.gltf", gltf.DataUri()));
  EXPECT_FALSE(bad.Ok);
  EXPECT_NE(bad.Error.find("alphaMode is \"HALF\""), std::string::npos) << bad.Error;
}

TEST_F(MeshReaders, GltfSkipsPointsAndLinesAndPartialNormalsWithAWarning)
{
  Gltf gltf = SquareDocument();
  const int position = gltf.Vec3(Square);
  gltf.Doc["meshes"][0]["primitives"].push_back(Primitive(position, -1, 0));
  gltf.Doc["meshes"][0]["primitives"].push_back(Primitive(position, -1, 3));
  Json lit = Primitive(position, gltf.Indices({ 1, 2, 3 }));
  lit["attributes"]["NORMAL"] = gltf.Vec3({ 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1 });
  gltf.Doc["meshes"][0]["primitives"].push_back(lit);

  const ReadResult result = Read(this->Write("mixed.glb", gltf.Glb()));
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetNumberOfPolys(), 3);
  EXPECT_EQ(result.Mesh->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(Parts(result.Mesh), (std::vector<int>{ 0, 0, 1 }));
  EXPECT_EQ(result.Warnings,
    (std::vector<std::string>{ "skipped 2 primitives of points or lines: shadelab draws triangles",
      "some primitives have no NORMAL, so the file's normals are ignored" }));

  // Without triangles there is nothing to draw.
  Gltf lines;
  lines.Scene({ lines.Node({ { "mesh", lines.Mesh({ Primitive(lines.Vec3(Square), -1, 1) }) } }) });
  this->ExpectError("lines.glb", lines.Glb(), { "no triangles" });
}

TEST_F(MeshReaders, GltfDefaultSceneWithoutScenesAndWithoutNodes)
{
  // "scene" picks the second scene, which shows the translated node.
  Gltf gltf = SquareDocument();
  gltf.Node({ { "mesh", 0 }, { "translation", { 0, 0, 5 } } });
  gltf.Doc["scenes"].push_back({ { "nodes", { 1 } } });
  gltf.Doc["scene"] = 1;
  ReadResult result = Read(this->Write("second.glb", gltf.Glb()));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectNear(Point(result.Mesh, 0), { 0, 0, 5 });

  // Without scenes: every node that is nobody's child.
  gltf.Doc.erase("scenes");
  gltf.Doc.erase("scene");
  gltf.Doc["nodes"][0]["children"] = { 1 };
  result = Read(this->Write("roots.glb", gltf.Glb()));
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 8); // node 1 once, as node 0's child

  // Without nodes: every mesh as it is.
  gltf.Doc.erase("nodes");
  result = Read(this->Write("meshes.glb", gltf.Glb()));
  ASSERT_TRUE(result.Ok) << result.Error;
  EXPECT_EQ(result.Mesh->GetNumberOfPoints(), 4);
}

// ---------------------------------------------------------------------------
// Bad input

// A mesh drawn by many nodes costs the file nothing: 310 KB of GLB drew one
// 50k-triangle mesh 200 times. Instances may make 4Mi triangles, counted
// before anything is read; 64 of these 65536 would be the most.
TEST_F(MeshReaders, GltfInstancesMayMakeAtMostFourMebiTriangles)
{
  Gltf gltf;
  const int position = gltf.Vec3({ 0, 0, 0, 1, 0, 0, 0, 1, 0 });
  std::vector<std::uint16_t> corners;
  for (int t = 0; t < 65536; ++t)
  {
    corners.insert(corners.end(), { 0, 1, 2 });
  }
  const int mesh = gltf.Mesh({ Primitive(position, gltf.Indices(corners)) });
  std::vector<int> nodes;
  for (int n = 0; n < 65; ++n)
  {
    nodes.push_back(gltf.Node({ { "mesh", mesh } }));
  }
  gltf.Scene(nodes);
  this->ExpectError("instances.glb", gltf.Glb(),
    { "its nodes draw its meshes' 65536 triangles as 4259840 (about 65 times); instances may "
      "make at most 4194304 triangles" });
}

TEST_F(MeshReaders, BadGlbContainers)
{
  const std::string glb = SquareDocument().Glb();
  this->ExpectError("cut.glb", glb.substr(0, glb.size() - 8),
    { "truncated: the GLB header says", "bytes, the file has" });
  this->ExpectError("header.glb", glb.substr(0, 10), { "truncated: a GLB header takes 12 bytes" });
  this->ExpectError(
    "longer.glb", glb + std::string(4, '\0'), { "the GLB header says", "but the file has" });
  std::string version = glb;
  version[4] = 1;
  this->ExpectError("version.glb", version, { "GLB version 1 is not supported" });
  std::string chunk = glb;
  chunk[12] = '\xff';
  chunk[13] = '\xff';
  this->ExpectError("chunk.glb", chunk, { "truncated: a GLB chunk at byte 12 says" });
  std::string type = glb;
  type[16] = 'X';
  this->ExpectError("type.glb", type, { "the GLB's first chunk is not JSON" });
  this->ExpectError("magic.gltf", glb.substr(0, 12), { "truncated", "GLB" });
  std::string magic = glb;
  magic[0] = 'x';
  this->ExpectError("magic.glb", magic, { "not a GLB: it starts with 'xlTF', not 'glTF'" });
  // A buffer without a uri is the BIN chunk, which this GLB lacks.
  const std::string json = SquareDocument().Text("");
  std::string noBin;
  Put(noBin, std::uint32_t{ 0x46546C67 });
  Put(noBin, std::uint32_t{ 2 });
  Put(noBin, static_cast<std::uint32_t>(20 + json.size()));
  Put(noBin, static_cast<std::uint32_t>(json.size()));
  Put(noBin, std::uint32_t{ 0x4E4F534A });
  this->ExpectError("nobin.glb", noBin + json, { "buffer 0 has no uri" });
}

TEST_F(MeshReaders, BadGltfDocumentsAndBuffers)
{
  const Gltf gltf = SquareDocument();
  this->ExpectError("syntax.gltf", gltf.DataUri().substr(0, 40), { "not JSON: line" });
  this->ExpectError("array.gltf", "[1, 2]", { "the glTF JSON is not an object" });
  this->ExpectError("asset.gltf", "{}", { "no \"asset\" object" });
  Gltf old = gltf;
  old.Doc["asset"]["version"] = "1.0";
  this->ExpectError("version.gltf", old.DataUri(), { "glTF version '1.0' is not supported" });
  Gltf basisu = gltf;
  basisu.Doc["extensionsRequired"] = { "KHR_texture_basisu" };
  this->ExpectError("basisu.gltf", basisu.DataUri(),
    { "requires the extension \"KHR_texture_basisu\", which shadelab does not read" });

  this->ExpectError("missing.gltf", gltf.Text("missing.bin"),
    { "buffer 0: 'missing.bin': cannot open: No such file or directory" });
  this->Write("short.bin", gltf.Buffer.substr(0, 10));
  this->ExpectError("short.gltf", gltf.Text("short.bin"),
    { "truncated: buffer 0 declares", "but 'short.bin' has 10" });
  // A uri naming a folder, a pipe (whose opening would block) or a device.
  this->ExpectError(
    "folder.gltf", gltf.Text("."), { "buffer 0: '.': cannot open: Is a directory" });
  ASSERT_EQ(mkfifo((this->Dir / "pipe").c_str(), 0600), 0);
  this->ExpectError(
    "pipe.gltf", gltf.Text("pipe"), { "buffer 0: 'pipe': is not a regular file but a FIFO" });
  fs::create_symlink("/dev/zero", this->Dir / "zero");
  this->ExpectError(
    "zero.gltf", gltf.Text("zero"), { "buffer 0: 'zero': lies outside the mesh's folder" });
  this->ExpectError("http.gltf", gltf.Text("http://example.com/a.bin"),
    { "is neither a data URI nor a relative file name" });
  this->ExpectError("percent.gltf", gltf.Text("a%2.bin"), { "malformed percent-escape" });
  this->ExpectError("plain.gltf", gltf.Text("data:application/octet-stream,AAAA"),
    { "buffer 0: a data URI that is not base64" });
  this->ExpectError("base64.gltf", gltf.Text("data:application/octet-stream;base64,AA!A"),
    { "buffer 0: malformed base64" });
  this->ExpectError("shortdata.gltf", gltf.Text("data:application/octet-stream;base64,AAAA"),
    { "truncated: buffer 0 declares", "its data URI has 3" });

  // Images are checked now, though they are for a later step.
  Gltf image = gltf;
  image.Doc["images"] = { { { "uri", "texture.png" } } };
  this->ExpectError(
    "image.glb", image.Glb(), { "image 0: 'texture.png': cannot open: No such file or directory" });
  image.Doc["images"] = { { { "uri", "data:image/png;base64,#" } } };
  this->ExpectError("imagedata.glb", image.Glb(), { "image 0: malformed base64" });
  image.Doc["images"] = { { { "bufferView", 9 } } };
  this->ExpectError("imageview.glb", image.Glb(), { "image 0 refers to bufferViews[9]" });
  this->Write("texture.png", "not decoded now");
  image.Doc["images"] = { { { "uri", "texture.png" } } };
  EXPECT_TRUE(Read(this->Write("image.glb", image.Glb())).Ok);
}

TEST_F(MeshReaders, BadGltfAccessors)
{
  const auto expect = [&](const std::string& name, const std::function<void(Gltf&)>& change,
                        std::initializer_list<const char*> keyWords)
  {
    Gltf gltf = SquareDocument();
    change(gltf);
    this->ExpectError(name + ".glb", gltf.Glb(), keyWords);
  };
  // accessors[0]: POSITION (view 0, 48 bytes); accessors[1]: indices (view 1, 12 bytes).
  expect("count", [](Gltf& g) { g.Doc["accessors"][0]["count"] = 5; },
    { "accessor 0 needs 5 elements of 12 bytes from byte 0 of bufferView 0, which has 48" });
  expect("offset", [](Gltf& g) { g.Doc["accessors"][0]["byteOffset"] = 4; },
    { "accessor 0 needs 4 elements of 12 bytes from byte 4" });
  expect("hugecount", [](Gltf& g) { g.Doc["accessors"][1]["count"] = 1e15; },
    { "accessor 1.count is '1e+15', not an integer >= 0" });
  expect("bigcount", [](Gltf& g) { g.Doc["accessors"][1]["count"] = 1000000000000ULL; },
    { "accessor 1 needs 1000000000000 elements" });
  expect("zero", [](Gltf& g) { g.Doc["accessors"][1]["count"] = 0; }, { "accessor 1: count is 0" });
  expect("negative", [](Gltf& g) { g.Doc["accessors"][1]["count"] = -3; },
    { "accessor 1.count is '-3', not an integer >= 0" });
  expect("view", [](Gltf& g) { g.Doc["bufferViews"][0]["byteLength"] = 4096; },
    { "bufferView 0's byteOffset 0 and byteLength 4096 go past the end of buffer 0, which has" });
  // Near 2^64 the end wrapped round: offset and length are said apart.
  expect("wrap", [](Gltf& g) { g.Doc["bufferViews"][0]["byteOffset"] = 18446744073709551600ULL; },
    { "bufferView 0's byteOffset 18446744073709551600 and byteLength 48 go past the end" });
  expect("noview", [](Gltf& g) { g.Doc["accessors"][0]["bufferView"] = 7; },
    { "accessor 0 refers to bufferViews[7], but the file has 2" });
  expect("noaccessor", [](Gltf& g) { g.Doc["meshes"][0]["primitives"][0]["indices"] = 9; },
    { "mesh 0 primitive 0 refers to accessors[9], but the file has 2" });
  expect("zeros",
    [](Gltf& g)
    {
      g.Doc["accessors"][0].erase("bufferView");
      g.Doc["accessors"][0]["count"] = 1000000000000ULL;
    },
    { "accessor 0 has no bufferView and 1000000000000 elements of zeros, more bytes than the "
      "file's buffers hold (" });
  expect("sparse",
    [](Gltf& g) {
      g.Doc["accessors"][0]["sparse"] = { { "count", 1 } };
    },
    { "accessor 0 sparse: not an object with indices and values" });
  expect("sparsecount",
    [](Gltf& g) {
      MakeSparse(g, 0, 5, { 0, 1, 2, 3, 3 }, {});
    },
    { "accessor 0 sparse: count 5 is not from 1 to the accessor's 4" });
  expect("sparseorder",
    [](Gltf& g) {
      MakeSparse(g, 0, 2, { 2, 1 }, { 0, 0, 0, 0, 0, 0 });
    },
    { "accessor 0 sparse index 1 is 1, not above the one before it" });
  expect("sparserange",
    [](Gltf& g) {
      MakeSparse(g, 0, 1, { 4 }, { 0, 0, 0 });
    },
    { "accessor 0 sparse index 0 is 4, not below the count 4" });
  expect("sparsevalues",
    [](Gltf& g) {
      MakeSparse(g, 0, 2, { 0, 1 }, { 0, 0, 0 });
    },
    { "accessor 0 sparse values needs 2 elements of 12 bytes from byte 0" });
  expect("stride", [](Gltf& g) { g.Doc["bufferViews"][0]["byteStride"] = 6; },
    { "bufferView 0: byteStride 6 is less than the 12 bytes of accessor 0's elements" });
  // 4 was "not a multiple of 4 from 12 to 252".
  expect("narrow", [](Gltf& g) { g.Doc["bufferViews"][0]["byteStride"] = 4; },
    { "bufferView 0: byteStride 4 is less than the 12 bytes of accessor 0's elements" });
  expect("odd", [](Gltf& g) { g.Doc["bufferViews"][0]["byteStride"] = 14; },
    { "bufferView 0: byteStride 14 is not one glTF allows (a multiple of 4 from 4 to 252)" });
  // Types glTF does not allow where they are used.
  expect("ushort", [](Gltf& g) { g.Doc["accessors"][0]["componentType"] = UnsignedShort; },
    { "POSITION accessor 0 is VEC3 of UNSIGNED_SHORT, which glTF does not allow there" });
  expect("vec2", [](Gltf& g) { g.Doc["accessors"][0]["type"] = "VEC2"; },
    { "POSITION accessor 0 is VEC2 of FLOAT" });
  expect("mat4", [](Gltf& g) { g.Doc["accessors"][0]["type"] = "MAT4"; },
    { "accessor 0: type 'MAT4' is not SCALAR, VEC2, VEC3 or VEC4" });
  expect("unknown", [](Gltf& g) { g.Doc["accessors"][0]["componentType"] = 9999; },
    { "componentType 9999 is not a glTF component type" });
  expect("floatindex", [](Gltf& g) { g.Doc["accessors"][1]["componentType"] = Float; },
    { "indices accessor 1 is SCALAR of FLOAT, not SCALAR of UNSIGNED_BYTE" });
  expect("normalizedindex", [](Gltf& g) { g.Doc["accessors"][1]["normalized"] = true; },
    { "indices accessor 1 is SCALAR of UNSIGNED_SHORT (normalized)" });
  expect("colour",
    [](Gltf& g)
    {
      g.Doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] =
        g.Values(std::vector<std::uint8_t>{ 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 }, UnsignedByte,
          "VEC3", 3);
    },
    { "COLOR_0 accessor 2 is VEC3 of UNSIGNED_BYTE, which glTF does not allow there" });
}

TEST_F(MeshReaders, GltfSceneDrawingAMeshMoreOftenThanMemoryAllowsIsRefusedUpFront)
{
  // One mesh of 65,535 points, drawn by as many nodes as make its copies
  // need more than half of the memory there is: refused from the counts,
  // before anything is built (else this test would take that memory).
  const std::uint64_t available = vtkShadelabFileReader::AvailableMemory();
  if (available == 0)
  {
    GTEST_SKIP() << "the available memory is not known here";
  }
  constexpr std::uint64_t points = 65535;
  Gltf gltf;
  const int mesh = gltf.Mesh({ Primitive(gltf.Vec3(std::vector<float>(3 * points, 1.0f))) });
  std::vector<int> nodes;
  const std::uint64_t copies = available / 2 / (100 * points) + 1;
  for (std::uint64_t n = 0; n < copies; ++n)
  {
    nodes.push_back(gltf.Node({ { "mesh", mesh } }));
  }
  gltf.Scene(nodes);
  this->ExpectError(
    "copies.glb", gltf.Glb(), { "the scene's meshes need about", "MiB of memory available allow" });
}

TEST_F(MeshReaders, BadGltfMeshesAndNodes)
{
  const auto expect = [&](const std::string& name, const std::function<void(Gltf&)>& change,
                        std::initializer_list<const char*> keyWords)
  {
    Gltf gltf = SquareDocument();
    change(gltf);
    this->ExpectError(name + ".glb", gltf.Glb(), keyWords);
  };
  expect("index", [](Gltf& g) { g.Buffer[48 + 10] = 9; },
    { "mesh 0 primitive 0: index 5 is 9, but POSITION has 4 elements" });
  expect("three", [](Gltf& g) { g.Doc["accessors"][1]["count"] = 5; },
    { "mesh 0 primitive 0 has 5 vertices, which make no whole triangles" });
  expect("normals",
    [](Gltf& g) {
      g.Doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = g.Vec3({ 0, 0, 1 });
    },
    { "NORMAL has 1 elements, POSITION 4" });
  expect("mode", [](Gltf& g) { g.Doc["meshes"][0]["primitives"][0]["mode"] = 7; },
    { "mode 7 is not a glTF primitive mode" });
  expect("position",
    [](Gltf& g) { g.Doc["meshes"][0]["primitives"][0]["attributes"].erase("POSITION"); },
    { "mesh 0 primitive 0 has no POSITION" });
  expect("noprimitives", [](Gltf& g) { g.Doc["meshes"][0]["primitives"] = Json::array(); },
    { "mesh 0 has no primitives" });
  expect("material", [](Gltf& g) { g.Doc["meshes"][0]["primitives"][0]["material"] = 3; },
    { "refers to materials[3], but the file has 0" });
  expect("mesh", [](Gltf& g) { g.Doc["nodes"][0]["mesh"] = 4; },
    { "node 0 refers to meshes[4], but the file has 1" });
  expect("cycle", [](Gltf& g) { g.Doc["nodes"][0]["children"] = { 0 }; },
    { "node 0 is reached twice: nodes must form trees" });
  expect("child", [](Gltf& g) { g.Doc["nodes"][0]["children"] = { 5 }; },
    { "refers to nodes[5], but the file has 1" });
  expect("both",
    [](Gltf& g)
    {
      g.Doc["nodes"][0]["matrix"] = { 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
      g.Doc["nodes"][0]["scale"] = { 1, 1, 1 };
    },
    { "node 0 has both a matrix and translation, rotation or scale" });
  expect("matrix",
    [](Gltf& g) {
      g.Doc["nodes"][0]["matrix"] = { 1, 0, 0 };
    },
    { "node 0.matrix is not an array of 16 numbers" });
  expect("rotation",
    [](Gltf& g) {
      g.Doc["nodes"][0]["rotation"] = { 0, 0, 0, 0 };
    },
    { "node 0.rotation is not a rotation quaternion" });
  expect("translation",
    [](Gltf& g) {
      g.Doc["nodes"][0]["translation"] = { 0, "x", 0 };
    },
    { "node 0.translation holds '\"x\"', not a number" });
  expect(
    "scene", [](Gltf& g) { g.Doc["scene"] = 2; }, { "refers to scenes[2], but the file has 1" });
  // Transforms that overflow doubles: the readers refuse non-finite points.
  expect("overflow",
    [](Gltf& g)
    {
      g.Doc["nodes"][0]["scale"] = { 1e308, 1e308, 1 };
      g.Doc["nodes"][0]["translation"] = { 1e308, 0, 0 };
    },
    { "infinite coordinate in vertex" });
}
}
