// The lecture's illumination model and shading rules in double precision:
// the oracle for tests and accuracy measurements (DESIGN.md, "The
// illumination model"). Each function mirrors, line by line, a GLSL function
// of the same name in shadelabShaderSource.cxx, so that a reader can hold one
// against the other.
//
// Everything is in one orthonormal frame of the caller's choice: the shaders
// use view coordinates, tests may use world coordinates.
#ifndef shadelabShadingOracle_h
#define shadelabShadingOracle_h

#include "shadelabIllumination.h"

#include <vector>

namespace shadelab
{
/** A light in the frame of the computation, as the shaders receive it. */
struct FrameLight
{
  LightKind Kind = LightKind::Point;
  Vec3 Position{};  // point, spot
  Vec3 Direction{}; // directional, spot: unit, the direction the light shines along
  Rgb Color{ 1, 1, 1 };
  double CosCutoff = 0; // spot: cos(half-angle)
  double Exponent = 0;  // spot
};

/** Everything the equation needs besides the surface point. */
struct IlluminationInputs
{
  Material Surface;
  Rgb Ambient{}; // Ia
  std::vector<FrameLight> Lights;
  Reflection Model = Reflection::BlinnPhong;
  bool Orthographic = false;
  Vec3 Eye{};                     // perspective: the camera position
  Vec3 ViewDirection{ 0, 0, -1 }; // orthographic: unit, the way the camera looks
};

/** Moves lights into the computation's frame (p' = R p + t, d' = R d). */
FrameLight ToFrame(const Light& light, const double rotation[3][3], const Vec3& translation);

/**
 * (1 - d)^ns for 0 <= d < 1, where d = 1 - cos of the specular angle,
 * computed as d = |A - B|^2 / 2 for unit A, B (no cancellation near 1).
 * For small d through the series of ln(1 - d), which keeps ns up to 1e6
 * smooth in float; pow elsewhere.
 */
double SpecularFalloff(double d, double ns);

/**
 * I = ka*Ia + sum_l Il*[kd*max(N.L, 0) + S_l] at point P with unit normal N.
 * S_l = 0 when N.L <= 0 or the specular base is <= 0; a light at P itself
 * (L undefined) and L = -V (H undefined) add nothing undefined. "N.L <= 0"
 * is taken as N.L <= 1e-5, so that float rounding cannot decide the case
 * where N.L is exactly 0 (see GrazingLimit).
 */
Rgb Illuminate(const IlluminationInputs& in, const Vec3& P, const Vec3& N);

/**
 * Phong shading: one fragment from interpolated position and normal. The
 * normal is renormalised; a zero-length or non-finite one falls back to the
 * geometric normal (facing the viewer). Back faces are lit with the normal
 * flipped.
 */
Rgb ShadeFragment(const IlluminationInputs& in, const Vec3& P, const Vec3& interpolatedN,
  const Vec3& geometricN, bool frontFacing);

/**
 * Gouraud shading: the colour at one vertex, for the front (N) or the back
 * (-N); the rasteriser interpolates it and the fragment picks by facing.
 * A zero-length or non-finite normal lights as ambient only.
 */
Rgb ShadeVertex(const IlluminationInputs& in, const Vec3& P, const Vec3& N, bool front);

/**
 * Flat shading: the equation once for triangle (P0, P1, P2), at its
 * provoking vertex (OpenGL's last vertex, P2) with the face normal
 * normalize((P1 - P0) x (P2 - P0)), flipped for a back face.
 */
Rgb ShadeFlat(
  const IlluminationInputs& in, const Vec3& P0, const Vec3& P1, const Vec3& P2, bool frontFacing);
}

#endif
