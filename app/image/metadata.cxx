#include "image/metadata.h"

#include "scene/scene.h"
#include "scene/scene_file.h"
#include "scene/scene_parts.h"
#include "settings/light_setting.h"
#include "settings/setting_kinds.h"
#include "shadelabJsonProblem.h"
#include "shadelabVersion.h"

#include <vtkCamera.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <string_view>

namespace shadelab
{
namespace
{
// Options that choose which of a batch's shots run, or what is printed, and
// not what a picture is; with whether each takes a value.
constexpr std::pair<std::string_view, bool> NotRecorded[] = { { "--shard", true },
  { "--skip-existing", false }, { "-q", false }, { "--quiet", false }, { "-v", false },
  { "--verbose", false } };

// How many arguments from argv[i] on are a NotRecorded option: 0, 1 or 2.
int NotRecordedAt(int argc, const char* const* argv, int i)
{
  const std::string_view arg = argv[i];
  for (const auto& [name, takesValue] : NotRecorded)
  {
    if (arg == name)
    {
      return takesValue && i + 1 < argc ? 2 : 1;
    }
    if (takesValue && arg.size() > name.size() && arg.substr(0, name.size()) == name &&
      arg[name.size()] == '=')
    {
      return 1;
    }
  }
  return 0;
}
}

std::string QuoteCommandLine(int argc, const char* const* argv)
{
  std::string line;
  bool options = true; // before "--"
  for (int i = 0; i < argc; ++i)
  {
    if (options && i > 0)
    {
      if (const int skip = NotRecordedAt(argc, argv, i))
      {
        i += skip - 1;
        continue;
      }
    }
    const std::string arg = argv[i];
    options = options && arg != "--";
    const bool plain = !arg.empty() &&
      arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                            "-_./=:,+@%") == std::string::npos;
    if (i > 0)
    {
      line += ' ';
    }
    if (plain)
    {
      line += arg;
      continue;
    }
    line += '\'';
    for (char c : arg)
    {
      line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    line += '\'';
  }
  return line;
}

nlohmann::ordered_json DescribeLight(const Light& light)
{
  nlohmann::ordered_json j = LightJson(light, "half_angle_deg");
  if (!Attenuated(light))
  {
    j.erase("attenuation"); // resolved to 1,0,0: the light does not fall off
  }
  if (!CastsShadows(light))
  {
    j.erase("shadows"); // only where it casts them: pictures without describe as before
  }
  return j;
}

nlohmann::ordered_json DescribeMaterial(const Material& m)
{
  nlohmann::ordered_json j{ { "name", m.Name }, { "ka", m.Ka }, { "kd", m.Kd }, { "ks", m.Ks },
    { "ns", m.Ns } };
  if (m.Translucency != 1)
  {
    j["a"] = m.Translucency; // only where translucent: opaque pictures describe as before
  }
  return j;
}

std::vector<std::pair<std::string, std::string>> DescribePicture(const std::string& commandLine,
  const SceneOptions& o, vtkCamera* camera, vtkPolyData* mesh, const std::string& shot,
  const std::vector<std::string>& panels)
{
  Vec3 position, focal, up;
  camera->GetPosition(position.data());
  camera->GetFocalPoint(focal.data());
  camera->GetViewUp(up.data());

  nlohmann::ordered_json j;
  j["shadelab"] = ShadelabVersion;
  j["command"] = commandLine;
  if (!shot.empty())
  {
    j["shot"] = shot;
  }
  if (!panels.empty())
  {
    j["panels"] = panels;
  }
  j["mesh"] = o.Mesh;
  j["shading"] = ToString(o.ShadingRule);
  j["reflection"] = ToString(o.ReflectionModel);
  j["material"] = DescribeMaterial(o.EffectiveMaterial());
  const std::vector<ScenePart> sceneParts = SceneParts(o, mesh);
  const bool texturedKd = std::any_of(
    sceneParts.begin(), sceneParts.end(), [](const ScenePart& part) { return part.Texture.Kd; });
  j["kd_from"] = UsesVertexKd(o, mesh) ? "vertex colors" : texturedKd ? "texture" : "material";
  if (!o.Texture.empty())
  {
    j["texture"] = { { "image", o.Texture }, { "wrap", ToString(o.TextureWrapping) },
      { "filter", ToString(o.TextureFiltering) } };
  }
  if (!o.Environment.empty())
  {
    j["environment"] = { { "image", o.Environment },
      { "up", ToString(o.EnvironmentUp.value_or(o.Up)) },
      { "filter", ToString(o.TextureFiltering) } };
  }
  if (o.NoNormalMaps())
  {
    j["normal_map"] = NoNormalMap;
  }
  if (const auto& relief = o.Relief())
  {
    j[o.BumpMap ? "bump_map" : "normal_map"] = { { "image", relief->Image },
      { "scale", relief->Scale }, { "wrap", ToString(o.TextureWrapping) },
      { "filter", ToString(o.TextureFiltering) },
      { "tangents", "per point, from the texture coordinates (shadelabVertexTangents.h)" } };
  }
  auto parts = nlohmann::ordered_json::array();
  for (const ScenePart& part : sceneParts)
  {
    nlohmann::ordered_json described{ { "index", part.Index }, { "name", part.Name },
      { "triangles", part.Triangles }, { "material", DescribeMaterial(part.Surface) },
      { "source", ToString(part.Source) }, { "overridden", part.Overridden } };
    const SurfaceTexture& t = part.Texture;
    if (t.Kd || t.Ka || t.Ks)
    {
      auto maps = nlohmann::ordered_json::array();
      for (const auto& [name, used] :
        { std::pair{ "kd", t.Kd }, std::pair{ "ka", t.Ka }, std::pair{ "ks", t.Ks } })
      {
        if (used)
        {
          maps.push_back(name);
        }
      }
      described["texture"] = { { "image", part.ImageName }, { "maps", maps },
        { "wrap", { ToString(t.Map.WrapS), ToString(t.Map.WrapT) } },
        { "filter", ToString(t.Map.Filter) } };
    }
    if (part.FileNormalTexture >= 0) // the file's (--normal-map's is the scene's, above)
    {
      described["normal_map"] = {
        { "image", FileTextureName(o, MeshTextures(mesh), part.FileNormalTexture) },
        { "scale", part.Relief->Scale },
        { "wrap", { ToString(part.Relief->Map.WrapS), ToString(part.Relief->Map.WrapT) } },
        { "filter", ToString(part.Relief->Map.Filter) }
      };
      if (part.FileBump)
      {
        // Whether it is grey is the image's: the description decodes none.
        described["normal_map"]["from"] = "a bump statement: a height map where the image is grey";
      }
    }
    parts.push_back(described);
  }
  j["parts"] = parts;
  j["ambient"] = o.Ambient;
  auto lights = nlohmann::ordered_json::array();
  for (const Light& light : EffectiveLights(o, position))
  {
    lights.push_back(DescribeLight(light));
  }
  j["lights"] = lights;
  if (o.ShadingRule == Shading::Raytrace)
  {
    j["reflections"] = o.Reflections; // its shadows are rays: no maps
  }
  else if (std::any_of(o.Lights.begin(), o.Lights.end(), CastsShadows) || o.Shadows)
  {
    j["shadow_map_size"] = o.ShadowMapSize;
  }
  nlohmann::ordered_json cam;
  cam["projection"] = o.Orthographic ? "orthographic" : "perspective";
  cam["position"] = position;
  cam["focal_point"] = focal;
  cam["view_up"] = up;
  if (o.Orthographic)
  {
    cam["parallel_scale"] = camera->GetParallelScale();
  }
  else
  {
    cam["view_angle_deg"] = camera->GetViewAngle();
  }
  j["camera"] = cam;
  j["size"] = { o.Size.Width, o.Size.Height };
  j["ssaa"] = o.Supersampling;
  j["background"] = o.TransparentBackground ? nlohmann::json("transparent")
    : o.EnvironmentBackground               ? nlohmann::json("environment")
                                            : nlohmann::json(o.Background);
  if (o.Fogging.Mode != FogMode::None)
  {
    j["fog"] = settings::FogSpec{}.Text(o.Fogging); // as --fog and the scene key write it
  }
  if (AnyTranslucent(sceneParts) && o.Peels > 0)
  {
    j["peels"] = o.Peels;
  }
  if (o.Drawn != Representation::Surface)
  {
    j["representation"] = ToString(o.Drawn);
    j[o.Drawn == Representation::Wireframe ? "line_width" : "point_size"] =
      o.Drawn == Representation::Wireframe ? o.LineWidth : o.PointSize;
  }
  j["normals"] = ToString(o.Normals);
  j["weighting"] = o.Computed.Weighting;
  j["feature_angle"] =
    o.Computed.FeatureAngle ? nlohmann::json(*o.Computed.FeatureAngle) : nlohmann::json();
  j["orient"] = o.Computed.Orient;

  // OpenImageIO's EXR writer stamps the current time unless DateTime is
  // set; an empty one keeps the file a function of the scene alone.
  return { { "Software", std::string("shadelab ") + ShadelabVersion },
    { "ImageDescription", JsonText(j) }, { "DateTime", "" } };
}
}
