// The kinds of value a plain setting has (a number within bounds, a triple,
// one of an enum's names, a flag, a file, a size) and the one template,
// Plain, that makes a Setting of a kind and a field of SceneOptions. A kind
// knows its value's text on the command line, its JSON and its JSON
// Schema; Plain makes every side of the setting from them.
#ifndef shadelab_setting_kinds_h
#define shadelab_setting_kinds_h

#include "core/cli_choice.h"
#include "settings/json_values.h"
#include "settings/setting.h"

#include <CLI/CLI.hpp>

#include <limits>
#include <optional>
#include <stdexcept>
#include <type_traits>

namespace shadelab
{
namespace settings
{
using nlohmann::json;
using nlohmann::ordered_json;

/** Who a setting is: its option, scene-file key, value name, help and commands. */
struct Entry
{
  std::string Option;    // "" where only scene files have it
  std::string Key;       // "" where only the command line has it
  std::string ValueName; // "" for a flag
  std::string Help;      // without the default, which Plain appends
  CommandSet Commands = PictureCommands;
  std::string Default = {}; // the default in words, where the value's text would mislead
  bool Always = false;      // given back even when it is the default
};

/**
 * Registers an option whose text goes through parse() into target; a parse
 * failure becomes CLI11's validation error, naming the option.
 */
template <typename T, typename Parse>
CLI::Option* AddParsed(
  CLI::App& command, const std::string& name, T& target, Parse parse, const std::string& help)
{
  return command.add_option_function<std::string>(
    name,
    [&target, parse, name](const std::string& text)
    {
      try
      {
        target = parse(text);
      }
      catch (const std::invalid_argument& e)
      {
        throw CLI::ValidationError(name, e.what());
      }
    },
    help);
}

/** A number as the command line gives it back: every digit a double has. */
std::string NumberText(double value);

/** shot[key], or shot[group][name] for a key "group.name". */
ordered_json& At(ordered_json& shot, const std::string& key);

/**
 * A finite number, within bounds that its message names: "'20' is outside
 * (0, 16] pixels"; from 0 (open) to infinity "'0' is not positive", from 0
 * (closed) "'-1' is negative".
 */
struct Number
{
  double Min = -std::numeric_limits<double>::infinity();
  double Max = std::numeric_limits<double>::infinity();
  bool OpenMin = false, OpenMax = false;
  std::string Unit; // "pixels", "degrees"

  static Number Positive()
  {
    return { 0, std::numeric_limits<double>::infinity(), true, false, "" };
  }
  static Number NonNegative()
  {
    return { 0, std::numeric_limits<double>::infinity(), false, false, "" };
  }

  static constexpr bool IsFlag = false, ReadsDirectly = false;
  double Parse(const std::string& text) const;
  template <typename T>
  CLI::Option* Declare(CLI::App& c, const Setting& s, T& target) const
  {
    return AddParsed(
      c, s.Option, target, [*this](const std::string& t) { return this->Parse(t); }, s.Help)
      ->option_text(s.ValueName);
  }
  std::string Text(double value) const { return NumberText(value); }
  std::string FromJson(const json& v, const std::string& path) const
  {
    return scene_file::Number(v, path);
  }
  ordered_json ToJson(double value) const { return value; }
  ordered_json Schema() const;
  double Sample(double other) const;
};

/**
 * A finite number in a closed range that CLI11's Range checks (its message:
 * "Value 270 not in range 0.000000 to 180.000000"), as --feature-angle
 * always has been.
 */
struct ClosedRange
{
  double Min, Max;

  static constexpr bool IsFlag = false, ReadsDirectly = false;
  CLI::Option* Declare(CLI::App& c, const Setting& s, std::optional<double>& target) const;
  std::string Text(double value) const { return NumberText(value); }
  std::string FromJson(const json& v, const std::string& path) const
  {
    return scene_file::Number(v, path);
  }
  ordered_json ToJson(double value) const { return value; }
  ordered_json Schema() const;
  double Sample(double) const { return this->Min + (this->Max - this->Min) / 3; }
};

/** A whole number in a closed range (CLI11's conversion and Range, with their messages). */
struct Integer
{
  int Min, Max;

  static constexpr bool IsFlag = false, ReadsDirectly = false;
  CLI::Option* Declare(CLI::App& c, const Setting& s, int& target) const;
  std::string Text(int value) const { return std::to_string(value); }
  std::string FromJson(const json& v, const std::string& path) const
  {
    return scene_file::Number(v, path);
  }
  ordered_json ToJson(int value) const { return value; }
  ordered_json Schema() const;
  int Sample(int other) const { return other == this->Min + 1 ? this->Min + 2 : this->Min + 1; }
};

/** Three numbers: a point, a direction (not of zero length) or a colour (none negative). */
struct Triple
{
  enum Meaning
  {
    Point,
    Direction,
    Colour,
    Attenuation // C0, C1, C2 (ParseAttenuation)
  } Is;

  static constexpr bool IsFlag = false, ReadsDirectly = false;
  Vec3 Parse(const std::string& text) const;
  template <typename T>
  CLI::Option* Declare(CLI::App& c, const Setting& s, T& target) const
  {
    return AddParsed(
      c, s.Option, target, [*this](const std::string& t) { return this->Parse(t); }, s.Help)
      ->option_text(s.ValueName);
  }
  std::string Text(const Vec3& v) const;
  std::string FromJson(const json& v, const std::string& path) const
  {
    return scene_file::Triple(v, path);
  }
  ordered_json ToJson(const Vec3& v) const { return v; }
  ordered_json Schema() const;
  Vec3 Sample(const Vec3& other) const;
};

/** --fog's text (ParseFog), a string in scene files. */
struct FogSpec
{
  static constexpr bool IsFlag = false, ReadsDirectly = false;
  CLI::Option* Declare(CLI::App& c, const Setting& s, Fog& target) const
  {
    return AddParsed(c, s.Option, target, ParseFog, s.Help)->option_text(s.ValueName);
  }
  std::string Text(const Fog& fog) const;
  std::string FromJson(const json& v, const std::string& path) const
  {
    return scene_file::Text(v, path);
  }
  ordered_json ToJson(const Fog& fog) const { return this->Text(fog); }
  ordered_json Schema() const;
  Fog Sample(const Fog& other) const;
};

/** One of an enum's names (its NameTable); Noun names the value in messages. */
template <typename Enum>
struct Choice
{
  std::string Noun;

  static constexpr bool IsFlag = false, ReadsDirectly = false;
  CLI::Option* Declare(CLI::App& c, const Setting& s, Enum& target) const
  {
    return AddChoice(c, s.Option, target, s.Help);
  }
  CLI::Option* Declare(CLI::App& c, const Setting& s, std::optional<Enum>& target) const
  {
    return AddChoice(c, s.Option, target, s.Help);
  }
  std::string Text(Enum value) const { return ToString(value); }
  std::string FromJson(const json& v, const std::string& path) const
  {
    return scene_file::Choice(v, path, this->Noun.c_str(), Names<Enum>());
  }
  ordered_json ToJson(Enum value) const { return ToString(value); }
  ordered_json Schema() const { return { { "enum", Names<Enum>() } }; }
  Enum Sample(Enum other) const
  {
    const auto& entries = NameTable<Enum>::Entries;
    return entries[entries[0].first == other ? 1 : 0].first;
  }
};

/** One of a list of names kept as text (the normals' weighting, named by the filter). */
struct NameChoice
{
  std::vector<std::string> Known;
  std::string Noun;

  static constexpr bool IsFlag = false, ReadsDirectly = false;
  CLI::Option* Declare(CLI::App& c, const Setting& s, std::string& target) const;
  std::string Text(const std::string& value) const { return value; }
  std::string FromJson(const json& v, const std::string& path) const
  {
    return scene_file::Choice(v, path, this->Noun.c_str(), this->Known);
  }
  ordered_json ToJson(const std::string& value) const { return value; }
  ordered_json Schema() const { return { { "enum", this->Known } }; }
  std::string Sample(const std::string& other) const
  {
    return this->Known[this->Known[0] == other ? 1 : 0];
  }
};

/** On or off: a flag on the command line, true or false in a scene file. */
struct Flag
{
  static constexpr bool IsFlag = true, ReadsDirectly = true;
  CLI::Option* Declare(CLI::App& c, const Setting& s, bool& target) const;
  bool FromJson(const json& v, const std::string& path, const std::filesystem::path&) const
  {
    return scene_file::Flag(v, path);
  }
  ordered_json ToJson(bool value) const { return value; }
  ordered_json Schema() const { return { { "type", "boolean" } }; }
  bool Sample(bool other) const { return !other; }
};

/** A file: in a scene file relative to the file's folder, unless absolute. */
struct File
{
  static constexpr bool IsFlag = false, ReadsDirectly = true;
  CLI::Option* Declare(CLI::App& c, const Setting& s, std::string& target) const;
  std::string Text(const std::string& value) const { return value; }
  std::string FromJson(
    const json& v, const std::string& path, const std::filesystem::path& folder) const;
  ordered_json ToJson(const std::string& value) const { return value; }
  ordered_json Schema() const { return { { "type", "string" } }; }
  std::string Sample(const std::string&) const { return "/samples/file.png"; }
};

/**
 * An image with a scale, IMAGE[:SCALE] (ParseScaledImage) in both: in a
 * scene file the image relative to the file's folder, unless absolute.
 */
struct ScaledFile
{
  static constexpr bool IsFlag = false, ReadsDirectly = true;
  CLI::Option* Declare(CLI::App& c, const Setting& s, std::optional<ScaledImage>& target) const
  {
    return AddParsed(c, s.Option, target, ParseScaledImage, s.Help)->option_text(s.ValueName);
  }
  std::string Text(const ScaledImage& image) const;
  ScaledImage FromJson(
    const json& v, const std::string& path, const std::filesystem::path& folder) const;
  ordered_json ToJson(const ScaledImage& image) const { return this->Text(image); }
  ordered_json Schema() const { return { { "type", "string" } }; }
  ScaledImage Sample(const ScaledImage&) const { return { "/samples/file.png", 0.5 }; }
};

/** A picture's size: WxH on the command line, [width, height] in a scene file. */
struct Size
{
  static constexpr bool IsFlag = false, ReadsDirectly = false;
  CLI::Option* Declare(CLI::App& c, const Setting& s, ImageSize& target) const
  {
    return AddParsed(c, s.Option, target, ParseSize, s.Help)->option_text(s.ValueName);
  }
  std::string Text(const ImageSize& size) const
  {
    return std::to_string(size.Width) + "x" + std::to_string(size.Height);
  }
  std::string FromJson(const json& v, const std::string& path) const;
  ordered_json ToJson(const ImageSize& size) const { return { size.Width, size.Height }; }
  ordered_json Schema() const;
  ImageSize Sample(const ImageSize&) const { return { 321, 123 }; }
};

template <typename T>
struct IsOptional : std::false_type
{
};
template <typename T>
struct IsOptional<std::optional<T>> : std::true_type
{
};

/**
 * The setting e of kind's values, kept in the member of a SceneOptions that
 * member(o) gives (a std::optional member is absent until given).
 */
template <typename Kind, typename Stored>
Setting Plain(const Entry& e, Kind kind, Stored& (*member)(SceneOptions&))
{
  constexpr bool optional = IsOptional<Stored>::value;
  static const SceneOptions defaults;
  // The member of a const SceneOptions too, only ever read through this.
  const auto field = [member](const SceneOptions& o) -> const Stored&
  { return member(const_cast<SceneOptions&>(o)); };
  Setting s;
  s.Option = e.Option;
  s.Key = e.Key;
  s.ValueName = e.ValueName;
  s.Commands = e.Commands;
  s.Always = e.Always;
  s.Default = e.Default;
  if constexpr (!optional && !Kind::IsFlag)
  {
    if (s.Default.empty())
    {
      s.Default = kind.Text(field(defaults));
    }
  }
  s.Help = e.Help + (s.Default.empty() ? "" : " (default " + s.Default + ")");
  // o's value when it is to be given back (written, or made words), else null.
  const auto given = [ kind, field, always = e.Always ](const SceneOptions& o) -> const auto*
  {
    const auto& value = field(o);
    if constexpr (optional)
    {
      return value ? &*value : nullptr;
    }
    else if constexpr (Kind::IsFlag)
    {
      return value != field(defaults) ? &value : nullptr;
    }
    else
    {
      return always || kind.Text(value) != kind.Text(field(defaults)) ? &value : nullptr;
    }
  };
  if (!s.Option.empty())
  {
    const Setting names = s; // its names and help, for the option's declaration
    s.Declare = [kind, member, names](CLI::App& c, SceneOptions& o)
    { return kind.Declare(c, names, member(o)); };
    s.Arguments = [kind, given, option = s.Option](
                    const SceneOptions& o, std::vector<std::string>& words)
    {
      if (const auto* value = given(o))
      {
        words.push_back(option);
        if constexpr (!Kind::IsFlag)
        {
          words.push_back(kind.Text(*value));
        }
      }
    };
  }
  if (!s.Key.empty())
  {
    s.Read = [kind, member, option = s.Option](const json& v, const std::string& path,
               const std::filesystem::path& folder, SceneOptions& o)
    {
      if constexpr (Kind::ReadsDirectly)
      {
        member(o) = kind.FromJson(v, path, folder);
      }
      else
      {
        // "=": CLI11 would take a value such as "-Z" for an option of its own.
        scene_file::Apply(o, { option + "=" + kind.FromJson(v, path) }, path);
      }
    };
    s.Write = [kind, given, key = s.Key](const SceneOptions& o, ordered_json& shot)
    {
      if (const auto* value = given(o))
      {
        At(shot, key) = kind.ToJson(*value);
      }
    };
    s.Schema = [kind, help = s.Help]()
    {
      ordered_json schema = kind.Schema();
      schema["description"] = help;
      return schema;
    };
  }
  s.Sample = [kind, member](SceneOptions& o)
  {
    auto& value = member(o);
    if constexpr (optional)
    {
      value = kind.Sample(typename Stored::value_type{});
    }
    else
    {
      value = kind.Sample(value);
    }
  };
  return s;
}

/** s, its key read and written by another setting's (--ka's by "material"'s). */
Setting ReadByParent(Setting s);

/**
 * A key of the scene files' own, a string that their reader takes itself
 * ("name", "output"): checked to be a string, written by nothing.
 */
Setting TextKey(const std::string& key, const std::string& description);
}
}

#endif
