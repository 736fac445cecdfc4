/**
 * @brief   a glTF material's baseColorTexture and normalTexture as textures of the mesh
 *
 * The texture's image (a file beside the document, or the bytes of a
 * bufferView or data URI: shadelabGLTFDocument.h) and its sampler's wrapS,
 * wrapT, magFilter and minFilter as glTF gives them (an absent sampler or
 * wrap is REPEAT, as glTF says; an absent filter, which glTF leaves to the
 * viewer, LINEAR). Only TEXCOORD_0 is read, so a baseColorTexture whose
 * texCoord is another set is not drawn, with a warning, and neither is a
 * texture without a source (its image comes from an extension).
 * KHR_texture_transform on it (offset, rotation, scale, and a texCoord
 * that overrides the textureInfo's) is given as the affine map of the
 * primitives' TEXCOORD_0, in glTF's (u, v), that the reader applies. A texture,
 * image or sampler index out of range, or a wrap or filter value glTF does
 * not define, is an error naming the place.
 */
#ifndef shadelabGLTFTexture_h
#define shadelabGLTFTexture_h

#include "shadelabGLTFDocument.h"
#include "shadelabPartMaterials.h"

#include <string>
#include <vector>

namespace shadelab::gltf
{
/**
 * KHR_texture_transform's map of texture coordinates: (u, v) becomes
 * (U[0] u + U[1] v + U[2], V[0] u + V[1] v + V[2]), translation times
 * rotation times scale as the extension defines them.
 */
struct UvTransform
{
  double U[3] = { 1, 0, 0 };
  double V[3] = { 0, 1, 0 };
};

/**
 * Maps `count` texture coordinates (s, t) by `map`; they are stored with
 * t = 1 - v, and mapped in glTF's (u, v).
 */
void MapTextureCoordinates(const UvTransform& map, float* st, std::size_t count);

/**
 * The index in `textures` of materials[k]'s (`material`'s, named `where`)
 * baseColorTexture, added unless it is there already, and in `transform`
 * the map of its coordinates (the identity without KHR_texture_transform);
 * -1 without one, or where it is not drawn, then with the reason in
 * `warning`.
 */
int BaseColorTexture(const Document& document, const Json& material, const std::string& where,
  std::vector<Texture>& textures, std::string& warning, UvTransform& transform);

/**
 * The index in `textures` of the material's normalTexture and in `scale`
 * its scale (1 without), as BaseColorTexture; `transform` is the map of
 * the coordinates, the base colour texture's where it has one (`mapped`):
 * a normal texture that maps them otherwise is not drawn, with a warning.
 */
int NormalTexture(const Document& document, const Json& material, const std::string& where,
  std::vector<Texture>& textures, std::string& warning, UvTransform& transform, bool mapped,
  double& scale);
}

#endif
