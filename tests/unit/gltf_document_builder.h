// A glTF document built in a test (its JSON and its one buffer, written as
// a .gltf with a file or data URI, or as a GLB), and the unit square made
// with it: what the glTF reader's tests share.
#ifndef shadelab_gltf_document_builder_h
#define shadelab_gltf_document_builder_h

#include "mesh_reader_fixture.h"

#include <vtkBase64Utilities.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab::test
{
using Json = nlohmann::json;

constexpr int Float = 5126, UnsignedByte = 5121, UnsignedShort = 5123, UnsignedInt = 5125;

// A glTF document under construction: its JSON and its one buffer.
class Gltf
{
public:
  Json Doc = { { "asset", { { "version", "2.0" } } } };
  std::string Buffer;
  std::vector<Json> MoreBuffers; // buffers 1, 2, ... as they are (placeholders, say)

  /** Appends `bytes` as a bufferView (4-byte aligned); its index. */
  int View(const std::string& bytes, int stride = 0)
  {
    Buffer.resize((Buffer.size() + 3) / 4 * 4, '\0');
    Json view = { { "buffer", 0 }, { "byteOffset", Buffer.size() },
      { "byteLength", bytes.size() } };
    if (stride)
    {
      view["byteStride"] = stride;
    }
    Buffer += bytes;
    return Add("bufferViews", view);
  }

  int Accessor(
    int view, int componentType, std::size_t count, const char* type, bool normalized = false)
  {
    Json accessor = { { "bufferView", view }, { "componentType", componentType },
      { "count", count }, { "type", type } };
    if (normalized)
    {
      accessor["normalized"] = true;
    }
    return Add("accessors", accessor);
  }

  /** `values` in a view of their own, as an accessor of `components` per element. */
  template <typename T>
  int Values(const std::vector<T>& values, int componentType, const char* type, int components,
    bool normalized = false)
  {
    std::string bytes;
    for (const T value : values)
    {
      Put(bytes, value);
    }
    return Accessor(View(bytes), componentType, values.size() / components, type, normalized);
  }

  int Vec3(const std::vector<float>& values) { return Values(values, Float, "VEC3", 3); }

  int Indices(const std::vector<std::uint16_t>& values)
  {
    return Values(values, UnsignedShort, "SCALAR", 1);
  }

  int Mesh(const std::vector<Json>& primitives)
  {
    return Add("meshes", { { "primitives", primitives } });
  }

  int Node(const Json& node) { return Add("nodes", node); }

  void Scene(const std::vector<int>& nodes)
  {
    Doc["scenes"] = Json::array({ { { "nodes", nodes } } });
    Doc["scene"] = 0;
  }

  /**
   * The document with its buffer given by `uri` ("" for a GLB's BIN chunk),
   * then MoreBuffers.
   */
  std::string Text(const std::string& uri) const
  {
    Json doc = Doc;
    doc["buffers"] = Json::array({ { { "byteLength", Buffer.size() } } });
    if (!uri.empty())
    {
      doc["buffers"][0]["uri"] = uri;
    }
    for (const Json& buffer : MoreBuffers)
    {
      doc["buffers"].push_back(buffer);
    }
    return doc.dump(2);
  }

  std::string DataUri() const
  {
    std::string encoded(Buffer.size() * 4 / 3 + 4, '\0');
    encoded.resize(vtkBase64Utilities::Encode(reinterpret_cast<const unsigned char*>(Buffer.data()),
      Buffer.size(), reinterpret_cast<unsigned char*>(encoded.data())));
    return Text("data:application/octet-stream;base64," + encoded);
  }

  std::string Glb() const
  {
    std::string json = Text("");
    json.resize((json.size() + 3) / 4 * 4, ' ');
    std::string bin = Buffer;
    bin.resize((bin.size() + 3) / 4 * 4, '\0');
    std::string glb;
    Put(glb, std::uint32_t{ 0x46546C67 });
    Put(glb, std::uint32_t{ 2 });
    Put(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
    Put(glb, static_cast<std::uint32_t>(json.size()));
    Put(glb, std::uint32_t{ 0x4E4F534A });
    glb += json;
    Put(glb, static_cast<std::uint32_t>(bin.size()));
    Put(glb, std::uint32_t{ 0x004E4942 });
    return glb + bin;
  }

private:
  int Add(const char* list, const Json& item)
  {
    Doc[list].push_back(item);
    return static_cast<int>(Doc[list].size()) - 1;
  }
};

// The unit square in the xy-plane as four corners, counter-clockwise from +z.
inline const std::vector<float> Square = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };

inline Json Primitive(int position, int indices = -1, int mode = 4)
{
  Json primitive = { { "attributes", { { "POSITION", position } } }, { "mode", mode } };
  if (indices >= 0)
  {
    primitive["indices"] = indices;
  }
  return primitive;
}

// A square of two triangles on one node: the smallest whole document.
inline Gltf SquareDocument(const Json& node = Json::object())
{
  Gltf gltf;
  const int position = gltf.Vec3(Square);                 // accessor 0, bufferView 0
  const int indices = gltf.Indices({ 0, 1, 2, 0, 2, 3 }); // accessor 1, bufferView 1
  const int mesh = gltf.Mesh({ Primitive(position, indices) });
  Json withMesh = node;
  withMesh["mesh"] = mesh;
  gltf.Scene({ gltf.Node(withMesh) });
  return gltf;
}
}

#endif
