// Shadow maps for hard shadows (--shadows): each light's distance to the
// nearest surface, baked into R32F textures (one texel per direction,
// nearest filtering, no interpolation) in the current OpenGL context. The
// triangles go to the GPU relative to the map's origin, subtracted in
// double, so a stored distance is within a few float roundings of the
// oracle's ray (test_shadow_maps: 5.3e-7 relative). Drawn with MIN blending
// and no depth buffer, without near or far planes (depth clamp).
#ifndef shadelabShadowMaps_h
#define shadelabShadowMaps_h

#include "shadelabPixelRays.h"

#include <array>
#include <string>
#include <vector>

namespace shadelab
{
/** The cube's faces in OpenGL's order (+x, -x, +y, -y, +z, -z): each one's view and up. */
struct CubeFace
{
  Vec3 Forward;
  Vec3 Up;
};
extern const CubeFace CubeFaces[6];

/**
 * The unit direction through point (x, y) of face f, in texels from the
 * face's left and bottom (texel (i, j)'s centre is i + 0.5, j + 0.5), as
 * OpenGL's cube map lookup selects it.
 */
Vec3 CubeDirection(int face, double x, double y, int size);

/**
 * A light's shadow map: for a point or spot light, the distance from it to
 * the nearest triangle in every direction, a cube map around it; for a
 * directional light, the depth along its direction of the nearest triangle
 * across a square that covers the mesh, an orthographic map. In the GLSL
 * that reads it, shadelabShadowLit (shadelabIlluminateSource.cxx), a point
 * P lit with N.L is lit when its own distance d is at most the texel's plus
 * the bias, whose parts GetBias gives:
 *   x*(d + |P|): float's roundings of the distances and of P in view
 *     coordinates, relative to both (x = 1e-5);
 *   y*(1 + min(tan(angle of incidence), z)), times d for a cube: a surface
 *     that slopes across a texel is nearer at the texel's centre than at P
 *     by up to tan times the texel's half diagonal (y is twice that, the
 *     texel's angle for a cube, its side for an orthographic map); the 1
 *     covers a normal that leans off the surface (gouraud's vertex
 *     normals), z = 50 the grazing angles and a face turned from the
 *     light. The angle is the face's under phong (ShaderFeatures::
 *     SlopesByFace), the lighting normal's under gouraud and flat.
 */
class ShadowMap
{
public:
  ShadowMap() = default;
  ~ShadowMap();
  ShadowMap(const ShadowMap&) = delete;
  ShadowMap& operator=(const ShadowMap&) = delete;

  /**
   * Bakes light's map of the triangles (world coordinates), size x size
   * texels a face, in the current OpenGL context (which the caller makes
   * current); an error text or "". Texels that meet no triangle hold FLT_MAX.
   */
  std::string Bake(const std::vector<Vec3>& points, const std::vector<TriangleCorners>& triangles,
    const Light& light, int size);

  /** A cube map (point and spot lights), else a 2D one. */
  bool IsCube() const { return this->Cube; }

  /**
   * World coordinates to the map's, row-major: a cube's are relative to the
   * light (its axes the world's); an orthographic map's q.xy are in [0, 1]
   * across it, q.z the depth along the direction.
   */
  const std::array<double, 16>& GetWorldToMap() const { return this->WorldToMap; }

  /** The bias's x, y, z as the class comment says, and w the size. */
  std::array<float, 4> GetBias() const;

  /**
   * What the shaders decide (shadelabShadowLit) at world point P, the
   * bias's slope from the cosine `slopeCos` between L and the normal the
   * rule slopes by (phong: the face's; others: the one that lights),
   * `fromEye` from the camera, computed in double from the map's texels
   * (read once, in the current context): whether the light reaches P.
   */
  bool Lit(const Vec3& P, double slopeCos, double fromEye) const;

  /** Face f's texels (an orthographic map: its only one), rows bottom first. */
  std::vector<float> ReadFace(int face) const;

  unsigned int GetTexture() const { return this->Texture; }
  int GetSize() const { return this->Size; }

  /** Frees the OpenGL objects (the current context). */
  void Release();

private:
  unsigned int Texture = 0, Framebuffer = 0, Program = 0, Buffer = 0, VertexArray = 0;
  int Size = 0;
  bool Cube = true;
  std::array<double, 16> WorldToMap{};
  double Side = 0;                                // an orthographic map's, in world units
  mutable std::vector<std::vector<float>> Texels; // each face's, once Lit has read them
};
}

#endif
