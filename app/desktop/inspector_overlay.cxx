// The texts over the inspector's panels: the HUD at the bottom left and the
// key list (key h) in the middle.
#include "desktop/inspector.h"
#include "scene/scene_parts.h"
#include "settings/setting_kinds.h"

#include <vtkTextProperty.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace shadelab
{
const char* Describe(LightMode mode)
{
  switch (mode)
  {
    case LightMode::Given:
      return "the light list";
    case LightMode::PointAtCamera:
      return "point light at camera";
    case LightMode::Directional:
      return "directional light along the view";
    case LightMode::Spot:
      return "spot light at camera (8 deg, e 4)";
  }
  return "?";
}

namespace
{
// The key list with every line padded to the longest: in a monospace font,
// centring the block then leaves the keys and their meanings in columns. A
// space each side keeps the text off the background box's edges.
std::string AlignedKeysHelp()
{
  std::vector<std::string> lines;
  std::istringstream help(ViewKeysHelp());
  std::size_t width = 0;
  for (std::string line; std::getline(help, line);)
  {
    width = std::max(width, line.size());
    lines.push_back(line);
  }
  std::string block;
  for (const std::string& line : lines)
  {
    block += (block.empty() ? " " : "\n ") + line + std::string(width - line.size() + 1, ' ');
  }
  return block;
}
}

std::string Fixed(double value, int digits)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

void Inspector::SetUpOverlay()
{
  this->Hud->GetTextProperty()->SetFontSize(15);
  this->Hud->GetTextProperty()->SetColor(0.9, 0.9, 0.6);
  this->Hud->SetPosition(8, 8);
  this->Overlay->AddActor2D(this->Hud);
  this->Help->SetInput(AlignedKeysHelp().c_str());
  vtkTextProperty* help = this->Help->GetTextProperty();
  help->SetFontSize(17);
  help->SetFontFamilyToCourier();
  help->SetBackgroundColor(0.05, 0.05, 0.1);
  help->SetBackgroundOpacity(0.85);
  help->SetJustificationToCentered();
  help->SetVerticalJustificationToCentered();
  this->Help->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Help->SetPosition(0.5, 0.5);
  this->Help->VisibilityOff();
  this->Overlay->AddActor2D(this->Help);
}

void Inspector::UpdateHud()
{
  const SceneOptions& s = this->State.Scene;
  const Material m = s.EffectiveMaterial();
  std::ostringstream material;
  material << m.Name << " (ns " << Fixed(m.Ns, 1);
  if (m.Translucency < 1)
  {
    material << ", a " << Fixed(m.Translucency, 2);
    if (s.Peels > 0)
    {
      material << ", " << s.Peels << (s.Peels == 1 ? " peel" : " peels");
    }
  }
  material << ")";
  // Parts that keep the file's materials: the default above is not all there is.
  const BuiltScene* shown = this->Slots.empty() ? nullptr : this->Slots.front().Scenes.GetShown();
  if (shown)
  {
    const std::vector<ScenePart> parts = SceneParts(s, shown->Mesh);
    const auto own = std::count_if(parts.begin(), parts.end(),
      [](const ScenePart& p) { return p.Source == MaterialSource::File; });
    if (own > 0)
    {
      material << ", file's on " << own << "/" << parts.size() << " parts";
    }
  }
  std::ostringstream hud;
  hud << (this->State.Compare ? "compare: " + this->Options.Panels.Modes
                              : std::string(ToString(s.ShadingRule)) + " shading")
      << " | " << (UsesHalfVector(s.ReflectionModel) ? "Blinn-Phong" : "Phong") << " | "
      << material.str() << " | " << Describe(this->State.Lights);
  if (s.Attenuation != NoAttenuation)
  {
    hud << " / (" << s.Attenuation[0] << " + " << s.Attenuation[1] << " d + " << s.Attenuation[2]
        << " d^2)";
  }
  if (s.Fogging.Mode != FogMode::None)
  {
    hud << " | fog " << settings::FogSpec{}.Text(s.Fogging);
  }
  hud << "\n";
  hud << this->Triangles << " triangles";
  // On the second line, the shorter: the first fills the view with fog on.
  if (s.Drawn != Representation::Surface)
  {
    hud << " as " << ToString(s.Drawn) << " of "
        << (s.Drawn == Representation::Points ? s.PointSize : s.LineWidth) << " px";
  }
  hud << " | normals: "
      << (s.Normals != NormalsMode::Compute && this->FileNormals ? "from the file"
                                                                 : s.Computed.Weighting.c_str())
      << " | terms:" << (this->State.Ambient ? " ambient" : "")
      << (this->State.Diffuse ? " diffuse" : "") << (this->State.Specular ? " specular" : "")
      << (!s.Environment.empty() && this->State.Reflected ? " environment" : "")
      << (s.MapsNormals(this->FileNormalMaps) && this->State.Relief
             ? (s.BumpMap ? " | bump map" : " | normal map")
             : "")
      << "\n";
  double mean = 0;
  for (double ms : this->FrameMs)
  {
    mean += ms / this->FrameMs.size();
  }
  hud << Fixed(mean, 1) << " ms/frame";
  if (this->Options.InteractiveShading && !this->State.Compare)
  {
    hud << " | while dragging: " << ToString(*this->Options.InteractiveShading)
        << (this->Dragging ? " (now)" : "");
  }
  hud << " | h: keys";
  if (!this->Problem.empty())
  {
    hud << "\n" << this->Problem;
  }
  this->Hud->SetInput(hud.str().c_str());
}
}
