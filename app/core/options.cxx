#include "core/options.h"

#include "core/cli_choice.h"
#include "vtkShadelabMeshNormals.h"

#include <CLI/CLI.hpp>

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

Vec3 ParseDirection(const std::string& text)
{
  const Vec3 d = ParseVec3(text);
  if (d[0] == 0 && d[1] == 0 && d[2] == 0)
  {
    throw std::invalid_argument("direction '" + text + "' has zero length");
  }
  return d;
}

// Registers an option whose text goes through parse() into target; a
// parse failure becomes CLI11's validation error, naming the option.
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

Light ParseLight(const std::string& text)
{
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
  std::size_t colourAt = 0;
  if (light.Kind != LightKind::Spot)
  {
    if (parts.size() < 2 || parts.size() > 3)
    {
      throw std::invalid_argument("'" + text + "' is not " + kind +
        (light.Kind == LightKind::Point ? ":X,Y,Z[:R,G,B]" : ":DX,DY,DZ[:R,G,B]"));
    }
    if (light.Kind == LightKind::Point)
    {
      light.Position = ParseVec3(parts[1]);
    }
    else
    {
      light.Direction = ParseDirection(parts[1]);
    }
    colourAt = 2;
  }
  else
  {
    if (parts.size() < 4 || parts.size() > 6)
    {
      throw std::invalid_argument(
        "'" + text + "' is not spot:X,Y,Z:DX,DY,DZ:HALF_ANGLE_DEG[:EXPONENT[:R,G,B]]");
    }
    light.Position = ParseVec3(parts[1]);
    light.Direction = ParseDirection(parts[2]);
    light.HalfAngleDeg = ParseNumber(parts[3]);
    if (!(light.HalfAngleDeg > 0 && light.HalfAngleDeg <= 90))
    {
      throw std::invalid_argument("spot half-angle '" + parts[3] + "' is outside (0, 90] degrees");
    }
    if (parts.size() > 4)
    {
      light.Exponent = NonNegative(ParseNumber(parts[4]), parts[4]);
    }
    colourAt = 5;
  }
  if (parts.size() > colourAt)
  {
    light.Color = ParseRgb(parts[colourAt]);
  }
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

Material SceneOptions::EffectiveMaterial() const
{
  const Material* base = FindLectureMaterial(this->MaterialName);
  Material m = base ? *base : Material{ this->MaterialName };
  m.Ka = this->Ka.value_or(m.Ka);
  m.Kd = this->Kd.value_or(m.Kd);
  m.Ks = this->Ks.value_or(m.Ks);
  m.Ns = this->Ns.value_or(m.Ns);
  return m;
}

void AddSceneOptions(CLI::App& command, SceneOptions& o)
{
  // Required unless a scene file gives the meshes (the render command checks).
  command.add_option("MESH", o.Mesh, "Mesh file: .obj .ply .stl .vtp .vtk");

  AddChoice(command, "--shading", o.ShadingRule, "Shading rule (default phong)");
  AddChoice(command, "--reflection", o.ReflectionModel, "Specular term (default blinn)");

  std::vector<std::string> names;
  for (const Material& m : LectureMaterials())
  {
    names.push_back(m.Name);
  }
  command.add_option("--material", o.MaterialName, "The lecture's material (default chrome)")
    ->check(CLI::IsMember(names))
    ->option_text(CLI::detail::join(names, "|"));
  AddParsed(command, "--ka", o.Ka, ParseRgb, "Ambient coefficients, overriding the material")
    ->option_text("R,G,B");
  AddParsed(command, "--kd", o.Kd, ParseRgb, "Diffuse coefficients")->option_text("R,G,B");
  AddParsed(command, "--ks", o.Ks, ParseRgb, "Specular coefficients")->option_text("R,G,B");
  AddParsed(
    command, "--ns", o.Ns, [](const std::string& t) { return NonNegative(ParseNumber(t), t); },
    "Specular exponent")
    ->option_text("X");
  AddParsed(command, "--ambient", o.Ambient, ParseRgb, "Ambient light Ia (default 0.2,0.2,0.2)")
    ->option_text("R,G,B");
  command
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
      "A light, repeatable: point:X,Y,Z[:R,G,B] | directional:DX,DY,DZ[:R,G,B] | "
      "spot:X,Y,Z:DX,DY,DZ:HALF_ANGLE_DEG[:EXPONENT[:R,G,B]]. "
      "None given: one white point light at the camera")
    ->option_text("SPEC")
    ->take_all();

  AddParsed(command, "--size", o.Size, ParseSize,
    "Image size in pixels (default " + std::to_string(o.Size.Width) + "x" +
      std::to_string(o.Size.Height) + ")")
    ->option_text("WxH");
  AddParsed(command, "--camera-position", o.CameraPosition, ParseVec3, "Camera position")
    ->option_text("X,Y,Z");
  AddParsed(
    command, "--camera-focal-point", o.CameraFocalPoint, ParseVec3, "Point the camera looks at")
    ->option_text("X,Y,Z");
  AddParsed(
    command, "--camera-view-up", o.CameraViewUp, ParseDirection, "Up direction (default 0,1,0)")
    ->option_text("X,Y,Z");
  AddParsed(
    command, "--view-angle", o.ViewAngle,
    [](const std::string& t)
    {
      const double a = ParseNumber(t);
      if (!(a > 0 && a < 180))
      {
        throw std::invalid_argument("'" + t + "' is outside (0, 180) degrees");
      }
      return a;
    },
    "Perspective camera's vertical view angle in degrees (default 30)")
    ->option_text("DEG");
  command.add_flag("--orthographic", o.Orthographic, "Parallel projection instead of perspective");
  AddParsed(
    command, "--parallel-scale", o.ParallelScale,
    [](const std::string& t)
    {
      const double s = ParseNumber(t);
      if (!(s > 0))
      {
        throw std::invalid_argument("'" + t + "' is not positive");
      }
      return s;
    },
    "Orthographic: half the view height in world units")
    ->option_text("S");
  AddParsed(command, "--background", o.Background, ParseRgb, "Background (default 0,0,0)")
    ->option_text("R,G,B");

  AddChoice(command, "--normals", o.Normals,
    "auto: the file's normals if it has them, else computed (default)");
  AddNormalsSettings(command, o.Computed);
}

void ApplySceneArguments(SceneOptions& o, const std::vector<std::string>& args)
{
  CLI::App app;
  AddSceneOptions(app, o);
  std::vector<std::string> reversed(args.rbegin(), args.rend()); // CLI11 takes them backwards
  try
  {
    app.parse(reversed);
  }
  catch (const CLI::ParseError& e)
  {
    std::string message = e.what();
    // "--view-angle: '200' is outside ...": the caller names the setting.
    const auto colon = message.find(": ");
    if (message.rfind("--", 0) == 0 && colon != std::string::npos)
    {
      message = message.substr(colon + 2);
    }
    throw std::invalid_argument(message);
  }
}

void AddNormalsSettings(CLI::App& command, NormalsSettings& s)
{
  command
    .add_option("--weighting", s.Weighting,
      "Vertex-normal weighting when normals are computed (default angle)")
    ->check(CLI::IsMember(Names<vtkShadelabMeshNormals::Weightings>()))
    ->option_text(JoinedNames<vtkShadelabMeshNormals::Weightings>("|"));
  command
    .add_option("--feature-angle", s.FeatureAngle,
      "Computed normals: split vertices where faces meet at more than DEG degrees "
      "(default: no splitting)")
    ->check(CLI::Range(0.0, 180.0))
    ->option_text("DEG");
  command.add_flag(
    "--orient", s.Orient, "Computed normals: make the faces' orientation consistent first");
}
}
