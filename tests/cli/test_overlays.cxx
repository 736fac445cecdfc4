// --edges and --normal-glyphs in headless pictures: the window's lines over
// the shading, in the colour and width asked for.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadelab_test;

namespace
{
const std::string Mesh = TestMesh("torus.obj").string();

// Pixels of exactly the 8-bit colour rgb.
std::size_t CountColour(const Image& image, const std::array<float, 3>& rgb)
{
  std::size_t n = 0;
  for (std::size_t i = 0; i < image.Pixels.size(); i += image.Channels)
  {
    n +=
      image.Pixels[i] == rgb[0] && image.Pixels[i + 1] == rgb[1] && image.Pixels[i + 2] == rgb[2];
  }
  return n;
}

Image Render(const TempDir& dir, const std::vector<std::string>& more)
{
  std::vector<std::string> args{ "render", Mesh, "-o", (dir / "a.png").string(), "--size",
    "200x150", "--material", "gold" };
  args.insert(args.end(), more.begin(), more.end());
  const RunResult r = RunShadelab(args);
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  return ReadImage(dir / "a.png");
}
}

TEST(Overlays, EdgesInTheirColourAndWidth)
{
  TempDir dir;
  const std::array<float, 3> red{ 255, 0, 0 };
  EXPECT_EQ(CountColour(Render(dir, {}), red), 0u);
  const std::size_t thin = CountColour(Render(dir, { "--edges", "--edge-color", "1,0,0" }), red);
  const std::size_t thick =
    CountColour(Render(dir, { "--edges", "--edge-color", "1,0,0", "--edge-width", "3" }), red);
  EXPECT_GT(thin, 1000u) << "the cow's 5,804 triangles show their edges";
  // The cow's 5,804 triangles in 200x150 pixels: its edges lie a few pixels
  // apart, so three-pixel lines overlap and cover about a third more.
  EXPECT_GT(thick, thin + thin / 4) << "three pixels wide cover more";
}

TEST(Overlays, NormalGlyphsInTheWindowsColour)
{
  TempDir dir;
  // The window's glyph colour (0.2, 0.9, 1.0) as 8 bits: 0.9 in float is
  // just under 0.9, so round(255 * 0.9f) is 229.
  const std::array<float, 3> cyan{ 51, 229, 255 };
  EXPECT_EQ(CountColour(Render(dir, {}), cyan), 0u);
  EXPECT_GT(CountColour(Render(dir, { "--normal-glyphs" }), cyan), 500u);
  // Flat shading draws no vertex normals, yet the glyphs are those that
  // gouraud and phong use.
  EXPECT_GT(CountColour(Render(dir, { "--normal-glyphs", "--shading", "flat" }), cyan), 500u);
}

TEST(Overlays, ASceneFileSaysItAsTheCommandLineDoes)
{
  TempDir dir;
  const Image cli = Render(dir, { "--edges", "--edge-color", "1,0,0", "--normal-glyphs" });
  WriteText(dir / "scene.json",
    R"({ "mesh": ")" + Mesh + R"(", "size": [200, 150], "material": "gold", "edges": true,
         "edge_color": [1, 0, 0], "normal_glyphs": true, "output": ")" +
      (dir / "scene.png").string() + R"(" })");
  ASSERT_EQ(RunShadelab({ "render", "--scene", (dir / "scene.json").string() }).ExitCode, 0);
  EXPECT_EQ(ReadImage(dir / "scene.png").Pixels, cli.Pixels);
}

TEST(Overlays, BadValuesAreOneLineErrors)
{
  TempDir dir;
  for (const std::string width : { "0", "17", "wide" })
  {
    const RunResult r =
      RunShadelab({ "render", Mesh, "-o", (dir / "a.png").string(), "--edge-width", width });
    EXPECT_EQ(r.ExitCode, 2) << width;
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
  }
  EXPECT_TRUE(dir.Files().empty());
}

// Edges lie exactly on their surface: seen straight on, a square's outline
// and diagonal are drawn over it along their whole length, not lost to the
// depth test (the surface is pushed back by a polygon offset).
TEST(Overlays, EdgesShowOverASquareSeenStraightOn)
{
  TempDir dir;
  WriteText(dir / "quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n");
  const RunResult r = RunShadelab(
    { "render", (dir / "quad.obj").string(), "-o", (dir / "q.png").string(), "--size", "101x101",
      "--orthographic", "--shading", "none", "--kd", "1,1,1", "--edges", "--edge-color", "1,0,0" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const Image image = ReadImage(dir / "q.png");
  ASSERT_EQ(image.Width, 101);
  const auto at = [&](int x, int y)
  { return &image.Pixels[(static_cast<std::size_t>(y) * image.Width + x) * image.Channels]; };
  const auto red = [&](int x, int y)
  {
    const float* p = at(x, y);
    return p[0] == 255 && p[1] == 0 && p[2] == 0;
  };
  // The square's extent: every pixel that is not background.
  int x0 = image.Width, x1 = -1, y0 = image.Height, y1 = -1;
  for (int y = 0; y < image.Height; ++y)
  {
    for (int x = 0; x < image.Width; ++x)
    {
      if (at(x, y)[0] > 0)
      {
        x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      }
    }
  }
  ASSERT_GT(x1 - x0, 40) << "the square fills the middle of the picture";
  // Along the diagonal (bottom left to top right on the screen) and across
  // the square's middle to its top and bottom outline: red within a pixel.
  int missing = 0, white = 0;
  for (int i = 2; i < 19; ++i)
  {
    const double t = i / 20.0;
    const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
    const int y = static_cast<int>(std::lround(y1 - t * (y1 - y0)));
    bool found = false;
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        found = found || red(x + dx, y + dy);
      }
    }
    missing += !found;
    const float* off = at(x, std::min(y + 4, y1 - 1)); // beside the line: the surface
    white += off[0] == 255 && off[1] == 255 && off[2] == 255;
    missing += !(red(x, y0) || red(x, y0 + 1)) + !(red(x, y1) || red(x, y1 - 1));
  }
  EXPECT_EQ(missing, 0) << "edge pixels not drawn";
  EXPECT_GT(white, 10) << "the surface between the edges is drawn too";
}
