#include "settings/scene_keys.h"

#include <algorithm>

namespace shadelab
{
namespace scene_file
{
namespace
{
// The key's part before its dot: "camera" of "camera.view_angle".
std::string TopKey(const std::string& key)
{
  return key.substr(0, key.find('.'));
}

// The setting that reads key, if any.
const Setting* Reader(const std::string& key)
{
  const auto& all = Settings();
  const auto s = std::find_if(
    all.begin(), all.end(), [&key](const Setting& s) { return s.Read && s.Key == key; });
  return s == all.end() ? nullptr : &*s;
}
}

std::vector<std::string> SceneKeys(const std::string& group)
{
  std::vector<std::string> keys;
  for (const Setting& s : Settings())
  {
    std::string key;
    if (group.empty())
    {
      key = TopKey(s.Key);
    }
    else if (s.Key.rfind(group + ".", 0) == 0 && s.Read)
    {
      key = s.Key.substr(group.size() + 1);
    }
    if (!key.empty() && std::find(keys.begin(), keys.end(), key) == keys.end())
    {
      keys.push_back(key);
    }
  }
  return keys;
}

void ReadSceneSettings(const json& settings, const std::filesystem::path& folder,
  const PathOfKey& where, SceneOptions& o)
{
  std::vector<std::pair<const Setting*, const json*>> last;
  const auto read = [&](const Setting& s, const json& value, const std::string& key)
  {
    if (s.ReadLast)
    {
      last.emplace_back(&s, &value);
    }
    else
    {
      s.Read(value, where(key), folder, o);
    }
  };
  for (const auto& item : settings.items())
  {
    const std::string& key = item.key();
    if (const Setting* s = Reader(key))
    {
      read(*s, item.value(), key);
      continue;
    }
    // An object of keys, such as "camera".
    ExpectObject(item.value(), where(key), SceneKeys(key));
    for (const auto& inner : item.value().items())
    {
      const std::string innerKey = key + "." + inner.key();
      read(*Reader(innerKey), inner.value(), innerKey);
    }
  }
  for (const auto& [s, value] : last)
  {
    s->Read(*value, where(s->Key), folder, o);
  }
}

void WriteSceneSettings(const SceneOptions& o, nlohmann::ordered_json& shot)
{
  for (const Setting& s : Settings())
  {
    if (s.Write)
    {
      s.Write(o, shot);
    }
  }
}

nlohmann::ordered_json SceneSchemaJson()
{
  using nlohmann::ordered_json;
  ordered_json shot = ordered_json::object();
  for (const Setting& s : Settings())
  {
    if (!s.Schema)
    {
      continue;
    }
    const auto dot = s.Key.find('.');
    if (dot == std::string::npos)
    {
      shot[s.Key] = s.Schema();
      continue;
    }
    ordered_json& group = shot[s.Key.substr(0, dot)];
    if (group.is_null())
    {
      group = { { "type", "object" }, { "properties", ordered_json::object() },
        { "additionalProperties", false } };
    }
    group["properties"][s.Key.substr(dot + 1)] = s.Schema();
  }
  const ordered_json triple{ { "type", "array" }, { "items", { { "type", "number" } } },
    { "minItems", 3 }, { "maxItems", 3 } };
  return { { "$schema", "https://json-schema.org/draft/2020-12/schema" },
    { "$id", "https://shadelab.invalid/scene.schema.json" }, { "title", "shadelab scene file" },
    { "description",
      "shadelab render --scene FILE.json. The top level gives every shot's defaults; each entry "
      "of \"shots\" overrides what it needs (a key replaces the default's; \"camera\" is merged "
      "key by key). Without \"shots\", the top level is the one shot. Each key means what the "
      "render option of the same name means (shadelab render --help). Mesh and texture paths "
      "are relative to the scene file's folder, outputs to the current folder." },
    { "type", "object" }, { "$ref", "#/$defs/shot" },
    { "properties",
      { { "shots",
        { { "type", "array" }, { "minItems", 1 },
          { "items", { { "$ref", "#/$defs/shot" }, { "unevaluatedProperties", false } } } } } } },
    { "unevaluatedProperties", false },
    { "$defs",
      { { "triple", triple },
        { "color", { { "$ref", "#/$defs/triple" }, { "items", { { "minimum", 0 } } } } },
        { "attenuation", { { "$ref", "#/$defs/color" }, { "not", { { "const", { 0, 0, 0 } } } } } },
        { "shot", { { "type", "object" }, { "properties", shot } } } } } };
}
}
}
