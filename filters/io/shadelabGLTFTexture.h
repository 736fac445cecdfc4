/**
 * @brief   a glTF material's baseColorTexture as a texture of the mesh
 *
 * The texture's image (a file beside the document, or the bytes of a
 * bufferView or data URI: shadelabGLTFDocument.h) and its sampler's wrapS,
 * wrapT, magFilter and minFilter as glTF gives them (an absent sampler or
 * wrap is REPEAT, as glTF says; an absent filter, which glTF leaves to the
 * viewer, LINEAR). Only TEXCOORD_0 is read, so a baseColorTexture whose
 * texCoord is another set is not drawn, with a warning, and neither is a
 * texture without a source (its image comes from an extension). A texture,
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
 * The index in `textures` of materials[k]'s (`material`'s, named `where`)
 * baseColorTexture, added unless it is there already; -1 without one, or
 * where it is not drawn, then with the reason in `warning`.
 */
int BaseColorTexture(const Document& document, const Json& material, const std::string& where,
  std::vector<Texture>& textures, std::string& warning);
}

#endif
