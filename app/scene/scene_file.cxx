#include "scene/scene_file.h"

#include "shadelabSceneSchema.h" // generated from data/scene.schema.json
#include "vtkShadelabMeshNormals.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>

namespace shadelab
{
namespace
{
using nlohmann::json;

// A problem at a JSON path.
struct SceneError
{
  std::string Path;
  std::string Message;
};

const std::vector<std::string> ShotKeys{ "name", "mesh", "output", "shading", "reflection",
  "material", "ambient", "lights", "camera", "size", "background", "normals", "weighting",
  "feature_angle", "orient", "pixel_type" };
const std::vector<std::string> CameraKeys{ "position", "focal_point", "view_up", "view_angle",
  "orthographic", "parallel_scale" };
const std::vector<std::string> MaterialKeys{ "name", "base", "ka", "kd", "ks", "ns" };
const std::vector<std::string> LightKeys{ "kind", "position", "direction", "color", "half_angle",
  "exponent" };

std::string Join(const std::vector<std::string>& words)
{
  std::string text;
  for (const std::string& w : words)
  {
    text += (text.empty() ? "" : ", ") + w;
  }
  return text;
}

std::string Quoted(const json& value)
{
  return value.dump();
}

// An object whose keys are all in `known`.
void ExpectObject(const json& value, const std::string& path, const std::vector<std::string>& known)
{
  if (!value.is_object())
  {
    throw SceneError{ path, "expected an object, not " + Quoted(value) };
  }
  for (const auto& item : value.items())
  {
    if (std::find(known.begin(), known.end(), item.key()) == known.end())
    {
      throw SceneError{ path.empty() ? item.key() : path + "." + item.key(),
        "unknown key (known: " + Join(known) + ")" };
    }
  }
}

std::string Text(const json& value, const std::string& path)
{
  if (!value.is_string())
  {
    throw SceneError{ path, "expected a string, not " + Quoted(value) };
  }
  return value.get<std::string>();
}

std::string Number(const json& value, const std::string& path)
{
  if (!value.is_number())
  {
    throw SceneError{ path, "expected a number, not " + Quoted(value) };
  }
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value.get<double>());
  return text;
}

// [x, y, z] as the options write it: "x,y,z".
std::string Triple(const json& value, const std::string& path)
{
  if (!value.is_array() || value.size() != 3 ||
    !std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_number(); }))
  {
    throw SceneError{ path, "expected three numbers [x, y, z], not " + Quoted(value) };
  }
  return Number(value[0], path) + "," + Number(value[1], path) + "," + Number(value[2], path);
}

// One of `known`, as a string.
std::string Choice(const json& value, const std::string& path, const char* what,
  const std::vector<std::string>& known)
{
  const std::string text = Text(value, path);
  if (std::find(known.begin(), known.end(), text) == known.end())
  {
    throw SceneError{ path,
      std::string("unknown ") + what + " \"" + text + "\" (known: " + Join(known) + ")" };
  }
  return text;
}

std::vector<std::string> MaterialNames()
{
  std::vector<std::string> names;
  for (const Material& m : LectureMaterials())
  {
    names.push_back(m.Name);
  }
  return names;
}

// A light object as --light writes it: kind:position:direction:...
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

// Sets what args say on o through the render command's own options; a
// problem becomes a SceneError at path.
void Apply(SceneOptions& o, const std::vector<std::string>& args, const std::string& path)
{
  try
  {
    ApplySceneArguments(o, args);
  }
  catch (const std::invalid_argument& e)
  {
    throw SceneError{ path, e.what() };
  }
}

// A shot's settings (defaults and overrides merged) onto shot. where(key)
// is the JSON path of a key.
template <typename Where>
void Convert(const json& s, Shot& shot, const std::filesystem::path& folder, Where where)
{
  SceneOptions& o = shot.Scene;
  for (const auto& item : s.items())
  {
    const std::string& key = item.key();
    const json& v = item.value();
    const std::string path = where(key);
    if (key == "name" || key == "output")
    {
      Text(v, path); // used by the output template
    }
    else if (key == "mesh")
    {
      const std::filesystem::path mesh(Text(v, path));
      o.Mesh = (mesh.is_absolute() ? mesh : folder / mesh).lexically_normal().string();
    }
    else if (key == "shading")
    {
      Apply(o, { "--shading", Choice(v, path, "shading", Names<Shading>()) }, path);
    }
    else if (key == "reflection")
    {
      Apply(o, { "--reflection", Choice(v, path, "reflection", Names<Reflection>()) }, path);
    }
    else if (key == "normals")
    {
      Apply(o, { "--normals", Choice(v, path, "normals", Names<NormalsMode>()) }, path);
    }
    else if (key == "weighting")
    {
      Apply(o,
        { "--weighting",
          Choice(v, path, "weighting", Names<vtkShadelabMeshNormals::Weightings>()) },
        path);
    }
    else if (key == "pixel_type")
    {
      shot.Pixels = *FromName<PixelType>(Choice(v, path, "pixel type", Names<PixelType>()));
    }
    else if (key == "material")
    {
      if (v.is_string())
      {
        Apply(o, { "--material", Choice(v, path, "material", MaterialNames()) }, path);
        continue;
      }
      ExpectObject(v, path, MaterialKeys);
      if (v.contains("base"))
      {
        Apply(o, { "--material", Choice(v["base"], path + ".base", "material", MaterialNames()) },
          path + ".base");
      }
      else
      {
        for (const char* needed : { "ka", "kd", "ks", "ns" })
        {
          if (!v.contains(needed))
          {
            throw SceneError{ path + "." + needed,
              "missing (a material without \"base\" gives all of ka, kd, ks, ns)" };
          }
        }
        o.MaterialName = "custom";
      }
      for (const char* k : { "ka", "kd", "ks" })
      {
        if (v.contains(k))
        {
          Apply(o, { std::string("--") + k, Triple(v[k], path + "." + k) }, path + "." + k);
        }
      }
      if (v.contains("ns"))
      {
        Apply(o, { "--ns", Number(v["ns"], path + ".ns") }, path + ".ns");
      }
      // Resolved now, so that a name of its own cannot lose the base's values.
      const Material m = o.EffectiveMaterial();
      o.Ka = m.Ka;
      o.Kd = m.Kd;
      o.Ks = m.Ks;
      o.Ns = m.Ns;
      if (v.contains("name"))
      {
        o.MaterialName = Text(v["name"], path + ".name");
      }
      else if (v.contains("base") &&
        (v.contains("ka") || v.contains("kd") || v.contains("ks") || v.contains("ns")))
      {
        o.MaterialName += "-custom";
      }
    }
    else if (key == "ambient" || key == "background")
    {
      Apply(o, { "--" + key, Triple(v, path) }, path);
    }
    else if (key == "lights")
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
    else if (key == "camera")
    {
      ExpectObject(v, path, CameraKeys);
      for (const auto& c : v.items())
      {
        const std::string at = where("camera." + c.key());
        if (c.key() == "orthographic")
        {
          if (!c.value().is_boolean())
          {
            throw SceneError{ at, "expected true or false, not " + Quoted(c.value()) };
          }
          o.Orthographic = c.value().get<bool>();
        }
        else if (c.key() == "view_angle" || c.key() == "parallel_scale")
        {
          Apply(o,
            { "--" + std::string(c.key() == "view_angle" ? "view-angle" : "parallel-scale"),
              Number(c.value(), at) },
            at);
        }
        else
        {
          std::string option = "--camera-" + c.key();
          std::replace(option.begin(), option.end(), '_', '-');
          Apply(o, { option, Triple(c.value(), at) }, at);
        }
      }
    }
    else if (key == "size")
    {
      if (v.is_array() && v.size() == 2 && v[0].is_number_integer() && v[1].is_number_integer())
      {
        Apply(o,
          { "--size",
            std::to_string(v[0].get<long long>()) + "x" + std::to_string(v[1].get<long long>()) },
          path);
      }
      else
      {
        throw SceneError{ path, "expected [width, height] in pixels, not " + Quoted(v) };
      }
    }
    else if (key == "feature_angle")
    {
      Apply(o, { "--feature-angle", Number(v, path) }, path);
    }
    else if (key == "orient")
    {
      if (!v.is_boolean())
      {
        throw SceneError{ path, "expected true or false, not " + Quoted(v) };
      }
      o.Computed.Orient = v.get<bool>();
    }
  }
}

std::string Stem(const std::string& path)
{
  return std::filesystem::path(path).stem().string();
}
}

const char* SceneSchema()
{
  return SceneSchemaJson;
}

const std::vector<std::string>& SceneShotKeys()
{
  return ShotKeys;
}

std::string ExpandOutputTemplate(const std::string& pattern, const Shot& shot,
  const std::string& name, std::size_t index, std::size_t count, std::string& output)
{
  const std::string digits = std::to_string(count > 0 ? count - 1 : 0);
  std::string number = std::to_string(index);
  number.insert(0, digits.size() > number.size() ? digits.size() - number.size() : 0, '0');
  const SceneOptions& o = shot.Scene;
  const std::map<std::string, std::string> fields{ { "mesh", Stem(o.Mesh) },
    { "shading", ToString(o.ShadingRule) }, { "reflection", ToString(o.ReflectionModel) },
    { "material", o.MaterialName }, { "weighting", o.Computed.Weighting },
    { "size", std::to_string(o.Size.Width) + "x" + std::to_string(o.Size.Height) },
    { "index", number }, { "name", name.empty() ? number : name } };
  output.clear();
  for (std::size_t i = 0; i < pattern.size(); ++i)
  {
    const char c = pattern[i];
    if ((c == '{' || c == '}') && i + 1 < pattern.size() && pattern[i + 1] == c)
    {
      output += c;
      ++i;
      continue;
    }
    if (c == '}')
    {
      return "unmatched '}' in \"" + pattern + "\" (write }} for a brace)";
    }
    if (c != '{')
    {
      output += c;
      continue;
    }
    const auto end = pattern.find('}', i);
    if (end == std::string::npos)
    {
      return "unmatched '{' in \"" + pattern + "\" (write {{ for a brace)";
    }
    const std::string field = pattern.substr(i + 1, end - i - 1);
    const auto found = fields.find(field);
    if (found == fields.end())
    {
      std::vector<std::string> known;
      for (const auto& f : fields)
      {
        known.push_back("{" + f.first + "}");
      }
      return "unknown field {" + field + "} in \"" + pattern + "\" (known: " + Join(known) + ")";
    }
    output += found->second;
    i = end;
  }
  return {};
}

std::string ReadSceneFile(
  const std::string& path, const std::string& outputTemplate, std::vector<Shot>& shots)
{
  std::ifstream in(path);
  if (!in)
  {
    return std::string("cannot read: ") + std::strerror(errno);
  }
  json scene;
  try
  {
    scene = json::parse(in, nullptr, true, /*ignore_comments=*/true);
  }
  catch (const json::exception& e)
  {
    // A syntax error ("[json.exception.parse_error.101] parse error at line
    // 3, column 5: ..."), or a number too large for a double
    // ("[json.exception.out_of_range.406] number overflow parsing '7e999'":
    // a finding of fuzz_scene_file).
    std::string what = e.what();
    const auto at = what.find("at line ");
    const auto close = what.find("] ");
    what = at != std::string::npos ? what.substr(at + 3)
      : close != std::string::npos ? what.substr(close + 2)
                                   : what;
    return "not JSON: " + what;
  }
  shots.clear();
  try
  {
    std::vector<std::string> topKeys = ShotKeys;
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
    for (std::size_t i = 0; i < list.size(); ++i)
    {
      const std::string prefix = scene.contains("shots") ? "shots[" + std::to_string(i) + "]" : "";
      ExpectObject(list[i], prefix, ShotKeys);
      // The shot's keys replace the defaults'; "camera" is merged key by key.
      json merged = defaults;
      for (const auto& item : list[i].items())
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
      const json& own = list[i];
      const auto where = [&](const std::string& key)
      {
        const auto dot = key.find('.');
        const std::string top = key.substr(0, dot);
        const bool fromShot = own.contains(top) &&
          (dot == std::string::npos ||
            (own[top].is_object() && own[top].contains(key.substr(dot + 1))));
        return fromShot && !prefix.empty() ? prefix + "." + key : key;
      };
      Shot shot;
      shot.Label = path + (prefix.empty() ? "" : " " + prefix);
      Convert(merged, shot, folder, where);
      if (shot.Scene.Mesh.empty())
      {
        throw SceneError{ where("mesh"), "missing: every shot needs a mesh" };
      }
      const std::string pattern = !outputTemplate.empty() ? outputTemplate
        : merged.contains("output")                       ? merged["output"].get<std::string>()
                                                          : std::string();
      if (pattern.empty())
      {
        throw SceneError{ where("output"), "missing: every shot needs an output (or give -o)" };
      }
      const std::string name = merged.contains("name") ? merged["name"].get<std::string>() : "";
      if (std::string problem =
            ExpandOutputTemplate(pattern, shot, name, i, list.size(), shot.Output);
          !problem.empty())
      {
        throw SceneError{ outputTemplate.empty() ? where("output") : "-o", problem };
      }
      const auto [other, added] = outputs.emplace(shot.Output, prefix);
      if (!added)
      {
        // The shot's resolved output, wherever its template came from.
        throw SceneError{ prefix.empty() ? "output" : prefix + ".output",
          "\"" + shot.Output + "\" is also " +
            (other->second.empty() ? "another shot" : other->second) + "'s output" };
      }
      shots.push_back(shot);
    }
  }
  catch (const SceneError& e)
  {
    shots.clear();
    return (e.Path.empty() ? "" : e.Path + ": ") + e.Message;
  }
  return {};
}
}
