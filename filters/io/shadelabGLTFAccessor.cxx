#include "shadelabGLTFAccessor.h"

#include "shadelabMeshReadError.h"
#include "shadelabScalarType.h"

#include <vtkByteSwap.h>

#include <algorithm>
#include <cstring>
#include <string_view>

namespace shadelab::gltf
{
namespace
{
struct ComponentName
{
  std::uint64_t Code;
  ScalarType Type;
  const char* Name;
};

constexpr ComponentName ComponentTypes[] = { { 5120, ScalarType::Int8, "BYTE" },
  { 5121, ScalarType::UInt8, "UNSIGNED_BYTE" }, { 5122, ScalarType::Int16, "SHORT" },
  { 5123, ScalarType::UInt16, "UNSIGNED_SHORT" }, { 5125, ScalarType::UInt32, "UNSIGNED_INT" },
  { 5126, ScalarType::Float32, "FLOAT" } };

constexpr std::string_view ElementTypes[] = { "SCALAR", "VEC2", "VEC3", "VEC4" };

// A sparse accessor's elements that replace the base's: element j of
// Values (Stride apart) becomes element Indices[j].
struct Substitutions
{
  std::vector<std::uint64_t> Indices; // strictly increasing, below the accessor's count
  const unsigned char* Values = nullptr;
  std::uint64_t Stride = 0;
};

// An accessor with its ranges checked: element i, component c is at
// Data + i * Stride + c * SizeOf(Type), or 0 where Data is null (an
// accessor without a bufferView), then Sparse's elements in their places.
struct Layout
{
  const unsigned char* Data = nullptr;
  std::uint64_t Count = 0;
  std::uint64_t Stride = 0;
  int Components = 0;
  const ComponentName* Component = nullptr;
  bool Normalized = false;
  Substitutions Sparse;
};

std::string Describe(const Layout& layout)
{
  return std::string(ElementTypes[layout.Components - 1]) + " of " + layout.Component->Name +
    (layout.Normalized ? " (normalized)" : "");
}

const ComponentName& ReadComponentType(const Json& accessor, const std::string& where)
{
  const std::uint64_t code = Unsigned(accessor, "componentType", where);
  for (const ComponentName& entry : ComponentTypes)
  {
    if (entry.Code == code)
    {
      return entry;
    }
  }
  Fail(where + ": componentType " + std::to_string(code) + " is not a glTF component type");
}

// SCALAR .. VEC4 as 1 .. 4; the matrix types no mesh attribute uses.
int ReadElementType(const Json& accessor, const std::string& where)
{
  const std::string type = String(accessor, "type", where);
  for (int k = 0; k < 4; ++k)
  {
    if (type == ElementTypes[k])
    {
      return k + 1;
    }
  }
  Fail(where + ": type '" + type + "' is not SCALAR, VEC2, VEC3 or VEC4");
}

// The bytes of accessor `where` in its bufferView, all ranges checked.
const unsigned char* ViewData(
  const Document& document, const Json& accessor, Layout& layout, const std::string& where)
{
  const std::uint64_t viewIndex = Unsigned(accessor, "bufferView", where);
  const std::string viewName = "bufferView " + std::to_string(viewIndex);
  const std::string_view bytes = ViewBytes(document, viewIndex, where);
  const Json& view = document.Root["bufferViews"][viewIndex];
  const std::uint64_t viewLength = bytes.size();
  const std::uint64_t elementBytes = layout.Components * SizeOf(layout.Component->Type);
  layout.Stride = elementBytes; // tightly packed, unless the view says otherwise
  if (view.contains("byteStride"))
  {
    layout.Stride = Unsigned(view, "byteStride", viewName);
    const std::string stride = viewName + ": byteStride " + std::to_string(layout.Stride);
    if (layout.Stride < elementBytes)
    {
      Fail(stride + " is less than the " + std::to_string(elementBytes) + " bytes of " + where +
        "'s elements");
    }
    if (layout.Stride < 4 || layout.Stride > 252 || layout.Stride % 4 != 0)
    {
      Fail(stride + " is not one glTF allows (a multiple of 4 from 4 to 252)");
    }
  }
  const std::uint64_t offset = Unsigned(accessor, "byteOffset", where, 0);
  // count <= viewLength keeps the product below 2^64 (stride <= 252).
  if (offset > viewLength || layout.Count > viewLength ||
    layout.Stride * (layout.Count - 1) + elementBytes > viewLength - offset)
  {
    Fail(where + " needs " + std::to_string(layout.Count) + " elements of " +
      std::to_string(elementBytes) + " bytes from byte " + std::to_string(offset) + " of " +
      viewName + ", which has " + std::to_string(viewLength));
  }
  return reinterpret_cast<const unsigned char*>(bytes.data()) + offset;
}

// Whether KHR_mesh_quantization allows `type` (normalized or not) for `use`.
bool Quantizable(Quantization use, ScalarType type, bool normalized)
{
  const bool signedType = type == ScalarType::Int8 || type == ScalarType::Int16;
  const bool unsignedType = type == ScalarType::UInt8 || type == ScalarType::UInt16;
  return use == Quantization::Integers      ? signedType || unsignedType
    : use == Quantization::SignedNormalized ? signedType && normalized
                                            : false;
}

// Throws unless `use` allows the accessor's element and component types
// (KHR_mesh_quantization's too where the document uses it: `quantized`).
void CheckUse(const Layout& layout, const AccessorUse& use, bool quantized, std::uint64_t index,
  const std::string& where)
{
  const ScalarType type = layout.Component->Type;
  if (use.Indices)
  {
    if (layout.Components != 1 || layout.Normalized ||
      (type != ScalarType::UInt8 && type != ScalarType::UInt16 && type != ScalarType::UInt32))
    {
      Fail(where + ": indices accessor " + std::to_string(index) + " is " + Describe(layout) +
        ", not SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
    }
    return;
  }
  const bool isFloat = type == ScalarType::Float32 && !layout.Normalized;
  const bool isNormalized = use.NormalizedIntegers && layout.Normalized &&
    (type == ScalarType::UInt8 || type == ScalarType::UInt16);
  const bool isQuantized = Quantizable(use.Quantized, type, layout.Normalized);
  if (layout.Components < use.MinComponents || layout.Components > use.MaxComponents ||
    (!isFloat && !isNormalized && !(quantized && isQuantized)))
  {
    Fail(where + ": " + use.Name + " accessor " + std::to_string(index) + " is " +
      Describe(layout) + ", which glTF does not allow there" +
      (isQuantized && !quantized ? " unless the file uses KHR_mesh_quantization" : ""));
  }
}

// The accessor's values as T, in the host's order: one copy and one swap
// (a no-op on little-endian hosts) of the whole range where the elements
// are packed, element by element where a byteStride spreads them; a sparse
// accessor's elements copied over those before the swap.
template <typename T>
std::vector<T> Load(const Layout& layout)
{
  const std::size_t elementBytes = layout.Components * sizeof(T);
  std::vector<T> values(layout.Count * layout.Components); // zeros without a bufferView
  if (layout.Data && layout.Stride == elementBytes)
  {
    std::memcpy(values.data(), layout.Data, values.size() * sizeof(T));
  }
  else if (layout.Data)
  {
    for (std::uint64_t i = 0; i < layout.Count; ++i)
    {
      std::memcpy(&values[i * layout.Components], layout.Data + i * layout.Stride, elementBytes);
    }
  }
  const Substitutions& sparse = layout.Sparse;
  for (std::size_t j = 0; j < sparse.Indices.size(); ++j)
  {
    std::memcpy(&values[sparse.Indices[j] * layout.Components], sparse.Values + j * sparse.Stride,
      elementBytes);
  }
  vtkByteSwap::SwapLERange(values.data(), values.size());
  return values;
}

// Calls store(k, value) for every value k of the accessor, as its type.
template <typename Store>
void Decode(const Layout& layout, Store&& store)
{
  const auto each = [&](const auto& values)
  {
    for (std::size_t k = 0; k < values.size(); ++k)
    {
      store(k, values[k]);
    }
  };
  switch (layout.Component->Type)
  {
    case ScalarType::Int8:
      return each(Load<std::int8_t>(layout));
    case ScalarType::UInt8:
      return each(Load<std::uint8_t>(layout));
    case ScalarType::Int16:
      return each(Load<std::int16_t>(layout));
    case ScalarType::UInt16:
      return each(Load<std::uint16_t>(layout));
    case ScalarType::UInt32:
      return each(Load<std::uint32_t>(layout));
    case ScalarType::Float32:
      return each(Load<float>(layout));
    case ScalarType::Int32: // not glTF's: its component types stop at these
    case ScalarType::Int64:
    case ScalarType::UInt64:
    case ScalarType::Float64:
      break;
  }
  throw MeshReadError("an accessor's component type is not glTF's");
}
// accessor.sparse of `where` (whose layout is `base`): its indices read and
// checked (increasing, each below the count, as glTF requires), its values'
// range checked.
Substitutions ReadSparse(
  const Document& document, const Json& sparse, const Layout& base, const std::string& where)
{
  const std::string name = where + " sparse";
  if (!sparse.is_object() || !sparse.contains("indices") || !sparse["indices"].is_object() ||
    !sparse.contains("values") || !sparse["values"].is_object())
  {
    Fail(name + ": not an object with indices and values");
  }
  Layout indices;
  indices.Count = Unsigned(sparse, "count", name);
  if (indices.Count == 0 || indices.Count > base.Count)
  {
    Fail(name + ": count " + std::to_string(indices.Count) + " is not from 1 to the accessor's " +
      std::to_string(base.Count));
  }
  indices.Components = 1;
  indices.Component = &ReadComponentType(sparse["indices"], name + " indices");
  const ScalarType type = indices.Component->Type;
  if (type != ScalarType::UInt8 && type != ScalarType::UInt16 && type != ScalarType::UInt32)
  {
    Fail(name + " indices: " + indices.Component->Name +
      ", not UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  }
  indices.Data = ViewData(document, sparse["indices"], indices, name + " indices");
  Substitutions result;
  result.Indices.resize(indices.Count);
  Decode(indices, [&](std::size_t k, auto value) { result.Indices[k] = value; });
  for (std::size_t j = 0; j < result.Indices.size(); ++j)
  {
    if (result.Indices[j] >= base.Count || (j > 0 && result.Indices[j] <= result.Indices[j - 1]))
    {
      Fail(name + " index " + std::to_string(j) + " is " + std::to_string(result.Indices[j]) +
        (result.Indices[j] >= base.Count ? ", not below the count " + std::to_string(base.Count)
                                         : ", not above the one before it"));
    }
  }
  Layout values = base;
  values.Count = indices.Count;
  result.Values = ViewData(document, sparse["values"], values, name + " values");
  result.Stride = values.Stride;
  return result;
}

// The accessor's layout for `use` (of `referrer`): its types checked
// against the use before any range is looked at, then its ranges.
Layout ReadLayout(const Document& document, std::uint64_t index, const AccessorUse& use,
  const std::string& referrer)
{
  const std::string where = "accessor " + std::to_string(index);
  const Json& accessor = Item(document.Root, "accessors", index, referrer);
  Layout layout;
  layout.Count = Unsigned(accessor, "count", where);
  if (layout.Count == 0)
  {
    Fail(where + ": count is 0");
  }
  layout.Component = &ReadComponentType(accessor, where);
  layout.Components = ReadElementType(accessor, where);
  if (accessor.contains("normalized"))
  {
    if (!accessor["normalized"].is_boolean())
    {
      Fail(where + ": normalized is not true or false");
    }
    layout.Normalized = accessor["normalized"].get<bool>();
  }
  CheckUse(layout, use, Uses(document.Root, "KHR_mesh_quantization"), index, referrer);
  if (const auto decoded = document.DecodedAccessors.find(index);
      decoded != document.DecodedAccessors.end())
  {
    // Draco's data, as many elements as the count (checked as decoded).
    layout.Data = reinterpret_cast<const unsigned char*>(decoded->second.data());
    layout.Stride = layout.Components * SizeOf(layout.Component->Type);
    return layout;
  }
  // Without a bufferView an accessor is zeros (for sparse values to fill
  // in): no more of them than the buffers hold bytes, as for any other
  // accessor (a morph target's zeros are as many as its mesh's positions).
  if (accessor.contains("bufferView"))
  {
    layout.Data = ViewData(document, accessor, layout, where);
  }
  else
  {
    std::uint64_t bufferBytes = 0;
    for (const std::string_view buffer : document.Buffers)
    {
      bufferBytes += buffer.size();
    }
    layout.Stride = layout.Components * SizeOf(layout.Component->Type);
    if (layout.Count > bufferBytes / layout.Stride)
    {
      Fail(where + " has no bufferView and " + std::to_string(layout.Count) +
        " elements of zeros, more bytes than the file's buffers hold (" +
        std::to_string(bufferBytes) + ")");
    }
  }
  if (accessor.contains("sparse"))
  {
    layout.Sparse = ReadSparse(document, accessor["sparse"], layout, where);
  }
  return layout;
}

}

std::uint64_t CountOf(
  const Document& document, std::uint64_t index, const AccessorUse& use, const std::string& where)
{
  return ReadLayout(document, index, use, where).Count;
}

FloatValues ReadFloats(
  const Document& document, std::uint64_t index, const AccessorUse& use, const std::string& where)
{
  const Layout layout = ReadLayout(document, index, use, where);
  const ScalarType type = layout.Component->Type;
  FloatValues result;
  result.Count = layout.Count;
  result.Components = layout.Components;
  if (type == ScalarType::Float32)
  {
    result.Values = Load<float>(layout);
  }
  else
  {
    // glTF's normalized integers: c over the type's largest value, at
    // least -1; other integers as they are.
    const double largest = layout.Normalized ? LargestValue(type) : 1;
    result.Values.resize(layout.Count * layout.Components);
    Decode(layout,
      [&](std::size_t k, auto value)
      { result.Values[k] = static_cast<float>(std::max(value / largest, -1.0)); });
  }
  return result;
}

std::vector<std::uint32_t> ReadIndices(
  const Document& document, std::uint64_t index, const std::string& where)
{
  const Layout layout = ReadLayout(document, index, IndicesUse, where);
  std::vector<std::uint32_t> indices(layout.Count);
  Decode(
    layout, [&](std::size_t k, auto value) { indices[k] = static_cast<std::uint32_t>(value); });
  return indices;
}
}
