// Shadow maps for hard shadows: a point light's distance to the nearest
// surface in every direction, baked into an R32F cube map (one texel per
// direction, nearest filtering, read with textureLod) in the current OpenGL
// context. The triangles go to the GPU relative to the light, subtracted in
// double, so a stored distance is within a few float roundings of the
// oracle's ray (test_shadow_maps: 5.3e-7 relative). Drawn with MIN blending
// and no depth buffer, without near or far planes (depth clamp).
//
// The first piece of shadows: spot and directional lights' maps, and the
// generated shaders' test against them (--shadows), build on it.
#ifndef shadelabShadowMaps_h
#define shadelabShadowMaps_h

#include "shadelabPixelRays.h"

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

class PointShadowMap
{
public:
  PointShadowMap() = default;
  ~PointShadowMap();
  PointShadowMap(const PointShadowMap&) = delete;
  PointShadowMap& operator=(const PointShadowMap&) = delete;

  /**
   * Bakes the distances from light to the mesh's triangles into a size x
   * size cube map, in the current context (which the caller makes current);
   * an error text or "". Directions that meet no triangle hold FLT_MAX.
   */
  std::string Bake(const std::vector<Vec3>& points, const std::vector<TriangleCorners>& triangles,
    const Vec3& light, int size);

  /** Face f's texels, rows bottom first (the current context). */
  std::vector<float> ReadFace(int face) const;

  unsigned int GetTexture() const { return this->Texture; }
  int GetSize() const { return this->Size; }

  /** Frees the OpenGL objects (the current context). */
  void Release();

private:
  unsigned int Texture = 0, Framebuffer = 0, Program = 0, Buffer = 0, VertexArray = 0;
  int Size = 0;
};
}

#endif
