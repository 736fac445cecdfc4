// The lecture's illumination model and shading rules in double precision:
// the oracle for tests and accuracy measurements (doc/design.md, "The
// illumination model"). Each function mirrors, line by line, a GLSL function
// of the same name in shadelabShaderSource.cxx, so that a reader can hold one
// against the other.
//
// Everything is in one orthonormal frame of the caller's choice: the shaders
// use view coordinates, tests may use world coordinates.
#ifndef shadelabShadingOracle_h
#define shadelabShadingOracle_h

#include "shadelabEnvironment.h"
#include "shadelabIllumination.h"
#include "shadelabNormalMap.h"
#include "shadelabTexture.h"

#include <cstddef>
#include <functional>
#include <optional>
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
  double CosCutoff = 0;             // spot: cos(half-angle)
  double Exponent = 0;              // spot
  Vec3 Attenuation = NoAttenuation; // point, spot: C0, C1, C2
  bool Shadows = false;             // it casts shadows: IlluminationInputs::Reaches decides
};

/** Everything the equation needs besides the surface point. */
struct IlluminationInputs
{
  Material Surface;
  // kd and/or ka times a texel, looked up per fragment under every rule
  // (ShadeTriangleFragment): Surface's are the factors.
  SurfaceTexture Texture;
  // Environment reflections: ks * E(R) added where the rule lights, its
  // Frame from the computation's frame (shadelabEnvironment.h).
  std::optional<EnvironmentMap> Environment;
  // A normal map: the normal that lights is perturbed by it where the rule
  // takes the normal (ShadeTriangleFragment, shadelabNormalMap.h).
  std::optional<NormalMap> NormalTexture;
  Rgb Ambient{}; // Ia
  std::vector<FrameLight> Lights;
  Reflection Model = Reflection::BlinnPhong;
  bool Orthographic = false;
  Vec3 Eye{};                     // perspective: the camera position
  Vec3 ViewDirection{ 0, 0, -1 }; // orthographic: unit, the way the camera looks
  // Shadows: whether light l (of Lights, casting shadows) reaches point P
  // lit with normal N, nothing in between (the shadow ray,
  // shadelabRayScene.h's LightReaches, in the caller's frame); asked only
  // where the light would add a term. None: every light reaches.
  std::function<bool(std::size_t l, const Vec3& P, const Vec3& N)> Reaches;
};

/** Moves lights into the computation's frame (p' = R p + t, d' = R d). */
FrameLight ToFrame(const Light& light, const double rotation[3][3], const Vec3& translation);

/** The light as it is: for computations in world coordinates. */
FrameLight ToFrame(const Light& light);

/**
 * (1 - d)^ns for 0 <= d < 1, where d = 1 - cos of the specular angle,
 * computed as d = |A - B|^2 / 2 for unit A, B (no cancellation near 1).
 * For small d through the series of ln(1 - d), which keeps ns up to 1e6
 * smooth in float; pow elsewhere.
 */
double SpecularFalloff(double d, double ns);

/** One light's share of the equation at a point, and the quantities it comes from. */
struct LightTerms
{
  // It reaches P: it has a direction there (a point light is not at P itself)
  // and, a spot, P lies inside its cone.
  bool Reaches = false;
  Vec3 L{};               // unit, towards the light; a directional light's is minus its direction
  double SpotCos = 1;     // spot: cos of the angle between its axis and the ray from it to P
  double SpotFactor = 1;  // spot: (SpotCos)^e inside the cone (1 for e = 0), 0 outside
  double Distance = 0;    // point, spot: from the light to P
  double Attenuation = 1; // point, spot: 1 / (C0 + C1*d + C2*d^2), d the Distance
  Rgb Il{};               // its colour as it reaches P: the colour times SpotFactor and Attenuation
  double NdotL = 0;
  // It casts shadows, would light P (Reaches, N.L > 0), and something lies
  // between: it adds neither diffuse nor specular.
  bool Shadowed = false;
  bool Lit =
    false; // N.L > 0 (taken as N.L > 1e-5, see Illuminate), not Shadowed: it adds a diffuse term
  // Blinn-Phong: H = normalize(L + V), or 0 where L = -V leaves it undefined;
  // Phong: R = 2(N.L)N - L.
  Vec3 HR{};
  double Base = 0;       // N.H or V.R
  bool Specular = false; // Lit and Base > 0 (H defined): it adds a specular term
  double Power = 0;      // Base^ns through SpecularFalloff where Specular, else 0
  Rgb DiffuseTerm{};     // kd*Il*(N.L) where Lit, else 0
  Rgb SpecularTerm{};    // ks*Il*Base^ns where Specular, else 0
};

/** The equation at one point, term by term: what Illuminate adds up. */
struct IlluminationTerms
{
  Vec3 P{};
  Vec3 N{};                       // the unit normal it was lit with; 0 lights as ambient only
  Vec3 V{};                       // unit, towards the viewer
  Rgb Ambient{};                  // ka*Ia
  std::vector<LightTerms> Lights; // in the order of IlluminationInputs::Lights
  // With an environment, where N is a normal (not 0): ks * E(R).
  std::optional<EnvironmentTerm> Environment;

  /** I = ka*Ia + sum_l (diffuse_l + specular_l) + ks*E(R). */
  Rgb Total() const;
};

/**
 * I = ka*Ia + sum_l Il*[kd*max(N.L, 0) + S_l] at point P with unit normal N,
 * term by term. S_l = 0 when N.L <= 0 or the specular base is <= 0; a light
 * at P itself (L undefined) and L = -V (H undefined) add nothing undefined.
 * "N.L <= 0" is taken as N.L <= 1e-5, so that float rounding cannot decide
 * the case where N.L is exactly 0 (see GrazingLimit).
 */
IlluminationTerms IlluminateTerms(const IlluminationInputs& in, const Vec3& P, const Vec3& N);

/** IlluminateTerms(in, P, N).Total(): the intensity. */
Rgb Illuminate(const IlluminationInputs& in, const Vec3& P, const Vec3& N);

/**
 * Whether phong lights with the interpolated normal: its length is above
 * 1e-6 and finite. Otherwise ShadeFragment falls back to the geometric one.
 */
bool UsableInterpolatedNormal(const Vec3& interpolatedN);

/** Whether a vertex (or flat's face) normal lights: ShadeVertex's test. */
bool UsableVertexNormal(const Vec3& N);

/**
 * Phong shading: one fragment from interpolated position and normal. The
 * normal is renormalised; a zero-length or non-finite one falls back to the
 * geometric normal (facing the viewer). Back faces are lit with the normal
 * flipped.
 */
IlluminationTerms ShadeFragment(const IlluminationInputs& in, const Vec3& P,
  const Vec3& interpolatedN, const Vec3& geometricN, bool frontFacing);

/**
 * Gouraud shading: the terms at one vertex, for the front (N) or the back
 * (-N); the rasteriser interpolates their sum and the fragment picks by
 * facing. A zero-length or non-finite normal lights as ambient only.
 */
IlluminationTerms ShadeVertex(
  const IlluminationInputs& in, const Vec3& P, const Vec3& N, bool front);

/**
 * Flat shading: the equation once for triangle (P0, P1, P2), at its
 * provoking vertex (OpenGL's last vertex, P2) with the face normal
 * normalize((P1 - P0) x (P2 - P0)), flipped for a back face.
 */
IlluminationTerms ShadeFlat(
  const IlluminationInputs& in, const Vec3& P0, const Vec3& P1, const Vec3& P2, bool frontFacing);
}

#endif
