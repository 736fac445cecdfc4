// The environment behind the mesh (--background environment): every pixel
// shows what covers it laid over the environment seen along the ray through
// its centre, C + (1 - a) E(d). Held against the same scene drawn over a
// transparent background (C and a, associated alpha) and E looked up here
// on its own: the ray from the picture's recorded camera, its direction in
// the environment's frame (for up +Y the world's axes: x right, y up, z
// towards the front view's camera), (s, t) by the convention's formulas,
// the texel by OpenGL's bilinear lookup (SampleTexture, held to OpenGL by
// the texture tests). Within the standard bound (1e-4 relative): the
// picture is laid over E in double and stored as float.
#include "oracle_scene.h"
#include "shadelabPixelRays.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace shadelab_test;
using nlohmann::json;

namespace
{
constexpr double Pi = 3.14159265358979323846;

// E along world direction d: the environment's frame for up +Y is the
// world's; s from the longitude, 0.5 straight ahead (-z), t from the
// latitude, 1 straight up; the longitude repeats, the latitude clamps.
Rgb EnvironmentAlong(const shadelab::TextureImage& image, const Vec3& d)
{
  shadelab::TextureMap map;
  map.Image = std::make_shared<shadelab::TextureImage>(image);
  map.WrapS = shadelab::TextureWrap::Repeat;
  map.WrapT = shadelab::TextureWrap::Clamp;
  const double s = 0.5 + std::atan2(d[0], -d[2]) / (2 * Pi);
  const double t = 0.5 + std::asin(d[1] / std::sqrt(dot(d, d))) / Pi;
  return shadelab::SampleTexture(map, s, t);
}

struct Rendered
{
  Image Picture;
  std::string Error;
};

Rendered RenderTeapot(const TempDir& dir, const std::string& name,
  const std::vector<std::string>& options, const std::string& size = "96x64")
{
  const auto out = dir / (name + ".exr");
  std::vector<std::string> args{ "render", TestMesh("teapot.obj").string(), "-o", out.string(),
    "--size", size, "--environment", (dir / "sky.png").string() };
  args.insert(args.end(), options.begin(), options.end());
  const RunResult r = RunShadelab(args);
  return { r.ExitCode == 0 ? ReadImage(out) : Image{}, r.Stderr };
}
}

// Plain, translucent (the far side through the near one, then the
// environment) and fogged towards no colour (the fog fades the mesh into
// the environment): each pixel is the transparent picture laid over E.
TEST(EnvironmentBackground, EveryPixelIsThePictureLaidOverTheEnvironmentAlongItsRay)
{
  TempDir dir;
  const EnvironmentImage sky = EnvironmentOf(EnvironmentKind::Pattern);
  WriteImage8(dir / "sky.png", sky.Width, sky.Height, sky.Bytes);
  const shadelab::TextureImage decoded = sky.Decoded();
  for (const std::vector<std::string>& extra :
    { std::vector<std::string>{}, { "--translucency", "0.5" }, { "--fog", "exp:0.15" } })
  {
    SCOPED_TRACE(extra.empty() ? "plain" : extra.front());
    std::vector<std::string> over = extra, clear = extra;
    over.insert(over.end(), { "--background", "environment" });
    clear.insert(clear.end(), { "--background", "transparent" });
    const Rendered environment = RenderTeapot(dir, "over", over);
    ASSERT_EQ(environment.Error, "");
    const Rendered transparent = RenderTeapot(dir, "clear", clear);
    ASSERT_EQ(transparent.Error, "");
    const Image& e = environment.Picture;
    const Image& t = transparent.Picture;
    ASSERT_EQ(t.Channels, 4);
    ASSERT_EQ(e.Width, t.Width);
    const json described = json::parse(e.Description);
    EXPECT_EQ(described.at("background"), "environment");
    const RecordedCamera c = CameraOf(e);
    shadelab::PinholeCamera camera;
    camera.Position = c.Position;
    camera.FocalPoint = c.Focal;
    camera.ViewUp = c.Up;
    camera.ViewAngle = c.ViewAngle;
    int uncovered = 0, partly = 0;
    for (int y = 0; y < e.Height; ++y)
    {
      for (int x = 0; x < e.Width; ++x)
      {
        const shadelab::Ray ray = shadelab::PictureRay(camera, e.Width, e.Height, x + 0.5, y + 0.5);
        const Rgb E = EnvironmentAlong(decoded, ray.Direction);
        // Files store rows from the top, as the picture counts them.
        const std::size_t at = static_cast<std::size_t>(y) * e.Width + x;
        const double a = t.Pixels[4 * at + 3];
        uncovered += a == 0;
        partly += a > 0 && a < 1;
        for (int k = 0; k < 3; ++k)
        {
          const double want = t.Pixels[4 * at + k] + (1 - a) * E[k];
          ASSERT_NEAR(e.Pixels[e.Channels * at + k], want,
            Standard.Relative * std::max(std::abs(want), Standard.Floor))
            << "pixel (" << x << ", " << y << ") channel " << k;
        }
      }
    }
    EXPECT_GT(uncovered, 1000);
    if (!extra.empty()) // translucency and fog leave pixels partly covered
    {
      EXPECT_GT(partly, 500);
    }
  }
}

// --ssaa N lays each sample over the environment along its own ray: the
// picture is the box average of the one rendered N times as large.
TEST(EnvironmentBackground, SupersamplingAveragesSamplesEachOverItsOwnRay)
{
  TempDir dir;
  const EnvironmentImage sky = EnvironmentOf(EnvironmentKind::Pattern);
  WriteImage8(dir / "sky.png", sky.Width, sky.Height, sky.Bytes);
  const Rendered small =
    RenderTeapot(dir, "ssaa", { "--background", "environment", "--ssaa", "2" }, "48x32");
  ASSERT_EQ(small.Error, "");
  const Rendered large = RenderTeapot(dir, "large", { "--background", "environment" }, "96x64");
  ASSERT_EQ(large.Error, "");
  const Image& s = small.Picture;
  const Image& l = large.Picture;
  double largest = 0;
  for (int y = 0; y < s.Height; ++y)
  {
    for (int x = 0; x < s.Width; ++x)
    {
      for (int k = 0; k < 3; ++k)
      {
        double sum = 0;
        for (int j = 0; j < 2; ++j)
        {
          for (int i = 0; i < 2; ++i)
          {
            sum +=
              l.Pixels[(static_cast<std::size_t>(2 * y + j) * l.Width + 2 * x + i) * l.Channels +
                k];
          }
        }
        largest = std::max(largest,
          std::abs(
            sum / 4 - s.Pixels[(static_cast<std::size_t>(y) * s.Width + x) * s.Channels + k]));
      }
    }
  }
  EXPECT_LT(largest, 1e-6); // float's rounding of the same average
}
