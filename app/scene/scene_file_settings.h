// A scene file's shot settings onto a Shot, a converter per kind of key.
// Each writes the value as its command-line option would take it and lets
// the render command's parsers decide (scene_file_values.h: Apply).
#ifndef shadelab_scene_file_settings_h
#define shadelab_scene_file_settings_h

#include "scene/scene_file.h"
#include "scene/scene_file_values.h"

#include <filesystem>
#include <functional>
#include <string>

namespace shadelab
{
namespace scene_file
{
/** The JSON path of a key ("mesh", "camera.position") of the shot being read. */
using PathOfKey = std::function<std::string(const std::string& key)>;

/**
 * A shot's settings (the defaults and the shot's own keys merged) onto
 * shot. Mesh paths are taken relative to folder.
 */
void ConvertShot(
  const json& settings, Shot& shot, const std::filesystem::path& folder, const PathOfKey& where);

/** "material": a name of the lecture's table, or an object (scene_file_material.cxx). */
void ConvertMaterial(const json& value, const std::string& path, SceneOptions& o);

/** "lights": an array of light objects (scene_file_lights.cxx). */
void ConvertLights(const json& value, const std::string& path, SceneOptions& o);
}
}

#endif
