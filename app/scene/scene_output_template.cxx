// The output name template of a scene file's shots (or of -o): fields from
// the shot's settings, so that many shots write many files.
#include "scene/scene_file.h"
#include "scene/scene_file_values.h"

#include <filesystem>
#include <map>

namespace shadelab
{
namespace
{
std::string Stem(const std::string& path)
{
  return std::filesystem::path(path).stem().string();
}

// The values of the fields for shot number index of count.
std::map<std::string, std::string> TemplateFields(
  const Shot& shot, const std::string& name, std::size_t index, std::size_t count)
{
  const std::string digits = std::to_string(count > 0 ? count - 1 : 0);
  std::string number = std::to_string(index);
  number.insert(0, digits.size() > number.size() ? digits.size() - number.size() : 0, '0');
  const SceneOptions& o = shot.Scene;
  return { { "mesh", Stem(o.Mesh) }, { "shading", ToString(o.ShadingRule) },
    { "reflection", ToString(o.ReflectionModel) }, { "material", o.MaterialName },
    { "weighting", o.Computed.Weighting },
    { "size", std::to_string(o.Size.Width) + "x" + std::to_string(o.Size.Height) },
    { "index", number }, { "name", name.empty() ? number : name } };
}
}

std::string ExpandOutputTemplate(const std::string& pattern, const Shot& shot,
  const std::string& name, std::size_t index, std::size_t count, std::string& output)
{
  const std::map<std::string, std::string> fields = TemplateFields(shot, name, index, count);
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
        "\" (known: " + scene_file::Join(known) + ")";
    }
    output += found->second;
    i = end;
  }
  return {};
}
}
