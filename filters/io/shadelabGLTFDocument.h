/**
 * @brief   a glTF 2.0 document: its JSON and its buffers, checked
 *
 * Load() takes a .gltf (JSON) or .glb (binary container: a JSON chunk and
 * a BIN chunk) file's bytes, parses the JSON with nlohmann-json and brings
 * in every buffer: the GLB's BIN chunk, base64 data URIs, or files beside
 * the document (URIs relative to its folder, percent-decoded). It checks
 * what VTK's vtkGLTFDocumentLoader crashes on or lets pass (see
 * vtkShadelabGLTFReader): the GLB's header and chunk lengths against the
 * file, asset.version 2.x, required extensions (none is supported), each
 * buffer's byteLength against the bytes there are, and that every image is
 * there to be read (a readable file, valid base64, or a bufferView that
 * exists). Every problem is a MeshReadError, one line.
 *
 * The typed getters read the JSON the same strict way, with messages that
 * name the place ("accessors[2].count").
 */
#ifndef shadelabGLTFDocument_h
#define shadelabGLTFDocument_h

#include <nlohmann/json.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace shadelab::gltf
{
using Json = nlohmann::json;

struct Document
{
  Json Root;
  std::vector<std::string_view> Buffers; // each exactly its byteLength long, in Storage
  // The file's bytes (a GLB's BIN chunk is used where it lies) and those of
  // the other buffers; on the heap, so that the views stay valid when the
  // document moves.
  std::vector<std::unique_ptr<std::string>> Storage;
};

/** The document in `fileBytes`, read from `fileName` (whose folder holds its files). */
Document Load(const std::string& fileName, std::string fileBytes);

/** root[key] as an array; an empty one when absent. Throws if it is not an array. */
const Json& List(const Json& root, const char* key);

/**
 * Item `index` of the top-level list `key` ("accessors"), which must be an
 * object; `referrer` says who refers to it, for the message.
 */
const Json& Item(
  const Json& root, const char* key, std::uint64_t index, const std::string& referrer);

/** object[key] as a non-negative integer, `fallback` when absent (-1: required). */
std::uint64_t Unsigned(
  const Json& object, const char* key, const std::string& where, long long fallback = -1);

/** Element k of `list` as a non-negative integer (`where` names the list). */
std::uint64_t UnsignedAt(const Json& list, std::size_t k, const std::string& where);

/** object[key] as a finite number, `fallback` when absent. */
double Number(const Json& object, const char* key, const std::string& where, double fallback);

/** object[key] as `count` finite numbers, `fallback` when absent. */
std::vector<double> Numbers(const Json& object, const char* key, const std::string& where,
  std::size_t count, const std::vector<double>& fallback);

/** object[key] as a string, "" when absent. */
std::string String(const Json& object, const char* key, const std::string& where);
}

#endif
