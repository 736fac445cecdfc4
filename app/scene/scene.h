// The VTK scene of one picture: the mesh's actor with its material, the
// lights and the camera, in a renderer.
#ifndef shadelab_scene_h
#define shadelab_scene_h

#include "core/options.h"
#include "shadelabShadingOracle.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <string>

class vtkActor;
class vtkPolyData;
class vtkRenderer;
class vtkShadelabShading;

namespace shadelab
{
/** What a built scene is made of; the shading must live as long as the actor draws. */
struct BuiltScene
{
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkShadelabShading> Shading;
  std::string Error;                           // an impossible scene (camera), else empty
  vtkPolyData* Mesh = nullptr;                 // what the actor draws, before the rule prepared it
  std::shared_ptr<const TextureImage> Texture; // --texture's image, decoded, or null
};

/**
 * Fills renderer with mesh as options describe, lit by the lecture's
 * shaders; `texture`, options.Texture decoded, where it gives one. With
 * `reuse`, a scene built before that drew the same mesh with the same rule,
 * its actor is taken over (its mapper keeps the uploaded buffers; only the
 * lighting changes).
 */
BuiltScene BuildScene(const SceneOptions& options, vtkPolyData* mesh, vtkRenderer* renderer,
  const BuiltScene* reuse = nullptr, std::shared_ptr<const TextureImage> texture = nullptr);

/**
 * The actor part of BuildScene: mesh lit as options say by `lights` (world
 * coordinates), under the renderer's camera as it is; `reuse` and `texture`
 * as there.
 */
BuiltScene BuildActor(const SceneOptions& options, const std::vector<Light>& lights,
  vtkPolyData* mesh, vtkRenderer* renderer, const BuiltScene* reuse = nullptr,
  std::shared_ptr<const TextureImage> texture = nullptr);

/**
 * What --texture makes of texture (options.Texture decoded): kd and ka
 * both, with options' wrap and filter; nothing used without it.
 */
SurfaceTexture SceneTexture(
  const SceneOptions& options, std::shared_ptr<const TextureImage> texture);

/**
 * Whether mesh's vertex colours are its kd: it has them ("Colors") and
 * options do not override kd (--material, --kd).
 */
bool UsesVertexKd(const SceneOptions& options, vtkPolyData* mesh);

/** The lights the scene uses: the given ones, or the lecture's default. */
std::vector<Light> EffectiveLights(const SceneOptions& options, const Vec3& cameraPosition);

/**
 * The oracle's inputs for options' scene lit by `lights`, in world
 * coordinates: material, texture (SceneTexture), Ia, reflection model; the
 * view is the caller's.
 */
IlluminationInputs WorldIllumination(const SceneOptions& options, const std::vector<Light>& lights,
  std::shared_ptr<const TextureImage> texture = nullptr);
}

#endif
