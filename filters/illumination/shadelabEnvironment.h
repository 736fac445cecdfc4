// Environment reflections, one of the lecture's maps (doc/design.md,
// "Maps"): an equirectangular image of what surrounds the scene, seen in
// the mirror direction. A surface adds ks * E(R), R the view vector
// reflected about the normal it is lit with, where its rule evaluates the
// equation (per fragment, per vertex, at the provoking vertex), and the
// shaders look E up as the oracle does here.
#ifndef shadelabEnvironment_h
#define shadelabEnvironment_h

#include "shadelabTexture.h"

#include <array>

namespace shadelab
{
/**
 * An equirectangular image with the textures' filter, its longitude
 * repeating and its latitude clamped, and the rotation from the frame of a
 * computation (world or view coordinates) to the environment's, whose y is
 * up: s = 0 and 1 lie behind (+z), s = 0.5 ahead (-z), t = 1 straight up.
 */
struct EnvironmentMap
{
  TextureMap Map;
  double Frame[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
};

/** One environment's share of the equation at a point. */
struct EnvironmentTerm
{
  Vec3 R{};                         // unit, towards what the mirror sees: 2(N.V)N - V
  Vec3 Direction{};                 // R in the environment's frame
  std::array<double, 2> TexCoord{}; // (s, t) of Direction
  Rgb Texel{};                      // E(R)
  Rgb Term{};                       // ks * E(R)
};

/**
 * (s, t) of direction d (any length) in the environment's frame:
 * s = 0.5 + atan2(d.x, -d.z) / 2pi, t = 0.5 + asin(d.y / |d|) / pi, the
 * latitude taken as atan2(d.y, |(d.x, d.z)|), which keeps its precision
 * near the poles.
 */
std::array<double, 2> EnvironmentTexCoord(const Vec3& d);

/**
 * What the environment shows along unit direction d (in the computation's
 * frame): R = d, its direction, (s, t) and texel; Term zero.
 */
EnvironmentTerm EnvironmentAlong(const EnvironmentMap& e, const Vec3& d);

/**
 * The environment's term for unit normal N and unit V towards the viewer,
 * with specular coefficient ks: EnvironmentAlong(R), its Term ks E(R).
 */
EnvironmentTerm EnvironmentAt(const EnvironmentMap& e, const Vec3& N, const Vec3& V, const Rgb& ks);
}

#endif
