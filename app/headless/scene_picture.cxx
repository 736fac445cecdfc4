#include "headless/scene_picture.h"

#include "headless/headless_renderer.h"
#include "headless/scene_frame.h"
#include "scene/overlays.h"
#include "scene/own_stage_files.h"

#include <vtkRenderer.h>

namespace shadelab
{
ScenePicture RenderScenePicture(
  const SceneOptions& options, SceneCache& scenes, MeshCache& meshes, HeadlessRenderer& renderer)
{
  ScenePicture picture;
  const SceneCache::Shown shown = scenes.Show(options, renderer.GetRenderer());
  if (!shown.Scene)
  {
    picture.Errors = { { shown.Input, shown.Error } };
    return picture;
  }
  picture.Scene = shown.Scene;
  if (auto [input, error] = RayTraceProblem(options); !error.empty())
  {
    picture.Errors = { { input, error } };
    return picture;
  }
  const SceneOverlays overlays(options, shown.Scene->Mesh, meshes, renderer.GetRenderer());
  renderer.SetMaximumNumberOfPeels(options.Peels);
  if (const std::string error = SceneFrame(options, *shown.Scene, renderer, picture.Picture);
      !error.empty())
  {
    picture.Errors = { { "render", error } };
  }
  // Stages of one's own that the driver refused drew nothing.
  else if (std::vector<InputProblem> refused = StageErrorLines(options, *shown.Scene);
           !refused.empty())
  {
    picture.Errors = std::move(refused);
  }
  return picture;
}
}
