// The ground truth of the accuracy measurements: the analytic
// surfaces' rays and normals, their tessellations, and the exact picture.
#include "shadelabAnalyticSurface.h"
#include "shadelabExactImage.h"
#include "shadelabVec3.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace shadelab::vec3;
using shadelab::AnalyticSurface;
using shadelab::Vec3;

namespace
{
const AnalyticSurface Sphere(AnalyticSurface::Kind::Sphere);
const AnalyticSurface Torus(AnalyticSurface::Kind::Torus);

// The distance from p to the surface, from its definition.
double Distance(const AnalyticSurface& s, const Vec3& p)
{
  if (s.GetKind() == AnalyticSurface::Kind::Sphere)
  {
    return length(p) - 1;
  }
  return std::hypot(std::hypot(p[0], p[1]) - 1, p[2]) - AnalyticSurface::MinorRadius;
}

void ExpectNear(const Vec3& a, const Vec3& b, double tolerance)
{
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(a[k], b[k], tolerance) << "component " << k;
  }
}
}

TEST(AnalyticSurface, KnownRaysHitWhereGeometrySays)
{
  auto hit = Sphere.Intersect({ 0, 0, 5 }, { 0, 0, -1 });
  ASSERT_TRUE(hit.Hit);
  EXPECT_DOUBLE_EQ(hit.T, 4);
  ExpectNear(hit.Normal, { 0, 0, 1 }, 1e-15);

  hit = Torus.Intersect({ 0, -5, 0 }, { 0, 1, 0 }); // the outer equator
  ASSERT_TRUE(hit.Hit);
  EXPECT_NEAR(hit.T, 5 - 1.4, 1e-12);
  ExpectNear(hit.Normal, { 0, -1, 0 }, 1e-12);

  hit = Torus.Intersect({ 1, 0, 5 }, { 0, 0, -1 }); // the top of the tube
  ASSERT_TRUE(hit.Hit);
  EXPECT_NEAR(hit.T, 5 - 0.4, 1e-12);
  ExpectNear(hit.Normal, { 0, 0, 1 }, 1e-12);

  EXPECT_FALSE(Torus.Intersect({ 0, 0, 5 }, { 0, 0, -1 }).Hit);  // through the hole
  EXPECT_FALSE(Sphere.Intersect({ 0, 0, 5 }, { 0, 0, 1 }).Hit);  // away from it
  EXPECT_FALSE(Sphere.Intersect({ 2, 0, 5 }, { 0, 0, -1 }).Hit); // beside it
}

TEST(AnalyticSurface, RandomRaysMeetTheSurfaceFirstWhereTheyHit)
{
  std::mt19937 random(6);
  std::uniform_real_distribution<double> uniform(-1, 1);
  for (const AnalyticSurface* s : { &Sphere, &Torus })
  {
    int hits = 0;
    for (int n = 0; n < 2000; ++n)
    {
      const Vec3 origin = 4.0 * normalize({ uniform(random), uniform(random), uniform(random) });
      const Vec3 target{ 1.2 * uniform(random), 1.2 * uniform(random), 0.5 * uniform(random) };
      const Vec3 direction = normalize(target - origin);
      const auto hit = s->Intersect(origin, direction);
      // Before the hit (or along the whole ray on a miss) the ray stays outside.
      const double end = hit.Hit ? hit.T : 8;
      for (int k = 0; k < 400; ++k)
      {
        const double t = end * k / 400.0;
        ASSERT_GT(Distance(*s, origin + t * direction), -1e-9)
          << s->GetName() << " ray " << n << " passes inside before t = " << end;
      }
      if (!hit.Hit)
      {
        continue;
      }
      ++hits;
      EXPECT_LT(std::abs(Distance(*s, hit.Point)), 1e-12) << s->GetName() << " ray " << n;
      EXPECT_NEAR(length(hit.Normal), 1, 1e-15);
      EXPECT_LT(dot(hit.Normal, direction), 0) << "the first hit faces the ray";
    }
    EXPECT_GT(hits, 500) << s->GetName();
  }
}

TEST(AnalyticSurface, TessellationsAreClosedOutwardAndOnTheSurface)
{
  for (const AnalyticSurface* s : { &Sphere, &Torus })
  {
    long long previous = 0;
    for (int level = 0; level < 4; ++level)
    {
      auto mesh = s->Tessellate(level);
      ASSERT_EQ(mesh->GetNumberOfPolys(), s->TriangleCount(level)) << s->GetName();
      EXPECT_GE(s->TriangleCount(level), 4 * previous);
      previous = s->TriangleCount(level);
      // Euler characteristic V - E + F: 2 for the sphere, 0 for the torus,
      // with E = 3F/2 for a closed triangle mesh.
      const long long v = mesh->GetNumberOfPoints(), f = mesh->GetNumberOfPolys();
      EXPECT_EQ(v - 3 * f / 2 + f, s->GetKind() == AnalyticSurface::Kind::Sphere ? 2 : 0);
      for (vtkIdType p = 0; p < mesh->GetNumberOfPoints(); ++p)
      {
        Vec3 x;
        mesh->GetPoint(p, x.data());
        ASSERT_LT(std::abs(Distance(*s, x)), 2e-7) << "float points on the surface";
      }
      auto ids = vtkSmartPointer<vtkIdList>::New();
      for (vtkIdType c = 0; c < mesh->GetNumberOfPolys(); ++c)
      {
        mesh->GetCellPoints(c, ids);
        Vec3 a, b, d;
        mesh->GetPoint(ids->GetId(0), a.data());
        mesh->GetPoint(ids->GetId(1), b.data());
        mesh->GetPoint(ids->GetId(2), d.data());
        const Vec3 centroid = (1.0 / 3) * (a + b + d);
        ASSERT_GT(dot(cross(b - a, d - a), s->Normal(centroid)), 0)
          << s->GetName() << " triangle " << c << " faces inwards";
      }
    }
  }
}

TEST(ExactImage, PixelsAreTheEquationAtTheRaysHits)
{
  shadelab::PinholeCamera camera;
  camera.Position = { 0, 0, 5 };
  camera.ViewAngle = 30;
  shadelab::IlluminationInputs in;
  in.Surface = *shadelab::FindLectureMaterial("gold");
  in.Ambient = { 0.2, 0.2, 0.2 };
  shadelab::FrameLight light;
  light.Position = { -3, 3, 5 };
  in.Lights = { light };
  const int width = 64, height = 48;
  const auto image = shadelab::RenderExactImage(Sphere, camera, width, height, in);
  ASSERT_EQ(image.Rgb.size(), 3u * width * height);

  // The disc's area: the sphere subtends asin(1/5) of a 15-degree half view.
  const double radiusPx =
    std::tan(std::asin(0.2)) / std::tan(15 * 3.14159265358979323846 / 180) * height / 2;
  int covered = 0;
  for (unsigned char c : image.Covered)
  {
    covered += c;
  }
  EXPECT_NEAR(covered, 3.14159265358979323846 * radiusPx * radiusPx, 2 * 3.1416 * radiusPx);

  // Pixel (40, 30): its ray by hand, its colour from the equation.
  const double t = std::tan(15 * 3.14159265358979323846 / 180);
  const Vec3 direction =
    normalize({ (2 * 40.5 / width - 1) * t * width / height, (2 * 30.5 / height - 1) * t, -1 });
  const auto hit = Sphere.Intersect(camera.Position, direction);
  ASSERT_TRUE(hit.Hit);
  in.Eye = camera.Position;
  const auto expected = shadelab::Illuminate(in, hit.Point, hit.Normal);
  const std::size_t p = 30 * width + 40;
  ASSERT_TRUE(image.Covered[p]);
  for (int k = 0; k < 3; ++k)
  {
    EXPECT_NEAR(image.Rgb[3 * p + k], expected[k], 1e-14);
  }
  EXPECT_FALSE(image.Covered[0]);
  EXPECT_EQ(image.Rgb[0], 0);
}
