// The inspector's picture as the `shadelab render` command, or the scene
// file, that makes it headless, pixel for pixel (Copy command, key y; Save
// scene, key j).
#include "desktop/inspector.h"

#include "core/errors.h"
#include "core/output_file.h"
#include "image/metadata.h"
#include "scene/comparison_panels.h"
#include "scene/scene_file.h"
#include "settings/command_line.h"

#include <filesystem>
#include <iostream>

namespace shadelab
{
SceneOptions Inspector::ShownScene() const
{
  const SceneOptions defaults;
  SceneOptions s = this->State.Scene;
  ShowTerms(s, this->State.Ambient, this->State.Diffuse, this->State.Specular,
    this->State.Reflected, this->State.Relief);
  s.Edges = this->State.Edges;
  s.NormalGlyphs = this->State.Glyphs;
  // The lecture's default light at the camera is render's default too.
  s.Lights =
    this->State.Lights == LightMode::PointAtCamera ? std::vector<Light>{} : this->CameraLights(s);
  Vec3 position, focal, up;
  this->Camera->GetPosition(position.data());
  this->Camera->GetFocalPoint(focal.data());
  this->Camera->GetViewUp(up.data());
  s.CameraPosition = position;
  s.CameraFocalPoint = focal;
  s.CameraViewUp = up;
  // The camera is whole: nothing is fitted or turned again.
  s.Up = defaults.Up;
  s.View = defaults.View;
  s.Azimuth = defaults.Azimuth;
  s.Elevation = defaults.Elevation;
  s.Zoom = defaults.Zoom;
  s.Fit = defaults.Fit;
  s.ViewAngle = this->Camera->GetViewAngle();
  s.Orthographic = this->Camera->GetParallelProjection();
  s.ParallelScale =
    s.Orthographic ? std::optional<double>(this->Camera->GetParallelScale()) : std::nullopt;
  const int* size = this->Window->GetSize();
  s.Size = { size[0], size[1] };
  s.Mesh = std::filesystem::absolute(s.Mesh).string();
  // The stages of one's own are the rule's they were applied under.
  for (std::string* stage : { &s.VertexShader, &s.FragmentShader })
  {
    if (this->State.StagesRule != s.ShadingRule)
    {
      stage->clear();
    }
    else if (!stage->empty())
    {
      *stage = std::filesystem::absolute(*stage).string();
    }
  }
  return s;
}

namespace
{
// Where the command and the scene file render to: MESHSTEM.png.
std::string PictureName(const SceneOptions& s)
{
  return std::filesystem::path(s.Mesh).stem().string() + ".png";
}
}

std::string Inspector::RenderCommand() const
{
  const SceneOptions s = this->ShownScene();
  std::vector<std::string> words{ "shadelab", "render", s.Mesh, "-o", PictureName(s) };
  const std::vector<std::string> options = SceneArguments(s);
  words.insert(words.end(), options.begin(), options.end());
  std::vector<const char*> argv;
  for (const std::string& word : words)
  {
    argv.push_back(word.c_str());
  }
  return QuoteCommandLine(static_cast<int>(argv.size()), argv.data());
}

void Inspector::CopyCommand()
{
  if (!this->SaveStages())
  {
    return;
  }
  const std::string command = this->RenderCommand();
  std::cout << "shadelab: render command: " << command << std::endl;
  if (this->Copy)
  {
    this->Copy(command);
  }
}

void Inspector::SaveScene(const std::string& path)
{
  if (!this->SaveStages())
  {
    return;
  }
  const SceneOptions s = this->ShownScene();
  if (const std::string error = WriteFile(path, WriteSceneText(s, PictureName(s))); !error.empty())
  {
    ReportError(path, error);
    return;
  }
  std::cout << "shadelab: scene file " << std::filesystem::absolute(path).string() << std::endl;
}
}
