// --light and "lights": each light object written as --light takes it
// (kind:position:direction:...), so that a light means what the option's
// light means.
#include "settings/light_setting.h"

#include "settings/setting_kinds.h"
#include "settings/special_settings.h"

namespace shadelab
{
namespace
{
using namespace scene_file;

const std::vector<std::string> LightKeys{ "kind", "position", "direction", "color", "half_angle",
  "exponent", "attenuation", "shadows" };

// A light's triples as --light writes them: the Triple kind's text.
std::string Triple(const Vec3& v)
{
  return settings::Triple{ settings::Triple::Point }.Text(v);
}

// A light object of a scene file as --light's text.
std::string LightText(const json& light, const std::string& path)
{
  ExpectObject(light, path, LightKeys);
  if (!light.contains("kind"))
  {
    throw SceneError{ path + ".kind", "missing (" + JoinedNames<LightKind>(", ", " or ") + ")" };
  }
  const std::string kind = Choice(light["kind"], path + ".kind", "kind", Names<LightKind>());
  const LightGeometry parts = GeometryOf(*FromName<LightKind>(kind));
  // No key the kind has not; then every key it has (a spot's exponent may
  // be left out).
  const std::pair<const char*, bool> keys[] = { { "position", parts.Position },
    { "direction", parts.Direction }, { "half_angle", parts.Cone }, { "exponent", parts.Cone },
    { "attenuation", parts.Position } };
  for (const auto& [key, has] : keys)
  {
    if (!has && light.contains(key))
    {
      throw SceneError{ path + "." + key, "not used by a " + kind + " light" };
    }
  }
  const auto field = [&](const char* key) -> const json&
  {
    if (!light.contains(key))
    {
      throw SceneError{ path + "." + key, "missing for a " + kind + " light" };
    }
    return light[key];
  };
  std::string text = kind;
  if (parts.Position)
  {
    text += ":" + scene_file::Triple(field("position"), path + ".position");
  }
  if (parts.Direction)
  {
    text += ":" + scene_file::Triple(field("direction"), path + ".direction");
  }
  if (parts.Cone)
  {
    text += ":" + Number(field("half_angle"), path + ".half_angle");
    text +=
      ":" + (light.contains("exponent") ? Number(light["exponent"], path + ".exponent") : "0");
  }
  if (light.contains("color"))
  {
    text += ":" + scene_file::Triple(light["color"], path + ".color");
  }
  if (light.contains("attenuation"))
  {
    text += "@" + scene_file::Triple(light["attenuation"], path + ".attenuation");
  }
  if (light.contains("shadows"))
  {
    if (!light["shadows"].is_boolean())
    {
      throw SceneError{ path + ".shadows",
        "expected true or false, not " + Quoted(light["shadows"]) };
    }
    text += light["shadows"].get<bool>() ? "+shadows" : "+no-shadows";
  }
  return text;
}

void ReadLights(const json& v, const std::string& path, SceneOptions& o)
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
    Apply(one, { "--light=" + LightText(v[i], at) }, at);
    o.Lights.push_back(one.Lights.at(0));
  }
}

nlohmann::ordered_json LightSchema()
{
  const nlohmann::ordered_json triple{ { "$ref", "#/$defs/triple" } };
  return { { "type", "array" },
    { "description", "Empty or absent: one white point light at the camera" },
    { "items",
      { { "type", "object" },
        { "properties",
          { { "kind", { { "enum", Names<LightKind>() } } }, { "position", triple },
            { "direction",
              { { "$ref", "#/$defs/triple" }, { "description", "The way the light shines" } } },
            { "color", { { "$ref", "#/$defs/color" } } },
            { "half_angle",
              { { "type", "number" }, { "exclusiveMinimum", 0 }, { "maximum", 90 } } },
            { "exponent", { { "type", "number" }, { "minimum", 0 } } },
            { "attenuation",
              { { "$ref", "#/$defs/attenuation" },
                { "description", "Its own C0, C1, C2, instead of the scene's" } } },
            { "shadows",
              { { "type", "boolean" },
                { "description", "Whether it casts shadows, instead of the scene's" } } } } },
        { "required", { "kind" } }, { "additionalProperties", false } } } };
}
}

std::string LightArgument(const Light& light)
{
  const LightGeometry parts = GeometryOf(light.Kind);
  std::string text = ToString(light.Kind);
  if (parts.Position)
  {
    text += ":" + Triple(light.Position);
  }
  if (parts.Direction)
  {
    text += ":" + Triple(light.Direction);
  }
  if (parts.Cone)
  {
    text +=
      ":" + settings::NumberText(light.HalfAngleDeg) + ":" + settings::NumberText(light.Exponent);
  }
  text += ":" + Triple(light.Color);
  if (light.Attenuation)
  {
    text += "@" + Triple(*light.Attenuation);
  }
  if (light.Shadows)
  {
    text += *light.Shadows ? "+shadows" : "+no-shadows";
  }
  return text;
}

nlohmann::ordered_json LightJson(const Light& light, const char* halfAngleKey)
{
  const LightGeometry parts = GeometryOf(light.Kind);
  nlohmann::ordered_json j;
  j["kind"] = ToString(light.Kind);
  if (parts.Position)
  {
    j["position"] = light.Position;
  }
  if (parts.Direction)
  {
    j["direction"] = light.Direction;
  }
  j["color"] = light.Color;
  if (parts.Cone)
  {
    j[halfAngleKey] = light.HalfAngleDeg;
    j["exponent"] = light.Exponent;
  }
  if (light.Attenuation)
  {
    j["attenuation"] = *light.Attenuation;
  }
  if (light.Shadows)
  {
    j["shadows"] = *light.Shadows;
  }
  return j;
}

namespace settings
{
Setting LightsSetting()
{
  Setting s;
  s.Option = "--light";
  s.Key = "lights";
  s.ValueName = "SPEC";
  s.Help = "A light, repeatable: point:X,Y,Z[:R,G,B] | directional:DX,DY,DZ[:R,G,B] | "
           "spot:X,Y,Z:DX,DY,DZ:HALF_ANGLE_DEG[:EXPONENT[:R,G,B]], a point or spot light "
           "followed by @C0,C1,C2 for its own attenuation (--attenuation); any light followed by "
           "+shadows or +no-shadows for its own choice (--shadows). "
           "None given: one white point light at the camera";
  s.Default = "one white point light at the camera";
  s.Commands = PictureCommands;
  s.Declare = [help = s.Help](CLI::App& c, SceneOptions& o)
  {
    return c
      .add_option_function<std::vector<std::string>>(
        "--light",
        [&o](const std::vector<std::string>& texts)
        {
          o.Lights.clear();
          for (const std::string& t : texts)
          {
            try
            {
              o.Lights.push_back(ParseLight(t));
            }
            catch (const std::invalid_argument& e)
            {
              throw CLI::ValidationError("--light", e.what());
            }
          }
        },
        help)
      ->option_text("SPEC")
      ->take_all();
  };
  s.Arguments = [](const SceneOptions& o, std::vector<std::string>& words)
  {
    for (const Light& light : o.Lights)
    {
      words.push_back("--light");
      words.push_back(LightArgument(light));
    }
  };
  s.Read = [](const json& v, const std::string& path, const std::filesystem::path&, SceneOptions& o)
  { ReadLights(v, path, o); };
  s.Write = [](const SceneOptions& o, ordered_json& shot)
  {
    if (!o.Lights.empty())
    {
      auto& lights = shot["lights"] = ordered_json::array();
      for (const Light& light : o.Lights)
      {
        lights.push_back(LightJson(light, "half_angle"));
      }
    }
  };
  s.Schema = LightSchema;
  s.Sample = [](SceneOptions& o)
  {
    Light spot;
    spot.Kind = LightKind::Spot;
    spot.Position = { 1.0 / 3, -2, 5 };
    spot.Direction = { 0, -1.0 / 3, -1 };
    spot.HalfAngleDeg = 12.5;
    spot.Exponent = 2.0 / 3;
    spot.Color = { 0.9, 0.8, 0.7 };
    spot.Attenuation = Vec3{ 1, 0.25, 1.0 / 16 };
    spot.Shadows = true;
    Light sun;
    sun.Kind = LightKind::Directional;
    sun.Direction = { 1, 2, 3 };
    o.Lights = { spot, sun, Light{} };
  };
  return s;
}
}
}
