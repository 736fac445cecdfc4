#include "scene/mesh_cache.h"

#include "shadelabCheckedFile.h"
#include "shadelabMeshReadError.h"

namespace shadelab
{
namespace
{
// The largest image a texture can be (MaxImagePixels, 8192 x 8192) as 16-bit
// RGBA without compression: a larger file is no texture shadelab would draw.
constexpr std::uint64_t MaxTextureFileBytes = 512ULL << 20;
}

const LoadedMesh& MeshCache::Get(const SceneOptions& o)
{
  const bool lit = UsesVertexNormals(o.ShadingRule);
  const Key key{ o.Mesh, o.Normals, o.Computed.Weighting, o.Computed.FeatureAngle.value_or(-1),
    o.Computed.Orient, lit, o.Relief().has_value(), o.NoNormalMaps() };
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
    try
    {
      // An image file is checked as the mesh files are before the decoder
      // opens it: /dev/zero or a FIFO would hold the decoder forever.
      if (bytes.empty())
      {
        OpenChecked(path, MaxTextureFileBytes);
      }
      loaded.Error = this->Decoder(path, bytes, *image);
    }
    catch (const MeshReadError& e)
    {
      loaded.Error = e.what();
    }
    if (loaded.Error.empty())
    {
      loaded.Image = image;
    }
    cached = this->Textures.emplace(path, loaded).first;
  }
  return cached->second;
}
}
