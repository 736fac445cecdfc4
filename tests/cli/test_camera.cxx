// Camera math: pictures whose covered pixels can be predicted.
#include "cli_test_support.h"

#include <vtkNew.h>
#include <vtkSphereSource.h>
#include <vtkXMLPolyDataWriter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace shadelab_test;

namespace
{
constexpr double Pi = 3.14159265358979323846;

void WriteSphere(const std::filesystem::path& path)
{
  vtkNew<vtkSphereSource> sphere; // unit radius, centred at the origin
  sphere->SetRadius(1);
  sphere->SetThetaResolution(512);
  sphere->SetPhiResolution(256);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(sphere->GetOutputPort());
  writer->SetFileName(path.c_str());
  ASSERT_EQ(writer->Write(), 1);
}

// Silhouette radius in pixels of a unit sphere seen from distance d with a
// vertical view angle a in an image h pixels high: the silhouette cone's
// half-angle is asin(1/d), and a direction at angle t off the axis lands
// (h/2) tan(t) / tan(a/2) pixels from the centre.
double PredictedRadius(double d, double angleDeg, int h)
{
  return h / 2.0 * std::tan(std::asin(1 / d)) / std::tan(angleDeg * Pi / 360);
}
}

// Orthographic, parallel scale S, image W x H: world x lands on column
// W/2 + x*H/(2S) and world y on row H/2 - y*H/(2S), rows counted from the
// top. The rectangle's edges fall on pixel boundaries, where OpenGL's rule (a
// pixel is covered when its centre is inside) leaves half a pixel of margin
// either way, so the covered set is predicted exactly; being off-centre, it
// also checks that up is up and right is right.
TEST(Camera, OrthographicRectangleCoversExactlyThePredictedPixels)
{
  TempDir dir;
  // x from 0.2 to 1.5, y from -0.5 to 0.3; at 50 pixels per unit that is
  // columns [110, 175) and rows [35, 75).
  WriteText(dir / "rect.obj", "v 0.2 -0.5 0\nv 1.5 -0.5 0\nv 1.5 0.3 0\nv 0.2 0.3 0\nf 1 2 3 4\n");
  const RunResult r = RunShadelab(
    { "render", (dir / "rect.obj").string(), "-o", (dir / "rect.png").string(), "--size", "200x100",
      "--shading", "none", "--kd", "1,1,1", "--orthographic", "--parallel-scale", "1",
      "--camera-position", "0,0,5", "--camera-focal-point", "0,0,0", "--camera-view-up", "0,1,0" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const Image image = ReadImage(dir / "rect.png");
  ASSERT_EQ(image.Width, 200);
  ASSERT_EQ(image.Height, 100);
  int wrong = 0;
  std::ostringstream first;
  for (int y = 0; y < 100; ++y)
  {
    for (int x = 0; x < 200; ++x)
    {
      const bool expected = x >= 110 && x < 175 && y >= 35 && y < 75;
      const bool covered = image.Pixels[(static_cast<size_t>(y) * 200 + x) * 3] > 0;
      if (expected != covered && wrong++ == 0)
      {
        first << "pixel (" << x << ", " << y << ") covered=" << covered;
      }
    }
  }
  EXPECT_EQ(wrong, 0) << first.str();
}

// Perspective: the covered area A gives the silhouette radius sqrt(A/pi).
// Tolerance 0.25 pixel: the 512x256 tessellation sits inside the sphere by at
// most 1 - cos(pi/256) of its radius (0.015 pixel here), and counting pixel
// centres inside a circle of radius ~190 misjudges its area by a few dozen
// pixels at most, under 0.05 pixel of radius; a wrong view angle or distance
// convention is off by several pixels.
TEST(Camera, PerspectiveSphereHasThePredictedSilhouetteRadius)
{
  TempDir dir;
  WriteSphere(dir / "sphere.vtp");
  const RunResult r = RunShadelab({ "render", (dir / "sphere.vtp").string(), "-o",
    (dir / "sphere.png").string(), "--size", "400x400", "--shading", "none", "--kd", "1,1,1",
    "--camera-position", "0,0,4", "--camera-focal-point", "0,0,0", "--view-angle", "30" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const double measured = std::sqrt(CountCovered(ReadImage(dir / "sphere.png")) / Pi);
  EXPECT_NEAR(measured, PredictedRadius(4, 30, 400), 0.25);
}

// No camera options: the bounding sphere of the box [-1,1]^3 (radius sqrt 3)
// is fitted into the narrower view angle, so the camera stands
// sqrt(3)/sin(15 deg) away along +Z; in a wide picture the vertical angle is
// the narrower one.
TEST(Camera, FittedCameraFramesTheBoundingSphere)
{
  TempDir dir;
  WriteSphere(dir / "sphere.vtp");
  const RunResult r = RunShadelab({ "render", (dir / "sphere.vtp").string(), "-o",
    (dir / "fit.png").string(), "--size", "600x300", "--shading", "none", "--kd", "1,1,1" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const double distance = std::sqrt(3.0) / std::sin(15 * Pi / 180);
  const double measured = std::sqrt(CountCovered(ReadImage(dir / "fit.png")) / Pi);
  EXPECT_NEAR(measured, PredictedRadius(distance, 30, 300), 0.25);
}

// A tall perspective picture: the horizontal half-angle, atan(tan(15 deg) *
// width/height), is the narrower one, and the bounding sphere is fitted to it.
TEST(Camera, FittedCameraUsesTheNarrowerAngleInATallPicture)
{
  TempDir dir;
  WriteSphere(dir / "sphere.vtp");
  const RunResult r = RunShadelab({ "render", (dir / "sphere.vtp").string(), "-o",
    (dir / "tall.png").string(), "--size", "300x600", "--shading", "none", "--kd", "1,1,1" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const double narrowHalfAngle = std::atan(std::tan(15 * Pi / 180) * 0.5);
  const double distance = std::sqrt(3.0) / std::sin(narrowHalfAngle);
  const double measured = std::sqrt(CountCovered(ReadImage(dir / "tall.png")) / Pi);
  EXPECT_NEAR(measured, PredictedRadius(distance, 30, 600), 0.25);
}

// A tall picture: the horizontal angle is the narrower one and holds the
// sphere, and the orthographic fit makes the parallel scale radius/aspect.
TEST(Camera, FittedOrthographicCameraHoldsTheSphereInATallPicture)
{
  TempDir dir;
  WriteSphere(dir / "sphere.vtp");
  const RunResult r =
    RunShadelab({ "render", (dir / "sphere.vtp").string(), "-o", (dir / "tall.png").string(),
      "--size", "200x400", "--shading", "none", "--kd", "1,1,1", "--orthographic" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  // Parallel scale sqrt(3)/0.5: 400 pixels span 2*sqrt(3)/0.5 world units.
  const double pixelsPerUnit = 400 / (2 * std::sqrt(3.0) / 0.5);
  const double measured = std::sqrt(CountCovered(ReadImage(dir / "tall.png")) / Pi);
  EXPECT_NEAR(measured, pixelsPerUnit, 0.25);
}

// Looking straight down, the default view-up (+Y) is along the view
// direction; the documented fallback is -Z at the top of the picture. A
// rectangle on the far side (z < 0) must then appear in the top half.
TEST(Camera, ViewFromAboveFallsBackToMinusZUp)
{
  TempDir dir;
  WriteText(dir / "far.obj", "v -0.5 0 -1\nv 0.5 0 -1\nv 0.5 0 -0.2\nv -0.5 0 -0.2\nf 1 2 3 4\n");
  const RunResult r =
    RunShadelab({ "render", (dir / "far.obj").string(), "-o", (dir / "above.png").string(),
      "--size", "100x100", "--shading", "none", "--kd", "1,1,1", "--orthographic",
      "--parallel-scale", "1", "--camera-position", "0,5,0", "--camera-focal-point", "0,0,0" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const Image image = ReadImage(dir / "above.png");
  size_t top = 0, bottom = 0;
  for (int y = 0; y < 100; ++y)
  {
    for (int x = 0; x < 100; ++x)
    {
      (y < 50 ? top : bottom) += image.Pixels[(static_cast<size_t>(y) * 100 + x) * 3] > 0;
    }
  }
  // z from -1 to -0.2 at 50 pixels per unit, -Z up: rows [0, 40), 50 columns.
  EXPECT_EQ(top, 40u * 50u);
  EXPECT_EQ(bottom, 0u);
}
