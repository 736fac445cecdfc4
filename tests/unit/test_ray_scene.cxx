// The oracle's rays: Embree's hierarchy must change nothing but the time.
// Every answer equals testing every triangle (IntersectTriangle) exactly,
// for rays at random, rays aimed at the corners and edges (where a pruned
// candidate would show), and from far away, at every scale; and the shadow
// rays of a quad over a plane, a torus shading itself and a mesh lit from
// behind fall where geometry says.
#include "shadelabRayScene.h"
#include "shadelabVec3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace shadelab;
using namespace shadelab::vec3;

namespace
{
struct Mesh
{
  std::vector<Vec3> Points;
  std::vector<TriangleCorners> Triangles;
};

// A torus about z of radii r (tube) and big, around by tube triangles' pairs.
Mesh Torus(double big, double r, int around, int tube)
{
  Mesh m;
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < tube; ++j)
    {
      const double u = 2 * M_PI * i / around, v = 2 * M_PI * j / tube;
      m.Points.push_back({ (big + r * std::cos(v)) * std::cos(u),
        (big + r * std::cos(v)) * std::sin(u), r * std::sin(v) });
      const auto at = [&](int a, int b) { return (a % around) * tube + (b % tube); };
      m.Triangles.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      m.Triangles.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  }
  return m;
}

// The plane z = 0 as two triangles of half-size 10, and a quad of half-size
// q at height z above it, facing up.
Mesh PlaneAndQuad(double q, double z)
{
  Mesh m;
  m.Points = { { -10, -10, 0 }, { 10, -10, 0 }, { 10, 10, 0 }, { -10, 10, 0 }, { -q, -q, z },
    { q, -q, z }, { q, q, z }, { -q, q, z } };
  m.Triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 4, 5, 6 }, { 4, 6, 7 } };
  return m;
}

Mesh Scaled(Mesh m, double scale, const Vec3& shift)
{
  for (Vec3& p : m.Points)
  {
    p = scale * p + shift;
  }
  return m;
}

// Every triangle tested: the answer the hierarchy must give.
RayScene::Hit BruteFirst(const Mesh& m, const Ray& ray)
{
  RayScene::Hit first;
  first.T = HUGE_VAL;
  for (std::size_t t = 0; t < m.Triangles.size(); ++t)
  {
    const TriangleCorners& c = m.Triangles[t];
    const TriangleHit h = IntersectTriangle(ray, m.Points[c[0]], m.Points[c[1]], m.Points[c[2]]);
    if (h.Inside && h.T < first.T)
    {
      first = { static_cast<std::int64_t>(t), h.T, h.Weights };
    }
  }
  return first;
}

// Rays at random through the mesh's box and aimed at its corners and edge
// midpoints (from origins spread over `reach` around the centre): the
// hierarchy's first hit and occlusion against every triangle's.
void ExpectSameAsEveryTriangle(const Mesh& m, double reach, int rays)
{
  const RayScene scene(m.Points, m.Triangles);
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(-1, 1);
  Vec3 centre{};
  for (const Vec3& p : m.Points)
  {
    centre = centre + (1.0 / m.Points.size()) * p;
  }
  int hits = 0;
  for (int i = 0; i < rays; ++i)
  {
    const Vec3 origin = centre + reach * Vec3{ unit(random), unit(random), unit(random) };
    const TriangleCorners& c = m.Triangles[random() % m.Triangles.size()];
    Vec3 target;
    switch (i % 3)
    {
      case 0: // a corner
        target = m.Points[c[0]];
        break;
      case 1: // an edge's midpoint
        target = 0.5 * (m.Points[c[0]] + m.Points[c[1]]);
        break;
      default: // inside
        target = (1.0 / 3) * (m.Points[c[0]] + m.Points[c[1]] + m.Points[c[2]]);
        break;
    }
    const Ray ray{ origin, normalize(target - origin) };
    const RayScene::Hit expected = BruteFirst(m, ray);
    const RayScene::Hit got = scene.First(ray);
    ASSERT_EQ(got.Triangle, expected.Triangle) << "ray " << i;
    if (expected.Triangle >= 0)
    {
      ++hits;
      EXPECT_EQ(got.T, expected.T) << "ray " << i;
      EXPECT_EQ(got.Weights, expected.Weights) << "ray " << i;
      EXPECT_TRUE(scene.Blocked(ray, 0, expected.T));
      EXPECT_FALSE(scene.Blocked(ray, 0, std::nextafter(expected.T, 0.0)));
    }
    else
    {
      EXPECT_FALSE(scene.Blocked(ray));
    }
  }
  EXPECT_GT(hits, rays / 2) << "the rays are aimed at the mesh";
}
}

TEST(RayScene, FirstHitsAndBlocksAsTestingEveryTriangleAtEveryScale)
{
  const Mesh torus = Torus(1, 0.3, 48, 24);
  for (const double scale : { 1e-6, 1.0, 1e6 })
  {
    SCOPED_TRACE(scale);
    // Near the torus, and far from it (as a camera 1e4 sizes away).
    ExpectSameAsEveryTriangle(Scaled(torus, scale, {}), 2 * scale, 600);
    ExpectSameAsEveryTriangle(Scaled(torus, scale, { 3 * scale, 0, 0 }), 1e4 * scale, 300);
  }
}

TEST(RayScene, TheNearestOfTwoTrianglesAtTheSameDistanceIsTheFirstInTheMesh)
{
  // The same triangle twice: at the same T, the first counts.
  const Mesh m{ { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, { { 0, 1, 2 }, { 0, 2, 1 } } };
  const RayScene scene(m.Points, m.Triangles);
  const RayScene::Hit hit = scene.First({ { 0.25, 0.25, 1 }, { 0, 0, -1 } });
  EXPECT_EQ(hit.Triangle, 0);
  EXPECT_EQ(hit.T, 1);
  EXPECT_EQ(scene.First({ { 0.25, 0.25, 1 }, { 0, 0, -1 } }, 1).Triangle, -1)
    << "T in (tMin, tMax]";
}

TEST(RayScene, AQuadShadowsThePlaneWhereItsCentralProjectionFallsUnderEachLightAtEveryScale)
{
  // The quad (half-size 1 at height 1) under a point light at height 4: its
  // shadow on the plane has half-size 4/3; under a light straight down, 1.
  // Spot lights cast as point lights (the cone is shading's, not visibility's).
  const Vec3 up{ 0, 0, 1 };
  for (const double scale : { 1e-6, 1.0, 1e6 })
  {
    SCOPED_TRACE(scale);
    const Mesh m = Scaled(PlaneAndQuad(1, 1), scale, { 0, 0, 0 });
    const RayScene scene(m.Points, m.Triangles);
    Light point;
    point.Position = scale * Vec3{ 0, 0, 4 };
    Light spot = point;
    spot.Kind = LightKind::Spot;
    spot.Direction = { 0, 0, -1 };
    spot.HalfAngleDeg = 80;
    Light directional;
    directional.Kind = LightKind::Directional;
    directional.Direction = { 0, 0, -1 };
    const std::pair<const Light*, double> lights[] = { { &point, 4.0 / 3 }, { &spot, 4.0 / 3 },
      { &directional, 1 } };
    for (const auto& [light, half] : lights)
    {
      SCOPED_TRACE(ToString(light->Kind));
      for (const double x : { 0.0, 0.5 * half, (1 - 1e-6) * half })
      {
        EXPECT_FALSE(scene.LightReaches(scale * Vec3{ x, 0.3, 0 }, up, *light)) << x;
      }
      for (const double x : { (1 + 1e-6) * half, 2 * half, 5.0 })
      {
        EXPECT_TRUE(scene.LightReaches(scale * Vec3{ x, 0.3, 0 }, up, *light)) << x;
      }
      // The quad's own top is lit: its shadow ray leaves it, not meets it.
      EXPECT_TRUE(scene.LightReaches(scale * Vec3{ 0.2, 0.1, 1 }, up, *light));
      // Beneath, a light that shines on the other side does not reach it.
      EXPECT_FALSE(scene.LightReaches(scale * Vec3{ 5, 0, 0 }, -up, *light));
    }
    // A light in the surface's plane grazes it: it does not light it (the
    // equation's N.L is 0), whatever the ray from just above meets.
    Light grazing = directional;
    grazing.Direction = { -1, 0, 0 };
    EXPECT_FALSE(scene.LightReaches(scale * Vec3{ 5, 0.3, 0 }, up, grazing));
    // A point light between the plane and the quad: the quad, beyond it,
    // casts nothing.
    Light under = point;
    under.Position = scale * Vec3{ 0, 0, 0.5 };
    EXPECT_TRUE(scene.LightReaches(scale * Vec3{ 0.1, 0.2, 0 }, up, under));
  }
}

TEST(RayScene, ATorusShadowsItselfAndAClosedMeshLitFromBehindIsDark)
{
  // A light far along +x: the outer rim facing it is lit; the inner rim on
  // the far side, facing +x too, looks at it through the hole and the
  // near side of the tube; the rim facing away is dark.
  const Mesh m = Torus(1, 0.3, 96, 48);
  const RayScene scene(m.Points, m.Triangles);
  Light sun;
  sun.Kind = LightKind::Directional;
  sun.Direction = { -1, 0, 0 };
  const Vec3 x{ 1, 0, 0 };
  // On the mesh: the tessellated torus's points at u = 0 and u = pi.
  EXPECT_TRUE(scene.LightReaches(m.Points[0], x, sun)) << "outer rim, facing the light";
  const Vec3 inner = m.Points[48 * 48 + 24]; // u = pi, v = pi: (-(1 - 0.3), 0, 0)
  EXPECT_NEAR(inner[0], -0.7, 1e-12);
  EXPECT_FALSE(scene.LightReaches(inner, x, sun)) << "inner rim, behind the near tube";
  EXPECT_FALSE(scene.LightReaches(m.Points[48 * 48], -x, sun)) << "outer rim, facing away";
  // Points inside the faces that look at the light from the near side
  // (their rays leave the torus for good): each shadow ray must leave its
  // own face, which rounding puts a little off the face's plane.
  int tested = 0;
  for (std::size_t t = 0; t < m.Triangles.size(); ++t)
  {
    const Vec3 &a = m.Points[m.Triangles[t][0]], &b = m.Points[m.Triangles[t][1]],
               &c = m.Points[m.Triangles[t][2]];
    Vec3 n;
    FaceNormal(a, b, c, n);
    if (a[0] > 0 && n[0] > 0.1)
    {
      for (const double w : { 0.1, 0.3, 0.45 })
      {
        const Vec3 p = w * a + (0.9 - w) * b + 0.1 * c;
        ++tested;
        EXPECT_TRUE(scene.LightReaches(p, n, sun)) << "face " << t << " at " << w;
      }
    }
  }
  EXPECT_GT(tested, 1000);
  // A light straight down reaches the tube's top.
  Light above = sun;
  above.Direction = { 0, 0, -1 };
  EXPECT_TRUE(scene.LightReaches(m.Points[12], { 0, 0, 1 }, above)) << "the tube's top";
}
