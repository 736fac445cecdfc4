// --fit tight against --fit sphere: meshes whose every vertex the test
// knows, projected with the camera that each picture's metadata records,
// span the picture exactly on the limiting axis and are centred on the
// other; the rendered silhouette touches the borders there. The sphere fit
// leaves room on every side.
#include "cli_test_support.h"
#include "image/comparison_picture.h" // the layout's documented constants

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadelab_test;

namespace
{
// An ellipsoid off the origin: 12 rings of 24 vertices and the two poles.
TestShape Ellipsoid(const Point3& radii, const Point3& centre)
{
  TestShape e;
  constexpr int rings = 12, segments = 24;
  e.Vertices.push_back({ centre[0], centre[1] + radii[1], centre[2] });
  for (int r = 1; r <= rings; ++r)
  {
    const double polar = M_PI * r / (rings + 1);
    for (int s = 0; s < segments; ++s)
    {
      const double around = 2 * M_PI * s / segments;
      e.Vertices.push_back({ centre[0] + radii[0] * std::sin(polar) * std::cos(around),
        centre[1] + radii[1] * std::cos(polar),
        centre[2] + radii[2] * std::sin(polar) * std::sin(around) });
    }
  }
  e.Vertices.push_back({ centre[0], centre[1] - radii[1], centre[2] });
  const auto at = [](int r, int s) { return 2 + (r - 1) * segments + s % segments; };
  const int south = 2 + rings * segments;
  for (int s = 0; s < segments; ++s)
  {
    e.Faces += "f 1 " + std::to_string(at(1, s + 1)) + " " + std::to_string(at(1, s)) + "\n";
    for (int r = 1; r < rings; ++r)
    {
      e.Faces += "f " + std::to_string(at(r, s)) + " " + std::to_string(at(r, s + 1)) + " " +
        std::to_string(at(r + 1, s + 1)) + " " + std::to_string(at(r + 1, s)) + "\n";
    }
    e.Faces += "f " + std::to_string(south) + " " + std::to_string(at(rings, s)) + " " +
      std::to_string(at(rings, s + 1)) + "\n";
  }
  return e;
}

struct Picture
{
  Image Pixels;
  Extents Projected;
};

Picture Render(const TempDir& dir, const TestShape& shape, const std::vector<std::string>& more)
{
  WriteText(dir / "shape.obj", shape.Obj());
  std::vector<std::string> args{ "render", (dir / "shape.obj").string(), "-o",
    (dir / "fit.png").string(), "--shading", "flat" };
  args.insert(args.end(), more.begin(), more.end());
  const RunResult r = RunShadelab(args);
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  Picture p{ ReadImage(dir / "fit.png"), {} };
  p.Projected = Project(CameraOf(p.Pixels), shape.Vertices, p.Pixels.Width, p.Pixels.Height);
  return p;
}

// The projection computed in double from the recorded camera: a millionth
// of a pixel is rounding, anything more a fit that is not exact.
constexpr double Exact = 1e-6;

// The rasterised silhouette against the projection: a pixel is covered when
// its centre is inside a triangle, so an edge lands within a pixel of where
// the projection puts it.
void ExpectSilhouetteMatches(const Picture& p)
{
  const Silhouette s = MeasureSilhouette(p.Pixels);
  EXPECT_NEAR(s.Left, p.Projected.Left, 1);
  EXPECT_NEAR(s.Right + 1, p.Projected.Right, 1);
  EXPECT_NEAR(s.Top, p.Projected.Top, 1);
  EXPECT_NEAR(s.Bottom + 1, p.Projected.Bottom, 1);
}

struct Case
{
  std::string Up;
  std::vector<std::string> View;
  bool Orthographic;
  std::string Size;
};

const std::vector<Case> Cases{
  { "+Y", { "--view", "front" }, false, "200x150" },
  { "+Y", { "--view", "iso" }, true, "200x150" },
  { "+Y", { "--view", "top" }, false, "120x160" },
  { "+Y", { "--view", "right", "--azimuth", "30", "--elevation", "20" }, true, "120x160" },
  { "+Z", { "--view", "front" }, true, "200x150" },
  { "+Z", { "--view", "iso" }, false, "120x160" },
  { "+Z", { "--view", "top" }, true, "200x150" },
  { "+Z", { "--view", "left", "--azimuth", "-40", "--elevation", "-25" }, false, "200x150" },
};

std::vector<std::string> ArgumentsOf(const Case& c)
{
  std::vector<std::string> args{ "--size", c.Size, "--up=" + c.Up };
  args.insert(args.end(), c.View.begin(), c.View.end());
  if (c.Orthographic)
  {
    args.push_back("--orthographic");
  }
  return args;
}

std::string NameOf(const Case& c)
{
  std::string name = "--up " + c.Up;
  for (const std::string& a : c.View)
  {
    name += " " + a;
  }
  return name + (c.Orthographic ? " --orthographic" : "") + " --size " + c.Size;
}
}

TEST(Fit, TightSpansThePictureOnTheLimitingAxisAndCentresTheOther)
{
  TempDir dir;
  for (const TestShape& shape : { Box({ 1, 2, 4 }), Ellipsoid({ 1.5, 0.8, 1.1 }, { 3, -1, 2 }) })
  {
    for (const Case& c : Cases)
    {
      SCOPED_TRACE(NameOf(c) + (shape.Vertices.size() == 8 ? " box" : " ellipsoid"));
      std::vector<std::string> args = ArgumentsOf(c);
      args.insert(args.end(), { "--fit", "tight" });
      const Picture p = Render(dir, shape, args);
      ASSERT_GT(p.Pixels.Width, 0);
      const double w = p.Pixels.Width, h = p.Pixels.Height;
      const Extents& e = p.Projected;
      // Inside the picture, centred both ways.
      EXPECT_GE(e.Left, -Exact);
      EXPECT_LE(e.Right, w + Exact);
      EXPECT_GE(e.Top, -Exact);
      EXPECT_LE(e.Bottom, h + Exact);
      EXPECT_NEAR((e.Left + e.Right) / 2, w / 2, Exact);
      EXPECT_NEAR((e.Top + e.Bottom) / 2, h / 2, Exact);
      // Spanning it exactly one way.
      const bool across = std::fabs(e.Right - e.Left - w) < Exact;
      const bool upward = std::fabs(e.Bottom - e.Top - h) < Exact;
      EXPECT_TRUE(across || upward) << e.Left << " " << e.Right << " " << e.Top << " " << e.Bottom;
      // And the pixels: the silhouette touches both borders of that axis.
      const Silhouette s = MeasureSilhouette(p.Pixels);
      if (across)
      {
        EXPECT_LE(s.Left, 1);
        EXPECT_GE(s.Right, w - 2);
      }
      else
      {
        EXPECT_LE(s.Top, 1);
        EXPECT_GE(s.Bottom, h - 2);
      }
      ExpectSilhouetteMatches(p);
    }
  }
}

TEST(Fit, TheSphereFitLeavesRoomOnEverySide)
{
  TempDir dir;
  for (const TestShape& shape : { Box({ 1, 2, 4 }), Ellipsoid({ 1.5, 0.8, 1.1 }, { 3, -1, 2 }) })
  {
    for (const Case& c : Cases)
    {
      SCOPED_TRACE(NameOf(c) + (shape.Vertices.size() == 8 ? " box" : " ellipsoid"));
      const Picture p = Render(dir, shape, ArgumentsOf(c));
      ASSERT_GT(p.Pixels.Width, 0);
      // The bounding sphere is larger than the mesh in every direction: at
      // least 2% of the picture stays free on each side.
      const double w = p.Pixels.Width, h = p.Pixels.Height;
      EXPECT_GT(p.Projected.Left, 0.02 * w);
      EXPECT_LT(p.Projected.Right, 0.98 * w);
      EXPECT_GT(p.Projected.Top, 0.02 * h);
      EXPECT_LT(p.Projected.Bottom, 0.98 * h);
      ExpectSilhouetteMatches(p);
    }
  }
}

TEST(Fit, ZoomAppliesAfterTheFit)
{
  TempDir dir;
  const TestShape box = Box({ 1, 2, 4 });
  for (const bool orthographic : { true, false })
  {
    SCOPED_TRACE(orthographic ? "orthographic" : "perspective");
    std::vector<std::string> args{ "--size", "200x150", "--view", "iso", "--fit", "tight" };
    if (orthographic)
    {
      args.push_back("--orthographic");
    }
    const Picture fitted = Render(dir, box, args);
    args.insert(args.end(), { "--zoom", "0.5" });
    const Picture zoomed = Render(dir, box, args);
    // The same camera but the magnification: half the parallel scale's
    // extent, or the view angle doubled (the tangent's ratio).
    const double ratio = orthographic ? 0.5 : std::tan(M_PI / 12) / std::tan(M_PI / 6);
    const auto span = [](const Extents& e) { return std::max(e.Right - e.Left, e.Bottom - e.Top); };
    EXPECT_NEAR(span(zoomed.Projected), ratio * span(fitted.Projected), Exact);
    EXPECT_NEAR((zoomed.Projected.Left + zoomed.Projected.Right) / 2, 100, Exact);
    ExpectSilhouetteMatches(zoomed);
  }
}

TEST(Fit, GivenCameraSettingsStayAsGiven)
{
  TempDir dir;
  const TestShape box = Box({ 1, 2, 4 });
  // A given focal point stays the picture's centre; only the distance is fitted.
  const Picture focal = Render(dir, box,
    { "--size", "200x150", "--view", "iso", "--fit", "tight", "--camera-focal-point", "0.3,0,0" });
  const RecordedCamera c = CameraOf(focal.Pixels);
  EXPECT_EQ(c.Focal, (Point3{ 0.3, 0, 0 }));
  const Extents& e = focal.Projected;
  EXPECT_TRUE(std::fabs(e.Left) < Exact || std::fabs(e.Right - 200) < Exact ||
    std::fabs(e.Top) < Exact || std::fabs(e.Bottom - 150) < Exact);
  EXPECT_GE(e.Left, -Exact);
  EXPECT_LE(e.Right, 200 + Exact);
  // A given position: nothing is fitted, the picture is the sphere fit's.
  const std::vector<std::string> given{ "--size", "200x150", "--camera-position", "6,5,9" };
  std::vector<std::string> tight = given;
  tight.insert(tight.end(), { "--fit", "tight" });
  EXPECT_EQ(Render(dir, box, tight).Pixels.Pixels, Render(dir, box, given).Pixels.Pixels);
}

TEST(Fit, ASceneFileAndCompareTakeIt)
{
  TempDir dir;
  WriteText(dir / "box.obj", Box({ 1, 2, 4 }).Obj());
  ASSERT_EQ(RunShadelab({ "render", (dir / "box.obj").string(), "-o", (dir / "cli.png").string(),
                          "--size", "200x150", "--view", "iso", "--fit", "tight" })
              .ExitCode,
    0);
  WriteText(dir / "scene.json",
    R"({ "mesh": "box.obj", "size": [200, 150], "camera": { "view": "iso", "fit": "tight" },
         "output": ")" +
      (dir / "scene.png").string() + R"(" })");
  const RunResult scene = RunShadelab({ "render", "--scene", (dir / "scene.json").string() });
  ASSERT_EQ(scene.ExitCode, 0) << scene.Stderr;
  EXPECT_EQ(ReadImage(dir / "scene.png").Pixels, ReadImage(dir / "cli.png").Pixels);
  // compare's panels share the camera options: its phong panel is render's picture.
  const RunResult compare =
    RunShadelab({ "compare", (dir / "box.obj").string(), "-o", (dir / "compare.png").string(),
      "--size", "200x150", "--view", "iso", "--fit", "tight", "--modes", "phong" });
  ASSERT_EQ(compare.ExitCode, 0) << compare.Stderr;
  const Image picture = ReadImage(dir / "compare.png"), alone = ReadImage(dir / "cli.png");
  ASSERT_EQ(picture.Channels, alone.Channels);
  std::vector<float> panel;
  for (int y = 0; y < alone.Height; ++y)
  {
    const auto row = picture.Pixels.begin() +
      (static_cast<std::size_t>(shadelab::LabelStripHeight + y) * picture.Width +
        shadelab::CellGap) *
        picture.Channels;
    panel.insert(panel.end(), row, row + alone.Width * alone.Channels);
  }
  EXPECT_EQ(panel, alone.Pixels);
}

TEST(Fit, BadValuesAreOneLineErrors)
{
  TempDir dir;
  WriteText(dir / "box.obj", Box({ 1, 2, 4 }).Obj());
  const RunResult r = RunShadelab(
    { "render", (dir / "box.obj").string(), "-o", (dir / "a.png").string(), "--fit", "loose" });
  EXPECT_EQ(r.ExitCode, 2);
  EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
  EXPECT_NE(r.Stderr.find("--fit"), std::string::npos) << r.Stderr;
  EXPECT_EQ(dir.Files(), std::vector<std::string>{ "box.obj" });
}
