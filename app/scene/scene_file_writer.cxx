// A scene file written from SceneOptions (scene_file.h): the inverse of
// reading one, with the same keys, for the inspector's Save scene.
#include "scene/scene_file.h"
#include "shadelabJsonProblem.h"

#include <nlohmann/json.hpp>

namespace shadelab
{
nlohmann::ordered_json LightJson(const Light& light, const char* halfAngleKey)
{
  nlohmann::ordered_json j;
  j["kind"] = ToString(light.Kind);
  if (light.Kind != LightKind::Directional)
  {
    j["position"] = light.Position;
  }
  if (light.Kind != LightKind::Point)
  {
    j["direction"] = light.Direction;
  }
  j["color"] = light.Color;
  if (light.Kind == LightKind::Spot)
  {
    j[halfAngleKey] = light.HalfAngleDeg;
    j["exponent"] = light.Exponent;
  }
  return j;
}

std::string WriteSceneText(const SceneOptions& s, const std::string& output)
{
  const SceneOptions d;
  nlohmann::ordered_json shot;
  shot["mesh"] = s.Mesh;
  shot["output"] = output;
  shot["size"] = { s.Size.Width, s.Size.Height };
  shot["shading"] = ToString(s.ShadingRule);
  shot["reflection"] = ToString(s.ReflectionModel);
  // A material named (--material, a row of the window's table) replaces
  // every part's; coefficients alone replace those of every part, the rest
  // staying the file's or the default's.
  const bool named = s.MaterialGiven || s.MaterialName != d.MaterialName;
  if (s.Ka || s.Kd || s.Ks || s.Ns)
  {
    auto material = nlohmann::ordered_json::object();
    if (named)
    {
      material["base"] = s.MaterialName;
    }
    const std::pair<const char*, const std::optional<Rgb>*> colours[] = { { "ka", &s.Ka },
      { "kd", &s.Kd }, { "ks", &s.Ks } };
    for (const auto& [key, value] : colours)
    {
      if (*value)
      {
        material[key] = **value;
      }
    }
    if (s.Ns)
    {
      material["ns"] = *s.Ns;
    }
    shot["material"] = material;
  }
  else if (named)
  {
    shot["material"] = s.MaterialName;
  }
  if (!s.Texture.empty())
  {
    shot["texture"] = s.Texture;
    shot["texture_wrap"] = ToString(s.TextureWrapping);
    shot["texture_filter"] = ToString(s.TextureFiltering);
  }
  shot["ambient"] = s.Ambient;
  if (!s.Lights.empty())
  {
    auto& lights = shot["lights"] = nlohmann::ordered_json::array();
    for (const Light& light : s.Lights)
    {
      lights.push_back(LightJson(light, "half_angle"));
    }
  }
  nlohmann::ordered_json camera;
  const std::pair<const char*, const std::optional<Vec3>*> points[] = { { "position",
                                                                          &s.CameraPosition },
    { "focal_point", &s.CameraFocalPoint }, { "view_up", &s.CameraViewUp } };
  for (const auto& [key, value] : points)
  {
    if (*value)
    {
      camera[key] = **value;
    }
  }
  camera["view_angle"] = s.ViewAngle;
  camera["orthographic"] = s.Orthographic;
  if (s.ParallelScale)
  {
    camera["parallel_scale"] = *s.ParallelScale;
  }
  if (s.View != d.View)
  {
    camera["view"] = ToString(s.View);
  }
  if (s.Azimuth != d.Azimuth)
  {
    camera["azimuth"] = s.Azimuth;
  }
  if (s.Elevation != d.Elevation)
  {
    camera["elevation"] = s.Elevation;
  }
  if (s.Zoom != d.Zoom)
  {
    camera["zoom"] = s.Zoom;
  }
  if (s.Fit != d.Fit)
  {
    camera["fit"] = ToString(s.Fit);
  }
  shot["camera"] = camera;
  if (s.Up != d.Up)
  {
    shot["up"] = ToString(s.Up);
  }
  if (s.TransparentBackground)
  {
    shot["background"] = "transparent";
  }
  else
  {
    shot["background"] = s.Background;
  }
  shot["normals"] = ToString(s.Normals);
  shot["weighting"] = s.Computed.Weighting;
  if (s.Computed.FeatureAngle)
  {
    shot["feature_angle"] = *s.Computed.FeatureAngle;
  }
  shot["orient"] = s.Computed.Orient;
  shot["edges"] = s.Edges;
  shot["edge_color"] = s.EdgeColor;
  shot["edge_width"] = s.EdgeWidth;
  shot["normal_glyphs"] = s.NormalGlyphs;
  if (s.Supersampling != d.Supersampling)
  {
    shot["ssaa"] = s.Supersampling;
  }
  return JsonText(shot, 2) + "\n";
}
}
