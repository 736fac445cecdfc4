#include "headless/scene_picture.h"

#include "headless/headless_renderer.h"
#include "scene/overlays.h"

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
    picture.Input = shown.Input;
    picture.Error = shown.Error;
    return picture;
  }
  picture.Scene = shown.Scene;
  const SceneOverlays overlays(options, shown.Scene->Mesh, meshes, renderer.GetRenderer());
  renderer.SetMaximumNumberOfPeels(options.Peels);
  picture.Picture = renderer.Render();
  if (!renderer.GetError().empty())
  {
    picture.Input = "render";
    picture.Error = renderer.GetError();
  }
  return picture;
}
}
