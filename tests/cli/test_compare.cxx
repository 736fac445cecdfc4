// `shadelab compare` end to end: the picture holds one panel per
// mode at the panel size, each exactly what `shadelab render` gives for
// that mode, labelled; the difference panel is zero for identical inputs
// and marks exactly the pixels where two rules differ; the components add
// up to the total; bad modes are one-line errors.
#include "cli_test_support.h"
#include "image/comparison_picture.h" // the layout's documented constants

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace shadelab_test;
using shadelab::CellGap;
using shadelab::ColourBarStripHeight;
using shadelab::LabelStripHeight;

namespace
{
constexpr int W = 96;
constexpr int H = 72;

// Panel `cell` of a comparison picture laid out in `columns` columns, as an image of its own.
Image PanelOf(const Image& picture, int cell, int columns)
{
  const int x0 = CellGap + (cell % columns) * (W + CellGap);
  const int y0 = (cell / columns) * (LabelStripHeight + H + CellGap) + LabelStripHeight;
  Image panel;
  panel.Width = W;
  panel.Height = H;
  panel.Channels = picture.Channels;
  for (int y = 0; y < H; ++y)
  {
    const auto row = picture.Pixels.begin() +
      (static_cast<size_t>(y0 + y) * picture.Width + x0) * picture.Channels;
    panel.Pixels.insert(panel.Pixels.end(), row, row + W * picture.Channels);
  }
  return panel;
}

// The label strip above panel `cell`: how many of its pixels are bright (text).
int TextPixels(const Image& picture, int cell, int columns)
{
  const int x0 = CellGap + (cell % columns) * (W + CellGap);
  const int y0 = (cell / columns) * (LabelStripHeight + H + CellGap);
  int bright = 0;
  for (int y = y0; y < y0 + LabelStripHeight; ++y)
  {
    for (int x = x0; x < x0 + W; ++x)
    {
      bright +=
        picture.Pixels[(static_cast<size_t>(y) * picture.Width + x) * picture.Channels] > 150;
    }
  }
  return bright;
}

float LargestDifference(const Image& a, const Image& b)
{
  float largest = 0;
  for (size_t i = 0; i < a.Pixels.size(); ++i)
  {
    largest = std::max(largest, std::fabs(a.Pixels[i] - b.Pixels[i]));
  }
  return largest;
}

const std::vector<std::string> Camera{ "--size", std::to_string(W) + "x" + std::to_string(H),
  "--camera-position", "5,5,9" };

RunResult Compare(const std::filesystem::path& out, std::vector<std::string> args)
{
  args.insert(args.begin(), { "compare", TestMesh("teapot.obj").string(), "-o", out.string() });
  args.insert(args.end(), Camera.begin(), Camera.end());
  return RunShadelab(args);
}
}

TEST(Compare, OnePanelPerModeEachExactlyWhatRenderGives)
{
  TempDir dir;
  const RunResult run = Compare(dir / "c.png", {});
  ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
  const Image picture = ReadImage(dir / "c.png");
  EXPECT_EQ(picture.Width, 3 * (W + CellGap) + CellGap) << "flat, gouraud, phong in one row";
  EXPECT_EQ(picture.Height, LabelStripHeight + H + CellGap);
  EXPECT_NE(picture.Description.find(R"("panels":["flat","gouraud","phong"])"), std::string::npos)
    << picture.Description;
  const std::vector<std::string> rules{ "flat", "gouraud", "phong" };
  std::vector<Image> panels;
  for (int i = 0; i < 3; ++i)
  {
    std::vector<std::string> args{ "render", TestMesh("teapot.obj").string(), "-o",
      (dir / (rules[i] + ".png")).string(), "--shading", rules[i] };
    args.insert(args.end(), Camera.begin(), Camera.end());
    const RunResult render = RunShadelab(args);
    ASSERT_EQ(render.ExitCode, 0) << render.Stderr;
    panels.push_back(PanelOf(picture, i, 3));
    // The same scene through the same code and context settings: the same
    // bytes, so no tolerance.
    EXPECT_EQ(LargestDifference(panels.back(), ReadImage(dir / (rules[i] + ".png"))), 0)
      << rules[i];
    EXPECT_GT(CountCovered(panels.back()), static_cast<size_t>(W * H / 10)) << rules[i];
    EXPECT_GT(TextPixels(picture, i, 3), 20) << rules[i] << "'s label";
  }
  EXPECT_GT(LargestDifference(panels[0], panels[2]), 10) << "flat and phong differ";
  EXPECT_GT(LargestDifference(panels[1], panels[2]), 2) << "gouraud and phong differ";
}

// The representation applies to every panel: each is what render draws
// with it, and the picture's metadata names it.
TEST(Compare, EveryPanelDrawnAsTheRepresentationSays)
{
  TempDir dir;
  const std::vector<std::string> drawn{ "--representation", "wireframe", "--line-width", "2" };
  const RunResult run = Compare(dir / "c.png", drawn);
  ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
  const Image picture = ReadImage(dir / "c.png");
  EXPECT_NE(picture.Description.find(R"("representation":"wireframe")"), std::string::npos)
    << picture.Description;
  EXPECT_NE(picture.Description.find(R"("line_width":2)"), std::string::npos);
  const std::vector<std::string> rules{ "flat", "gouraud", "phong" };
  for (int i = 0; i < 3; ++i)
  {
    std::vector<std::string> args{ "render", TestMesh("teapot.obj").string(), "-o",
      (dir / (rules[i] + ".png")).string(), "--shading", rules[i] };
    args.insert(args.end(), Camera.begin(), Camera.end());
    args.insert(args.end(), drawn.begin(), drawn.end());
    const RunResult render = RunShadelab(args);
    ASSERT_EQ(render.ExitCode, 0) << render.Stderr;
    const Image wireframe = ReadImage(dir / (rules[i] + ".png"));
    EXPECT_EQ(LargestDifference(PanelOf(picture, i, 3), wireframe), 0) << rules[i];
    EXPECT_NE(wireframe.Description.find(R"("representation":"wireframe")"), std::string::npos);
  }
}

TEST(Compare, LabelsSayWhatDiffers)
{
  TempDir dir;
  const RunResult run =
    Compare(dir / "c.png", { "--modes", "phong,phong:material=gold:reflection=phong" });
  ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
  const Image picture = ReadImage(dir / "c.png");
  EXPECT_NE(
    picture.Description.find(R"("panels":["phong","phong, material gold, reflection phong"])"),
    std::string::npos)
    << picture.Description;
  EXPECT_GT(TextPixels(picture, 1, 2), TextPixels(picture, 0, 2)) << "the longer label";
  EXPECT_GT(LargestDifference(PanelOf(picture, 0, 2), PanelOf(picture, 1, 2)), 10);
}

TEST(Compare, DifferenceOfIdenticalModesIsZero)
{
  TempDir dir;
  const RunResult run = Compare(dir / "c.png", { "--modes", "phong,phong", "--diff", "1,2" });
  ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
  EXPECT_NE(run.Stdout.find("largest 0, mean 0, 0 of"), std::string::npos) << run.Stdout;
  const Image picture = ReadImage(dir / "c.png");
  EXPECT_EQ(picture.Width, 3 * (W + CellGap) + CellGap);
  EXPECT_EQ(picture.Height, LabelStripHeight + H + CellGap + ColourBarStripHeight)
    << "a colour bar beneath";
  const Image heat = PanelOf(picture, 2, 3);
  EXPECT_EQ(*std::max_element(heat.Pixels.begin(), heat.Pixels.end()), 0) << "all black";
  EXPECT_GT(TextPixels(picture, 2, 3), 20) << "the difference panel's label";
}

TEST(Compare, DifferenceMarksExactlyThePixelsWhereTheRulesDiffer)
{
  TempDir dir;
  const RunResult run =
    Compare(dir / "c.png", { "--modes", "gouraud,phong", "--diff", "gouraud,phong" });
  ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
  const Image picture = ReadImage(dir / "c.png");
  const Image a = PanelOf(picture, 0, 3), b = PanelOf(picture, 1, 3), heat = PanelOf(picture, 2, 3);
  int marked = 0;
  for (size_t p = 0; p < static_cast<size_t>(W) * H; ++p)
  {
    float d = 0;
    for (int c = 0; c < 3; ++c)
    {
      d = std::max(d, std::fabs(a.Pixels[3 * p + c] - b.Pixels[3 * p + c]));
    }
    const bool hot = heat.Pixels[3 * p] > 0; // red rises first in the heat map
    marked += hot;
    // Panels are 8-bit: a float difference below half a step may round to
    // either side, so a 1-step difference may be unmarked; from 2 steps on
    // the heat map's red is at least 3 * 2/255 of full scale, visible.
    if (d >= 2)
    {
      EXPECT_TRUE(hot) << "pixel " << p << " differs by " << d;
    }
    if (!hot)
    {
      EXPECT_LE(d, 1) << "pixel " << p << " is unmarked";
    }
  }
  EXPECT_GT(marked, 50);
}

TEST(Compare, ComponentsAddUpToTheTotal)
{
  TempDir dir;
  // Float output: the terms unclamped, so that they add up exactly.
  const RunResult run = Compare(dir / "c.exr", { "--modes", "gouraud,phong", "--components" });
  ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
  const Image picture = ReadImage(dir / "c.exr");
  ASSERT_EQ(picture.Width, 4 * (W + CellGap) + CellGap) << "ambient, diffuse, specular, total";
  ASSERT_EQ(picture.Height, 2 * (LabelStripHeight + H + CellGap)) << "a row per mode";
  for (int mode = 0; mode < 2; ++mode)
  {
    const Image ambient = PanelOf(picture, 4 * mode, 4),
                diffuse = PanelOf(picture, 4 * mode + 1, 4),
                specular = PanelOf(picture, 4 * mode + 2, 4),
                total = PanelOf(picture, 4 * mode + 3, 4);
    float largest = 0, specularLargest = 0;
    for (size_t i = 0; i < total.Pixels.size(); ++i)
    {
      if (i % picture.Channels == 3)
      {
        continue; // alpha
      }
      largest = std::max(largest,
        std::fabs(ambient.Pixels[i] + diffuse.Pixels[i] + specular.Pixels[i] - total.Pixels[i]));
      specularLargest = std::max(specularLargest, specular.Pixels[i]);
    }
    // Float32 arithmetic per term, and gouraud's colours interpolated by
    // llvmpipe one varying at a time: seen 2e-5. 1e-4 still catches a
    // missing or doubled term (chrome's ambient alone is 0.05).
    EXPECT_LT(largest, 1e-4) << "mode " << mode;
    EXPECT_GT(specularLargest, 0.2) << "chrome has a highlight";
  }
}

TEST(Compare, BadModesAndDifferencesAreOneLineErrors)
{
  TempDir dir;
  for (const auto& [args, says] : std::vector<std::pair<std::vector<std::string>, std::string>>{
         { { "--modes", "phong:colour=red" }, "mode 'phong:colour=red'" },
         { { "--modes", "glossy" }, "mode 'glossy'" },
         { { "--modes", "phong,,flat" }, "mode '': is empty" },
         { { "--modes", "phong:material=unobtainium" }, "unobtainium" },
         { { "--modes", "flat,phong", "--diff", "flat,gouraud" }, "'gouraud' is neither" },
         { { "--modes", "flat,phong", "--diff", "3,1" }, "'3' is neither" },
         { { "--diff", "flat" }, "not two modes" } })
  {
    const RunResult run = Compare(dir / "c.png", args);
    EXPECT_EQ(run.ExitCode, 2) << says;
    EXPECT_NE(run.Stderr.find(says), std::string::npos) << run.Stderr;
    EXPECT_EQ(std::count(run.Stderr.begin(), run.Stderr.end(), '\n'), 1) << run.Stderr;
    EXPECT_TRUE(dir.Files().empty());
  }
  const RunResult missing =
    RunShadelab({ "compare", (dir / "none.obj").string(), "-o", (dir / "c.png").string() });
  EXPECT_EQ(missing.ExitCode, 1);
  EXPECT_NE(missing.Stderr.find("none.obj"), std::string::npos) << missing.Stderr;
  const RunResult folder = RunShadelab(
    { "compare", TestMesh("teapot.obj").string(), "-o", (dir / "no/such/c.png").string() });
  EXPECT_EQ(folder.ExitCode, 1);
  EXPECT_TRUE(dir.Files().empty());
}

// A comparison picture beyond 4096x4096 is refused before anything renders,
// in one line that says what to change (400 panels once took 3.7 GB, then
// "the image writer failed").
TEST(Compare, APictureBeyondTheLimitIsRefusedFirst)
{
  TempDir dir;
  const RunResult r = RunShadelab({ "compare", TestMesh("teapot.obj").string(), "-o",
    (dir / "big.png").string(), "--modes", "flat,phong", "--size", "3000x3000" });
  EXPECT_EQ(r.ExitCode, 1) << r.Stderr;
  EXPECT_NE(
    r.Stderr.find("more than 4096x4096: fewer panels or a smaller --size"), std::string::npos)
    << r.Stderr;
  EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
  EXPECT_TRUE(FilesIn(dir.path()).empty());
}
