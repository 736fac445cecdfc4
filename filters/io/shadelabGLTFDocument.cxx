#include "shadelabGLTFDocument.h"

#include "shadelabCheckedFile.h"
#include "shadelabGLTFDraco.h"
#include "shadelabGLTFMeshopt.h"
#include "shadelabGLTFUri.h"
#include "shadelabJsonProblem.h"
#include "shadelabMeshReadError.h"
#include "shadelabTextScanner.h"
#include "vtkShadelabFileReader.h"

#include <vtkByteSwap.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string_view>

namespace shadelab::gltf
{
namespace
{
constexpr std::uint32_t GlbMagic = 0x46546C67;    // "glTF"
constexpr std::uint32_t JsonChunk = 0x4E4F534A;   // "JSON"
constexpr std::uint32_t BinaryChunk = 0x004E4942; // "BIN\0"
constexpr std::size_t GlbHeaderBytes = 12;        // magic, version, length
constexpr std::size_t ChunkHeaderBytes = 8;       // length, type

// The extensions that a document may require: those that shadelab reads
// (KHR_texture_transform on base colour textures).
constexpr std::string_view Readable[] = { "KHR_texture_transform", "KHR_mesh_quantization",
  "EXT_meshopt_compression", "KHR_draco_mesh_compression" };

std::uint32_t LoadUInt32(std::string_view bytes, std::size_t offset)
{
  std::uint32_t value;
  std::memcpy(&value, bytes.data() + offset, sizeof value);
  vtkByteSwap::SwapLE(&value);
  return value;
}

[[noreturn]] void Truncated(const std::string& message)
{
  throw MeshReadError("truncated: " + message, vtkErrorCode::PrematureEndOfFileError);
}

// A GLB's JSON text and, if it has one, its BIN chunk.
struct GlbChunks
{
  std::string_view Json;
  std::string_view Binary;
  bool HasBinary = false;
};

GlbChunks ReadGlb(std::string_view bytes)
{
  if (bytes.size() < GlbHeaderBytes)
  {
    Truncated("a GLB header takes 12 bytes, the file has " + std::to_string(bytes.size()));
  }
  const std::uint32_t version = LoadUInt32(bytes, 4);
  const std::uint32_t length = LoadUInt32(bytes, 8);
  if (version != 2)
  {
    Fail("GLB version " + std::to_string(version) + " is not supported (only 2)");
  }
  if (length > bytes.size())
  {
    Truncated("the GLB header says " + std::to_string(length) + " bytes, the file has " +
      std::to_string(bytes.size()));
  }
  if (length < bytes.size())
  {
    Fail("the GLB header says " + std::to_string(length) + " bytes, but the file has " +
      std::to_string(bytes.size()));
  }
  GlbChunks chunks;
  bool first = true;
  for (std::size_t offset = GlbHeaderBytes; offset < bytes.size(); first = false)
  {
    if (bytes.size() - offset < ChunkHeaderBytes)
    {
      Truncated("a GLB chunk header at byte " + std::to_string(offset) + " is cut off");
    }
    const std::uint32_t chunkLength = LoadUInt32(bytes, offset);
    const std::uint32_t type = LoadUInt32(bytes, offset + 4);
    offset += ChunkHeaderBytes;
    if (chunkLength > bytes.size() - offset)
    {
      Truncated("a GLB chunk at byte " + std::to_string(offset - ChunkHeaderBytes) + " says " +
        std::to_string(chunkLength) + " bytes, only " + std::to_string(bytes.size() - offset) +
        " follow");
    }
    const std::string_view data = bytes.substr(offset, chunkLength);
    offset += chunkLength;
    if (first != (type == JsonChunk))
    {
      Fail(first ? "the GLB's first chunk is not JSON" : "the GLB has a second JSON chunk");
    }
    if (first)
    {
      chunks.Json = data;
    }
    else if (type == BinaryChunk)
    {
      if (chunks.HasBinary)
      {
        Fail("the GLB has two BIN chunks");
      }
      chunks.Binary = data;
      chunks.HasBinary = true;
    }
    // Chunks of other types are for extensions: the spec says to skip them.
  }
  if (chunks.Json.data() == nullptr)
  {
    Fail("the GLB has no JSON chunk");
  }
  return chunks;
}

Json ParseJson(std::string_view text)
{
  try
  {
    Json root = ParseWithin<Json>(text);
    if (!root.is_object())
    {
      Fail("the glTF JSON is not an object");
    }
    return root;
  }
  catch (const Json::exception& e)
  {
    Fail("not JSON: " + JsonProblem(e));
  }
}

void CheckAsset(const Json& root)
{
  if (!root.contains("asset") || !root["asset"].is_object())
  {
    Fail("no \"asset\" object: not a glTF document");
  }
  const std::string version = String(root["asset"], "version", "asset");
  if (version.substr(0, 2) != "2.")
  {
    Fail("glTF version " + Quote(version) + " is not supported (only 2.x)");
  }
  for (const Json& extension : List(root, "extensionsRequired"))
  {
    if (extension.is_string() &&
      std::find(std::begin(Readable), std::end(Readable), extension.get<std::string>()) !=
        std::end(Readable))
    {
      continue;
    }
    // dump(): the name in quotes, escaped onto one line.
    Fail("requires the extension " + JsonExcerpt(extension) + ", which shadelab does not read");
  }
}

// Each buffer as a view of the GLB's BIN chunk (no copy) or of bytes that
// `document` keeps: a file's or a data URI's.
void LoadBuffers(
  Document& document, const std::string& fileName, bool allowOutside, const GlbChunks* glb)
{
  const Json& list = List(document.Root, "buffers");
  for (std::size_t b = 0; b < list.size(); ++b)
  {
    const std::string where = "buffer " + std::to_string(b);
    const Json& buffer = Item(document.Root, "buffers", b, where);
    const std::uint64_t length = Unsigned(buffer, "byteLength", where);
    std::string_view bytes;
    std::string source;
    const bool hasData = buffer.contains("uri") || (glb && b == 0 && glb->HasBinary);
    document.Placeholders.push_back(IsPlaceholder(document.Root, buffer, hasData, where));
    if (document.Placeholders.back())
    {
      document.Buffers.emplace_back();
      continue;
    }
    if (!buffer.contains("uri"))
    {
      if (!glb || b != 0 || !glb->HasBinary)
      {
        Fail(where + " has no uri" +
          (!glb        ? ""
              : b != 0 ? ", and only buffer 0 can be the GLB's BIN chunk"
                       : ", and the GLB has no BIN chunk"));
      }
      bytes = glb->Binary;
      source = "the GLB's BIN chunk";
    }
    else
    {
      const std::string uri = String(buffer, "uri", where);
      if (uri.compare(0, 5, "data:") == 0)
      {
        document.Storage.push_back(std::make_unique<std::string>(DecodeDataUri(uri, where)));
        source = "its data URI";
      }
      else
      {
        const std::string path = FilePath(fileName, allowOutside, uri, where);
        document.Storage.push_back(std::make_unique<std::string>(Referred(
          where, uri, [&] { return vtkShadelabFileReader::ReadFileBytes(path.c_str()); })));
        source = Quote(uri);
      }
      bytes = *document.Storage.back();
    }
    if (bytes.size() < length)
    {
      Truncated(where + " declares " + std::to_string(length) + " bytes, but " + source + " has " +
        std::to_string(bytes.size()));
    }
    document.Buffers.push_back(bytes.substr(0, length));
  }
}

// Every image, as a file's path or its bytes: a document whose image is
// missing is as broken as one whose buffer is, and is refused now.
void LoadImages(Document& document, const std::string& fileName, bool allowOutside)
{
  const Json& images = List(document.Root, "images");
  for (std::size_t i = 0; i < images.size(); ++i)
  {
    const std::string where = "image " + std::to_string(i);
    const Json& image = Item(document.Root, "images", i, where);
    if (image.contains("bufferView"))
    {
      document.Images.push_back(
        { "", ViewBytes(document, Unsigned(image, "bufferView", where), where) });
      continue;
    }
    const std::string uri = String(image, "uri", where);
    if (uri.empty())
    {
      Fail(where + " has neither a uri nor a bufferView");
    }
    if (uri.compare(0, 5, "data:") == 0)
    {
      document.Storage.push_back(std::make_unique<std::string>(DecodeDataUri(uri, where)));
      document.Images.push_back({ "", *document.Storage.back() });
    }
    else
    {
      const std::string path = FilePath(fileName, allowOutside, uri, where);
      Referred(where, uri, [&] { vtkShadelabFileReader::CheckReadable(path.c_str()); });
      document.Images.push_back({ path, {} });
    }
  }
}
}

bool Uses(const Json& root, const char* extension)
{
  const Json& used = List(root, "extensionsUsed");
  return std::find(used.begin(), used.end(), extension) != used.end();
}

std::string_view ViewBytes(
  const Document& document, std::uint64_t index, const std::string& referrer)
{
  const std::string viewName = "bufferView " + std::to_string(index);
  const Json& view = Item(document.Root, "bufferViews", index, referrer);
  if (const auto decoded = document.DecodedViews.find(index);
      decoded != document.DecodedViews.end())
  {
    return decoded->second;
  }
  return BufferRange(document, view, viewName, viewName + "'s",
    [&](std::uint64_t buffer)
    {
      return viewName + " is not compressed, but its buffer " + std::to_string(buffer) +
        " is an EXT_meshopt_compression placeholder without data";
    });
}

std::string_view BufferRange(const Document& document, const Json& range, const std::string& where,
  const std::string& what, const std::function<std::string(std::uint64_t)>& placeholder)
{
  const std::uint64_t bufferIndex = Unsigned(range, "buffer", where);
  Item(document.Root, "buffers", bufferIndex, where);
  if (document.Placeholders[bufferIndex])
  {
    Fail(placeholder(bufferIndex));
  }
  const std::string_view buffer = document.Buffers[bufferIndex];
  const std::uint64_t offset = Unsigned(range, "byteOffset", where, 0);
  const std::uint64_t length = Unsigned(range, "byteLength", where);
  if (offset > buffer.size() || length > buffer.size() - offset)
  {
    // Offset and length apart: their sum can pass 2^64.
    Fail(what + " byteOffset " + std::to_string(offset) + " and byteLength " +
      std::to_string(length) + " go past the end of buffer " + std::to_string(bufferIndex) +
      ", which has " + std::to_string(buffer.size()) + " bytes");
  }
  return buffer.substr(offset, length);
}

Document Load(const std::string& fileName, std::string fileBytes, bool allowOutside)
{
  Document document;
  document.Storage.push_back(std::make_unique<std::string>(std::move(fileBytes)));
  const std::string_view bytes = *document.Storage.back();
  const bool isGlb = bytes.size() >= 4 && LoadUInt32(bytes, 0) == GlbMagic;
  const std::string_view name = fileName;
  if (!isGlb && name.size() >= 4 && ToLower(name.substr(name.size() - 4)) == ".glb")
  {
    // Said as what it is, rather than as JSON that fails to parse.
    std::string start;
    for (const char c : bytes.substr(0, 4))
    {
      start += std::isprint(static_cast<unsigned char>(c)) ? std::string(1, c) : "?";
    }
    Fail("not a GLB: it starts with '" + start + "', not 'glTF'");
  }
  GlbChunks glb;
  if (isGlb)
  {
    glb = ReadGlb(bytes);
  }
  document.Root = ParseJson(isGlb ? glb.Json : bytes);
  CheckAsset(document.Root);
  LoadBuffers(document, fileName, allowOutside, isGlb ? &glb : nullptr);
  DecodeMeshoptViews(document);
  LoadImages(document, fileName, allowOutside);
  DecodeDracoPrimitives(document);
  return document;
}
}
