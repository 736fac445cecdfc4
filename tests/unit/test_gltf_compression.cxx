// Compressed and quantized glTF: KHR_mesh_quantization's integer
// attributes, EXT_meshopt_compression's bufferViews and
// KHR_draco_mesh_compression's primitives, in documents made here with
// meshoptimizer's and Draco's encoders, in Debian's assimp-testmodels and in
// the shared files from the wild; and their bad input, one line each.
#include "gltf_document_builder.h"
#include "mesh_reader_fixture.h"
#include "vtkShadelabFileReader.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include <draco/compression/decode.h>
#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace
{
using namespace shadelab::test;

constexpr int Byte = 5120, Short = 5122;
const fs::path AssimpModels = "/usr/share/assimp/models/glTF2";
const fs::path Wild = fs::path(SHADELAB_SOURCE_DIR) / "../shared/data/wild";

template <typename T>
std::string Bytes(const std::vector<T>& values)
{
  std::string bytes;
  for (const T value : values)
  {
    Put(bytes, value);
  }
  return bytes;
}

// With SHADELAB_FUZZ_SEEDS set to a folder, the documents that read well
// are written there too, as seeds for the fuzz targets (tests/fuzz/corpus/glb
// holds them).
void Seed(const std::string& name, const std::string& bytes)
{
  if (const char* folder = std::getenv("SHADELAB_FUZZ_SEEDS"))
  {
    std::ofstream(fs::path(folder) / name, std::ios::binary) << bytes;
  }
}

// Every value of a point array, in order (empty without the array).
std::vector<double> Values(vtkDataArray* array)
{
  std::vector<double> values;
  for (vtkIdType i = 0; array && i < array->GetNumberOfValues(); ++i)
  {
    values.push_back(array->GetComponent(
      i / array->GetNumberOfComponents(), static_cast<int>(i % array->GetNumberOfComponents())));
  }
  return values;
}

std::vector<double> PointValues(vtkPolyData* mesh)
{
  return Values(mesh->GetPoints()->GetData());
}

// Two reads give the same mesh: points, normals, texture coordinates and
// triangles, value for value.
void ExpectSameMesh(vtkPolyData* actual, vtkPolyData* expected)
{
  EXPECT_EQ(PointValues(actual), PointValues(expected));
  EXPECT_EQ(
    Values(actual->GetPointData()->GetNormals()), Values(expected->GetPointData()->GetNormals()));
  EXPECT_EQ(
    Values(actual->GetPointData()->GetTCoords()), Values(expected->GetPointData()->GetTCoords()));
  EXPECT_EQ(Triangles(actual), Triangles(expected));
}

// ---------------------------------------------------------------------------
// KHR_mesh_quantization

// The square with SHORT normalized positions (padded to 8 bytes), BYTE
// normalized normals (padded to 4) and UNSIGNED_SHORT texture coordinates,
// on a node that doubles it.
Gltf QuantizedSquare()
{
  Gltf gltf;
  const std::vector<std::int16_t> positions = { -32768, -16384, 0, 0, 32767, -16384, 0, 0, 32767,
    16384, 100, 0, -32767, 16384, 100, 0 };
  const std::vector<std::int8_t> normals = { 0, 0, 127, 0, -128, 127, 0, 0, 0, 0, -128, 0, 90, -90,
    0, 0 };
  const int position = gltf.Accessor(gltf.View(Bytes(positions), 8), Short, 4, "VEC3", true);
  const int normal = gltf.Accessor(gltf.View(Bytes(normals), 4), Byte, 4, "VEC3", true);
  const int uv = gltf.Values(
    std::vector<std::uint16_t>{ 0, 0, 3, 0, 3, 2, 0, 2 }, UnsignedShort, "VEC2", 2, false);
  Json primitive = Primitive(position, gltf.Indices({ 0, 1, 2, 0, 2, 3 }));
  primitive["attributes"]["NORMAL"] = normal;
  primitive["attributes"]["TEXCOORD_0"] = uv;
  gltf.Scene({ gltf.Node({ { "mesh", gltf.Mesh({ primitive }) }, { "scale", { 2, 2, 2 } } }) });
  gltf.Doc["extensionsUsed"] = { "KHR_mesh_quantization" };
  gltf.Doc["extensionsRequired"] = { "KHR_mesh_quantization" };
  return gltf;
}

// glTF's dequantization of a signed normalized integer, as a float.
float SignedNormalized(int c, double largest)
{
  return static_cast<float>(std::max(c / largest, -1.0));
}

TEST_F(MeshReaders, GltfQuantizedAttributesReadAsTheSpecDequantizesThem)
{
  const std::string glb = QuantizedSquare().Glb();
  Seed("quantized.glb", glb);
  const ReadResult result = Read(this->Write("quantized.glb", glb));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  // Positions: max(c / 32767, -1), doubled by the node (exact in double).
  const std::vector<int> shorts = { -32768, -16384, 0, 32767, -16384, 0, 32767, 16384, 100, -32767,
    16384, 100 };
  std::vector<double> expected;
  for (const int c : shorts)
  {
    expected.push_back(2.0 * SignedNormalized(c, 32767));
  }
  EXPECT_EQ(PointValues(result.Mesh), expected);
  EXPECT_EQ(expected[0], -2.0); // -32768 is -1, not -1.00003
  // Normals: max(c / 127, -1), renormalised after the transform; the clamp
  // shows in (-128, 127, 0), which is (-1, 1, 0)/sqrt(2), not tilted.
  vtkDataArray* normals = result.Mesh->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  const double half = std::sqrt(0.5);
  const std::vector<std::array<double, 3>> unit = { { 0, 0, 1 }, { -half, half, 0 }, { 0, 0, -1 },
    { half, -half, 0 } };
  for (vtkIdType v = 0; v < 4; ++v)
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_NEAR(normals->GetComponent(v, k), unit[v][k], 1e-7) << v << " " << k;
    }
  }
  // UNSIGNED_SHORT texture coordinates, not normalized: as they are (t = 1 - v).
  EXPECT_EQ(Values(result.Mesh->GetPointData()->GetTCoords()),
    (std::vector<double>{ 0, 1, 3, 1, 3, -1, 0, -1 }));
}

TEST_F(MeshReaders, BadQuantizedAttributes)
{
  Gltf unused = QuantizedSquare();
  unused.Doc.erase("extensionsUsed");
  unused.Doc.erase("extensionsRequired");
  this->ExpectError("unused.glb", unused.Glb(),
    { "POSITION accessor 0 is VEC3 of SHORT (normalized), which glTF does not allow there unless "
      "the file uses KHR_mesh_quantization" });
  // NORMAL takes normalized BYTE and SHORT only, TEXCOORD no signed normalized
  // type without the extension, and nothing takes UNSIGNED_INT.
  Gltf byteNormal = QuantizedSquare();
  byteNormal.Doc["accessors"][1]["normalized"] = false;
  this->ExpectError("bytenormal.glb", byteNormal.Glb(),
    { "NORMAL accessor 1 is VEC3 of BYTE, which glTF does not allow there" });
  Gltf unsignedNormal = QuantizedSquare();
  unsignedNormal.Doc["accessors"][1]["componentType"] = UnsignedByte;
  this->ExpectError("ubytenormal.glb", unsignedNormal.Glb(),
    { "NORMAL accessor 1 is VEC3 of UNSIGNED_BYTE (normalized), which glTF does not allow there" });
  Gltf uintPosition = QuantizedSquare();
  uintPosition.Doc["accessors"][0]["componentType"] = UnsignedInt;
  this->ExpectError("uint.glb", uintPosition.Glb(),
    { "POSITION accessor 0 is VEC3 of UNSIGNED_INT (normalized), which glTF does not allow "
      "there" });
}

// ---------------------------------------------------------------------------
// EXT_meshopt_compression

// Plain: float positions and normals, indices as TRIANGLES. Filtered:
// positions through the EXPONENTIAL filter, 4-byte normals through the
// OCTAHEDRAL one, indices as INDICES.
enum class Variant
{
  Plain,
  Filtered
};

// One bufferView of the square: its bytes (filtered as meshopt's encoders
// make them), its element size, meshopt's mode and filter.
struct MeshoptView
{
  std::string Bytes;
  std::size_t Stride;
  const char* Mode;
  const char* Filter;
};

std::vector<MeshoptView> SquareViews(Variant variant)
{
  const std::vector<float> normals = { 0, 0, 1, 0, 0.6f, 0, 0.8f, 0, 0, -0.6f, 0.8f, 0, 0.28f,
    0.96f, 0, 0 };
  const std::string indices = Bytes(std::vector<std::uint16_t>{ 0, 1, 2, 0, 2, 3 });
  if (variant == Variant::Plain)
  {
    std::string normalBytes;
    for (std::size_t v = 0; v < 4; ++v)
    {
      normalBytes += Bytes(std::vector<float>(&normals[4 * v], &normals[4 * v + 3]));
    }
    return { { Bytes(Square), 12, "ATTRIBUTES", "NONE" }, { normalBytes, 12, "ATTRIBUTES", "NONE" },
      { indices, 2, "TRIANGLES", "NONE" } };
  }
  std::string positions(48, '\0'), octahedral(16, '\0');
  meshopt_encodeFilterExp(positions.data(), 4, 12, 15, Square.data());
  meshopt_encodeFilterOct(octahedral.data(), 4, 4, 8, normals.data());
  return { { positions, 12, "ATTRIBUTES", "EXPONENTIAL" },
    { octahedral, 4, "ATTRIBUTES", "OCTAHEDRAL" }, { indices, 2, "INDICES", "NONE" } };
}

// `view` encoded in meshopt's bitstream for its mode.
std::string Encode(const MeshoptView& view)
{
  const std::size_t count = view.Bytes.size() / view.Stride;
  const std::string mode = view.Mode;
  if (mode == "ATTRIBUTES")
  {
    std::string encoded(meshopt_encodeVertexBufferBound(count, view.Stride), '\0');
    encoded.resize(meshopt_encodeVertexBuffer(reinterpret_cast<unsigned char*>(encoded.data()),
      encoded.size(), view.Bytes.data(), count, view.Stride));
    return encoded;
  }
  std::vector<unsigned int> indices(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    std::uint16_t index;
    std::memcpy(&index, view.Bytes.data() + 2 * k, 2);
    indices[k] = index;
  }
  // (meshoptimizer asserts that a TRIANGLES count is a multiple of 3.)
  const bool triangles = mode == "TRIANGLES";
  std::string encoded(triangles ? meshopt_encodeIndexBufferBound(count, 4)
                                : meshopt_encodeIndexSequenceBound(count, 4),
    '\0');
  auto* out = reinterpret_cast<unsigned char*>(encoded.data());
  encoded.resize(triangles
      ? meshopt_encodeIndexBuffer(out, encoded.size(), indices.data(), count)
      : meshopt_encodeIndexSequence(out, encoded.size(), indices.data(), count));
  return encoded;
}

// `view`'s bytes as decoding gives them: its filter undone.
std::string Unfiltered(const MeshoptView& view)
{
  std::string bytes = view.Bytes;
  const std::size_t count = bytes.size() / view.Stride;
  if (std::string(view.Filter) == "OCTAHEDRAL")
  {
    meshopt_decodeFilterOct(bytes.data(), count, view.Stride);
  }
  else if (std::string(view.Filter) == "EXPONENTIAL")
  {
    meshopt_decodeFilterExp(bytes.data(), count, view.Stride);
  }
  return bytes;
}

// The square's document: its views (0 positions, 1 normals, 2 indices)
// plain, or compressed into buffer 0 with the uncompressed layout in
// placeholder buffer 1. Octahedral normals are BYTE normalized.
Gltf MeshoptDocument(Variant variant, bool compressed)
{
  Gltf gltf;
  std::size_t placeholder = 0;
  for (const MeshoptView& view : SquareViews(variant))
  {
    const bool attributes = std::string(view.Mode) == "ATTRIBUTES";
    if (!compressed)
    {
      gltf.View(Unfiltered(view), attributes ? static_cast<int>(view.Stride) : 0);
      continue;
    }
    const std::string encoded = Encode(view);
    gltf.Buffer.resize((gltf.Buffer.size() + 3) / 4 * 4, '\0');
    Json extension = { { "buffer", 0 }, { "byteOffset", gltf.Buffer.size() },
      { "byteLength", encoded.size() }, { "byteStride", view.Stride },
      { "count", view.Bytes.size() / view.Stride }, { "mode", view.Mode } };
    if (std::string(view.Filter) != "NONE")
    {
      extension["filter"] = view.Filter;
    }
    gltf.Buffer += encoded;
    Json parent = { { "buffer", 1 }, { "byteOffset", placeholder },
      { "byteLength", view.Bytes.size() },
      { "extensions", { { "EXT_meshopt_compression", extension } } } };
    if (attributes)
    {
      parent["byteStride"] = view.Stride;
    }
    placeholder += (view.Bytes.size() + 3) / 4 * 4;
    gltf.Doc["bufferViews"].push_back(parent);
  }
  Json primitive =
    Primitive(gltf.Accessor(0, Float, 4, "VEC3"), gltf.Accessor(2, UnsignedShort, 6, "SCALAR"));
  primitive["attributes"]["NORMAL"] = variant == Variant::Filtered
    ? gltf.Accessor(1, Byte, 4, "VEC3", true)
    : gltf.Accessor(1, Float, 4, "VEC3");
  gltf.Scene({ gltf.Node({ { "mesh", gltf.Mesh({ primitive }) } }) });
  if (compressed)
  {
    gltf.MoreBuffers.push_back({ { "byteLength", placeholder },
      { "extensions", { { "EXT_meshopt_compression", { { "fallback", true } } } } } });
    gltf.Doc["extensionsUsed"] = { "EXT_meshopt_compression" };
    gltf.Doc["extensionsRequired"] = { "EXT_meshopt_compression" };
  }
  if (variant == Variant::Filtered)
  {
    gltf.Doc["extensionsUsed"].push_back("KHR_mesh_quantization");
  }
  return gltf;
}

TEST_F(MeshReaders, GltfMeshoptCompressedViewsReadAsTheUncompressedDocument)
{
  for (const Variant variant : { Variant::Plain, Variant::Filtered })
  {
    const std::string name = variant == Variant::Plain ? "plain" : "filtered";
    SCOPED_TRACE(name);
    const ReadResult plain =
      Read(this->Write(name + ".glb", MeshoptDocument(variant, false).Glb()));
    const std::string glb = MeshoptDocument(variant, true).Glb();
    Seed(name + "-meshopt.glb", glb);
    const ReadResult compressed = Read(this->Write(name + "-meshopt.glb", glb));
    ASSERT_TRUE(plain.Ok) << plain.Error;
    ASSERT_TRUE(compressed.Ok) << compressed.Error;
    ExpectTriangleMesh(compressed.Mesh);
    ExpectSameMesh(compressed.Mesh, plain.Mesh);
    // The filtered values are the floats to within their bits' steps (15
    // of mantissa for the positions, 8 for the octahedral normals).
    const bool exact = variant == Variant::Plain;
    const std::vector<double> points = PointValues(compressed.Mesh);
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      EXPECT_NEAR(points[k], Square[k], exact ? 0 : 1.0 / (1 << 14)) << k;
    }
    vtkDataArray* normals = compressed.Mesh->GetPointData()->GetNormals();
    ASSERT_NE(normals, nullptr);
    EXPECT_NEAR(normals->GetComponent(1, 0), 0.6, exact ? 1e-7 : 0.02);
    EXPECT_NEAR(normals->GetComponent(3, 1), 0.96, exact ? 1e-7 : 0.02);
  }
}

TEST_F(MeshReaders, BadMeshoptCompressedViews)
{
  const auto expect = [&](const std::string& name, const std::function<void(Gltf&)>& change,
                        std::initializer_list<const char*> keyWords)
  {
    Gltf gltf = MeshoptDocument(Variant::Filtered, true);
    change(gltf);
    this->ExpectError(name + ".glb", gltf.Glb(), keyWords);
  };
  const auto extension = [](Gltf& g, int view) -> Json&
  { return g.Doc["bufferViews"][view]["extensions"]["EXT_meshopt_compression"]; };
  // View 0: positions (EXPONENTIAL), 4 elements of 12 bytes; view 1:
  // octahedral normals; view 2: the indices (INDICES).
  expect("garbage", [](Gltf& g) { std::fill(g.Buffer.begin(), g.Buffer.end(), '\x5a'); },
    { "bufferView 0 EXT_meshopt_compression: its",
      "bytes are not ATTRIBUTES data of 4 elements of "
      "12 bytes (meshoptimizer's error -1)" });
  expect("truncated",
    [&](Gltf& g) { extension(g, 0)["byteLength"] = extension(g, 0)["byteLength"].get<int>() / 2; },
    { "bufferView 0 EXT_meshopt_compression: its", "bytes are not ATTRIBUTES data" });
  expect("indexgarbage",
    [&](Gltf& g)
    {
      const std::size_t offset = extension(g, 2)["byteOffset"];
      g.Buffer.replace(offset, 1, "\x7f");
    },
    { "bufferView 2 EXT_meshopt_compression: its", "bytes are not INDICES data" });
  expect("count", [&](Gltf& g) { extension(g, 0)["count"] = 5; },
    { "bufferView 0 EXT_meshopt_compression: count 5 times byteStride 12 is not the view's "
      "byteLength 48" });
  expect("hugecount", [&](Gltf& g) { extension(g, 0)["count"] = 1ULL << 62; },
    { "count 4611686018427387904 times byteStride 12 is not the view's byteLength 48" });
  expect("source", [&](Gltf& g) { extension(g, 0)["byteLength"] = 100000; },
    { "bufferView 0 EXT_meshopt_compression: byteOffset 0 and byteLength 100000 go past the end "
      "of buffer 0" });
  expect("parent", [](Gltf& g) { g.Doc["bufferViews"][2]["byteOffset"] = 1000; },
    { "bufferView 2's byteOffset 1000 and byteLength 12 go past the end of buffer 1" });
  expect("mode", [&](Gltf& g) { extension(g, 0)["mode"] = "STRIPS"; },
    { "bufferView 0 EXT_meshopt_compression: mode 'STRIPS' is not ATTRIBUTES, TRIANGLES or "
      "INDICES" });
  expect("filter", [&](Gltf& g) { extension(g, 1)["filter"] = "ZIGZAG"; },
    { "filter 'ZIGZAG' is not NONE, OCTAHEDRAL, QUATERNION or EXPONENTIAL" });
  expect("octstride", [&](Gltf& g) { extension(g, 0)["filter"] = "OCTAHEDRAL"; },
    { "bufferView 0 EXT_meshopt_compression: byteStride 12 does not suit its filter" });
  expect("quatstride", [&](Gltf& g) { extension(g, 1)["filter"] = "QUATERNION"; },
    { "bufferView 1 EXT_meshopt_compression: byteStride 4 does not suit its filter" });
  expect("indexfilter", [&](Gltf& g) { extension(g, 2)["filter"] = "EXPONENTIAL"; },
    { "bufferView 2 EXT_meshopt_compression: a filter applies to ATTRIBUTES only" });
  expect("indexstride", [&](Gltf& g) { extension(g, 2)["byteStride"] = 3; },
    { "byteStride 3 is not 2 or 4, as TRIANGLES and INDICES need" });
  expect("triangles",
    [&](Gltf& g)
    {
      extension(g, 2)["mode"] = "TRIANGLES";
      extension(g, 2)["count"] = 4;
    },
    { "count 4 is not a multiple of 3, as TRIANGLES needs" });
  expect("stride", [&](Gltf& g) { extension(g, 0)["byteStride"] = 256 + 4; },
    { "byteStride 260 is not a multiple of 4 from 4 to 256, as ATTRIBUTES needs" });
  expect("fromplaceholder", [&](Gltf& g) { extension(g, 0)["buffer"] = 1; },
    { "bufferView 0 EXT_meshopt_compression: its buffer 1 is a placeholder without data" });
  expect("plainview",
    [](Gltf& g) { g.Doc["bufferViews"][0]["extensions"].erase("EXT_meshopt_compression"); },
    { "bufferView 0 is not compressed, but its buffer 1 is an EXT_meshopt_compression "
      "placeholder without data" });
  // The decoded views may take half of the memory there is: a placeholder
  // of 2^50 bytes whose view asks for all of them.
  if (vtkShadelabFileReader::AvailableMemory() > 0)
  {
    expect("memory",
      [&](Gltf& g)
      {
        g.MoreBuffers[0]["byteLength"] = 1ULL << 50;
        g.Doc["bufferViews"][0]["byteLength"] = 12ULL << 46;
        extension(g, 0)["count"] = 1ULL << 46;
      },
      { "bufferView 0 EXT_meshopt_compression: its views decode into",
        "MiB, more than half of "
        "the" });
  }
}

// ---------------------------------------------------------------------------
// KHR_draco_mesh_compression

// An octahedron of six irregular corners, outward faces; its positions
// quantized to 12 bits by Draco's encoder.
const std::vector<std::array<float, 3>> Corners = { { 1.1f, 0.03f, 0 }, { -0.73f, 0, 0.01f },
  { 0.02f, 0.9f, 0 }, { 0, -1.3f, 0.05f }, { 0, 0.01f, 0.7f }, { 0.04f, 0, -0.6f } };
const std::vector<std::array<int, 3>> Faces = { { 0, 2, 4 }, { 2, 1, 4 }, { 1, 3, 4 }, { 3, 0, 4 },
  { 2, 0, 5 }, { 1, 2, 5 }, { 3, 1, 5 }, { 0, 3, 5 } };
constexpr int QuantizationBits = 12;

struct DracoMesh
{
  std::string Bytes;
  int Points = 0;
  int Faces = 0;
  int PositionId = 0;
};

DracoMesh EncodeOctahedron()
{
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(static_cast<int>(Faces.size()));
  const int position =
    builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  for (std::size_t f = 0; f < Faces.size(); ++f)
  {
    builder.SetAttributeValuesForFace(position, draco::FaceIndex(static_cast<std::uint32_t>(f)),
      Corners[Faces[f][0]].data(), Corners[Faces[f][1]].data(), Corners[Faces[f][2]].data());
  }
  const std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, QuantizationBits);
  draco::EncoderBuffer buffer;
  EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
  DracoMesh result;
  result.Bytes.assign(buffer.data(), buffer.size());
  // The accessors' counts are the decoded mesh's, as a glTF writer takes them.
  draco::DecoderBuffer input;
  input.Init(buffer.data(), buffer.size());
  const auto decoded = draco::Decoder().DecodeMeshFromBuffer(&input);
  EXPECT_TRUE(decoded.ok());
  result.Points = static_cast<int>(decoded.value()->num_points());
  result.Faces = static_cast<int>(decoded.value()->num_faces());
  result.PositionId = static_cast<int>(
    decoded.value()->GetNamedAttribute(draco::GeometryAttribute::POSITION)->unique_id());
  return result;
}

// The octahedron, Draco-compressed: accessors 0 (POSITION) and 1 (indices)
// without bufferViews, the Draco data in bufferView 0.
Gltf DracoDocument(const DracoMesh& mesh)
{
  Gltf gltf;
  const int view = gltf.View(mesh.Bytes);
  gltf.Doc["accessors"] =
    Json::array({ { { "componentType", Float }, { "count", mesh.Points }, { "type", "VEC3" } },
      { { "componentType", UnsignedShort }, { "count", 3 * mesh.Faces }, { "type", "SCALAR" } } });
  Json primitive = Primitive(0, 1);
  primitive["extensions"]["KHR_draco_mesh_compression"] = { { "bufferView", view },
    { "attributes", { { "POSITION", mesh.PositionId } } } };
  gltf.Scene({ gltf.Node({ { "mesh", gltf.Mesh({ primitive }) } }) });
  gltf.Doc["extensionsUsed"] = { "KHR_draco_mesh_compression" };
  gltf.Doc["extensionsRequired"] = { "KHR_draco_mesh_compression" };
  return gltf;
}

TEST_F(MeshReaders, GltfDracoCompressedPrimitiveHasItsTriangles)
{
  const DracoMesh mesh = EncodeOctahedron();
  const std::string glb = DracoDocument(mesh).Glb();
  Seed("draco.glb", glb);
  const ReadResult result = Read(this->Write("draco.glb", glb));
  ASSERT_TRUE(result.Ok) << result.Error;
  ExpectTriangleMesh(result.Mesh);
  // Draco moves each coordinate to its 12-bit grid over the largest extent
  // (2.4 from y -1.3 to 1.1): within one step of the float corners.
  const double step = 2.4 / ((1 << QuantizationBits) - 1);
  const auto near = [&](vtkIdType p, const std::array<float, 3>& corner)
  {
    double x[3];
    result.Mesh->GetPoint(p, x);
    return std::abs(x[0] - corner[0]) < step && std::abs(x[1] - corner[1]) < step &&
      std::abs(x[2] - corner[2]) < step;
  };
  // Each triangle read is one of the octahedron's, its corners in the same
  // turn (whichever first).
  const auto triangles = Triangles(result.Mesh);
  ASSERT_EQ(triangles.size(), Faces.size());
  std::vector<bool> found(Faces.size());
  for (const auto& t : triangles)
  {
    for (std::size_t f = 0; f < Faces.size(); ++f)
    {
      for (int turn = 0; turn < 3; ++turn)
      {
        if (near(t[turn], Corners[Faces[f][0]]) && near(t[(turn + 1) % 3], Corners[Faces[f][1]]) &&
          near(t[(turn + 2) % 3], Corners[Faces[f][2]]))
        {
          found[f] = true;
        }
      }
    }
  }
  EXPECT_EQ(std::count(found.begin(), found.end(), true), static_cast<long>(Faces.size()));
}

TEST_F(MeshReaders, BadDracoCompressedPrimitives)
{
  const DracoMesh mesh = EncodeOctahedron();
  const auto expect = [&](const std::string& name, const std::function<void(Gltf&)>& change,
                        std::initializer_list<const char*> keyWords)
  {
    Gltf gltf = DracoDocument(mesh);
    change(gltf);
    this->ExpectError(name + ".glb", gltf.Glb(), keyWords);
  };
  const auto extension = [](Gltf& g) -> Json&
  { return g.Doc["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]; };
  const char* where = "mesh 0 primitive 0 KHR_draco_mesh_compression: ";
  expect("garbage", [](Gltf& g) { std::fill(g.Buffer.begin(), g.Buffer.end(), '\x5a'); },
    { where, "bufferView 0 is not a Draco mesh: " });
  expect("truncated",
    [&](Gltf& g) { g.Doc["bufferViews"][0]["byteLength"] = mesh.Bytes.size() / 2; },
    { where, "bufferView 0 is not a Draco mesh: " });
  expect("id", [&](Gltf& g) { extension(g)["attributes"]["POSITION"] = 7; },
    { where, "POSITION's Draco attribute id 7 is not in the compressed mesh" });
  expect("name", [&](Gltf& g) { extension(g)["attributes"]["NORMAL"] = 0; },
    { where, "NORMAL is not one of the primitive's attributes" });
  expect("count", [](Gltf& g) { g.Doc["accessors"][0]["count"] = 5; },
    { where, "accessor 0 has count 5, the Draco mesh 6" });
  expect("indexcount", [](Gltf& g) { g.Doc["accessors"][1]["count"] = 3; },
    { where, "accessor 1 has count 3, the Draco mesh 24" });
  expect("type", [](Gltf& g) { g.Doc["accessors"][0]["type"] = "VEC2"; },
    { where, "POSITION's accessor 0 is 'VEC2', its Draco attribute has 3 components" });
  expect("integers", [](Gltf& g) { g.Doc["accessors"][0]["componentType"] = UnsignedByte; },
    { where, "POSITION's Draco values do not fit accessor 0's componentType" });
  expect("indextype", [](Gltf& g) { g.Doc["accessors"][1]["componentType"] = Float; },
    { where, "indices accessor 1 is not of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT" });
  expect("strip", [](Gltf& g) { g.Doc["meshes"][0]["primitives"][0]["mode"] = 5; },
    { where, "mode 5: shadelab reads Draco's faces as TRIANGLES (4) only" });
  expect("noindices", [](Gltf& g) { g.Doc["meshes"][0]["primitives"][0].erase("indices"); },
    { where, "the primitive has no indices or no attributes for the Draco mesh to fill" });
  expect("sparse",
    [](Gltf& g) {
      g.Doc["accessors"][0]["sparse"] = { { "count", 1 } };
    },
    { where, "accessor 0 is Draco-compressed, and cannot be sparse" });
  expect("view", [&](Gltf& g) { extension(g)["bufferView"] = 4; },
    { "refers to bufferViews[4], but the file has 1" });
}

// ---------------------------------------------------------------------------
// Files made elsewhere

std::size_t TriangleCount(const ReadResult& result)
{
  return result.Ok ? Triangles(result.Mesh).size() : 0;
}

// The triangles whose three corners lie apart: Draco's encoder drops the
// others (corners that share an index or a position).
std::size_t ProperTriangleCount(const ReadResult& result)
{
  std::size_t count = 0;
  for (const auto& t : Triangles(result.Mesh))
  {
    std::array<std::array<double, 3>, 3> p;
    for (int k = 0; k < 3; ++k)
    {
      result.Mesh->GetPoint(t[k], p[k].data());
    }
    count += p[0] != p[1] && p[1] != p[2] && p[0] != p[2];
  }
  return count;
}

TEST_F(MeshReaders, AssimpsDracoEngineHasTheTrianglesOfItsUncompressedGlb)
{
  const fs::path draco = AssimpModels / "draco/2CylinderEngine.gltf";
  const fs::path glb = AssimpModels / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb";
  if (!fs::is_regular_file(draco) || !fs::is_regular_file(glb))
  {
    GTEST_SKIP() << "Debian's assimp-testmodels is not installed";
  }
  const ReadResult compressed = Read(draco);
  const ReadResult plain = Read(glb);
  ASSERT_TRUE(compressed.Ok) << compressed.Error;
  ASSERT_TRUE(plain.Ok) << plain.Error;
  ExpectTriangleMesh(compressed.Mesh);
  // 121496 triangles drawn from the GLB, 11160 of them degenerate, which
  // the Draco file's writer left out (its accessors say so, mesh by mesh).
  EXPECT_EQ(TriangleCount(plain), 121496u);
  EXPECT_EQ(TriangleCount(compressed), ProperTriangleCount(plain));
}

TEST_F(MeshReaders, WildDracoAndMeshoptBoxesHaveTwelveTriangles)
{
  for (const char* file : { "glb-draco/Box_Draco.glb", "glb-meshopt/BoxMeshopt.glb" })
  {
    if (!fs::is_regular_file(Wild / file))
    {
      GTEST_SKIP() << Wild / file << " is not here (the shared test data beside the repository)";
    }
    SCOPED_TRACE(file);
    const ReadResult result = Read(Wild / file);
    ASSERT_TRUE(result.Ok) << result.Error;
    ExpectTriangleMesh(result.Mesh);
    EXPECT_EQ(TriangleCount(result), 12u);
  }
}
}
