// probe on raster pictures with --shadows (doc/design.md, "Shadows" and
// "Explaining a pixel"): each light's `shadowed` is the oracle's shadow
// ray, and `shadow_map_agrees` is the picture's own map test redone in
// double (ShadowMap::Lit), so where it agrees the picture is the oracle's.
#include "probe_support.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

// Shadows on the teapot (the lid, the spout and the handle shade its body):
// each light's `shadowed` is the oracle's shadow ray, and where the
// picture's shadow map decided alike (`shadow_map_agrees`) the rendered
// value is the oracle's within the bound; where it did not, the picture
// differs from the oracle at the shadow's edge, as the probe says.
TEST(Probe, ShadowedIsTheShadowRayAndTheMapsAgreementIsThePictures)
{
  for (const char* rule : { "phong", "gouraud", "flat" })
  {
    std::vector<std::array<int, 2>> pixels;
    for (int y = 0; y < 96; y += 3)
    {
      for (int x = 0; x < 128; x += 3)
      {
        pixels.push_back({ x, y });
      }
    }
    std::string error;
    const std::vector<json> p =
      Probe({ Teapot, "--size", "128x96", "--camera-position", "0,5,8", "--camera-focal-point",
              "0,1.3,0", "--view-angle", "32", "--material", "gold", "--shading", rule, "--shadows",
              "--light", "point:-6,2,0", "--light", "directional:-1,-0.5,-0.2:0.4,0.4,0.4",
              "--light", "point:4,6,5:0.3,0.3,0.3+no-shadows" },
        pixels, error);
    ASSERT_EQ(error, "");
    int shadowed = 0, agreed = 0, disagreed = 0;
    for (const json& at : p)
    {
      if (!at.at("hit").get<bool>())
      {
        continue;
      }
      const json& lights = at.at("lights");
      EXPECT_FALSE(lights.at(2).contains("shadowed")) << "a light that casts none";
      bool agrees = true;
      for (int l = 0; l < 2; ++l)
      {
        shadowed += lights.at(l).at("shadowed").get<bool>();
        agrees = agrees && lights.at(l).value("shadow_map_agrees", true);
      }
      if (!agrees)
      {
        ++disagreed;
        continue;
      }
      ++agreed;
      if (!NearACase(lights))
      {
        ExpectWithinTheBound(Vec(at.at("rendered")), Vec(at.at("oracle")));
      }
    }
    std::printf(
      "[probe] %s: %d light-pixels in shadow; the maps agree at %d pixels, disagree at %d\n", rule,
      shadowed, agreed, disagreed);
    EXPECT_GT(shadowed, 50) << rule;
    EXPECT_LT(disagreed, agreed / 20) << rule;
  }
}

// The torus shadowing itself under phong, lit nearly in its plane: at its
// terminator the interpolated normal leans towards the light while the
// faces turn away, and the map's bias slopes by the face. The probe's map
// test must slope by the same face: at every compared pixel it agrees with
// the ray, as the picture does (ShadowOracle's torus_phong), and the
// picture is the oracle's there.
TEST(Probe, TheMapsAgreementSlopesByTheFaceAsPhongsShaderDoes)
{
  Scene s;
  s.Rule = Shading::Phong;
  s.Geometry.Cells = 12;
  s.Size = 192;
  s.Geometry.Torus = true;
  s.Shadows = true;
  s.Lights = { Directional({ 0.4, -1, -0.15 }) };
  TempDir dir;
  std::string error;
  const Image image = Render(s, dir, error);
  ASSERT_EQ(error, "");
  const Oracle oracle(s);
  // Every compared pixel: the terminator's acne lay at single pixels.
  std::vector<std::array<int, 2>> pixels;
  for (int y = 0; y < s.Size; ++y)
  {
    for (int x = 0; x < s.Size; ++x)
    {
      if (oracle.At(x, y).What == Expected::Interior)
      {
        pixels.push_back({ x, y });
      }
    }
  }
  const std::vector<json> answers = Probe(SceneArguments(s, dir), pixels, error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(answers.size(), pixels.size());
  int shadowed = 0, disagreed = 0;
  for (std::size_t i = 0; i < answers.size(); ++i)
  {
    const auto [x, y] = pixels[i];
    SCOPED_TRACE(PixelName(x, y));
    const json& light = answers[i].at("lights").at(0);
    if (!light.contains("shadow_map_agrees"))
    {
      continue; // N.L <= 0: the light adds nothing, no ray is cast
    }
    shadowed += light.at("shadowed").get<bool>();
    disagreed += !light.at("shadow_map_agrees").get<bool>();
    ExpectWithinTheBound(Got(image, x, y), Vec(answers[i].at("oracle")));
  }
  std::printf("[probe] torus under phong: %zu pixels, %d in shadow, the map disagrees at %d\n",
    answers.size(), shadowed, disagreed);
  EXPECT_GT(shadowed, 5);
  EXPECT_EQ(disagreed, 0);
}
