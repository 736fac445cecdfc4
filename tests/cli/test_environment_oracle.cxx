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
#include "oracle_scene.h"

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
            (kind == EnvironmentKind::Single    ? "single"
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
    s.ZUp = false;
    s.Model = Reflection::Phong;
    s.Textured = true;
    add("textured_phong_model_" + std::string(ToString(r)), s);
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
      SCOPED_TRACE(std::string(ToString(r)) +
        (kind == EnvironmentKind::Single ? " single" : " horizon"));
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
