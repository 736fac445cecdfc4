#include "core/scene_arguments.h"

#include "core/report_text.h"

namespace shadelab
{
namespace
{
std::string Number(double value)
{
  return FormatNumber("%.17g", value);
}

std::string Triple(const std::array<double, 3>& v)
{
  return Number(v[0]) + "," + Number(v[1]) + "," + Number(v[2]);
}
}

std::string LightArgument(const Light& light)
{
  std::string text = ToString(light.Kind);
  if (light.Kind != LightKind::Directional)
  {
    text += ":" + Triple(light.Position);
  }
  if (light.Kind != LightKind::Point)
  {
    text += ":" + Triple(light.Direction);
  }
  if (light.Kind == LightKind::Spot)
  {
    text += ":" + Number(light.HalfAngleDeg) + ":" + Number(light.Exponent);
  }
  return text + ":" + Triple(light.Color);
}

std::vector<std::string> SceneArguments(const SceneOptions& s)
{
  const SceneOptions d;
  std::vector<std::string> a;
  const auto add = [&a](const char* option, const std::string& value)
  {
    a.push_back(option);
    a.push_back(value);
  };
  const auto triple = [&add](const char* option, const std::optional<Vec3>& value)
  {
    if (value)
    {
      add(option, Triple(*value));
    }
  };
  const auto flag = [&a](const char* option, bool on)
  {
    if (on)
    {
      a.push_back(option);
    }
  };
  if (s.ShadingRule != d.ShadingRule)
  {
    add("--shading", ToString(s.ShadingRule));
  }
  if (s.ReflectionModel != d.ReflectionModel)
  {
    add("--reflection", ToString(s.ReflectionModel));
  }
  if (s.MaterialGiven || s.MaterialName != d.MaterialName) // given: it replaces the file's
  {
    add("--material", s.MaterialName);
  }
  triple("--ka", s.Ka);
  triple("--kd", s.Kd);
  triple("--ks", s.Ks);
  if (s.Ns)
  {
    add("--ns", Number(*s.Ns));
  }
  if (!s.Texture.empty())
  {
    add("--texture", s.Texture);
  }
  if (s.TextureWrapping != d.TextureWrapping)
  {
    add("--texture-wrap", ToString(s.TextureWrapping));
  }
  if (s.TextureFiltering != d.TextureFiltering)
  {
    add("--texture-filter", ToString(s.TextureFiltering));
  }
  if (s.Ambient != d.Ambient)
  {
    add("--ambient", Triple(s.Ambient));
  }
  for (const Light& light : s.Lights)
  {
    add("--light", LightArgument(light));
  }
  add("--size", std::to_string(s.Size.Width) + "x" + std::to_string(s.Size.Height));
  if (s.Supersampling != d.Supersampling)
  {
    add("--ssaa", std::to_string(s.Supersampling));
  }
  triple("--camera-position", s.CameraPosition);
  triple("--camera-focal-point", s.CameraFocalPoint);
  triple("--camera-view-up", s.CameraViewUp);
  if (s.Up != d.Up)
  {
    add("--up", ToString(s.Up));
  }
  if (s.View != d.View)
  {
    add("--view", ToString(s.View));
  }
  if (s.Azimuth != d.Azimuth)
  {
    add("--azimuth", Number(s.Azimuth));
  }
  if (s.Elevation != d.Elevation)
  {
    add("--elevation", Number(s.Elevation));
  }
  if (s.Zoom != d.Zoom)
  {
    add("--zoom", Number(s.Zoom));
  }
  if (s.Fit != d.Fit)
  {
    add("--fit", ToString(s.Fit));
  }
  if (s.ViewAngle != d.ViewAngle)
  {
    add("--view-angle", Number(s.ViewAngle));
  }
  flag("--orthographic", s.Orthographic);
  flag("--allow-outside-references", s.AllowOutsideReferences);
  if (s.ParallelScale)
  {
    add("--parallel-scale", Number(*s.ParallelScale));
  }
  if (s.TransparentBackground)
  {
    add("--background", "transparent");
  }
  else if (s.Background != d.Background)
  {
    add("--background", Triple(s.Background));
  }
  flag("--edges", s.Edges);
  if (s.EdgeColor != d.EdgeColor)
  {
    add("--edge-color", Triple(s.EdgeColor));
  }
  if (s.EdgeWidth != d.EdgeWidth)
  {
    add("--edge-width", Number(s.EdgeWidth));
  }
  flag("--normal-glyphs", s.NormalGlyphs);
  if (s.Normals != d.Normals)
  {
    add("--normals", ToString(s.Normals));
  }
  if (s.Computed.Weighting != d.Computed.Weighting)
  {
    add("--weighting", s.Computed.Weighting);
  }
  if (s.Computed.FeatureAngle)
  {
    add("--feature-angle", Number(*s.Computed.FeatureAngle));
  }
  flag("--orient", s.Computed.Orient);
  return a;
}
}
