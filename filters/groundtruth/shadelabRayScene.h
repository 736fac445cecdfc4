// A triangle mesh that rays are cast into in double precision: the first
// triangle a ray meets, and whether any triangle lies between a surface
// point and a light (the oracle's shadow rays). Embree's bounding-volume
// hierarchy finds the candidates; each candidate is tested in double
// (IntersectTriangle), so the answers are those of testing every triangle,
// in a time that grows with the logarithm of the triangle count.
#ifndef shadelabRayScene_h
#define shadelabRayScene_h

#include "shadelabIllumination.h"
#include "shadelabPixelRays.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace shadelab
{
/**
 * How far along its normal a surface point moves before its shadow ray
 * leaves, as a share of the mesh's bounding-box diagonal: far enough that
 * the ray cannot meet the point's own triangle or a neighbour in the same
 * plane again at any scale (double's rounding at the point is ~1e-16 of its
 * coordinates), near enough that no occluder thinner than this is skipped.
 */
constexpr double ShadowRayOffset = 1e-9;

class RayScene
{
public:
  /** The mesh, in world coordinates: its points and its triangles' corners. */
  RayScene(std::vector<Vec3> points, std::vector<TriangleCorners> triangles);
  ~RayScene();
  RayScene(const RayScene&) = delete;
  RayScene& operator=(const RayScene&) = delete;

  struct Hit
  {
    std::int64_t Triangle = -1; // -1: none
    double T = 0;               // the point is origin + T * direction
    std::array<double, 3> Weights{};
  };

  /**
   * The triangle ray meets first with T in (tMin, tMax]; at the same T, the
   * first in the mesh's order. Exactly what testing every triangle with
   * IntersectTriangle gives.
   */
  Hit First(const Ray& ray, double tMin = 0, double tMax = HUGE_VAL) const;

  /** IntersectTriangle of ray with the mesh's triangle t: the double test behind every answer. */
  TriangleHit Intersect(const Ray& ray, std::int64_t t) const;

  /** Whether ray meets any triangle with T in (tMin, tMax]. */
  bool Blocked(const Ray& ray, double tMin = 0, double tMax = HUGE_VAL) const;

  /**
   * Whether light reaches point, a point of the mesh whose surface faces
   * the side `normal` (unit) points to: the shadow ray, from the point moved
   * ShadowRayOffset of the diagonal along the normal, towards the light (a
   * point or spot light's position, against a directional light's
   * direction) meets no triangle before the light. A light on the other side
   * of the surface than the normal does not reach it.
   */
  bool LightReaches(const Vec3& point, const Vec3& normal, const Light& light) const;

  /** The bounding box's diagonal, world units. */
  double Diagonal() const { return this->Size; }

  const std::vector<Vec3>& GetPoints() const { return this->Points; }
  const std::vector<TriangleCorners>& GetTriangles() const { return this->Triangles; }

private:
  struct Embree;
  // Casts ray into the hierarchy, each candidate triangle tested by test,
  // which returns the T beyond which no further candidate counts (-inf:
  // stop); any: Embree's occlusion query, else its nearest-hit query.
  void Cast(const Ray& ray, double tMin, double tMax,
    const std::function<double(std::int64_t)>& test, bool any) const;

  std::vector<Vec3> Points;
  std::vector<TriangleCorners> Triangles;
  Vec3 Centre{};
  double Size = 0;
  std::unique_ptr<Embree> Bvh;
};
}

#endif
