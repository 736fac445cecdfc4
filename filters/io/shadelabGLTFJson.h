/**
 * @brief   glTF's JSON read strictly: typed getters whose messages name the place
 *
 * Each getter throws a MeshReadError, one line naming the place
 * ("accessors[2].count") and what is wrong there.
 */
#ifndef shadelabGLTFJson_h
#define shadelabGLTFJson_h

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace shadelab::gltf
{
using Json = nlohmann::json;

/** Throws `message` as a MeshReadError: every glTF problem is one. */
[[noreturn]] void Fail(const std::string& message);

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
