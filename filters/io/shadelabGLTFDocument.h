/**
 * @brief   a glTF 2.0 document: its JSON and its buffers, checked
 *
 * Load() takes a .gltf (JSON) or .glb (binary container: a JSON chunk and
 * a BIN chunk) file's bytes, parses the JSON with nlohmann-json and brings
 * in every buffer: the GLB's BIN chunk, base64 data URIs, or files beside
 * the document (URIs relative to its folder, percent-decoded). It checks
 * what VTK's vtkGLTFDocumentLoader crashes on or lets pass (see
 * vtkShadelabGLTFReader): the GLB's header and chunk lengths against the
 * file, asset.version 2.x, required extensions (only those read
 * here), each buffer's byteLength against the bytes there are, and that
 * every image is there to be read (a readable file, valid base64, or a
 * bufferView within its buffer). Every problem is a MeshReadError, one line.
 *
 * Compressed data is decoded as the document loads, so that whatever reads
 * a bufferView or an accessor sees plain glTF: EXT_meshopt_compression's
 * bufferViews (shadelabGLTFMeshopt.h) and the accessors that
 * KHR_draco_mesh_compression's primitives fill (shadelabGLTFDraco.h).
 *
 * Its JSON is read through the typed getters of shadelabGLTFJson.h.
 */
#ifndef shadelabGLTFDocument_h
#define shadelabGLTFDocument_h

#include "shadelabGLTFJson.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab::gltf
{
/** An image of the document: a file beside it, or bytes that it holds. */
struct Image
{
  std::string Path;       // the file, resolved against the document's folder; "" when embedded
  std::string_view Bytes; // the encoded image where embedded (a bufferView, a data URI)
};

struct Document
{
  Json Root;
  std::vector<Image> Images;             // images[i]
  std::vector<std::string_view> Buffers; // each exactly its byteLength long, in Storage
  // EXT_meshopt_compression's placeholders, whose Buffers are empty: only
  // the compressed bufferViews' layouts refer to them.
  std::vector<bool> Placeholders;
  // Decoded bytes, in Storage: a compressed bufferView's, and those of an
  // accessor of a Draco-compressed primitive (packed, little-endian).
  std::map<std::uint64_t, std::string_view> DecodedViews;
  std::map<std::uint64_t, std::string_view> DecodedAccessors;
  // The file's bytes (a GLB's BIN chunk is used where it lies) and those of
  // the other buffers; on the heap, so that the views stay valid when the
  // document moves.
  std::vector<std::unique_ptr<std::string>> Storage;
};

/**
 * The document in `fileBytes`, read from `fileName`, whose folder holds its
 * files: a buffer or image uri that leads elsewhere is refused unless
 * allowOutside (shadelabCheckedFile.h).
 */
Document Load(const std::string& fileName, std::string fileBytes, bool allowOutside);

/** Whether the document lists `extension` in extensionsUsed. */
bool Uses(const Json& root, const char* extension);

/**
 * The bytes of bufferView `index`, which `referrer` uses; throws unless it
 * exists and lies within its buffer.
 */
std::string_view ViewBytes(
  const Document& document, std::uint64_t index, const std::string& referrer);

/**
 * The bytes that `range` names by its "buffer", "byteOffset" (default 0)
 * and "byteLength": a bufferView, or the EXT_meshopt_compression object of
 * one. Throws, its members' errors naming `where`, the error that
 * `placeholder` makes of the buffer's index when the buffer is a
 * placeholder without data (made only then), and one that starts with
 * `what` ("bufferView 2's") when the range goes past the buffer's end.
 */
std::string_view BufferRange(const Document& document, const Json& range, const std::string& where,
  const std::string& what, const std::function<std::string(std::uint64_t)>& placeholder);

}

#endif
