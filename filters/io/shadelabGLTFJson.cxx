#include "shadelabGLTFJson.h"

#include "shadelabJsonProblem.h"
#include "shadelabMeshReadError.h"
#include "shadelabTextScanner.h"

#include <cmath>

namespace shadelab::gltf
{
void Fail(const std::string& message)
{
  throw MeshReadError(message);
}

namespace
{
std::string Place(const std::string& where, const char* key)
{
  return where + "." + key;
}

std::uint64_t AsUnsigned(const Json& value, const std::string& place)
{
  if (!value.is_number_unsigned() && !(value.is_number_integer() && value.get<std::int64_t>() >= 0))
  {
    Fail(place + " is " + Quote(JsonExcerpt(value)) + ", not an integer >= 0");
  }
  return value.get<std::uint64_t>();
}
}

const Json& List(const Json& root, const char* key)
{
  static const Json empty = Json::array();
  if (!root.contains(key))
  {
    return empty;
  }
  const Json& list = root[key];
  if (!list.is_array())
  {
    Fail(std::string("\"") + key + "\" is not an array");
  }
  return list;
}

const Json& Item(
  const Json& root, const char* key, std::uint64_t index, const std::string& referrer)
{
  const Json& list = List(root, key);
  if (index >= list.size())
  {
    Fail(referrer + " refers to " + key + "[" + std::to_string(index) + "], but the file has " +
      std::to_string(list.size()));
  }
  const Json& item = list[index];
  if (!item.is_object())
  {
    Fail(std::string(key) + "[" + std::to_string(index) + "] is not an object");
  }
  return item;
}

std::uint64_t Unsigned(
  const Json& object, const char* key, const std::string& where, long long fallback)
{
  if (!object.contains(key))
  {
    if (fallback < 0)
    {
      Fail(where + " has no " + key);
    }
    return static_cast<std::uint64_t>(fallback);
  }
  return AsUnsigned(object[key], Place(where, key));
}

std::uint64_t UnsignedAt(const Json& list, std::size_t k, const std::string& where)
{
  return AsUnsigned(list[k], where + "[" + std::to_string(k) + "]");
}

double Number(const Json& object, const char* key, const std::string& where, double fallback)
{
  if (!object.contains(key))
  {
    return fallback;
  }
  const Json& value = object[key];
  if (!value.is_number() || !std::isfinite(value.get<double>()))
  {
    Fail(Place(where, key) + " is " + Quote(JsonExcerpt(value)) + ", not a number");
  }
  return value.get<double>();
}

std::vector<double> Numbers(const Json& object, const char* key, const std::string& where,
  std::size_t count, const std::vector<double>& fallback)
{
  if (!object.contains(key))
  {
    return fallback;
  }
  const Json& value = object[key];
  if (!value.is_array() || value.size() != count)
  {
    Fail(Place(where, key) + " is not an array of " + std::to_string(count) + " numbers");
  }
  std::vector<double> numbers;
  for (const Json& item : value)
  {
    if (!item.is_number() || !std::isfinite(item.get<double>()))
    {
      Fail(Place(where, key) + " holds " + Quote(JsonExcerpt(item)) + ", not a number");
    }
    numbers.push_back(item.get<double>());
  }
  return numbers;
}

std::string String(const Json& object, const char* key, const std::string& where)
{
  if (!object.contains(key))
  {
    return {};
  }
  const Json& value = object[key];
  if (!value.is_string())
  {
    Fail(Place(where, key) + " is " + Quote(JsonExcerpt(value)) + ", not a string");
  }
  return value.get<std::string>();
}
}
