#include "shadelabGLTFMeshopt.h"

#include "shadelabTextScanner.h"
#include "vtkShadelabFileReader.h"

#include <meshoptimizer.h>

#include <cstdint>
#include <memory>
#include <string_view>

namespace shadelab::gltf
{
namespace
{
constexpr const char* Meshopt = "EXT_meshopt_compression";

enum class MeshoptMode
{
  Attributes,
  Triangles,
  Indices
};

enum class MeshoptFilter
{
  None,
  Octahedral,
  Quaternion,
  Exponential
};

// The view's extension object, or null without one.
const Json* MeshoptExtension(const Json& object, const std::string& where)
{
  if (!object.contains("extensions") || !object["extensions"].is_object() ||
    !object["extensions"].contains(Meshopt))
  {
    return nullptr;
  }
  const Json& extension = object["extensions"][Meshopt];
  if (!extension.is_object())
  {
    Fail(where + ": " + Meshopt + " is not an object");
  }
  return &extension;
}

// extension[key] (`fallback` when absent) as the Enum of its place in `names`.
template <typename Enum, std::size_t N>
Enum OneOf(const Json& extension, const char* key, const char* (&names)[N], const char* fallback,
  const std::string& where)
{
  const std::string name = extension.contains(key) ? String(extension, key, where) : fallback;
  for (std::size_t k = 0; k < N; ++k)
  {
    if (name == names[k])
    {
      return static_cast<Enum>(k);
    }
  }
  std::string list;
  for (std::size_t k = 0; k < N; ++k)
  {
    list += std::string(k == 0 ? "" : k + 1 == N ? " or " : ", ") + names[k];
  }
  Fail(where + ": " + key + " " + Quote(name) + " is not " + list);
}

// The rules of the extension's spec on stride, count and filter, which the
// decoders would otherwise assert.
void CheckMeshoptLayout(MeshoptMode mode, MeshoptFilter filter, std::uint64_t stride,
  std::uint64_t count, const std::string& where)
{
  const std::string strideText = "byteStride " + std::to_string(stride);
  if (count == 0)
  {
    Fail(where + ": count is 0");
  }
  if (mode == MeshoptMode::Attributes && (stride == 0 || stride > 256 || stride % 4 != 0))
  {
    Fail(where + ": " + strideText + " is not a multiple of 4 from 4 to 256, as ATTRIBUTES needs");
  }
  if (mode != MeshoptMode::Attributes && stride != 2 && stride != 4)
  {
    Fail(where + ": " + strideText + " is not 2 or 4, as TRIANGLES and INDICES need");
  }
  if (mode == MeshoptMode::Triangles && count % 3 != 0)
  {
    Fail(
      where + ": count " + std::to_string(count) + " is not a multiple of 3, as TRIANGLES needs");
  }
  if (mode != MeshoptMode::Attributes && filter != MeshoptFilter::None)
  {
    Fail(where + ": a filter applies to ATTRIBUTES only");
  }
  if ((filter == MeshoptFilter::Octahedral && stride != 4 && stride != 8) ||
    (filter == MeshoptFilter::Quaternion && stride != 8))
  {
    Fail(where + ": " + strideText + " does not suit its filter (OCTAHEDRAL 4 or 8, QUATERNION 8)");
  }
}

// The decoded bytes of compressed view `index` (`view`, whose extension is
// `extension`); `decodedBytes` counts those of the views before it.
std::string DecodeView(const Document& document, const Json& view, const Json& extension,
  std::uint64_t index, std::uint64_t& decodedBytes)
{
  const std::string viewName = "bufferView " + std::to_string(index);
  const std::string where = viewName + " " + Meshopt;
  static const char* modes[] = { "ATTRIBUTES", "TRIANGLES", "INDICES" };
  static const char* filters[] = { "NONE", "OCTAHEDRAL", "QUATERNION", "EXPONENTIAL" };
  const auto mode = OneOf<MeshoptMode>(extension, "mode", modes, "", where);
  const auto filter = OneOf<MeshoptFilter>(extension, "filter", filters, "NONE", where);
  const std::uint64_t stride = Unsigned(extension, "byteStride", where);
  const std::uint64_t count = Unsigned(extension, "count", where);
  CheckMeshoptLayout(mode, filter, stride, count, where);

  // The decoded data fill the view exactly, which lies within its buffer
  // (a placeholder's byteLength says how much the views take).
  const std::uint64_t length = Unsigned(view, "byteLength", viewName);
  if (view.contains("byteStride") && Unsigned(view, "byteStride", viewName) != stride)
  {
    Fail(where + ": byteStride " + std::to_string(stride) + " is not the view's " +
      std::to_string(Unsigned(view, "byteStride", viewName)));
  }
  if (count > length / stride || count * stride != length)
  {
    Fail(where + ": count " + std::to_string(count) + " times byteStride " +
      std::to_string(stride) + " is not the view's byteLength " + std::to_string(length));
  }
  const std::uint64_t parent = Unsigned(view, "buffer", viewName);
  const std::uint64_t parentLength =
    Unsigned(Item(document.Root, "buffers", parent, viewName), "byteLength", viewName);
  const std::uint64_t offset = Unsigned(view, "byteOffset", viewName, 0);
  if (offset > parentLength || length > parentLength - offset)
  {
    Fail(viewName + "'s byteOffset " + std::to_string(offset) + " and byteLength " +
      std::to_string(length) + " go past the end of buffer " + std::to_string(parent) +
      ", which has " + std::to_string(parentLength) + " bytes");
  }
  // The codec can shrink data up to 64 times, so a small file can ask for much:
  // all views together may take half of the memory there is.
  decodedBytes += length;
  const std::uint64_t available = vtkShadelabFileReader::AvailableMemory();
  if (available > 0 && decodedBytes > available / 2)
  {
    Fail(where + ": its views decode into " + std::to_string(decodedBytes >> 20) +
      " MiB, more than half of the " + std::to_string(available >> 20) +
      " MiB of memory available");
  }

  // The compressed bytes, in a buffer with data.
  const std::string_view compressedBytes = BufferRange(document, extension, where, where + ":",
    [&](std::uint64_t buffer) {
      return where + ": its buffer " + std::to_string(buffer) + " is a placeholder without data";
    });
  const auto* compressed = reinterpret_cast<const unsigned char*>(compressedBytes.data());
  const size_t sourceLength = compressedBytes.size();

  std::string bytes(length, '\0');
  const int status = mode == MeshoptMode::Attributes
    ? meshopt_decodeVertexBuffer(bytes.data(), count, stride, compressed, sourceLength)
    : mode == MeshoptMode::Triangles
    ? meshopt_decodeIndexBuffer(bytes.data(), count, stride, compressed, sourceLength)
    : meshopt_decodeIndexSequence(bytes.data(), count, stride, compressed, sourceLength);
  if (status != 0)
  {
    Fail(where + ": its " + std::to_string(sourceLength) + " bytes are not " +
      modes[static_cast<int>(mode)] + " data of " + std::to_string(count) + " elements of " +
      std::to_string(stride) + " bytes (meshoptimizer's error " + std::to_string(status) + ")");
  }
  // The filters work in place on whole elements (a std::string's bytes are
  // aligned to 8 at least, enough for their 16- and 32-bit loads).
  switch (filter)
  {
    case MeshoptFilter::Octahedral:
      meshopt_decodeFilterOct(bytes.data(), count, stride);
      break;
    case MeshoptFilter::Quaternion:
      meshopt_decodeFilterQuat(bytes.data(), count, stride);
      break;
    case MeshoptFilter::Exponential:
      meshopt_decodeFilterExp(bytes.data(), count, stride);
      break;
    case MeshoptFilter::None:
      break;
  }
  return bytes;
}
}

bool IsPlaceholder(const Json& root, const Json& buffer, bool hasData, const std::string& where)
{
  if (const Json* extension = MeshoptExtension(buffer, where))
  {
    if (extension->contains("fallback") && !(*extension)["fallback"].is_boolean())
    {
      Fail(where + ": " + Meshopt + ".fallback is not true or false");
    }
    if (extension->value("fallback", false))
    {
      return true;
    }
  }
  return !hasData && Uses(root, Meshopt);
}

void DecodeMeshoptViews(Document& document)
{
  const Json& views = List(document.Root, "bufferViews");
  std::uint64_t decodedBytes = 0;
  for (std::size_t v = 0; v < views.size(); ++v)
  {
    const std::string where = "bufferView " + std::to_string(v);
    const Json& view = Item(document.Root, "bufferViews", v, where);
    if (const Json* extension = MeshoptExtension(view, where))
    {
      document.Storage.push_back(
        std::make_unique<std::string>(DecodeView(document, view, *extension, v, decodedBytes)));
      document.DecodedViews[v] = *document.Storage.back();
    }
  }
}
}
