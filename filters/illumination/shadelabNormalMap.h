// Normal and bump maps, two of the lecture's maps (doc/design.md, "Maps"):
// an image whose texel is a direction in the surface's tangent space, or a
// height whose gradient tilts the normal (Blinn's bump), which takes the
// place of the normal where the rule takes the normal (per fragment, per
// vertex, at the provoking vertex). The shaders perturb the normal as
// MapNormal does here, in float.
#ifndef shadelabNormalMap_h
#define shadelabNormalMap_h

#include "shadelabTexture.h"

#include <array>

namespace shadelab
{
/**
 * A map of the normal with the textures' wrap and filter, its values taken
 * as stored (data, no sRGB conversion). A tangent-space normal map: its RGB
 * in [0, 1] is the vector 2 RGB - 1 along (T, B, N), its x and y times
 * Scale (glTF's normalTexture). A height (bump) map: its R is a height h,
 * and the vector is (-Scale dh_s, -Scale dh_t, 1), dh_s = h(s + 1/width, t)
 * - h(s, t) and dh_t = h(s, t + 1/height) - h(s, t) its differences one
 * texel apart, each h looked up as a texel is (wrap and filter): Blinn's
 * perturbation in the tangent frame, Scale the height of white above black
 * in texels' widths.
 */
struct NormalMap
{
  TextureMap Map;
  double Scale = 1;
  bool Height = false; // a height (bump) map
};

/**
 * A vertex's tangent: xyz along the texture's s (any length), w = +1 or -1
 * the handedness, B = w N x T (glTF's TANGENT).
 */
using Tangent = std::array<double, 4>;

/** One normal perturbed by the map, with what it was made of. */
struct NormalMapping
{
  Vec3 N{};                         // unit, as the rule would light without the map
  Vec3 T{};                         // the tangent made orthogonal to N, unit (0: none)
  Vec3 B{};                         // w N x T
  std::array<double, 2> TexCoord{}; // (s, t) where the map is read
  Rgb Texel{};                      // the map there
  bool Height = false;              // the map is a height map
  std::array<double, 3> Heights{};  // its h at st, one texel along s, one along t
  Vec3 TangentSpace{};              // the texel's vector along (T, B, N), as NormalMap says
  Vec3 Perturbed{};                 // unit: what lights; N where T or the sum has no length
};

/**
 * Every texel's R, G and B are equal: a height map's image (grey), which
 * as a normal map would point every normal along (1, 1, 1) or its opposite.
 */
bool IsGrey(const TextureImage& image);

/**
 * Unit normal N perturbed by the map at st, in the frame of tangent: T is
 * tangent's xyz less its part along N, normalised; the normal is
 * normalize(x T + y B + z N) of TangentSpace. A tangent along N or of no
 * length, or a texel whose vector has none, leaves N as it is.
 */
NormalMapping MapNormal(
  const NormalMap& map, const Vec3& N, const Tangent& tangent, const std::array<double, 2>& st);
}

#endif
