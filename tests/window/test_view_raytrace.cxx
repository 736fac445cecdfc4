// The comparison layout's raytrace panel in a real window (harness:
// viewer.h): phong draws it while the camera moves, and once the camera
// rests it is ray traced and shows what `render --shading raytrace` draws
// for the panel's size and camera.
#include "viewer.h"

#include <gtest/gtest.h>

#include <string>

using namespace shadelab_test;

namespace
{
// Two panels side by side, phong | raytrace: the left or right half of a
// screenshot, below the labels and above the HUD.
Change Halves(const Image& a, bool aRight, const Image& b, bool bRight, float by)
{
  Change change;
  for (int y = 30; y < H - HudHeight; ++y)
  {
    for (int x = 0; x < W / 2; ++x)
    {
      const float* p = &a.Pixels[(static_cast<size_t>(y) * a.Width + x + (aRight ? W / 2 : 0)) * 3];
      const float* q = &b.Pixels[(static_cast<size_t>(y) * b.Width + x + (bRight ? W / 2 : 0)) * 3];
      for (int c = 0; c < 3; ++c)
      {
        const float d = std::abs(p[c] - q[c]);
        change.Largest = std::max(change.Largest, d);
        change.Pixels += d > by;
      }
    }
  }
  return change;
}
}

TEST(View, TheRaytracePanelIsPhongWhileMovingAndRaytracedAtRest)
{
  Viewer viewer({ "--compare", "--modes", "phong,raytrace" });
  ASSERT_TRUE(viewer.HasWindow()) << viewer.Stderr();
  ASSERT_FALSE(viewer.Await("shadelab: traced the raytrace panel").empty()) << viewer.Stderr();
  const Image traced = viewer.Screenshot();
  ASSERT_EQ(traced.Width, W);
  // The panel's picture is render's for the panel: 240x360, the camera
  // the window starts with (viewer.h) fitted to it. Both are the same
  // double-precision rays, quantised alike: equal, to the panel's edges.
  TempDir dir;
  const RunResult render = RunShadelab({ "render", TestMesh("teapot.obj").string(), "-o",
    (dir / "r.png").string(), "--size", std::to_string(W / 2) + "x" + std::to_string(H),
    "--camera-position", "5,5,9", "--shading", "raytrace" });
  ASSERT_EQ(render.ExitCode, 0) << render.Stderr;
  const Image rendered = ReadImage(dir / "r.png");
  const Change vsRender = Halves(traced, true, rendered, false, 0);
  EXPECT_EQ(vsRender.Pixels, 0) << "render's raytrace picture, largest " << vsRender.Largest;
  // Ray tracing adds the teapot's reflections of itself: not phong's panel.
  EXPECT_GT(Halves(traced, true, traced, false, 2).Pixels, 100) << "phong beside it";

  // While the mouse is down the panel is phong's, as the panel beside it.
  viewer.Drag(W / 4, H / 2, 40, true);
  const Image dragging = viewer.Screenshot();
  EXPECT_EQ(Halves(dragging, true, dragging, false, 0).Pixels, 0) << "phong while dragging";
  viewer.Release();
  ASSERT_FALSE(viewer.Await("shadelab: traced the raytrace panel").empty()) << viewer.Stderr();
  const Image again = viewer.Screenshot();
  EXPECT_GT(Halves(again, true, again, false, 2).Pixels, 100) << "traced again at rest";
  EXPECT_GT(Halves(again, true, traced, true, 2).Pixels, 100) << "from the turned camera";
}
