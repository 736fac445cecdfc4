// --ssaa N: each pixel is the box average of N x N samples, exactly the
// picture rendered N times as large and averaged, so that what the oracle
// tests show of a plain picture holds for an anti-aliased one too.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace shadelab_test;

namespace
{
const std::string Mesh = TestMesh("teapot.obj").string();

// big averaged over n x n blocks, computed here on its own: the sum of a
// block in double is exact (at most 64 floats of one picture's range), so
// its order does not matter, and the mean rounds to float once.
std::vector<float> BoxAverage(const Image& big, int n)
{
  const int w = big.Width / n, h = big.Height / n, c = big.Channels;
  std::vector<float> out(static_cast<std::size_t>(w) * h * c);
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      for (int k = 0; k < c; ++k)
      {
        double sum = 0;
        for (int sy = 0; sy < n; ++sy)
        {
          for (int sx = 0; sx < n; ++sx)
          {
            sum +=
              big.Pixels[(static_cast<std::size_t>(y * n + sy) * big.Width + x * n + sx) * c + k];
          }
        }
        out[(static_cast<std::size_t>(y) * w + x) * c + k] = static_cast<float>(sum / (n * n));
      }
    }
  }
  return out;
}

RunResult Render(const std::filesystem::path& out, const std::string& size,
  const std::vector<std::string>& more = {})
{
  std::vector<std::string> args{ "render", Mesh, "-o", out.string(), "--size", size, "--material",
    "gold" };
  args.insert(args.end(), more.begin(), more.end());
  return RunShadelab(args);
}
}

TEST(Supersampling, IsExactlyTheBoxAverageOfTheLargerPicture)
{
  TempDir dir;
  for (const int n : { 2, 3 })
  {
    SCOPED_TRACE(n);
    // The camera is fitted in both: the same aspect gives the same camera.
    ASSERT_EQ(Render(dir / "ssaa.exr", "80x60", { "--ssaa", std::to_string(n) }).ExitCode, 0);
    ASSERT_EQ(Render(dir / "ssaa.png", "80x60", { "--ssaa", std::to_string(n) }).ExitCode, 0);
    ASSERT_EQ(
      Render(dir / "big.exr", std::to_string(80 * n) + "x" + std::to_string(60 * n)).ExitCode, 0);
    const Image ssaa = ReadImage(dir / "ssaa.exr");
    const Image png = ReadImage(dir / "ssaa.png");
    const std::vector<float> expected = BoxAverage(ReadImage(dir / "big.exr"), n);
    ASSERT_EQ(ssaa.Width, 80);
    ASSERT_EQ(ssaa.Pixels.size(), expected.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < expected.size(); ++i)
    {
      differing += ssaa.Pixels[i] != expected[i];
      // The 8-bit file quantises the average: round(255*clamp(I, 0, 1)).
      const double clamped = std::fmin(std::fmax(expected[i], 0.0f), 1.0f);
      differing += png.Pixels[i] != std::floor(255 * clamped + 0.5);
    }
    EXPECT_EQ(differing, 0u);
  }
}

TEST(Supersampling, ASceneFileShotSaysItAsTheCommandLineDoes)
{
  TempDir dir;
  ASSERT_EQ(Render(dir / "cli.png", "80x60", { "--ssaa", "2" }).ExitCode, 0);
  WriteText(dir / "scene.json",
    R"({ "mesh": ")" + Mesh + R"(", "size": [80, 60], "material": "gold", "ssaa": 2,
      "output": ")" +
      (dir / "scene.png").string() + R"(" })");
  ASSERT_EQ(RunShadelab({ "render", "--scene", (dir / "scene.json").string() }).ExitCode, 0);
  EXPECT_EQ(ReadImage(dir / "scene.png").Pixels, ReadImage(dir / "cli.png").Pixels);
  EXPECT_NE(ReadImage(dir / "scene.png").Description.find("\"ssaa\":2"), std::string::npos);
}

TEST(Supersampling, BadValuesAreOneLineErrors)
{
  TempDir dir;
  for (const std::string n : { "0", "9", "two" })
  {
    const RunResult r = Render(dir / "a.png", "80x60", { "--ssaa", n });
    EXPECT_EQ(r.ExitCode, 2) << n;
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
    EXPECT_NE(r.Stderr.find("--ssaa"), std::string::npos) << r.Stderr;
  }
  const RunResult big = Render(dir / "a.png", "4000x3000", { "--ssaa", "8" });
  EXPECT_EQ(big.ExitCode, 1);
  EXPECT_EQ(big.Stderr,
    "shadelab: error: render: --ssaa 8 renders 32000x24000, beyond 16384 a side and 67108864 "
    "pixels in all: a smaller --size or --ssaa\n");
  EXPECT_TRUE(dir.Files().empty());
}
