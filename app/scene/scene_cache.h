// The loop that the batch, the comparison and the window share: a mesh from
// the MeshCache (read and its normals computed once), the actor built
// before for the same mesh and rule taken over (it keeps its uploaded
// buffers and compiled program; only the lighting changes), the scene set
// up in a renderer.
#ifndef shadelab_scene_cache_h
#define shadelab_scene_cache_h

#include "scene/mesh_cache.h"
#include "scene/scene.h"

#include <map>
#include <string>
#include <utility>
#include <vector>

class vtkPolyData;
class vtkRenderer;

namespace shadelab
{
/** The actors built for one renderer, one per mesh and rule. */
class SceneCache
{
public:
  explicit SceneCache(MeshCache& meshes)
    : Meshes(&meshes)
  {
  }

  struct Shown
  {
    const BuiltScene* Scene = nullptr; // null on error
    const LoadedMesh* Mesh = nullptr;  // the mesh as read, when it could be
    std::string Input;                 // on error: what failed (the mesh file, "camera")
    std::string Error;                 // on error: why, one line
  };

  /**
   * Shows options' scene in renderer and hides every other actor of this
   * cache there. Without lights, the camera is set up as options say
   * (BuildScene); with them, the renderer's camera is used as it is and
   * the actor lit by them (BuildActor). The stages of one's own are
   * `stages` where given (the window's edited ones), else the files
   * options name.
   */
  Shown Show(const SceneOptions& options, vtkRenderer* renderer,
    const std::vector<Light>* lights = nullptr, const OwnStages* stages = nullptr);

  /** The scene shown last, or null. */
  const BuiltScene* GetShown() const;

  /**
   * Takes the actors of every mesh but `keep` out of renderer and frees
   * their OpenGL resources: a batch that moved on to another mesh.
   */
  void ForgetOtherMeshes(const vtkPolyData* keep, vtkRenderer* renderer);

private:
  using Key = std::pair<Shading, const vtkPolyData*>;
  MeshCache* Meshes;
  std::map<Key, BuiltScene> Scenes;
  Key Current{ Shading::None, nullptr };
};
}

#endif
