// probe on ray-traced pictures (doc/design.md, "Ray tracing" and
// "Explaining a pixel"): where the sample's light comes from, each surface
// its rays met (the camera's, the mirrors', through translucent ones) with
// its own light, each light's shadow ray, and what it adds; the adds sum
// to the oracle. On the ray-traced oracle test's mirror grid under the
// square and on its translucent sheets: the probe's oracle equals the
// test's own (oracle_scene.h) and what render drew, within the oracle
// tests' bound, at every compared pixel of a coarse grid.
#include "probe_support.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

namespace
{
// Every fourth pixel each way that the oracle compares, probed and held to
// the test's oracle and the rendered picture; the answers.
std::vector<json> ProbeAgainstTheOracle(const Scene& s)
{
  TempDir dir;
  std::string error;
  const Image image = Render(s, dir, error);
  EXPECT_EQ(error, "");
  const Oracle oracle(s);
  const std::vector<std::array<int, 2>> pixels = ComparedPixels(s, oracle);
  const std::vector<json> answers = Probe(SceneArguments(s, dir), pixels, error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(answers.size(), pixels.size());
  for (std::size_t i = 0; i < answers.size() && i < pixels.size(); ++i)
  {
    const auto [x, y] = pixels[i];
    const json& a = answers[i];
    SCOPED_TRACE(PixelName(x, y));
    // The probe's rays meet the triangles through Embree, the test's by
    // projection: the same points up to roundings.
    ExpectNear(Vec(a.at("oracle")), oracle.At(x, y).Value, 1e-9, "probe's and test's oracle");
    ExpectWithinTheBound(Got(image, x, y), Vec(a.at("oracle")));
    Rgb sum{ 0, 0, 0 };
    for (const json& source : a.at("raytrace").at("sources"))
    {
      sum = sum + Vec(source.at("adds"));
    }
    ExpectNear(sum, Vec(a.at("oracle")), 1e-12, "the sources' adds and the oracle");
    const json& first = a.at("raytrace").at("sources").at(0);
    EXPECT_EQ(first.at("triangle"), a.at("triangle")) << "the first source is the nearest surface";
  }
  return answers;
}

// How many answers have a source of `kind` that adds something.
std::size_t WithSource(const std::vector<json>& answers, const std::string& kind)
{
  return std::count_if(answers.begin(), answers.end(),
    [&](const json& a)
    {
      const json& sources = a.at("raytrace").at("sources");
      return std::any_of(sources.begin(), sources.end(),
        [&](const json& s) {
          return s.at("kind") == kind && Vec(s.at("adds")) != Rgb{ 0, 0, 0 };
        });
    });
}
}

TEST(ProbeRaytrace, MirrorsAndShadowsSumToTheOracle)
{
  Scene s;
  s.Rule = Shading::Raytrace;
  s.Geometry.Cells = 12;
  s.Size = 192;
  s.Geometry.Occluder = true;
  s.Geometry.Bump = 0;
  s.Lights = { Point({ 0.6, 0.6, 1.4 }) };
  s.Surface.Ks = { 0.75, 0.8125, 0.875 };
  const std::vector<json> answers = ProbeAgainstTheOracle(s);
  EXPECT_GE(WithSource(answers, "reflected"), 20u) << "pixels whose mirror sees the square";
  const std::size_t shadowed = std::count_if(answers.begin(), answers.end(),
    [](const json& a)
    { return a.at("raytrace").at("sources").at(0).at("shadowed").at(0) == true; });
  EXPECT_GE(shadowed, 20u) << "pixels in the square's shadow";
}

TEST(ProbeRaytrace, LightThroughTranslucentSheetsSumsToTheOracle)
{
  Scene s;
  s.Rule = Shading::Raytrace;
  s.Geometry.Sheets = { 2, 0, 1 };
  s.Translucency = 0.5;
  s.Reflections = 0;
  const std::vector<json> answers = ProbeAgainstTheOracle(s);
  EXPECT_GE(WithSource(answers, "transmitted"), 20u) << "pixels under more than one sheet";
}
