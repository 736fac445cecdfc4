#include "settings/setting_kinds.h"

#include "core/report_text.h"

#include <cmath>
#include <cstdlib>

namespace shadelab
{
namespace settings
{
namespace
{
// A check that the text is a finite number, as ParseNumber reads it: CLI11's
// own Range lets NaN through (every comparison with it is false).
CLI::Validator FiniteNumber()
{
  return CLI::Validator(
    [](const std::string& text)
    {
      try
      {
        ParseNumber(text);
        return std::string();
      }
      catch (const std::invalid_argument& e)
      {
        return std::string(e.what());
      }
    },
    "");
}

// The bounds as JSON Schema says them.
void Bounds(ordered_json& schema, double min, double max, bool openMin, bool openMax)
{
  if (std::isfinite(min))
  {
    schema[openMin ? "exclusiveMinimum" : "minimum"] = min;
  }
  if (std::isfinite(max))
  {
    schema[openMax ? "exclusiveMaximum" : "maximum"] = max;
  }
}
}

std::string NumberText(double value)
{
  // The shortest text that reads back as the same double: 0.2, not
  // 0.20000000000000001.
  for (const char* format : { "%.15g", "%.16g" })
  {
    const std::string text = FormatNumber(format, value);
    if (std::strtod(text.c_str(), nullptr) == value)
    {
      return text;
    }
  }
  return FormatNumber("%.17g", value);
}

ordered_json& At(ordered_json& shot, const std::string& key)
{
  const auto dot = key.find('.');
  return dot == std::string::npos ? shot[key] : shot[key.substr(0, dot)][key.substr(dot + 1)];
}

double Number::Parse(const std::string& text) const
{
  const double v = ParseNumber(text);
  const bool below = this->OpenMin ? !(v > this->Min) : !(v >= this->Min);
  const bool above = this->OpenMax ? !(v < this->Max) : !(v <= this->Max);
  if (!below && !above)
  {
    return v;
  }
  if (std::isinf(this->Max))
  {
    throw std::invalid_argument(
      "'" + text + (this->OpenMin ? "' is not positive" : "' is negative"));
  }
  throw std::invalid_argument("'" + text + "' is outside " + (this->OpenMin ? "(" : "[") +
    FormatNumber("%g", this->Min) + ", " + FormatNumber("%g", this->Max) +
    (this->OpenMax ? ")" : "]") + (this->Unit.empty() ? "" : " " + this->Unit));
}

ordered_json Number::Schema() const
{
  ordered_json schema{ { "type", "number" } };
  Bounds(schema, this->Min, this->Max, this->OpenMin, this->OpenMax);
  return schema;
}

double Number::Sample(double other) const
{
  // Inside the bounds, other than other, with bits a round trip could lose.
  const double lo = std::isfinite(this->Min) ? this->Min : 0;
  const double hi = std::isfinite(this->Max) ? this->Max : lo + 100;
  const double sample = lo + (hi - lo) / 3;
  return sample != other ? sample : lo + (hi - lo) / 7;
}

CLI::Option* ClosedRange::Declare(
  CLI::App& c, const Setting& s, std::optional<double>& target) const
{
  return c.add_option(s.Option, target, s.Help)
    ->check(FiniteNumber())
    ->check(CLI::Range(this->Min, this->Max))
    ->option_text(s.ValueName);
}

ordered_json ClosedRange::Schema() const
{
  ordered_json schema{ { "type", "number" } };
  Bounds(schema, this->Min, this->Max, false, false);
  return schema;
}

CLI::Option* Integer::Declare(CLI::App& c, const Setting& s, int& target) const
{
  return c.add_option(s.Option, target, s.Help)
    ->check(CLI::Range(this->Min, this->Max))
    ->option_text(s.ValueName);
}

ordered_json Integer::Schema() const
{
  return { { "type", "integer" }, { "minimum", this->Min }, { "maximum", this->Max } };
}

Vec3 Triple::Parse(const std::string& text) const
{
  switch (this->Is)
  {
    case Point:
      return ParseVec3(text);
    case Direction:
      return ParseDirection(text);
    case Colour:
      return ParseRgb(text);
    case Attenuation:
      return ParseAttenuation(text);
  }
  throw std::logic_error("Triple: no such meaning");
}

std::string Triple::Text(const Vec3& v) const
{
  return NumberText(v[0]) + "," + NumberText(v[1]) + "," + NumberText(v[2]);
}

ordered_json Triple::Schema() const
{
  return { { "$ref",
    this->Is == Colour          ? "#/$defs/color"
      : this->Is == Attenuation ? "#/$defs/attenuation"
                                : "#/$defs/triple" } };
}

Vec3 Triple::Sample(const Vec3& other) const
{
  const Vec3 sample{ 1.0 / 3, 2.0 / 7, 5.0 / 9 };
  return sample != other ? sample : Vec3{ 1.0 / 9, 1.0 / 3, 2.0 / 7 };
}

std::string FogSpec::Text(const Fog& fog) const
{
  std::string text = ToString(fog.Mode);
  switch (fog.Mode)
  {
    case FogMode::None:
      return text;
    case FogMode::Linear:
      text += ":" + NumberText(fog.Start) + "," + NumberText(fog.End);
      break;
    case FogMode::Exp:
    case FogMode::Exp2:
      text += ":" + NumberText(fog.Density);
      break;
  }
  if (fog.Color)
  {
    text += ":" + Triple{ Triple::Colour }.Text(*fog.Color);
  }
  return text;
}

ordered_json FogSpec::Schema() const
{
  return { { "type", "string" },
    { "pattern",
      "^(none|linear:[^:,]+,[^:,]+(:[^:,]+,[^:,]+,[^:,]+)?|exp2?:[^:,]+(:[^:,]+,[^:,]+,[^:,]+)?)"
      "$" } };
}

Fog FogSpec::Sample(const Fog& other) const
{
  Fog sample;
  sample.Mode = FogMode::Linear;
  sample.Start = 1.0 / 3;
  sample.End = 25.0 / 7;
  sample.Color = Rgb{ 0.5, 2.0 / 3, 0.75 };
  if (sample == other)
  {
    sample.Mode = FogMode::Exp2;
    sample.Density = 2.0 / 9;
  }
  return sample;
}

CLI::Option* NameChoice::Declare(CLI::App& c, const Setting& s, std::string& target) const
{
  return c.add_option(s.Option, target, s.Help)
    ->check(CLI::IsMember(this->Known))
    ->option_text(CLI::detail::join(this->Known, "|"));
}

CLI::Option* Flag::Declare(CLI::App& c, const Setting& s, bool& target) const
{
  return c.add_flag(s.Option, target, s.Help);
}

CLI::Option* File::Declare(CLI::App& c, const Setting& s, std::string& target) const
{
  return c.add_option(s.Option, target, s.Help)->option_text(s.ValueName);
}

std::string File::FromJson(
  const json& v, const std::string& path, const std::filesystem::path& folder) const
{
  const std::filesystem::path file(scene_file::Text(v, path));
  return (file.is_absolute() ? file : folder / file).lexically_normal().string();
}

std::string ScaledFile::Text(const ScaledImage& image) const
{
  // The scale written whenever the name alone would read as IMAGE:SCALE.
  const bool ambiguous = ParseScaledImage(image.Image).Image != image.Image;
  return image.Scale == 1 && !ambiguous ? image.Image : image.Image + ":" + NumberText(image.Scale);
}

ScaledImage ScaledFile::FromJson(
  const json& v, const std::string& path, const std::filesystem::path& folder) const
{
  ScaledImage image;
  try
  {
    image = ParseScaledImage(scene_file::Text(v, path));
  }
  catch (const std::invalid_argument& e)
  {
    throw scene_file::SceneError{ path, e.what() };
  }
  if (image.Image != NoNormalMap) // a keyword, not a file beside the scene
  {
    image.Image = File{}.FromJson(image.Image, path, folder);
  }
  return image;
}

std::string Size::FromJson(const json& v, const std::string& path) const
{
  if (v.is_array() && v.size() == 2 && v[0].is_number_integer() && v[1].is_number_integer())
  {
    return std::to_string(v[0].get<long long>()) + "x" + std::to_string(v[1].get<long long>());
  }
  throw scene_file::SceneError{ path,
    "expected [width, height] in pixels, not " + scene_file::Quoted(v) };
}

ordered_json Size::Schema() const
{
  return { { "type", "array" },
    { "items", { { "type", "integer" }, { "minimum", 1 }, { "maximum", MaxImageSide } } },
    { "minItems", 2 }, { "maxItems", 2 } };
}

Setting ReadByParent(Setting s)
{
  s.Read = nullptr;
  s.Write = nullptr;
  s.Schema = nullptr;
  return s;
}

Setting TextKey(const std::string& key, const std::string& description)
{
  Setting s;
  s.Key = key;
  s.Help = description;
  s.Read = [](const json& v, const std::string& path, const std::filesystem::path&, SceneOptions&)
  { scene_file::Text(v, path); };
  s.Schema = [description]() {
    return ordered_json{ { "type", "string" }, { "description", description } };
  };
  return s;
}
}
}
