#include "scene/scene_file_settings.h"

#include "vtkShadelabMeshNormals.h"

#include <algorithm>

namespace shadelab
{
namespace scene_file
{
namespace
{
const std::vector<std::string> CameraKeys{ "position", "focal_point", "view_up", "view_angle",
  "orthographic", "parallel_scale", "view", "azimuth", "elevation", "zoom", "fit" };

// The camera's keys; each one's path comes from where, which knows whether
// the shot or the defaults gave it.
void ConvertCamera(const json& v, const std::string& path, const PathOfKey& where, SceneOptions& o)
{
  ExpectObject(v, path, CameraKeys);
  for (const auto& c : v.items())
  {
    const std::string at = where("camera." + c.key());
    if (c.key() == "orthographic")
    {
      o.Orthographic = Flag(c.value(), at);
    }
    else if (c.key() == "view")
    {
      Apply(o, { "--view", Choice(c.value(), at, "view", Names<ViewPreset>()) }, at);
    }
    else if (c.key() == "fit")
    {
      Apply(o, { "--fit", Choice(c.value(), at, "fit", Names<FitMode>()) }, at);
    }
    else if (c.key() == "view_angle" || c.key() == "parallel_scale" || c.key() == "azimuth" ||
      c.key() == "elevation" || c.key() == "zoom")
    {
      std::string option = "--" + c.key();
      std::replace(option.begin(), option.end(), '_', '-');
      Apply(o, { option, Number(c.value(), at) }, at);
    }
    else
    {
      std::string option = "--camera-" + c.key();
      std::replace(option.begin(), option.end(), '_', '-');
      Apply(o, { option, Triple(c.value(), at) }, at);
    }
  }
}

void ConvertSize(const json& v, const std::string& path, SceneOptions& o)
{
  if (v.is_array() && v.size() == 2 && v[0].is_number_integer() && v[1].is_number_integer())
  {
    Apply(o,
      { "--size",
        std::to_string(v[0].get<long long>()) + "x" + std::to_string(v[1].get<long long>()) },
      path);
  }
  else
  {
    throw SceneError{ path, "expected [width, height] in pixels, not " + Quoted(v) };
  }
}

// A key whose value is one of an option's choices.
void ConvertChoice(const std::string& key, const json& v, const std::string& path, SceneOptions& o)
{
  std::vector<std::string> known;
  if (key == "shading")
  {
    known = Names<Shading>();
  }
  else if (key == "reflection")
  {
    known = Names<Reflection>();
  }
  else if (key == "normals")
  {
    known = Names<NormalsMode>();
  }
  else
  {
    known = Names<vtkShadelabMeshNormals::Weightings>();
  }
  Apply(o, { "--" + key, Choice(v, path, key.c_str(), known) }, path);
}
}

void ConvertShot(
  const json& settings, Shot& shot, const std::filesystem::path& folder, const PathOfKey& where)
{
  SceneOptions& o = shot.Scene;
  // The material last: it is resolved whole (ConvertMaterial), and with a
  // texture its ka and kd are the texel's factors.
  const json* material = nullptr;
  std::string materialPath;
  for (const auto& item : settings.items())
  {
    const std::string& key = item.key();
    const json& v = item.value();
    const std::string path = where(key);
    if (key == "name" || key == "output")
    {
      Text(v, path); // used by the output template
    }
    else if (key == "mesh" || key == "texture")
    {
      const std::filesystem::path file(Text(v, path));
      (key == "mesh" ? o.Mesh : o.Texture) =
        (file.is_absolute() ? file : folder / file).lexically_normal().string();
    }
    else if (key == "texture_wrap")
    {
      Apply(o, { "--texture-wrap", Choice(v, path, "texture wrap", Names<TextureWrap>()) }, path);
    }
    else if (key == "texture_filter")
    {
      Apply(
        o, { "--texture-filter", Choice(v, path, "texture filter", Names<TextureFilter>()) }, path);
    }
    else if (key == "shading" || key == "reflection" || key == "normals" || key == "weighting")
    {
      ConvertChoice(key, v, path, o);
    }
    else if (key == "pixel_type")
    {
      shot.Pixels = *FromName<PixelType>(Choice(v, path, "pixel type", Names<PixelType>()));
    }
    else if (key == "material")
    {
      material = &v;
      materialPath = path;
    }
    else if (key == "background" && v.is_string() && v.get<std::string>() == "transparent")
    {
      Apply(o, { "--background", "transparent" }, path);
    }
    else if (key == "ambient" || key == "background")
    {
      Apply(o, { "--" + key, Triple(v, path) }, path);
    }
    else if (key == "lights")
    {
      ConvertLights(v, path, o);
    }
    else if (key == "camera")
    {
      ConvertCamera(v, path, where, o);
    }
    else if (key == "size")
    {
      ConvertSize(v, path, o);
    }
    else if (key == "up")
    {
      // "=": CLI11 would take "-Z" for an option of its own.
      Apply(o, { "--up=" + Choice(v, path, "up axis", Names<UpAxis>()) }, path);
    }
    else if (key == "ssaa" || key == "orbit" || key == "fps")
    {
      Apply(o, { "--" + key, Number(v, path) }, path);
    }
    else if (key == "feature_angle")
    {
      Apply(o, { "--feature-angle", Number(v, path) }, path);
    }
    else if (key == "orient")
    {
      o.Computed.Orient = Flag(v, path);
    }
    else if (key == "edges")
    {
      o.Edges = Flag(v, path);
    }
    else if (key == "normal_glyphs")
    {
      o.NormalGlyphs = Flag(v, path);
    }
    else if (key == "edge_color")
    {
      Apply(o, { "--edge-color", Triple(v, path) }, path);
    }
    else if (key == "edge_width")
    {
      Apply(o, { "--edge-width", Number(v, path) }, path);
    }
  }
  if (material)
  {
    ConvertMaterial(*material, materialPath, o);
  }
}
}
}
