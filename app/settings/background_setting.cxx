// --background: a colour, transparent (alpha 0 around the mesh, whose
// colours stay those it has over black: OpenImageIO's associated alpha), or
// the environment (--environment seen along each pixel's ray).
#include "settings/setting_kinds.h"
#include "settings/special_settings.h"

namespace shadelab
{
namespace settings
{
Setting BackgroundSetting()
{
  const Triple colour{ Triple::Colour };
  Setting s;
  s.Option = "--background";
  s.Key = "background";
  s.ValueName = "R,G,B|transparent|environment";
  s.Default = colour.Text(SceneOptions{}.Background);
  s.Help =
    "Background colour, or transparent (alpha in PNG, TIFF and EXR), or environment (--environment "
    "seen along each pixel's ray, what covers the pixel laid over it) (default " +
    s.Default + ")";
  s.Commands = PictureCommands;
  s.Declare = [names = s](CLI::App& c, SceneOptions& o)
  {
    return c
      .add_option_function<std::string>(
        names.Option,
        [&o](const std::string& text)
        {
          o.TransparentBackground = text == "transparent";
          o.EnvironmentBackground = text == "environment";
          try
          {
            o.Background =
              o.TransparentBackground || o.EnvironmentBackground ? Rgb{ 0, 0, 0 } : ParseRgb(text);
          }
          catch (const std::invalid_argument& e)
          {
            throw CLI::ValidationError("--background", e.what());
          }
        },
        names.Help)
      ->option_text(names.ValueName);
  };
  // o's value as text, or "" for the default.
  const auto given = [colour](const SceneOptions& o)
  {
    return o.TransparentBackground                ? std::string("transparent")
      : o.EnvironmentBackground                   ? std::string("environment")
      : o.Background != SceneOptions{}.Background ? colour.Text(o.Background)
                                                  : std::string();
  };
  s.Arguments = [given](const SceneOptions& o, std::vector<std::string>& words)
  {
    if (const std::string text = given(o); !text.empty())
    {
      words.push_back("--background");
      words.push_back(text);
    }
  };
  s.Read = [colour](
             const json& v, const std::string& path, const std::filesystem::path&, SceneOptions& o)
  {
    const bool named = v.is_string() &&
      (v.get<std::string>() == "transparent" || v.get<std::string>() == "environment");
    scene_file::Apply(
      o, { "--background=" + (named ? v.get<std::string>() : colour.FromJson(v, path)) }, path);
  };
  s.Write = [colour, given](const SceneOptions& o, ordered_json& shot)
  {
    if (!given(o).empty())
    {
      shot["background"] = o.TransparentBackground || o.EnvironmentBackground
        ? ordered_json(given(o))
        : colour.ToJson(o.Background);
    }
  };
  s.Schema = [help = s.Help]()
  {
    return ordered_json{ { "oneOf",
                           { { { "$ref", "#/$defs/color" } }, { { "const", "transparent" } },
                             { { "const", "environment" } } } },
      { "description", help } };
  };
  s.Sample = [](SceneOptions& o) { o.TransparentBackground = true; };
  return s;
}
}
}
