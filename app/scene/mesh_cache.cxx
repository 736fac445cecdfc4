#include "scene/mesh_cache.h"

namespace shadelab
{
const LoadedMesh& MeshCache::Get(const SceneOptions& o)
{
  const bool lit = o.ShadingRule == Shading::Gouraud || o.ShadingRule == Shading::Phong;
  const Key key{ o.Mesh, o.Normals, o.Computed.Weighting, o.Computed.FeatureAngle.value_or(-1),
    o.Computed.Orient, lit };
  auto cached = this->Meshes.find(key);
  if (cached == this->Meshes.end())
  {
    cached = this->Meshes.emplace(key, LoadMesh(o)).first;
  }
  return cached->second;
}
}
