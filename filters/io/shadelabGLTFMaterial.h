/**
 * @brief   a glTF material in the lecture's terms
 *
 * glTF's metallic-roughness model has no ka, kd, ks, ns; LectureMaterial
 * maps it by a common Blinn-Phong approximation (doc/user/formats-and-materials.md,
 * "Materials from glTF"): with base colour B (baseColorFactor's r g b), metallic m and
 * roughness r (their factors, each clamped to [0, 1]; defaults 1, 1, 1 as
 * the specification says),
 *
 *     kd = B (1 - m)              metals have no diffuse colour
 *     ka = kd
 *     ks = 0.04 (1 - m) + B m     dielectrics reflect 4%, metals their colour
 *     ns = 2 / r^4 - 2            Blinn-Phong's exponent for GGX's alpha = r^2,
 *                                 clamped to [0, 10000]
 *
 * The opacity a (Translucency) is baseColorFactor's alpha with alphaMode
 * BLEND, 1 with OPAQUE (the default), and 1 or 0 with MASK as the alpha
 * reaches alphaCutoff or not.
 *
 * baseColorTexture T multiplies kd and ka (shadelabGLTFTexture.h), as it
 * multiplies baseColorFactor in glTF; in ks it multiplies B m, the metal's
 * part: ks = 0.04 (1 - m) + B m T (KsTextureScale).
 */
#ifndef shadelabGLTFMaterial_h
#define shadelabGLTFMaterial_h

#include "shadelabGLTFJson.h"
#include "shadelabIllumination.h"

#include <string>

namespace shadelab::gltf
{
/** materials[k] (`material`) as the lecture's coefficients; `where` names it in messages. */
Material LectureMaterial(const Json& material, const std::string& where);
/** The part of LectureMaterial's ks that baseColorTexture multiplies: B m. */
Rgb KsTextureScale(const Json& material, const std::string& where);
}

#endif
