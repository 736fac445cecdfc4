// Meshes read once per run: a batch's shots, a comparison's panels and the
// viewer's weightings ask for the same file again and again, often with
// other normals settings.
#ifndef shadelab_mesh_cache_h
#define shadelab_mesh_cache_h

#include "scene/mesh_input.h"

#include <map>
#include <string>
#include <tuple>

namespace shadelab
{
class MeshCache
{
public:
  /**
   * The mesh that options ask for (file, normals mode and settings), read
   * and its normals computed the first time; a LoadedMesh with its Error
   * when it cannot be read. The reference stays valid while the cache lives.
   */
  const LoadedMesh& Get(const SceneOptions& options);

private:
  // What makes two meshes the same: the file and how its normals are got
  // (LoadMesh computes them only for the lit rules).
  using Key = std::tuple<std::string, NormalsMode, std::string, double, bool, bool>;
  std::map<Key, LoadedMesh> Meshes;
};
}

#endif
