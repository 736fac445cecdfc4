// View presets about the up axis (--up, --view), and --azimuth, --elevation,
// --zoom: a box of known proportions, seen orthographically, shows the
// silhouette each preset predicts.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>

using namespace shadelab_test;

namespace
{
using V = std::array<double, 3>;

// A box 1 x 2 x 4 (X, Y, Z) about the origin: every view of it differs.
constexpr V BoxSize{ 1, 2, 4 };

V Cross(const V& a, const V& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}

// The box's extent along a unit direction w.
double Extent(const V& w)
{
  return std::fabs(w[0]) * BoxSize[0] + std::fabs(w[1]) * BoxSize[1] + std::fabs(w[2]) * BoxSize[2];
}

V Unit(const V& v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / n, v[1] / n, v[2] / n };
}

// The silhouette's width over height for a camera at eye (a direction from
// the focal point) with screen-up up.
double PredictedAspect(const V& eye, const V& up)
{
  const V d = Unit(eye);
  const V right = Unit(Cross(up, d));
  const V screenUp = Cross(d, right);
  return Extent(right) / Extent(screenUp);
}

Silhouette Render(const TempDir& dir, const std::vector<std::string>& more)
{
  std::vector<std::string> args{ "render", (dir / "box.obj").string(), "-o",
    (dir / "view.png").string(), "--size", "400x400", "--orthographic", "--shading", "flat" };
  args.insert(args.end(), more.begin(), more.end());
  const RunResult r = RunShadelab(args);
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  return MeasureSilhouette(ReadImage(dir / "view.png"));
}

double Aspect(const Silhouette& s)
{
  return static_cast<double>(s.Width) / s.Height;
}
}

TEST(Views, EachPresetShowsThePredictedSilhouetteForUpYAndUpZ)
{
  TempDir dir;
  WriteText(dir / "box.obj", Box(BoxSize).Obj());
  // What the presets mean, as the contract words them: for up +Y front looks
  // along -Z (the camera at +Z), for up +Z along +Y (the camera at -Y); right
  // is +X for both; top looks down with the front at the bottom of the
  // picture; iso from front, right and above.
  struct Axes
  {
    std::string Up;
    V U, F, R;
  };
  for (const Axes& a : { Axes{ "+Y", { 0, 1, 0 }, { 0, 0, 1 }, { 1, 0, 0 } },
         Axes{ "+Z", { 0, 0, 1 }, { 0, -1, 0 }, { 1, 0, 0 } } })
  {
    const auto neg = [](const V& v) { return V{ -v[0], -v[1], -v[2] }; };
    const std::vector<std::tuple<std::string, V, V>> presets{ { "front", a.F, a.U },
      { "back", neg(a.F), a.U }, { "right", a.R, a.U }, { "left", neg(a.R), a.U },
      { "top", a.U, neg(a.F) }, { "bottom", neg(a.U), a.F },
      { "iso", { a.F[0] + a.R[0] + a.U[0], a.F[1] + a.R[1] + a.U[1], a.F[2] + a.R[2] + a.U[2] },
        a.U } };
    for (const auto& [view, eye, up] : presets)
    {
      SCOPED_TRACE("--up " + a.Up + " --view " + view);
      const Silhouette s = Render(dir, { "--up", a.Up, "--view", view });
      // A pixel either way at each edge of a silhouette some 90 to 350
      // pixels long: 3% covers it.
      EXPECT_NEAR(Aspect(s), PredictedAspect(eye, up), 0.03 * PredictedAspect(eye, up));
    }
  }
}

TEST(Views, AzimuthElevationAndZoomTurnAndMagnifyTheFittedCamera)
{
  TempDir dir;
  WriteText(dir / "box.obj", Box(BoxSize).Obj());
  const Silhouette front = Render(dir, {});
  const Silhouette right = Render(dir, { "--view", "right" });
  // A quarter turn about the view-up from the front is the right view.
  const Silhouette turned = Render(dir, { "--azimuth", "90" });
  EXPECT_NEAR(turned.Width, right.Width, 2);
  EXPECT_NEAR(turned.Height, right.Height, 2);
  // Elevation 45 from the right view: the box's Y and X extents mix.
  const Silhouette raised = Render(dir, { "--view", "right", "--elevation", "45" });
  const V eye{ std::cos(M_PI / 4), std::sin(M_PI / 4), 0 };
  EXPECT_NEAR(Aspect(raised), PredictedAspect(eye, { -eye[1], eye[0], 0 }), 0.05);
  // The azimuth turns about the up axis, from the top too: the picture
  // spins a quarter turn (a turn about the top view's screen-up would tip
  // the camera down to a side view instead).
  const Silhouette top = Render(dir, { "--view", "top" });
  const Silhouette spun = Render(dir, { "--view", "top", "--azimuth", "90" });
  EXPECT_NEAR(spun.Width, top.Height, 2);
  EXPECT_NEAR(spun.Height, top.Width, 2);
  // Zoom 2: twice the size.
  const Silhouette zoomed = Render(dir, { "--zoom", "2" });
  EXPECT_NEAR(zoomed.Height, 2 * front.Height, 3);
  EXPECT_NEAR(zoomed.Width, 2 * front.Width, 3);
}

TEST(Views, ASceneFileSaysItAsTheCommandLineDoes)
{
  TempDir dir;
  WriteText(dir / "box.obj", Box(BoxSize).Obj());
  const Silhouette cli =
    Render(dir, { "--up", "+Z", "--view", "iso", "--azimuth", "10", "--zoom", "1.5" });
  WriteText(dir / "scene.json",
    R"({ "mesh": "box.obj", "size": [400, 400], "shading": "flat", "up": "+Z",
         "camera": { "orthographic": true, "view": "iso", "azimuth": 10, "zoom": 1.5 },
         "output": ")" +
      (dir / "scene.png").string() + R"(" })");
  ASSERT_EQ(RunShadelab({ "render", "--scene", (dir / "scene.json").string() }).ExitCode, 0);
  const Silhouette scene = MeasureSilhouette(ReadImage(dir / "scene.png"));
  EXPECT_EQ(scene.Width, cli.Width);
  EXPECT_EQ(scene.Height, cli.Height);
}

TEST(Views, BadValuesAreOneLineErrors)
{
  TempDir dir;
  WriteText(dir / "box.obj", Box(BoxSize).Obj());
  for (const std::vector<std::string>& bad : { std::vector<std::string>{ "--view", "sideways" },
         { "--up", "W" }, { "--zoom", "0" }, { "--azimuth", "left" } })
  {
    const RunResult r = RunShadelab(
      { "render", (dir / "box.obj").string(), "-o", (dir / "a.png").string(), bad[0], bad[1] });
    EXPECT_EQ(r.ExitCode, 2) << bad[0];
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
    EXPECT_NE(r.Stderr.find(bad[0]), std::string::npos) << r.Stderr;
  }
  EXPECT_EQ(dir.Files(), std::vector<std::string>{ "box.obj" });
}
