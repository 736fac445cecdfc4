#include "scene/scene_file.h"

#include "core/output_path.h"
#include "settings/scene_keys.h"
#include "shadelabCheckedFile.h"
#include "shadelabJsonProblem.h"
#include "shadelabMeshReadError.h"

#include <cstdint>
#include <filesystem>
#include <map>

namespace shadelab
{
namespace
{
using namespace scene_file;

// A scene of a hundred thousand shots is a few MB; more is not a scene.
constexpr std::uint64_t MaxSceneFileBytes = 64ULL << 20;

// The file's JSON (comments allowed): "" or the problem.
std::string ParseSceneJson(const std::string& path, json& scene)
{
  std::string text;
  try
  {
    text = OpenChecked(path, MaxSceneFileBytes).ReadAll();
  }
  catch (const MeshReadError& e)
  {
    return e.what();
  }
  try
  {
    scene = ParseWithin<json>(text, /*comments=*/true);
  }
  catch (const json::exception& e)
  {
    return "not JSON: " + JsonProblem(e);
  }
  return {};
}

// The shot's keys replace the defaults'; "camera" is merged key by key.
json MergeShot(const json& defaults, const json& own)
{
  json merged = defaults;
  for (const auto& item : own.items())
  {
    if (item.key() == "camera" && merged.contains("camera") && merged["camera"].is_object() &&
      item.value().is_object())
    {
      merged["camera"].update(item.value());
    }
    else
    {
      merged[item.key()] = item.value();
    }
  }
  return merged;
}

// A key's JSON path: under the shot's prefix when the shot gave it, else at
// the top, where the defaults are.
PathOfKey PathsIn(const json& own, const std::string& prefix)
{
  return [&own, prefix](const std::string& key)
  {
    const auto dot = key.find('.');
    const std::string top = key.substr(0, dot);
    const bool fromShot = own.contains(top) &&
      (dot == std::string::npos ||
        (own[top].is_object() && own[top].contains(key.substr(dot + 1))));
    return fromShot && !prefix.empty() ? prefix + "." + key : key;
  };
}

// Where a shot's pictures go: the output template (-o, else its "output")
// filled for shot number index of count; an --orbit's frames may make many.
std::vector<Shot> ExpandShotOutput(const json& merged, const std::string& outputTemplate,
  const PathOfKey& where, std::size_t index, std::size_t count, const Shot& shot)
{
  const std::string pattern = !outputTemplate.empty() ? outputTemplate
    : merged.contains("output")                       ? merged["output"].get<std::string>()
                                                      : std::string();
  if (pattern.empty())
  {
    throw SceneError{ where("output"), "missing: every shot needs an output (or give -o)" };
  }
  const std::string name = merged.contains("name") ? merged["name"].get<std::string>() : "";
  std::vector<Shot> shots;
  if (std::string problem = ExpandShot(pattern, shot, name, index, count, shots); !problem.empty())
  {
    throw SceneError{ outputTemplate.empty() ? where("output") : "-o", problem };
  }
  return shots;
}

// The shots of a parsed scene file; throws SceneError.
std::vector<Shot> ReadShots(
  const json& scene, const std::string& path, const std::string& outputTemplate)
{
  const std::vector<std::string> shotKeys = SceneKeys();
  std::vector<std::string> topKeys = shotKeys;
  topKeys.push_back("shots");
  ExpectObject(scene, "", topKeys);
  json defaults = scene;
  defaults.erase("shots");
  json list = scene.contains("shots") ? scene["shots"] : json::array({ json::object() });
  if (!list.is_array() || list.empty())
  {
    throw SceneError{ "shots", "expected a non-empty array of shots, not " + Quoted(list) };
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::map<std::string, std::string> outputs; // output -> the shot that writes it
  std::vector<Shot> shots;
  for (std::size_t i = 0; i < list.size(); ++i)
  {
    const std::string prefix = scene.contains("shots") ? "shots[" + std::to_string(i) + "]" : "";
    ExpectObject(list[i], prefix, shotKeys);
    const json merged = MergeShot(defaults, list[i]);
    const PathOfKey where = PathsIn(list[i], prefix);
    Shot shot;
    shot.Label = path + (prefix.empty() ? "" : " " + prefix);
    shot.MakeFolders = true;
    ReadSceneSettings(merged, folder, where, shot.Scene);
    if (shot.Scene.Mesh.empty())
    {
      throw SceneError{ where("mesh"), "missing: every shot needs a mesh" };
    }
    for (const Shot& expanded :
      ExpandShotOutput(merged, outputTemplate, where, i, list.size(), shot))
    {
      const auto [other, added] = outputs.emplace(OutputIdentity(expanded.Output), prefix);
      if (!added)
      {
        // The shot's resolved output, wherever its template came from.
        throw SceneError{ prefix.empty() ? "output" : prefix + ".output",
          "\"" + expanded.Output + "\" is also " +
            (other->second.empty() ? "another shot" : other->second) + "'s output" };
      }
      shots.push_back(expanded);
    }
  }
  return shots;
}
}

std::string SceneSchema()
{
  return JsonText(SceneSchemaJson(), 2) + "\n";
}

std::string ReadSceneFile(
  const std::string& path, const std::string& outputTemplate, std::vector<Shot>& shots)
{
  json scene;
  if (std::string problem = ParseSceneJson(path, scene); !problem.empty())
  {
    return problem;
  }
  shots.clear();
  try
  {
    shots = ReadShots(scene, path, outputTemplate);
  }
  catch (const SceneError& e)
  {
    return (e.Path.empty() ? "" : e.Path + ": ") + e.Message;
  }
  return {};
}
}
