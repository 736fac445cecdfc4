#include "shadelabGLTFDraco.h"

#include "shadelabTextScanner.h"

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include <vtkByteSwap.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <type_traits>
#include <vector>

namespace shadelab::gltf
{
namespace
{
constexpr const char* Draco = "KHR_draco_mesh_compression";

// glTF's componentType codes.
namespace GltfComponent
{
constexpr std::uint64_t Byte = 5120, UnsignedByte = 5121, Short = 5122, UnsignedShort = 5123,
                        UnsignedInt = 5125, Float = 5126;
}

// `values` as little-endian bytes, as a glTF buffer holds them.
template <typename T>
std::string LittleEndian(std::vector<T> values)
{
  vtkByteSwap::SwapLERange(values.data(), values.size());
  return std::string(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

// The attribute's value at each point, `components` of T each; false where
// one does not convert (out of T's range) or is not finite.
template <typename T>
bool ConvertAttribute(
  const draco::PointAttribute& attribute, std::uint32_t points, int components, std::string& bytes)
{
  std::vector<T> values(std::size_t{ points } * components);
  for (std::uint32_t p = 0; p < points; ++p)
  {
    const draco::AttributeValueIndex index = attribute.mapped_index(draco::PointIndex(p));
    T* out = &values[std::size_t{ p } * components];
    if (index.value() >= attribute.size() ||
      !attribute.ConvertValue<T>(index, static_cast<std::int8_t>(components), out))
    {
      return false;
    }
    if constexpr (std::is_floating_point_v<T>)
    {
      for (int k = 0; k < components; ++k)
      {
        if (!std::isfinite(out[k]))
        {
          return false;
        }
      }
    }
  }
  bytes = LittleEndian(std::move(values));
  return true;
}

// Accessor `index` of the primitive (`where`), which decoding fills: its
// count must be `count`; it may have no sparse substitutions, nor be filled
// twice.
const Json& Filled(
  const Document& document, std::uint64_t index, std::uint64_t count, const std::string& where)
{
  const std::string name = "accessor " + std::to_string(index);
  const Json& accessor = Item(document.Root, "accessors", index, where);
  if (accessor.contains("sparse"))
  {
    Fail(where + ": " + name + " is Draco-compressed, and cannot be sparse");
  }
  if (document.DecodedAccessors.count(index) != 0)
  {
    Fail(where + ": " + name + " is filled by another Draco-compressed primitive too");
  }
  if (Unsigned(accessor, "count", name) != count)
  {
    Fail(where + ": " + name + " has count " + std::to_string(Unsigned(accessor, "count", name)) +
      ", the Draco mesh " + std::to_string(count));
  }
  return accessor;
}

std::string AttributeBytes(const Document& document, const draco::Mesh& mesh,
  const std::string& name, std::uint64_t id, std::uint64_t index, const std::string& where)
{
  const Json& accessor = Filled(document, index, mesh.num_points(), where);
  const draco::PointAttribute* attribute = id > std::numeric_limits<std::uint32_t>::max()
    ? nullptr
    : mesh.GetAttributeByUniqueId(static_cast<std::uint32_t>(id));
  if (!attribute)
  {
    Fail(where + ": " + name + "'s Draco attribute id " + std::to_string(id) +
      " is not in the compressed mesh");
  }
  const std::string type = String(accessor, "type", "accessor " + std::to_string(index));
  const int components = type == "SCALAR" ? 1 : type == "VEC2" ? 2 : type == "VEC3" ? 3 : 4;
  if (attribute->num_components() != components || (components == 4 && type != "VEC4"))
  {
    Fail(where + ": " + name + "'s accessor " + std::to_string(index) + " is " + Quote(type) +
      ", its Draco attribute has " + std::to_string(attribute->num_components()) + " components");
  }
  const std::uint32_t points = mesh.num_points();
  std::string bytes;
  bool converted = false;
  switch (Unsigned(accessor, "componentType", "accessor " + std::to_string(index)))
  {
    case GltfComponent::Byte:
      converted = ConvertAttribute<std::int8_t>(*attribute, points, components, bytes);
      break;
    case GltfComponent::UnsignedByte:
      converted = ConvertAttribute<std::uint8_t>(*attribute, points, components, bytes);
      break;
    case GltfComponent::Short:
      converted = ConvertAttribute<std::int16_t>(*attribute, points, components, bytes);
      break;
    case GltfComponent::UnsignedShort:
      converted = ConvertAttribute<std::uint16_t>(*attribute, points, components, bytes);
      break;
    case GltfComponent::UnsignedInt:
      converted = ConvertAttribute<std::uint32_t>(*attribute, points, components, bytes);
      break;
    case GltfComponent::Float:
      converted = ConvertAttribute<float>(*attribute, points, components, bytes);
      break;
    default:
      Fail(where + ": " + name + "'s accessor " + std::to_string(index) +
        " has no glTF componentType");
  }
  if (!converted)
  {
    Fail(where + ": " + name + "'s Draco values do not fit accessor " + std::to_string(index) +
      "'s componentType (out of range or not finite)");
  }
  return bytes;
}

// The faces' corners in the indices accessor's component type.
template <typename T>
std::string FaceCorners(const draco::Mesh& mesh, const std::string& where)
{
  std::vector<T> corners;
  corners.reserve(3 * std::size_t{ mesh.num_faces() });
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f)
  {
    for (const draco::PointIndex& corner : mesh.face(f))
    {
      if (corner.value() >= mesh.num_points() || corner.value() > std::numeric_limits<T>::max())
      {
        Fail(where + ": face " + std::to_string(f.value()) + " has corner " +
          std::to_string(corner.value()) + ", not below the " + std::to_string(mesh.num_points()) +
          " points or beyond its indices' type");
      }
      corners.push_back(static_cast<T>(corner.value()));
    }
  }
  return LittleEndian(std::move(corners));
}

std::string IndexBytes(
  const Document& document, const draco::Mesh& mesh, std::uint64_t index, const std::string& where)
{
  const Json& accessor = Filled(document, index, 3 * std::uint64_t{ mesh.num_faces() }, where);
  switch (Unsigned(accessor, "componentType", "accessor " + std::to_string(index)))
  {
    case GltfComponent::UnsignedByte:
      return FaceCorners<std::uint8_t>(mesh, where);
    case GltfComponent::UnsignedShort:
      return FaceCorners<std::uint16_t>(mesh, where);
    case GltfComponent::UnsignedInt:
      return FaceCorners<std::uint32_t>(mesh, where);
    default:
      Fail(where + ": indices accessor " + std::to_string(index) +
        " is not of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  }
}

void DecodePrimitive(Document& document, const Json& primitive, const std::string& where)
{
  const Json& extension = primitive["extensions"][Draco];
  if (!extension.is_object() || !extension.contains("attributes") ||
    !extension["attributes"].is_object())
  {
    Fail(where + ": not an object with a bufferView and attributes");
  }
  const std::uint64_t view = Unsigned(extension, "bufferView", where);
  const std::string_view compressed = ViewBytes(document, view, where);
  if (!primitive.contains("indices") || !primitive.contains("attributes") ||
    !primitive["attributes"].is_object())
  {
    Fail(where + ": the primitive has no indices or no attributes for the Draco mesh to fill");
  }
  draco::DecoderBuffer buffer;
  buffer.Init(compressed.data(), compressed.size());
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok())
  {
    Fail(where + ": bufferView " + std::to_string(view) +
      " is not a Draco mesh: " + decoded.status().error_msg_string());
  }
  const draco::Mesh& mesh = *decoded.value();
  const Json& attributes = primitive["attributes"];
  for (const auto& item : extension["attributes"].items())
  {
    const std::string& name = item.key();
    if (!attributes.contains(name))
    {
      Fail(where + ": " + name + " is not one of the primitive's attributes");
    }
    const std::uint64_t index = Unsigned(attributes, name.c_str(), where);
    const std::uint64_t id = Unsigned(extension["attributes"], name.c_str(), where);
    document.Storage.push_back(
      std::make_unique<std::string>(AttributeBytes(document, mesh, name, id, index, where)));
    document.DecodedAccessors[index] = *document.Storage.back();
  }
  const std::uint64_t indices = Unsigned(primitive, "indices", where);
  document.Storage.push_back(
    std::make_unique<std::string>(IndexBytes(document, mesh, indices, where)));
  document.DecodedAccessors[indices] = *document.Storage.back();
}
}

void DecodeDracoPrimitives(Document& document)
{
  const Json& meshes = List(document.Root, "meshes");
  for (std::size_t m = 0; m < meshes.size(); ++m)
  {
    const std::string meshName = "mesh " + std::to_string(m);
    const Json& primitives = List(Item(document.Root, "meshes", m, meshName), "primitives");
    for (std::size_t p = 0; p < primitives.size(); ++p)
    {
      const Json& primitive = primitives[p];
      const std::string where = meshName + " primitive " + std::to_string(p) + " " + Draco;
      if (!primitive.is_object() || !primitive.contains("extensions") ||
        !primitive["extensions"].is_object() || !primitive["extensions"].contains(Draco))
      {
        continue;
      }
      // Points and lines are skipped (vtkShadelabGLTFReader draws
      // triangles), a mode beyond glTF's is the reader's error; Draco's
      // faces are a triangle list.
      const std::uint64_t mode = Unsigned(primitive, "mode", where, 4);
      if (mode == 5 || mode == 6)
      {
        Fail(where + ": mode " + std::to_string(mode) +
          ": shadelab reads Draco's faces as TRIANGLES (4) only");
      }
      if (mode == 4)
      {
        DecodePrimitive(document, primitive, where);
      }
    }
  }
}
}
