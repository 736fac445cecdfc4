// The VTK scene of one picture: the mesh's actors, a part or several parts
// each with its material, the lights and the camera, in a renderer.
#ifndef shadelab_scene_h
#define shadelab_scene_h

#include "core/options.h"
#include "scene/scene_parts.h"
#include "shadelabOwnStages.h"
#include "shadelabShadingOracle.h"

#include <vtkSmartPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkActor;
class vtkCamera;
class vtkPolyData;
class vtkRenderer;
class vtkShadelabShading;

namespace shadelab
{
class ShadowCasters;
}

namespace shadelab
{
/**
 * An actor of a scene: the mesh's parts that one material and texture
 * draw (all of them when they share them), with the shading, which must
 * live as long as the actor draws.
 */
struct DrawnParts
{
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkShadelabShading> Shading;
  std::vector<int> Parts; // ScenePart indices, ascending
};

/** What a built scene is made of. */
struct BuiltScene
{
  // One per material and texture the parts are drawn with, in the order of
  // their first part: a mesh with one part or none, or one look for all,
  // has one.
  std::vector<DrawnParts> Drawn;
  std::string Error;           // an impossible scene (camera), else empty
  vtkPolyData* Mesh = nullptr; // what the actors draw, before the rule prepared it
  SceneImages Images;          // its textures' images, decoded
  // What casts its shadows, shared by its actors (none without shadows):
  // a scene built again on the same mesh keeps the maps that still hold.
  std::shared_ptr<ShadowCasters> Casters;
};

/**
 * Fills renderer with mesh as options describe, lit by the lecture's
 * shaders, each part with its material and texture (scene/scene_parts.h),
 * their images decoded in `images`. With `reuse`, a scene built
 * before that drew the same mesh with the same rule and the same parts
 * together, its actors are taken over (their mappers keep the uploaded
 * buffers; only the lighting changes).
 */
BuiltScene BuildScene(const SceneOptions& options, vtkPolyData* mesh, vtkRenderer* renderer,
  const BuiltScene* reuse = nullptr, const SceneImages& images = {}, const OwnStages& stages = {});

/**
 * The actor part of BuildScene: mesh lit as options say by `lights` (world
 * coordinates), under the renderer's camera as it is; `reuse`, `images`
 * and `stages` as there.
 */
BuiltScene BuildActor(const SceneOptions& options, const std::vector<Light>& lights,
  vtkPolyData* mesh, vtkRenderer* renderer, const BuiltScene* reuse = nullptr,
  const SceneImages& images = {}, const OwnStages& stages = {});

/**
 * Whether mesh's vertex colours are its kd: it has them ("Colors") and
 * options do not override kd (--material, --kd).
 */
bool UsesVertexKd(const SceneOptions& options, vtkPolyData* mesh);

/**
 * `lights` with each point and spot light's attenuation and each light's
 * shadows resolved: its own, else the scene's (options' Attenuation,
 * Shadows; ray traced, every light casts). Resolved lights stay as they are.
 */
std::vector<Light> ResolvedLights(std::vector<Light> lights, const SceneOptions& options);

/** The lights the scene uses, resolved (ResolvedLights): the given ones, or the lecture's default.
 */
std::vector<Light> EffectiveLights(const SceneOptions& options, const Vec3& cameraPosition);

/**
 * The oracle's inputs for options' scene lit by `lights`, in world
 * coordinates: Ia, reflection model and the options' material (a part's
 * own, and its texture, are the caller's to set); the view is the caller's.
 */
IlluminationInputs WorldIllumination(const SceneOptions& options, const std::vector<Light>& lights);

/** WorldIllumination seen through camera: its position, projection and direction of view. */
IlluminationInputs CameraIllumination(
  const SceneOptions& options, const std::vector<Light>& lights, vtkCamera* camera);
}

#endif
