// One picture of a scene as `render` makes it, in the caller's renderer:
// the scene shown through a SceneCache (its mesh read once), its overlays,
// one frame. Each panel of `compare`, and the picture `probe` explains.
#ifndef shadelab_scene_picture_h
#define shadelab_scene_picture_h

#include "core/errors.h"
#include "image/image_pixels.h"
#include "scene/scene_cache.h"

#include <vector>

namespace shadelab
{
class HeadlessRenderer;

struct ScenePicture
{
  FloatImage Picture;
  const BuiltScene* Scene = nullptr; // what was drawn, its camera in the renderer
  // On error what failed (the mesh, "camera", "render") and why, one line
  // each (a stage of one's own that the driver refused: a line per error);
  // else none.
  std::vector<InputProblem> Errors;
};

/** options' scene drawn by renderer, which was started at its size. */
ScenePicture RenderScenePicture(
  const SceneOptions& options, SceneCache& scenes, MeshCache& meshes, HeadlessRenderer& renderer);
}

#endif
