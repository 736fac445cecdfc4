// A scene file written from SceneOptions (scene_file.h): the inverse of
// reading one, with the same keys, for the inspector's Save scene.
#include "scene/scene_file.h"
#include "settings/scene_keys.h"
#include "shadelabJsonProblem.h"

namespace shadelab
{
std::string WriteSceneText(const SceneOptions& s, const std::string& output)
{
  nlohmann::ordered_json shot;
  shot["mesh"] = s.Mesh;
  shot["output"] = output;
  scene_file::WriteSceneSettings(s, shot);
  return JsonText(shot, 2) + "\n";
}
}
