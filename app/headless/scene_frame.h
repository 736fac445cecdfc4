// A scene's frame as its rule makes it: the raster rules' from the
// renderer, raytrace's from the ray tracer, through the scene's camera.
#ifndef shadelab_scene_frame_h
#define shadelab_scene_frame_h

#include "image/image_pixels.h"
#include "scene/scene.h"

#include <string>

namespace shadelab
{
class HeadlessRenderer;

/**
 * What options ask that --shading raytrace does not draw, as the option
 * and why in one line ("" when nothing): the surface's edges, points and
 * overlays are the raster's.
 */
std::pair<std::string, std::string> RayTraceProblem(const SceneOptions& options);

/**
 * frame: the picture of `scene` (options', built in renderer's renderer),
 * rendered, or for raytrace traced through the renderer's camera. The
 * renderer's error (HeadlessRenderer::GetError), or "".
 */
std::string SceneFrame(const SceneOptions& options, const BuiltScene& scene,
  HeadlessRenderer& renderer, FloatImage& frame);
}

#endif
