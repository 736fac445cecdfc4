// The output name template of a scene file's shots (or of -o): fields from
// the shot's settings, so that many shots write many files; with --orbit,
// {frame} makes a file per frame.
#include "core/output_path.h"
#include "scene/camera.h"
#include "scene/scene_file.h"
#include "settings/json_values.h"

#include <filesystem>
#include <map>

namespace shadelab
{
namespace
{
using Fields = std::map<std::string, std::string>;

std::string Stem(const std::string& path)
{
  return std::filesystem::path(path).stem().string();
}

// index zero-padded to as many digits as count - 1 has.
std::string Padded(std::size_t index, std::size_t count)
{
  const std::string digits = std::to_string(count > 0 ? count - 1 : 0);
  std::string number = std::to_string(index);
  number.insert(0, digits.size() > number.size() ? digits.size() - number.size() : 0, '0');
  return number;
}

// The values of the fields for shot number index of count.
Fields TemplateFields(
  const Shot& shot, const std::string& name, std::size_t index, std::size_t count)
{
  const std::string number = Padded(index, count);
  const SceneOptions& o = shot.Scene;
  return { { "mesh", Stem(o.Mesh) }, { "shading", ToString(o.ShadingRule) },
    { "reflection", ToString(o.ReflectionModel) }, { "material", o.MaterialName },
    { "weighting", o.Computed.Weighting },
    { "size", std::to_string(o.Size.Width) + "x" + std::to_string(o.Size.Height) },
    { "index", number }, { "name", name.empty() ? number : name } };
}

std::string Expand(const std::string& pattern, const Fields& fields, std::string& output)
{
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
      return "unknown field {" + field + "} in \"" + pattern +
        "\" (known: " + scene_file::Join(known) +
        (field == "frame" ? "; {frame} numbers --orbit's frames" : "") + ")";
    }
    output += found->second;
    i = end;
  }
  return {};
}
}

std::string ExpandOutputTemplate(const std::string& pattern, const Shot& shot,
  const std::string& name, std::size_t index, std::size_t count, std::string& output)
{
  return Expand(pattern, TemplateFields(shot, name, index, count), output);
}

std::string ExpandShot(const std::string& pattern, const Shot& shot, const std::string& name,
  std::size_t index, std::size_t count, std::vector<Shot>& shots)
{
  Fields fields = TemplateFields(shot, name, index, count);
  Shot expanded = shot;
  const int frames = shot.Scene.Orbit;
  if (frames == 0)
  {
    const std::string error = Expand(pattern, fields, expanded.Output);
    if (error.empty())
    {
      shots.push_back(expanded);
    }
    return error;
  }
  // The pattern has {frame} exactly when the output depends on its value.
  std::string second;
  fields["frame"] = "1";
  if (const std::string error = Expand(pattern, fields, second); !error.empty())
  {
    return error;
  }
  fields["frame"] = "0";
  Expand(pattern, fields, expanded.Output); // as above: it expands
  if (expanded.Output == second)
  {
    const std::string extension = LowerExtension(expanded.Output);
    if (extension != ".gif" && extension != ".mp4")
    {
      return "\"" + pattern +
        "\" has no {frame} (a picture per frame of --orbit) nor the extension .gif or .mp4 "
        "(one animation of them all)";
    }
    expanded.Animation = true;
    shots.push_back(expanded);
    return {};
  }
  for (int k = 0; k < frames; ++k)
  {
    expanded.Scene = OrbitFrame(shot.Scene, k);
    fields["frame"] = Padded(static_cast<std::size_t>(k), static_cast<std::size_t>(frames));
    Expand(pattern, fields, expanded.Output); // as above: it expands
    shots.push_back(expanded);
  }
  return {};
}
}
