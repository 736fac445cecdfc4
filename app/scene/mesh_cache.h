// Meshes and their textures' images read once per run: a batch's shots, a
// comparison's panels and the viewer's weightings ask for the same file
// again and again, often with other normals settings.
#ifndef shadelab_mesh_cache_h
#define shadelab_mesh_cache_h

#include "scene/mesh_input.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

namespace shadelab
{
/**
 * Decodes an image for a texture, from the file at path or, when bytes are
 * given, from those (named path in errors): "" or the problem, one line.
 * The image writer process does it (image_writer_process.h), since it is
 * the one that links OpenImageIO.
 */
using ImageDecoder = std::function<std::string(
  const std::string& path, const std::vector<std::uint8_t>& bytes, TextureImage& image)>;

struct LoadedTexture
{
  std::shared_ptr<const TextureImage> Image; // null on error
  std::string Error;                         // one line, without the file name
};

class MeshCache
{
public:
  /** `timer` (if given) times each mesh's reading and normals (LoadMesh). */
  explicit MeshCache(ImageDecoder decoder, PhaseTimer* timer = nullptr)
    : Decoder(std::move(decoder))
    , Timer(timer)
  {
  }

  /**
   * The mesh that options ask for (file, normals mode and settings), read
   * and its normals computed the first time; a LoadedMesh with its Error
   * when it cannot be read. The reference stays valid while the cache lives.
   */
  const LoadedMesh& Get(const SceneOptions& options);

  /**
   * The image file at path or, where bytes are given, the image they
   * encode (a mesh file's embedded one, path naming it), decoded the first
   * time it is asked for by that name; the reference stays valid.
   */
  const LoadedTexture& GetTexture(
    const std::string& path, const std::vector<std::uint8_t>& bytes = {});

private:
  ImageDecoder Decoder;
  PhaseTimer* Timer;
  std::map<std::string, LoadedTexture> Textures;
  // What makes two meshes the same: the file and how its normals are got
  // (LoadMesh computes them only for the lit rules), and what decides its
  // tangents (SceneOptions::MapsNormals: a map given, the file's dropped).
  using Key = std::tuple<std::string, NormalsMode, std::string, double, bool, bool, bool, bool>;
  std::map<Key, LoadedMesh> Meshes;
};
}

#endif
