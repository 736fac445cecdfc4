#include "core/options.h"

#include "core/cli_choice.h"
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabMeshReader.h"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace shadelab
{
namespace
{
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

// --material and the coefficients that override it.
void AddMaterialOptions(CLI::App& command, SceneOptions& o)
{
  const std::vector<std::string> names = LectureMaterialNames();
  command
    .add_option("--material", o.MaterialName,
      "The lecture's material (default chrome, or the mesh's colours as kd)")
    ->check(CLI::IsMember(names))
    ->each([&o](const std::string&) { o.MaterialGiven = true; })
    ->option_text(CLI::detail::join(names, "|"));
  AddParsed(command, "--ka", o.Ka, ParseRgb, "Ambient coefficients, overriding the material")
    ->option_text("R,G,B");
  AddParsed(command, "--kd", o.Kd, ParseRgb, "Diffuse coefficients")->option_text("R,G,B");
  AddParsed(command, "--ks", o.Ks, ParseRgb, "Specular coefficients")->option_text("R,G,B");
  AddParsed(command, "--ns", o.Ns, ParseNonNegative, "Specular exponent")->option_text("X");
  command
    .add_option("--texture", o.Texture,
      "An image (any format OpenImageIO reads; 8-bit sRGB decoded to linear) whose texel at "
      "the mesh's texture coordinates is kd and ka, looked up per fragment under every rule "
      "(times --kd and --ka when given)")
    ->option_text("IMAGE");
  AddChoice(command, "--texture-wrap", o.TextureWrapping,
    "The texture beyond [0, 1]: repeat, clamp to the edge texels, or mirror (default repeat)");
  AddChoice(command, "--texture-filter", o.TextureFiltering,
    "Texel lookup: bilinear between the four nearest texel centres, or the nearest texel; no "
    "mipmaps (default bilinear)");
}

// --ambient and the repeatable --light.
void AddLightOptions(CLI::App& command, SceneOptions& o)
{
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
}

// The picture's size, its camera and its background.
void AddViewOptions(CLI::App& command, SceneOptions& o)
{
  AddParsed(command, "--size", o.Size, ParseSize,
    "Image size in pixels (default " + std::to_string(o.Size.Width) + "x" +
      std::to_string(o.Size.Height) + ")")
    ->option_text("WxH");
  command
    .add_option("--ssaa", o.Supersampling,
      "Anti-aliasing: N x N samples per pixel, averaged in float before quantising; exactly "
      "the box average of the picture rendered N times as large (default 1)")
    ->check(CLI::Range(1, MaxSupersampling))
    ->option_text("N");
  AddParsed(command, "--camera-position", o.CameraPosition, ParseVec3, "Camera position")
    ->option_text("X,Y,Z");
  AddParsed(
    command, "--camera-focal-point", o.CameraFocalPoint, ParseVec3, "Point the camera looks at")
    ->option_text("X,Y,Z");
  AddParsed(
    command, "--camera-view-up", o.CameraViewUp, ParseDirection, "Up direction (default 0,1,0)")
    ->option_text("X,Y,Z");
  AddChoice(command, "--up", o.Up,
    "The world axis up on the screen when the camera is fitted (default +Y)");
  AddChoice(command, "--view", o.View,
    "Where the fitted camera looks from: for up +Y front looks along -Z, for up +Z along +Y; "
    "iso from front, right and above (default front)");
  AddChoice(command, "--fit", o.Fit,
    "How the missing camera settings are fitted: sphere, the bounding sphere fills the view "
    "(VTK's ResetCamera); tight, the mesh's projection fills the picture (default sphere)");
  command.add_flag("--edges", o.Edges, "The triangles' edges over the shading");
  AddParsed(command, "--edge-color", o.EdgeColor, ParseRgb, "Their colour (default 0.05,0.05,0.05)")
    ->option_text("R,G,B");
  AddParsed(
    command, "--edge-width", o.EdgeWidth,
    [](const std::string& t)
    {
      const double w = ParseNumber(t);
      if (!(w > 0 && w <= 16))
      {
        throw std::invalid_argument("'" + t + "' is outside (0, 16] pixels");
      }
      return w;
    },
    "Their width in pixels (default 1)")
    ->option_text("W");
  command.add_flag("--normal-glyphs", o.NormalGlyphs,
    "A line along each vertex normal (those gouraud and phong use)");
  AddParsed(command, "--azimuth", o.Azimuth, ParseNumber,
    "Turn the camera by DEG about the up axis (--camera-view-up when given, else --up's) "
    "through the focal point")
    ->option_text("DEG");
  AddParsed(command, "--elevation", o.Elevation, ParseNumber,
    "Then by DEG up about the horizontal through the focal point")
    ->option_text("DEG");
  AddParsed(
    command, "--zoom", o.Zoom,
    [](const std::string& t)
    {
      const double f = ParseNumber(t);
      if (!(f > 0))
      {
        throw std::invalid_argument("'" + t + "' is not positive");
      }
      return f;
    },
    "Magnify by F: the view angle (orthographic: the parallel scale) divided by F (default 1)")
    ->option_text("F");
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
  command
    .add_option_function<std::string>(
      "--background",
      [&o](const std::string& text)
      {
        // Transparent: alpha 0 around the mesh, whose colours stay those
        // it has over black (OpenImageIO's associated alpha).
        o.TransparentBackground = text == "transparent";
        try
        {
          o.Background = o.TransparentBackground ? Rgb{ 0, 0, 0 } : ParseRgb(text);
        }
        catch (const std::invalid_argument& e)
        {
          throw CLI::ValidationError("--background", e.what());
        }
      },
      "Background colour, or transparent (alpha in PNG, TIFF and EXR) (default 0,0,0)")
    ->option_text("R,G,B|transparent");
}
}

Material SceneOptions::EffectiveMaterial() const
{
  const Material* base = FindLectureMaterial(this->MaterialName);
  return this->Overridden(base ? *base : Material{ this->MaterialName });
}

Material SceneOptions::Overridden(Material m) const
{
  // --texture is every part's kd and ka: their factors become 1.
  const bool textured = !this->Texture.empty();
  m.Ka = this->Ka.value_or(textured ? Rgb{ 1, 1, 1 } : m.Ka);
  m.Kd = this->Kd.value_or(textured ? Rgb{ 1, 1, 1 } : m.Kd);
  m.Ks = this->Ks.value_or(m.Ks);
  m.Ns = this->Ns.value_or(m.Ns);
  return m;
}

std::vector<std::string> LectureMaterialNames()
{
  std::vector<std::string> names;
  for (const Material& m : LectureMaterials())
  {
    names.push_back(m.Name);
  }
  return names;
}

std::string MeshFileHelp()
{
  return std::string("Mesh file: ") + vtkShadelabMeshReader::GetKnownExtensions();
}

void AddSceneOptions(CLI::App& command, SceneOptions& o)
{
  // Required unless a scene file gives the meshes (the render command checks).
  command.add_option("MESH", o.Mesh, MeshFileHelp());
  AddChoice(command, "--shading", o.ShadingRule, "Shading rule (default phong)");
  AddChoice(command, "--reflection", o.ReflectionModel, "Specular term (default blinn)");
  AddMaterialOptions(command, o);
  AddLightOptions(command, o);
  AddViewOptions(command, o);
  AddChoice(command, "--normals", o.Normals,
    "auto: the file's normals if it has them, else computed (default)");
  AddNormalsSettings(command, o.Computed);
  AddTrustOptions(command, o.AllowOutsideReferences);
}

void AddTrustOptions(CLI::App& command, bool& allowOutsideReferences)
{
  command.add_flag("--allow-outside-references", allowOutsideReferences,
    "Read the files that the mesh names (MTL libraries, texture maps, glTF buffers and images) "
    "also where they lie outside the mesh's folder: for meshes you trust (default: refused)");
}

void AddOrbitOptions(CLI::App& command, SceneOptions& o)
{
  command
    .add_option("--orbit", o.Orbit,
      "N frames turning the camera once about the up axis through the focal point (frame k "
      "at --azimuth plus 360*k/N degrees): into a -o template with {frame}, or one .gif or "
      ".mp4 (through the ffmpeg program)")
    ->check(CLI::Range(1, MaxOrbitFrames))
    ->option_text("N");
  AddParsed(
    command, "--fps", o.FramesPerSecond,
    [](const std::string& t)
    {
      const double f = ParseNumber(t);
      if (!(f > 0 && f <= MaxFramesPerSecond))
      {
        throw std::invalid_argument(
          "'" + t + "' is outside (0, " + std::to_string(MaxFramesPerSecond) + "] frames a second");
      }
      return f;
    },
    "An --orbit animation's frames a second (default 25; a .gif's at most 50)")
    ->option_text("F");
}

void ApplySceneArguments(SceneOptions& o, const std::vector<std::string>& args)
{
  CLI::App app;
  AddSceneOptions(app, o);
  AddOrbitOptions(app, o);
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
    ->check(FiniteNumber())
    ->check(CLI::Range(0.0, 180.0))
    ->option_text("DEG");
  command.add_flag(
    "--orient", s.Orient, "Computed normals: make the faces' orientation consistent first");
}
}
