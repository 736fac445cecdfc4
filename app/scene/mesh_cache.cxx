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
    // Without face normals (LoadMesh's default): no picture draws them.
    cached = this->Meshes.emplace(key, LoadMesh(o, this->Timer)).first;
  }
  return cached->second;
}

const LoadedTexture& MeshCache::GetTexture(
  const std::string& path, const std::vector<std::uint8_t>& bytes)
{
  auto cached = this->Textures.find(path);
  if (cached == this->Textures.end())
  {
    LoadedTexture loaded;
    auto image = std::make_shared<TextureImage>();
    loaded.Error = this->Decoder(path, bytes, *image);
    if (loaded.Error.empty())
    {
      loaded.Image = image;
    }
    cached = this->Textures.emplace(path, loaded).first;
  }
  return cached->second;
}
}
