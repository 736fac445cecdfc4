// The VTK scene of one picture: the mesh's actor with its material, the
// lights and the camera, in a renderer.
#ifndef shadelab_scene_h
#define shadelab_scene_h

#include "options.h"

#include <string>

class vtkPolyData;
class vtkRenderer;

namespace shadelab
{
/**
 * Fills renderer with mesh as options describe. Returns an error text for an
 * impossible scene, else an empty string.
 */
std::string BuildScene(const SceneOptions& options, vtkPolyData* mesh, vtkRenderer* renderer);

/** The lights the scene uses: the given ones, or the lecture's default. */
std::vector<Light> EffectiveLights(const SceneOptions& options, const Vec3& cameraPosition);
}

#endif
