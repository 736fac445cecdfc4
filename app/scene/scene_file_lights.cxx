// "lights": each light object written as --light takes it
// (kind:position:direction:...), so that a light means what the option's
// light means.
#include "scene/scene_file_settings.h"

namespace shadelab
{
namespace scene_file
{
namespace
{
const std::vector<std::string> LightKeys{ "kind", "position", "direction", "color", "half_angle",
  "exponent" };

std::string LightText(const json& light, const std::string& path)
{
  ExpectObject(light, path, LightKeys);
  if (!light.contains("kind"))
  {
    throw SceneError{ path + ".kind", "missing (" + JoinedNames<LightKind>(", ", " or ") + ")" };
  }
  const std::string kind = Choice(light["kind"], path + ".kind", "kind", Names<LightKind>());
  auto field = [&](const char* key) -> const json&
  {
    if (!light.contains(key))
    {
      throw SceneError{ path + "." + key, "missing for a " + kind + " light" };
    }
    return light[key];
  };
  auto forbid = [&](const char* key)
  {
    if (light.contains(key))
    {
      throw SceneError{ path + "." + key, "not used by a " + kind + " light" };
    }
  };
  std::string text = kind;
  const LightKind known = *FromName<LightKind>(kind);
  if (known == LightKind::Point)
  {
    forbid("direction");
    forbid("half_angle");
    forbid("exponent");
    text += ":" + Triple(field("position"), path + ".position");
  }
  else if (known == LightKind::Directional)
  {
    forbid("position");
    forbid("half_angle");
    forbid("exponent");
    text += ":" + Triple(field("direction"), path + ".direction");
  }
  else
  {
    text += ":" + Triple(field("position"), path + ".position") + ":" +
      Triple(field("direction"), path + ".direction") + ":" +
      Number(field("half_angle"), path + ".half_angle") + ":" +
      (light.contains("exponent") ? Number(light["exponent"], path + ".exponent") : "0");
  }
  if (light.contains("color"))
  {
    text += ":" + Triple(light["color"], path + ".color");
  }
  return text;
}
}

void ConvertLights(const json& v, const std::string& path, SceneOptions& o)
{
  if (!v.is_array())
  {
    throw SceneError{ path, "expected an array of lights, not " + Quoted(v) };
  }
  o.Lights.clear();
  for (std::size_t i = 0; i < v.size(); ++i)
  {
    const std::string at = path + "[" + std::to_string(i) + "]";
    SceneOptions one;
    Apply(one, { "--light", LightText(v[i], at) }, at);
    o.Lights.push_back(one.Lights.at(0));
  }
}
}
}
