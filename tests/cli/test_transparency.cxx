// --background transparent: alpha 0 where no surface is and 1 where it is,
// in PNG, TIFF and EXR, and where the mesh is the colours are those of the
// picture on an opaque black background.
#include "cli_test_support.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

namespace
{
const std::string Mesh = TestMesh("teapot.obj").string();

Image Render(const TempDir& dir, const std::string& name, const std::string& background)
{
  const RunResult r = RunShadelab({ "render", Mesh, "-o", (dir / name).string(), "--size", "120x90",
    "--material", "gold", "--background", background });
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  return ReadImage(dir / name);
}
}

TEST(Transparency, AlphaIsCoverageAndTheColoursStay)
{
  TempDir dir;
  for (const std::string ext : { ".png", ".tif", ".exr" })
  {
    SCOPED_TRACE(ext);
    const Image opaque = Render(dir, "opaque" + ext, "0,0,0");
    const Image clear = Render(dir, "clear" + ext, "transparent");
    ASSERT_EQ(opaque.Channels, 3);
    ASSERT_EQ(clear.Channels, 4);
    const float one = ext == ".exr" ? 1.0f : 255.0f; // ReadImage gives 8-bit files as 0..255
    std::size_t inside = 0, wrong = 0;
    for (std::size_t p = 0; p < opaque.Pixels.size() / 3; ++p)
    {
      const float* o = &opaque.Pixels[3 * p];
      const float* c = &clear.Pixels[4 * p];
      const bool covered = o[0] + o[1] + o[2] > 0; // gold under ambient light is never black
      inside += covered;
      wrong += c[3] != (covered ? one : 0.0f);
      for (int k = 0; k < 3; ++k)
      {
        wrong += c[k] != (covered ? o[k] : 0.0f);
      }
    }
    EXPECT_GT(inside, 1000u);
    EXPECT_EQ(wrong, 0u);
  }
}

TEST(Transparency, FormatsWithoutAlphaAndComparisonsSaySo)
{
  TempDir dir;
  const RunResult jpeg =
    RunShadelab({ "render", Mesh, "-o", (dir / "a.jpg").string(), "--background", "transparent" });
  EXPECT_EQ(jpeg.ExitCode, 1);
  EXPECT_EQ(jpeg.Stderr,
    "shadelab: error: " + (dir / "a.jpg").string() +
      ": the jpeg format cannot store transparency (--background transparent: .png, .tif or "
      ".exr)\n");
  const RunResult compare =
    RunShadelab({ "compare", Mesh, "-o", (dir / "c.png").string(), "--background", "transparent" });
  EXPECT_EQ(compare.ExitCode, 2);
  EXPECT_NE(
    compare.Stderr.find("--background transparent is for render's pictures"), std::string::npos)
    << compare.Stderr;
  EXPECT_TRUE(dir.Files().empty());
}
