// Rays through pixels (filters/groundtruth/shadelabPixelRays) against VTK's
// own camera: a world point that vtkCamera projects to picture point (x, y)
// lies on the ray through (x, y), for perspective and orthographic cameras
// turned and zoomed as the command line does; the triangle met, its
// barycentric weights and the distance to the nearest edge that may cover
// the pixel.
#include "shadelabPixelRays.h"
#include "shadelabVec3.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace shadelab;
using namespace shadelab::vec3;

namespace
{
// Where vtkCamera puts world point p in a width x height picture: its
// composite projection, then the viewport, y from the top.
std::array<double, 2> VtkPicturePoint(vtkCamera* c, int width, int height, const Vec3& p)
{
  vtkMatrix4x4* m =
    c->GetCompositeProjectionTransformMatrix(static_cast<double>(width) / height, -1, 1);
  const double in[4] = { p[0], p[1], p[2], 1 };
  double out[4];
  m->MultiplyPoint(in, out);
  return { (out[0] / out[3] + 1) * width / 2, (1 - out[1] / out[3]) * height / 2 };
}

// Distance from p to the line of ray.
double OffRay(const Ray& ray, const Vec3& p)
{
  const Vec3 d = p - ray.Origin;
  return length(d - dot(d, ray.Direction) * ray.Direction);
}
}

// The cameras the command line makes: default, orthographic, narrow and
// wide pictures, turned and zoomed; 1e-12 of the scene's size is double
// rounding through the two routes (the matrix and the ray).
TEST(PixelRays, PassThroughWhatVtkCameraProjectsThere)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (bool orthographic : { false, true })
  {
    for (const auto& [width, height] : { std::pair{ 640, 480 }, std::pair{ 300, 700 } })
    {
      vtkNew<vtkCamera> camera;
      camera->SetPosition(0.3, 0.4, 6);
      camera->SetFocalPoint(0.1, -0.2, 0.05);
      camera->SetViewUp(0.1, 1, 0);
      camera->OrthogonalizeViewUp();
      camera->SetViewAngle(25);
      camera->SetParallelProjection(orthographic);
      camera->SetParallelScale(1.3);
      camera->Azimuth(20);
      camera->Elevation(-10);
      camera->OrthogonalizeViewUp();
      camera->Zoom(1.5);
      const PinholeCamera pinhole = PinholeCameraOf(camera);
      for (int i = 0; i < 200; ++i)
      {
        const Vec3 p{ u(random), u(random), u(random) };
        const auto [x, y] = VtkPicturePoint(camera, width, height, p);
        const Ray ray = PictureRay(pinhole, width, height, x, y);
        ASSERT_LT(OffRay(ray, p), 1e-12) << "orthographic " << orthographic << " point " << i;
        ASSERT_NEAR(length(ray.Direction), 1, 1e-15);
      }
    }
  }
}

TEST(PixelRays, TriangleWeightsAndInside)
{
  const Vec3 a{ 0, 0, 0 }, b{ 2, 0, 0 }, c{ 0, 2, 1 };
  const Vec3 target = 0.2 * a + 0.5 * b + 0.3 * c;
  const Ray ray{ { 3, -1, 5 }, normalize(target - Vec3{ 3, -1, 5 }) };
  const TriangleHit hit = IntersectTriangle(ray, a, b, c);
  EXPECT_TRUE(hit.Inside);
  EXPECT_NEAR(hit.Weights[0], 0.2, 1e-15);
  EXPECT_NEAR(hit.Weights[1], 0.5, 1e-15);
  EXPECT_NEAR(hit.Weights[2], 0.3, 1e-15);
  EXPECT_NEAR(hit.T, length(target - ray.Origin), 1e-14);
  // Outside, behind the ray's origin, of no area.
  EXPECT_FALSE(
    IntersectTriangle({ { 3, -1, 5 }, normalize(Vec3{ 5, 5, 0 } - Vec3{ 3, -1, 5 }) }, a, b, c)
      .Inside);
  EXPECT_FALSE(IntersectTriangle({ { 3, -1, 5 }, -ray.Direction }, a, b, c).Inside);
  EXPECT_FALSE(IntersectTriangle(ray, a, b, 2 * b).Inside);
}

// An orthographic camera on +Z whose pixels are unit squares (a 100x100
// picture of [-50, 50]^2): a triangle's edges are where they are drawn.
TEST(PixelRays, NearestTriangleAndItsEdgeDistance)
{
  PinholeCamera camera;
  camera.Position = { 0, 0, 10 };
  camera.Orthographic = true;
  camera.ParallelScale = 50;
  // Triangle 0 at z = 0 covers y >= x of [-40, 40]^2 (picture x and y in
  // [10, 90]); triangle 1, nearer, a small one over picture x in [30, 40]
  // and y in [40, 50]; triangle 2, farther and clockwise, over most of the
  // picture.
  const std::vector<Vec3> points{ { -40, 40, 0 }, { 40, 40, 0 }, { -40, -40, 0 }, { -20, 0, 1 },
    { -10, 0, 1 }, { -20, 10, 1 }, { -50, 50, -1 }, { 150, 50, -1 }, { -50, -150, -1 } };
  const std::vector<TriangleCorners> triangles{ { 0, 2, 1 }, { 3, 4, 5 }, { 6, 7, 8 } };
  const PictureTriangles picture(camera, 100, 100, points, triangles);

  // Picture point (30, 20): on triangle 0, 10 pixels from its top edge;
  // triangle 1 is 20 pixels away, triangle 2 is behind.
  PictureTriangles::Hit hit = picture.Under(30, 20);
  EXPECT_EQ(hit.Triangle, 0);
  EXPECT_TRUE(hit.Front);
  EXPECT_NEAR(hit.EdgeDistance, 10, 1e-12);
  const Vec3 on =
    hit.Weights[0] * points[0] + hit.Weights[1] * points[2] + hit.Weights[2] * points[1];
  EXPECT_NEAR(on[0], -20, 1e-12);
  EXPECT_NEAR(on[1], 30, 1e-12);
  // Picture point (29, 45): triangle 0, whose neighbour in front, triangle
  // 1, has an edge one pixel away.
  hit = picture.Under(29, 45);
  EXPECT_EQ(hit.Triangle, 0);
  EXPECT_NEAR(hit.EdgeDistance, 1, 1e-12);
  // Picture point (32, 45): triangle 1 itself, 2 pixels from its left edge.
  hit = picture.Under(32, 45);
  EXPECT_EQ(hit.Triangle, 1);
  EXPECT_NEAR(hit.EdgeDistance, 2, 1e-12);
  // Picture point (55, 50): triangle 2, farther; triangle 0's diagonal,
  // 5/sqrt(2) pixels away, may cover it.
  hit = picture.Under(55, 50);
  EXPECT_EQ(hit.Triangle, 2);
  EXPECT_FALSE(hit.Front);
  EXPECT_NEAR(hit.EdgeDistance, 5 / std::sqrt(2), 1e-12);
  // Nothing below: the edge distance to the nearest of any triangle.
  const PictureTriangles alone(camera, 100, 100, points, { triangles[0] });
  hit = alone.Under(5, 50);
  EXPECT_EQ(hit.Triangle, -1);
  EXPECT_NEAR(hit.EdgeDistance, 5, 1e-12);
}
