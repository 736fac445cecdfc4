// One fragment of a triangle under each shading rule (doc/design.md, "The
// shading rules"), through the oracle: where the rule evaluates the
// equation, with which normal, and how the rasteriser mixes what it gives.
// What the oracle tests expect of a pixel and what `shadelab probe` explains.
#ifndef shadelabTriangleFragment_h
#define shadelabTriangleFragment_h

#include "shadelabShadingOracle.h"

#include <array>
#include <optional>

namespace shadelab
{
/** A triangle as drawn and one fragment of it. */
struct TriangleFragment
{
  std::array<Vec3, 3> Positions{}; // in draw order: the last one provokes (flat)
  std::array<Vec3, 3> Normals{};   // the vertex normals as drawn (gouraud, phong)
  // The fragment's barycentric weights, perspective-correct (as the
  // rasteriser interpolates): those of the point on the triangle itself.
  std::array<double, 3> Weights{};
  bool Front = true; // the triangle faces the viewer (counter-clockwise on the screen)
  // kd per vertex (the mesh's colours), instead of the material's.
  std::optional<std::array<Rgb, 3>> VertexKd;
  // The vertices' texture coordinates (s, t), read where the inputs have a texture.
  std::array<std::array<double, 2>, 3> TexCoords{};
  // The vertices' tangents, read where the inputs have a normal map.
  std::array<Tangent, 3> Tangents{};
};

/** The fragment as its rule shades it. */
struct ShadedFragment
{
  Rgb Color{}; // the rule's value: the oracle's intensity of the fragment
  // The kd that lit: the material's, or from VertexKd flat's provoking
  // vertex's and the others' the weights' mix (gouraud lit each vertex with its own);
  // times Texel where the texture is kd's.
  Rgb Kd{};
  // With a texture: the texture coordinates at the fragment (the weights'
  // mix) and the texel there, which kd and/or ka are multiplied by.
  std::optional<std::array<double, 2>> TexCoord;
  std::optional<Rgb> Texel;
  std::optional<Rgb> Ks; // with a texture: the ks that lit (the texel's where it is ks's)
  Vec3 Point{};          // the fragment on the surface: the weights' mix of the positions
  Vec3 FaceNormal{};     // normalize((P1 - P0) x (P2 - P0)) as drawn, 0 for no area
  // phong: the interpolated normal was too short, so the face normal lit.
  bool FaceNormalFallback = false;
  // How the rule lit: flat at the provoking vertex with the face normal,
  // phong at Point with the interpolated normal, gouraud the weights' mix of
  // Vertices (the colour is interpolated, so its terms are too). Empty for
  // none, which does not light.
  IlluminationTerms Terms;
  std::array<IlluminationTerms, 3> Vertices; // gouraud: the equation at each vertex
  // With a normal map, the normal it gave where the rule lit: phong's at
  // the fragment, flat's at the provoking vertex (Mapped), gouraud's at
  // each vertex (VerticesMapped). Empty where the normal had no length.
  std::optional<NormalMapping> Mapped;
  std::array<std::optional<NormalMapping>, 3> VerticesMapped;
};

/**
 * Shades fragment f under rule: none gives kd; flat ShadeFlat; gouraud
 * ShadeVertex at each vertex, mixed by the weights; phong ShadeFragment with
 * the interpolated normal, falling back to the face normal turned towards
 * the viewer. Back faces light with their normals flipped. With VertexKd,
 * each vertex that lights uses its own kd (flat the provoking vertex's),
 * none and phong the weights' mix of them. With a texture, every rule looks
 * it up per fragment, at the weights' mix of the texture coordinates: none
 * and phong light with kd and ka times the texel; flat and gouraud light
 * their vertices with the factors alone and multiply the ambient and the
 * diffuse terms they give (mixed, for gouraud) by the texel. A ks texture
 * likewise: phong lights with the texel's ks (SurfaceTexture::TexelKs),
 * flat and gouraud light with ks = 1 and multiply the specular terms by
 * it. The equation is linear in kd, ka and ks, so that is the equation with kd and ka textured
 * where the rule evaluates it, the texture itself seen per fragment. An
 * environment's ks*E(R) goes with the specular terms: E(R) where the rule
 * lights (gouraud's mixed from its vertices, flat's at the provoking
 * vertex), times the ks that lights. A normal map perturbs the normal
 * where the rule takes it: phong's unit interpolated normal with the
 * weights' mix of the tangents and the texel at the fragment; gouraud's at
 * each vertex with its tangent and its texel; flat's face normal with the
 * provoking vertex's tangent and texel. The perturbed normal then lights as
 * the normal would (back faces flipped).
 */
ShadedFragment ShadeTriangleFragment(
  const IlluminationInputs& in, Shading rule, const TriangleFragment& f);

/**
 * The terms mixed by weights w: every vector, number and colour; a flag
 * set where any vertex's is.
 */
IlluminationTerms MixTerms(
  const std::array<IlluminationTerms, 3>& terms, const std::array<double, 3>& w);
}

#endif
