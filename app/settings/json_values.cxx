#include "settings/json_values.h"

#include "settings/command_line.h"
#include "shadelabJsonProblem.h"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace shadelab
{
namespace scene_file
{
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
  return JsonExcerpt(value);
}

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

std::string Triple(const json& value, const std::string& path)
{
  if (!value.is_array() || value.size() != 3 ||
    !std::all_of(value.begin(), value.end(), [](const json& v) { return v.is_number(); }))
  {
    throw SceneError{ path, "expected three numbers [x, y, z], not " + Quoted(value) };
  }
  return Number(value[0], path) + "," + Number(value[1], path) + "," + Number(value[2], path);
}

bool Flag(const json& value, const std::string& path)
{
  if (!value.is_boolean())
  {
    throw SceneError{ path, "expected true or false, not " + Quoted(value) };
  }
  return value.get<bool>();
}

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
}
}
