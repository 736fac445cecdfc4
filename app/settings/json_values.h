// Reading a scene file's JSON values: each reader checks the value's type
// and throws SceneError at its JSON path, so that every message names where
// in the file the problem is.
#ifndef shadelab_json_values_h
#define shadelab_json_values_h

#include "core/options.h"

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace shadelab
{
namespace scene_file
{
using nlohmann::json;

/** A problem at a JSON path. */
struct SceneError
{
  std::string Path;
  std::string Message;
};

/** "a, b, c". */
std::string Join(const std::vector<std::string>& words);

/** The value as JSON writes it, for messages. */
std::string Quoted(const json& value);

/** Checks that value is an object whose keys are all in known. */
void ExpectObject(
  const json& value, const std::string& path, const std::vector<std::string>& known);

std::string Text(const json& value, const std::string& path);

/** A number as the options write it (every digit a double has). */
std::string Number(const json& value, const std::string& path);

/** [x, y, z] as the options write it: "x,y,z". */
std::string Triple(const json& value, const std::string& path);

/** true or false. */
bool Flag(const json& value, const std::string& path);

/** One of known, as a string; what names it in the message. */
std::string Choice(const json& value, const std::string& path, const char* what,
  const std::vector<std::string>& known);

/**
 * Sets what args say on o through the settings' own options, so that a key
 * means exactly what its option means; a problem becomes a SceneError at
 * path.
 */
void Apply(SceneOptions& o, const std::vector<std::string>& args, const std::string& path);

/** The JSON path of a key ("mesh", "camera.position") of the shot being read. */
using PathOfKey = std::function<std::string(const std::string& key)>;
}
}

#endif
