// --edges and --normal-glyphs in headless pictures: the window's lines over
// the shading, in the colour and width asked for.
#include "cli_test_support.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

namespace
{
const std::string Mesh = TestMesh("cow.obj").string();

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
  EXPECT_GT(thick, thin + thin / 2) << "three pixels wide cover more";
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
