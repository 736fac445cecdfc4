// The option values' parsers: each throws std::invalid_argument with a
// message that names what is wrong with the text, which CLI11 then reports
// against the option.
#include "core/options.h"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace shadelab
{
namespace
{
std::array<double, 3> ParseTriple(const std::string& text, const char* what)
{
  const auto parts = Split(text, ',');
  if (parts.size() != 3)
  {
    throw std::invalid_argument("'" + text + "' is not " + what);
  }
  return { ParseNumber(parts[0]), ParseNumber(parts[1]), ParseNumber(parts[2]) };
}

double NonNegative(double value, const std::string& text)
{
  if (value < 0)
  {
    throw std::invalid_argument("'" + text + "' is negative");
  }
  return value;
}
// spot:X,Y,Z:DX,DY,DZ:HALF_ANGLE_DEG[:EXPONENT[:R,G,B]], less its colour.
Light ParseSpot(const std::string& text, const std::vector<std::string>& parts)
{
  if (parts.size() < 4 || parts.size() > 6)
  {
    throw std::invalid_argument(
      "'" + text + "' is not spot:X,Y,Z:DX,DY,DZ:HALF_ANGLE_DEG[:EXPONENT[:R,G,B]]");
  }
  Light light;
  light.Kind = LightKind::Spot;
  light.Position = ParseVec3(parts[1]);
  light.Direction = ParseDirection(parts[2]);
  light.HalfAngleDeg = ParseNumber(parts[3]);
  if (!(light.HalfAngleDeg > 0 && light.HalfAngleDeg <= 90))
  {
    throw std::invalid_argument("spot half-angle '" + parts[3] + "' is outside (0, 90] degrees");
  }
  if (parts.size() > 4)
  {
    light.Exponent = ParseNonNegative(parts[4]);
  }
  return light;
}
}

Vec3 ParseDirection(const std::string& text)
{
  const Vec3 d = ParseVec3(text);
  if (d[0] == 0 && d[1] == 0 && d[2] == 0)
  {
    throw std::invalid_argument("direction '" + text + "' has zero length");
  }
  return d;
}

double ParseNonNegative(const std::string& text)
{
  return NonNegative(ParseNumber(text), text);
}

std::vector<std::string> Split(const std::string& text, char separator)
{
  std::vector<std::string> parts;
  std::string::size_type start = 0;
  while (true)
  {
    const auto end = text.find(separator, start);
    parts.push_back(text.substr(start, end - start));
    if (end == std::string::npos)
    {
      return parts;
    }
    start = end + 1;
  }
}

double ParseNumber(const std::string& text)
{
  double value = 0;
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+')
  {
    ++first;
  }
  const auto [end, error] = std::from_chars(first, last, value);
  if (error != std::errc() || end != last || text.empty())
  {
    throw std::invalid_argument("'" + text + "' is not a number");
  }
  if (!std::isfinite(value))
  {
    throw std::invalid_argument("'" + text + "' is not a finite number");
  }
  return value;
}

ScaledImage ParseScaledImage(const std::string& text)
{
  ScaledImage image{ text, 1 };
  const std::size_t colon = text.rfind(':');
  if (colon != std::string::npos)
  {
    try
    {
      image.Scale = ParseNumber(text.substr(colon + 1));
      image.Image = text.substr(0, colon);
    }
    catch (const std::invalid_argument&)
    {
      // not a number: the colon is the image's name's own
    }
  }
  if (image.Image.empty())
  {
    throw std::invalid_argument("'" + text + "' names no image");
  }
  return image;
}

Vec3 ParseVec3(const std::string& text)
{
  return ParseTriple(text, "three numbers X,Y,Z");
}

Rgb ParseRgb(const std::string& text)
{
  Rgb c = ParseTriple(text, "a colour R,G,B");
  for (double v : c)
  {
    NonNegative(v, text);
  }
  return c;
}

Vec3 ParseAttenuation(const std::string& text)
{
  const Vec3 c = ParseTriple(text, "an attenuation C0,C1,C2");
  if (c[0] < 0 || c[1] < 0 || c[2] < 0)
  {
    throw std::invalid_argument("attenuation '" + text + "' has a negative coefficient");
  }
  if (c == Vec3{ 0, 0, 0 })
  {
    throw std::invalid_argument(
      "attenuation '" + text + "' is all zero: the light would be infinitely bright");
  }
  return c;
}

Fog ParseFog(const std::string& text)
{
  const auto parts = Split(text, ':');
  Fog fog;
  const std::optional<FogMode> mode = FromName<FogMode>(parts[0]);
  if (!mode)
  {
    throw std::invalid_argument(
      "unknown fog '" + parts[0] + "' (known: " + JoinedNames<FogMode>(", ") + ")");
  }
  fog.Mode = *mode;
  const bool none = fog.Mode == FogMode::None;
  if (none ? parts.size() != 1 : parts.size() < 2 || parts.size() > 3)
  {
    throw std::invalid_argument("'" + text +
      "' is not none, linear:START,END[:R,G,B], exp:DENSITY[:R,G,B] or exp2:DENSITY[:R,G,B]");
  }
  if (fog.Mode == FogMode::Linear)
  {
    const auto ends = Split(parts[1], ',');
    if (ends.size() != 2)
    {
      throw std::invalid_argument("'" + parts[1] + "' is not START,END");
    }
    fog.Start = ParseNumber(ends[0]);
    fog.End = ParseNumber(ends[1]);
    if (!(fog.End > fog.Start))
    {
      throw std::invalid_argument(
        "fog END '" + ends[1] + "' is not beyond START '" + ends[0] + "'");
    }
  }
  else if (!none)
  {
    fog.Density = ParseNumber(parts[1]);
    if (fog.Density < 0)
    {
      throw std::invalid_argument("fog density '" + parts[1] + "' is negative");
    }
  }
  if (parts.size() == 3)
  {
    fog.Color = ParseRgb(parts[2]);
  }
  return fog;
}

ImageSize ParseSize(const std::string& text)
{
  const auto x = text.find_first_of("xX");
  const std::string w = text.substr(0, x);
  const std::string h = x == std::string::npos ? std::string() : text.substr(x + 1);
  int width = 0, height = 0;
  const auto pw = std::from_chars(w.data(), w.data() + w.size(), width);
  const auto ph = std::from_chars(h.data(), h.data() + h.size(), height);
  if (x == std::string::npos || w.empty() || h.empty() || pw.ec != std::errc() ||
    ph.ec != std::errc() || pw.ptr != w.data() + w.size() || ph.ptr != h.data() + h.size())
  {
    throw std::invalid_argument("'" + text + "' is not a size WIDTHxHEIGHT");
  }
  if (width < 1 || height < 1 || width > MaxImageSide || height > MaxImageSide ||
    static_cast<long long>(width) * height > MaxImagePixels)
  {
    throw std::invalid_argument("'" + text + "' is outside 1x1 to " + std::to_string(MaxImageSide) +
      " a side and " + std::to_string(MaxImagePixels) + " pixels in all");
  }
  return { width, height };
}

Pixel ParsePixel(const std::string& text)
{
  const auto whole = [](const std::string& part, int& value)
  {
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    return !part.empty() && error == std::errc() && end == part.data() + part.size() && value >= 0;
  };
  const auto parts = Split(text, ',');
  Pixel p;
  if (parts.size() != 2 || !whole(parts[0], p.X) || !whole(parts[1], p.Y))
  {
    throw std::invalid_argument("'" + text + "' is not a pixel X,Y (whole numbers from 0)");
  }
  return p;
}

std::string RenderedSize(const SceneOptions& o, ImageSize& rendered)
{
  const long long n = o.Supersampling;
  const long long width = o.Size.Width * n, height = o.Size.Height * n;
  if (width > MaxImageSide || height > MaxImageSide || width * height > MaxImagePixels)
  {
    return "--ssaa " + std::to_string(n) + " renders " + std::to_string(width) + "x" +
      std::to_string(height) + ", beyond " + std::to_string(MaxImageSide) + " a side and " +
      std::to_string(MaxImagePixels) + " pixels in all: a smaller --size or --ssaa";
  }
  rendered = { static_cast<int>(width), static_cast<int>(height) };
  return {};
}

Light ParseLight(const std::string& whole)
{
  // SPEC[@C0,C1,C2][+shadows|+no-shadows]: its own choice of shadows last.
  std::optional<bool> shadows;
  std::string spec = whole;
  for (const auto& [suffix, casts] : { std::pair{ "+shadows", true }, { "+no-shadows", false } })
  {
    const std::string_view s = suffix;
    if (spec.size() > s.size() && spec.compare(spec.size() - s.size(), s.size(), s) == 0)
    {
      shadows = casts;
      spec.resize(spec.size() - s.size());
      break;
    }
  }
  // SPEC[@C0,C1,C2]: the light's own attenuation after the '@'.
  const auto at = spec.find('@');
  const std::string text = spec.substr(0, at);
  const auto parts = Split(text, ':');
  Light light;
  const std::string& kind = parts[0];
  const std::optional<LightKind> known = FromName<LightKind>(kind);
  if (!known)
  {
    throw std::invalid_argument(
      "unknown light kind '" + kind + "' (known: " + JoinedNames<LightKind>(", ") + ")");
  }
  light.Kind = *known;
  std::size_t colourAt = 2;
  switch (light.Kind)
  {
    case LightKind::Point:
    case LightKind::Directional:
    {
      const bool point = light.Kind == LightKind::Point;
      if (parts.size() < 2 || parts.size() > 3)
      {
        throw std::invalid_argument(
          "'" + text + "' is not " + kind + (point ? ":X,Y,Z[:R,G,B]" : ":DX,DY,DZ[:R,G,B]"));
      }
      (point ? light.Position : light.Direction) =
        point ? ParseVec3(parts[1]) : ParseDirection(parts[1]);
      break;
    }
    case LightKind::Spot:
      light = ParseSpot(text, parts);
      colourAt = 5;
      break;
  }
  if (parts.size() > colourAt)
  {
    light.Color = ParseRgb(parts[colourAt]);
  }
  if (at != std::string::npos)
  {
    if (!GeometryOf(light.Kind).Position)
    {
      throw std::invalid_argument(
        "'" + spec + "': a " + kind + " light has no attenuation (it has no position)");
    }
    light.Attenuation = ParseAttenuation(spec.substr(at + 1));
  }
  light.Shadows = shadows;
  return light;
}

std::pair<int, int> ParseShard(const std::string& text)
{
  const auto slash = text.find('/');
  int index = -1, count = 0;
  if (slash != std::string::npos)
  {
    const auto i = std::from_chars(text.data(), text.data() + slash, index);
    const auto n = std::from_chars(text.data() + slash + 1, text.data() + text.size(), count);
    if (i.ec != std::errc() || i.ptr != text.data() + slash || n.ec != std::errc() ||
      n.ptr != text.data() + text.size())
    {
      index = -1;
    }
  }
  if (index < 0 || count < 1 || index >= count)
  {
    throw std::invalid_argument("'" + text + "' is not a shard I/N with 0 <= I < N");
  }
  return { index, count };
}
}
