// Surfaces known exactly (a sphere, a torus): the ground truth of the
// speed-accuracy measurements. Rays meet them in double precision with the
// exact normal, and they tessellate at any density with every vertex on the
// surface, so the only difference between a tessellation's picture and the
// exact one is what tessellation, interpolation and float arithmetic cost.
#ifndef shadelabAnalyticSurface_h
#define shadelabAnalyticSurface_h

#include "shadelabIllumination.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace shadelab
{
struct RayHit
{
  bool Hit = false;
  double T = 0; // the ray parameter: Point = origin + T * direction
  Vec3 Point{};
  Vec3 Normal{}; // unit, pointing out of the solid
};

class AnalyticSurface
{
public:
  enum class Kind
  {
    Sphere, // radius 1 about the origin
    Torus   // about the z axis through the origin: tube radius MinorRadius about a circle of 1
  };
  static constexpr double MinorRadius = 0.4;

  explicit AnalyticSurface(Kind kind)
    : Shape(kind)
  {
  }
  Kind GetKind() const { return this->Shape; }
  const char* GetName() const;

  /** The first hit of origin + t * direction (direction unit) with t > 0, if any. */
  RayHit Intersect(const Vec3& origin, const Vec3& direction) const;

  /** The outward unit normal at a point on (or near) the surface. */
  Vec3 Normal(const Vec3& point) const;

  /**
   * A closed, consistently oriented triangle mesh with float points on the
   * surface and no normals. Level 0 has about 100 triangles and each
   * level four times as many: the sphere is an icosahedron subdivided
   * level + 1 times (80 * 4^level triangles), the torus a grid of
   * 12 * 2^level steps around its axis by 5 * 2^level around the tube
   * (120 * 4^level triangles), whose cells are as near square as such a
   * grid gets (12:5 against the radii's 2.5:1).
   */
  vtkSmartPointer<vtkPolyData> Tessellate(int level) const;

  /** The number of triangles Tessellate(level) makes. */
  long long TriangleCount(int level) const;

private:
  Kind Shape;
};
}

#endif
