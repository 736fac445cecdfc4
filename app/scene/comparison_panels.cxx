#include "scene/comparison_panels.h"

#include "settings/command_line.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <stdexcept>

namespace shadelab
{
namespace
{
// The settings a mode may change: those whose values hold no ',' or ':'
// (the separators). The camera, size and lights are the comparison's own,
// shared by every panel. A panel of --shading's rule draws with the
// stages of one's own given for the comparison, unless it names its own;
// the other rules' panels draw their generated stages.
const std::array<const char*, 9> ModeKeys{ "shading", "reflection", "material", "weighting", "ns",
  "normals", "specular_form", "vertex_shader", "fragment_shader" };

Panel ParseMode(const std::string& mode, const SceneOptions& base)
{
  const auto fail = [&mode](const std::string& problem)
  { throw std::invalid_argument("mode '" + mode + "': " + problem); };
  if (mode.empty())
  {
    fail("is empty");
  }
  std::vector<std::string> args;
  std::string changes;
  bool ownStages = false;
  const std::vector<std::string> parts = Split(mode, ':');
  for (std::size_t i = 0; i < parts.size(); ++i)
  {
    const std::string& part = parts[i];
    const auto equals = part.find('=');
    if (equals == std::string::npos && i == 0)
    {
      args.insert(args.end(), { "--shading", part });
      continue;
    }
    const std::string key = part.substr(0, equals);
    if (equals == std::string::npos ||
      std::find(ModeKeys.begin(), ModeKeys.end(), key) == ModeKeys.end())
    {
      fail("'" + part +
        "' is not KEY=VALUE with KEY one of shading, reflection, material, "
        "weighting, ns, normals, specular_form, vertex_shader, fragment_shader");
    }
    const std::string value = part.substr(equals + 1);
    ownStages = ownStages || key == "vertex_shader" || key == "fragment_shader";
    std::string option = "--" + key;
    std::replace(option.begin(), option.end(), '_', '-');
    args.insert(args.end(), { option, value });
    if (key != "shading")
    {
      changes += ", " + key + " " + value;
    }
  }
  Panel panel;
  panel.Scene = base;
  panel.Mode = mode;
  try
  {
    ApplySceneArguments(panel.Scene, args);
  }
  catch (const std::invalid_argument& e)
  {
    fail(e.what());
  }
  if (!ownStages && panel.Scene.ShadingRule != base.ShadingRule)
  {
    panel.Scene.VertexShader.clear();
    panel.Scene.FragmentShader.clear();
  }
  panel.Label = ToString(panel.Scene.ShadingRule) + changes;
  return panel;
}
}

const char* const ModesHelp =
  "Panels, comma-separated: MODE = [RULE][:KEY=VALUE]..., RULE none|flat|gouraud|phong|raytrace, "
  "KEY one of shading, reflection, material, weighting, ns, normals, specular_form, "
  "vertex_shader, fragment_shader; e.g. phong,phong:material=gold,gouraud:weighting=area or "
  "phong,phong:fragment_shader=mine.frag (default flat,gouraud,phong)";

void AddComparisonOptions(CLI::App& command, ComparisonOptions& o)
{
  command.add_option("--modes", o.Modes, ModesHelp)->option_text("MODE,...");
  command
    .add_option("--diff", o.Difference,
      "Add a panel of |A - B| per pixel (the largest over R, G, B of what 8-bit pictures show), "
      "as a heat map scaled to its largest value, with a colour bar; A and B are modes as "
      "written in --modes or their numbers from 1")
    ->option_text("A,B");
  command.add_flag("--components", o.Components,
    "Show each mode as its ambient | diffuse | specular terms and their total, a row per mode");
}

Comparison PlanComparison(const ComparisonOptions& o, const SceneOptions& base)
{
  if (base.TransparentBackground)
  {
    // Panels sit on label strips and beside each other: a picture of render's.
    throw std::invalid_argument("--background transparent is for render's pictures");
  }
  Comparison c;
  c.Modes = ParseModes(o.Modes, base);
  c.Panels = o.Components ? SplitIntoTerms(c.Modes) : c.Modes;
  c.Columns = o.Components ? 4 : 0;
  if (!o.Difference.empty())
  {
    const auto [a, b] = ParseDifference(o.Difference, c.Modes);
    // With --components a mode's total is the last of its four panels.
    c.DifferenceA = o.Components ? 4 * a + 3 : a;
    c.DifferenceB = o.Components ? 4 * b + 3 : b;
    c.DifferenceLabel = "|" + c.Modes[a].Label + " - " + c.Modes[b].Label + "|";
  }
  return c;
}

std::vector<Panel> ParseModes(const std::string& text, const SceneOptions& base)
{
  std::vector<Panel> panels;
  for (const std::string& mode : Split(text, ','))
  {
    panels.push_back(ParseMode(mode, base));
  }
  return panels;
}

void ShowTerms(
  SceneOptions& s, bool ambient, bool diffuse, bool specular, bool environment, bool normalMap)
{
  constexpr Rgb Zero{ 0, 0, 0 };
  s.Ka = ambient ? s.Ka : Zero;
  s.Kd = diffuse ? s.Kd : Zero;
  s.Ks = specular ? s.Ks : Zero;
  if (!environment)
  {
    // The environment goes, and the background that shows it with it: black.
    s.Environment.clear();
    s.EnvironmentBackground = false;
  }
  if (!normalMap)
  {
    // The options' and the file's maps: none at all.
    s.NormalMap = ScaledImage{ NoNormalMap, 1 };
    s.BumpMap.reset();
  }
}

std::vector<Panel> SplitIntoTerms(const std::vector<Panel>& panels)
{
  std::vector<Panel> split;
  for (const Panel& panel : panels)
  {
    for (const Terms terms : { Terms::Ambient, Terms::Diffuse, Terms::Specular, Terms::All })
    {
      Panel p = panel;
      p.Shown = terms;
      p.Label += std::string(": ") + ToString(terms);
      const bool all = terms == Terms::All;
      ShowTerms(p.Scene, all || terms == Terms::Ambient, all || terms == Terms::Diffuse,
        all || terms == Terms::Specular);
      split.push_back(p);
    }
  }
  return split;
}

std::pair<int, int> ParseDifference(const std::string& text, const std::vector<Panel>& modes)
{
  const std::vector<std::string> names = Split(text, ',');
  if (names.size() != 2)
  {
    throw std::invalid_argument("'" + text + "' is not two modes A,B");
  }
  std::array<int, 2> found{ -1, -1 };
  for (int k = 0; k < 2; ++k)
  {
    const std::string& name = names[k];
    for (std::size_t i = 0; i < modes.size() && found[k] < 0; ++i)
    {
      if (modes[i].Mode == name)
      {
        found[k] = static_cast<int>(i);
      }
    }
    int number = 0;
    const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), number);
    if (found[k] < 0 && error == std::errc() && end == name.data() + name.size() && number >= 1 &&
      number <= static_cast<int>(modes.size()))
    {
      found[k] = number - 1;
    }
    if (found[k] < 0)
    {
      throw std::invalid_argument("'" + name +
        "' is neither one of the modes nor a number from 1 to " + std::to_string(modes.size()));
    }
  }
  return { found[0], found[1] };
}

const char* ToString(Terms terms)
{
  switch (terms)
  {
    case Terms::All:
      return "total";
    case Terms::Ambient:
      return "ambient";
    case Terms::Diffuse:
      return "diffuse";
    case Terms::Specular:
      return "specular";
  }
  return "?";
}
}
