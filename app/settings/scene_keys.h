// The settings in scene files: their keys, read onto a SceneOptions and
// written from one, and the files' JSON Schema, all from the table of
// settings. A key's value goes through its option's own parser, so that it
// means exactly what the option means.
#ifndef shadelab_scene_keys_h
#define shadelab_scene_keys_h

#include "settings/json_values.h"
#include "settings/setting.h"

#include <filesystem>
#include <string>
#include <vector>

namespace shadelab
{
namespace scene_file
{
/** A shot's keys ("" ) or those of an object of keys ("camera"), in the table's order. */
std::vector<std::string> SceneKeys(const std::string& group = "");

/**
 * A shot's settings (the defaults and the shot's own keys merged, every
 * key known) onto o; files relative to folder. Throws SceneError at the
 * JSON path where gives.
 */
void ReadSceneSettings(const json& settings, const std::filesystem::path& folder,
  const PathOfKey& where, SceneOptions& o);

/** o's settings as a shot's keys, into shot (those that are not the defaults, and the size). */
void WriteSceneSettings(const SceneOptions& o, nlohmann::ordered_json& shot);

/** The scene files' JSON Schema (`shadelab render --print-schema`, data/scene.schema.json). */
nlohmann::ordered_json SceneSchemaJson();
}
}

#endif
