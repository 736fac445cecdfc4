// Environment reflections through the lecture's equation, pixel by pixel:
// orthographic renders by `shadelab render --environment` of the test grid
// (its vertex normals a bowl, so that R sweeps across the environment)
// against the double-precision oracle, which looks the environment up as
// shadelabEnvironment.h defines it. Every rule that lights, both filters,
// an environment whose up is the world's z, with a texture, and the 8-bit
// picture; the scenes and the comparison are oracle_scene.h's.
//
// The tolerance is the standard one (1e-4 relative): the image is uploaded
// as float texels, which llvmpipe filters in float (test_texture_oracle.cxx
// says how that was measured), and R's direction in float moves (s, t) by
// about 1e-7, some 1e-6 of a texel of these small images. With the nearest
// texel, pixels within the oracle's edge margin of a switch to another
// texel are left out (Oracle::Switches), as for textures.
#include "probe_support.h"

#include <gtest/gtest.h>

using namespace shadelab_test;
using shadelab::TextureFilter;

namespace
{
std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);
  for (Shading r : LitRules)
  {
    for (EnvironmentKind kind :
      { EnvironmentKind::Single, EnvironmentKind::Horizon, EnvironmentKind::Pattern })
    {
      for (TextureFilter filter : { TextureFilter::Nearest, TextureFilter::Bilinear })
      {
        Scene s;
        s.Rule = r;
        s.Environment = kind;
        s.Filter = filter;
        add(std::string(ToString(r)) + "_" +
            (kind == EnvironmentKind::Single       ? "single"
                : kind == EnvironmentKind::Horizon ? "horizon"
                                                   : "pattern") +
            "_" + ToString(filter),
          s);
      }
    }
    Scene s;
    s.Rule = r;
    s.Environment = EnvironmentKind::Pattern;
    s.ZUp = true;
    add("z_up_" + std::string(ToString(r)), s);
    s.OwnUp = true;
    add("own_z_up_" + std::string(ToString(r)), s);
    s.ZUp = s.OwnUp = false;
    s.Model = Reflection::Phong;
    s.Textured = true;
    add("textured_phong_model_" + std::string(ToString(r)), s);
    s.Textured = false;
    s.Model = Reflection::BlinnPhong;
    s.Drawn = shadelab::Representation::Wireframe;
    add("wireframe_" + std::string(ToString(r)), s);
    s = ColouredLights();
    s.Rule = r;
    s.Environment = EnvironmentKind::Pattern;
    s.EightBit = true;
    add("coloured_lights_" + std::string(ToString(r)) + "_png", s);
  }
  return cases;
}

class EnvironmentOracle : public testing::TestWithParam<Case>
{
};

// The picture's (x, y) channel c.
float At(const Image& image, int x, int y, int c)
{
  return image.Pixels[(static_cast<std::size_t>(y) * image.Width + x) * image.Channels + c];
}
}

TEST_P(EnvironmentOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, EnvironmentOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });

// A single-colour environment adds exactly ks * colour, whatever the
// normal, under every rule; under phong a two-colour one adds ks times one
// colour or the other, both on this grid (the nearest texel: no mix
// between them). Flat's plane reflects one way only, and gouraud mixes its
// vertices' colours across the horizon.
// Against the same scene without it, so that nothing but the environment
// is compared; within float's rounding of the sum (2e-6).
TEST(Environment, AddsKsTimesWhatItSees)
{
  for (Shading r : LitRules)
  {
    for (EnvironmentKind kind : { EnvironmentKind::Single, EnvironmentKind::Horizon })
    {
      if (kind == EnvironmentKind::Horizon && r != Shading::Phong)
      {
        continue;
      }
      SCOPED_TRACE(
        std::string(ToString(r)) + (kind == EnvironmentKind::Single ? " single" : " horizon"));
      Scene s;
      s.Rule = r;
      s.Filter = TextureFilter::Nearest;
      TempDir dir;
      std::string error;
      const Image without = Render(s, dir, error);
      ASSERT_EQ(error, "");
      s.Environment = kind;
      const Image with = Render(s, dir, error);
      ASSERT_EQ(error, "");
      ASSERT_EQ(with.Pixels.size(), without.Pixels.size());
      const auto added = [&](const unsigned char* colour, int c)
      { return s.Surface.Ks[c] * static_cast<float>(colour[c] / 255.0); };
      std::size_t sky = 0, ground = 0, other = 0;
      for (int y = 0; y < with.Height; ++y)
      {
        for (int x = 0; x < with.Width; ++x)
        {
          if (At(without, x, y, 0) == 0 && At(without, x, y, 1) == 0 && At(without, x, y, 2) == 0)
          {
            continue; // the background
          }
          const auto is = [&](const unsigned char* colour)
          {
            for (int c = 0; c < 3; ++c)
            {
              if (std::abs(At(with, x, y, c) - At(without, x, y, c) - added(colour, c)) > 2e-6)
              {
                return false;
              }
            }
            return true;
          };
          if (kind == EnvironmentKind::Single)
          {
            other += !is(SingleEnvironment);
            ++sky;
            continue;
          }
          sky += is(Sky);
          ground += is(Ground);
          other += !is(Sky) && !is(Ground);
        }
      }
      EXPECT_EQ(other, 0u);
      EXPECT_GT(sky, 500u);
      if (kind == EnvironmentKind::Horizon)
      {
        EXPECT_GT(ground, 500u);
      }
    }
  }
}

// A batch keeps a rule's actor from shot to shot (SceneCache), and with it
// the uploaded environment when the image is the same: the next shot's
// filter must still apply, and another image must replace it. Each shot of
// a scene file equals its own render.
TEST(EnvironmentBatch, EachShotReflectsAsItsOwnRender)
{
  TempDir dir;
  Scene s;
  const std::string mesh = SceneArguments(s, dir).front();
  for (const auto& [name, kind] : { std::pair{ "pattern.png", EnvironmentKind::Pattern },
         { "horizon.png", EnvironmentKind::Horizon } })
  {
    const EnvironmentImage e = EnvironmentOf(kind);
    WriteImage8(dir / name, e.Width, e.Height, e.Bytes);
  }
  const auto image = [&dir](const char* name) { return (dir / name).string(); };
  ExpectEachShotIsItsOwnRender(dir,
    R"({ "mesh": ")" + mesh + R"(", "environment": "pattern.png", "size": [64, 64],
         "material": "chrome",
         "shots": [ { "texture_filter": "nearest" }, { "texture_filter": "bilinear" },
                    { "environment": "horizon.png" } ] })",
    mesh,
    { { "--environment", image("pattern.png"), "--texture-filter", "nearest" },
      { "--environment", image("pattern.png"), "--texture-filter", "bilinear" },
      { "--environment", image("horizon.png"), "--texture-filter", "bilinear" } });
  // The picture says what it reflects.
  const json described = json::parse(ReadImage(dir / "shot0.exr").Description);
  EXPECT_EQ(described.at("environment"),
    json({ { "image", (dir / "pattern.png").string() }, { "up", "+Y" }, { "filter", "nearest" } }));
  EXPECT_NE(ReadImage(dir / "shot0.exr").Pixels, ReadImage(dir / "shot1.exr").Pixels);
  EXPECT_NE(ReadImage(dir / "shot1.exr").Pixels, ReadImage(dir / "shot2.exr").Pixels);
}

// probe explains the environment's term where it lights: R, (s, t), the
// texel and ks*E(R) as the oracle has them, adding up with the other terms
// to the oracle (gouraud's at each vertex, mixed by the weights), and the
// render within the oracle tests' bound of it.
TEST(EnvironmentProbe, ItsTermAddsUpToTheOracle)
{
  for (Shading r : LitRules)
  {
    SCOPED_TRACE(ToString(r));
    Scene s;
    s.Rule = r;
    s.Environment = EnvironmentKind::Pattern;
    TempDir dir;
    const Oracle oracle(s);
    const std::vector<std::array<int, 2>> pixels = ComparedPixels(s, oracle);
    std::string error;
    const std::vector<json> probes = Probe(SceneArguments(s, dir), pixels, error);
    ASSERT_EQ(error, "");
    ASSERT_EQ(probes.size(), pixels.size());
    ASSERT_GT(probes.size(), 100u);
    for (std::size_t i = 0; i < probes.size(); ++i)
    {
      const json& p = probes[i];
      const Rgb total = Vec(p.at("oracle"));
      if (r == Shading::Gouraud)
      {
        Rgb mixed{};
        for (const json& v : p.at("vertices"))
        {
          ASSERT_TRUE(v.contains("environment"));
          mixed = mixed + v.at("weight").get<double>() * TermsSum(v);
        }
        ExpectNear(mixed, total, 1e-12, "the vertices' terms mixed");
      }
      else
      {
        const shadelab::IlluminationTerms expected = oracle.At(pixels[i][0], pixels[i][1]).Terms;
        ASSERT_TRUE(expected.Environment);
        const json& e = p.at("environment");
        // The probe lights the mesh as read (float normals, 3e-8 off the
        // grid's), the harness the grid in double: R and E(R) agree to
        // that; the probe's own terms add up exactly.
        ExpectNear(Vec(e.at("R")), expected.Environment->R, 1e-6, "R");
        ExpectNear(Vec(e.at("texel")), expected.Environment->Texel, 1e-6, "E(R)");
        ExpectNear(Vec(e.at("term")), s.Surface.Ks * Vec(e.at("texel")), 1e-12, "ks*E(R)");
        ExpectNear(TermsSum(p), total, 1e-12, "the terms' sum");
      }
      ExpectWithinTheBound(Vec(p.at("rendered")), total);
    }
  }
}
