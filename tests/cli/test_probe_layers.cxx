// probe on translucent pictures (doc/design.md, "Translucency" and
// "Explaining a pixel"): every surface under the pixel, nearest first, with
// its a and I, and their composite, the oracle. On the translucency oracle
// test's three sheets: the probe's oracle equals the test's own
// (oracle_scene.h) and what render drew, within the oracle tests' bound, at
// every compared pixel of a coarse grid, and what each layer adds sums to
// it; its coverage is the picture's
// alpha with a transparent background; the layers beyond --peels are said
// to be left out.
#include "probe_support.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

namespace
{
Scene Sheets()
{
  Scene s = ColouredLights();
  s.Geometry.VertexColors = true;
  s.Geometry.Sheets = { 2, 0, 1 };
  s.Translucency = 0.5;
  return s;
}

// Probes the compared pixels of s, and checks each against the test's
// oracle and the rendered picture; the answers, for more checks.
std::vector<json> ProbeAgainstTheOracle(const Scene& s, const Image& image)
{
  TempDir dir;
  const Oracle oracle(s);
  const auto pixels = ComparedPixels(s, oracle);
  std::string error;
  const std::vector<json> answers = Probe(SceneArguments(s, dir), pixels, error);
  EXPECT_EQ(error, "");
  EXPECT_EQ(answers.size(), pixels.size());
  for (std::size_t i = 0; i < answers.size() && i < pixels.size(); ++i)
  {
    const auto [x, y] = pixels[i];
    const json& a = answers[i];
    SCOPED_TRACE(PixelName(x, y));
    ExpectNear(Vec(a.at("oracle")), oracle.At(x, y).Value, 1e-12, "probe's and test's oracle");
    ExpectWithinTheBound(Got(image, x, y), Vec(a.at("oracle")));
    // layers[0] is what the rest explains; the layers lie ever deeper, and
    // what each adds sums to the oracle (the background is black).
    EXPECT_EQ(a.at("layers").at(0).at("triangle"), a.at("triangle"));
    Rgb sum{ 0, 0, 0 };
    double depth = -1e300;
    for (const json& layer : a.at("layers"))
    {
      sum = sum + Vec(layer.at("adds"));
      EXPECT_GT(layer.at("depth").get<double>(), depth);
      depth = layer.at("depth").get<double>();
    }
    ExpectNear(sum, Vec(a.at("oracle")), 1e-12, "the layers' adds and the oracle");
  }
  return answers;
}
}

TEST(ProbeLayers, ComposeTheOracleAndTheRenderedPixel)
{
  const Scene s = Sheets();
  TempDir dir;
  std::string error;
  const Image image = Render(s, dir, error);
  ASSERT_EQ(error, "");
  const std::vector<json> answers = ProbeAgainstTheOracle(s, image);
  std::size_t threeDeep = 0;
  for (const json& a : answers)
  {
    threeDeep += a.at("layers").size() == 3;
    EXPECT_EQ(a.at("coverage"), 1.0); // over the opaque black background
  }
  EXPECT_GE(threeDeep, 20u) << "pixels where all three sheets overlap";
}

TEST(ProbeLayers, CoverageIsTheAlphaOverATransparentBackground)
{
  Scene s = Sheets();
  s.TransparentBackground = true;
  TempDir dir;
  std::string error;
  const Image image = Render(s, dir, error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(image.Channels, 4);
  const Oracle oracle(s);
  const auto pixels = ComparedPixels(s, oracle);
  const std::vector<json> answers = ProbeAgainstTheOracle(s, image);
  ASSERT_EQ(answers.size(), pixels.size());
  for (std::size_t i = 0; i < answers.size(); ++i)
  {
    const auto [x, y] = pixels[i];
    const std::size_t layers = answers[i].at("layers").size();
    const double coverage = 1 - std::pow(0.5, static_cast<double>(layers));
    EXPECT_DOUBLE_EQ(answers[i].at("coverage").get<double>(), coverage) << PixelName(x, y);
    const float alpha = image.Pixels[(static_cast<std::size_t>(y) * image.Width + x) * 4 + 3];
    EXPECT_NEAR(alpha, coverage, 1e-6) << PixelName(x, y);
  }
}

TEST(ProbeLayers, SayWhichLayersPeelsLeaveOut)
{
  Scene s = Sheets();
  s.Peels = 1;
  TempDir dir;
  std::vector<std::string> args{ "probe" };
  const std::vector<std::string> scene = SceneArguments(s, dir);
  args.insert(args.end(), scene.begin(), scene.end());
  const Oracle oracle(s);
  // A pixel under all three sheets.
  std::vector<std::array<int, 2>> deep;
  std::string error;
  for (const json& a : Probe(scene, ComparedPixels(s, oracle), error))
  {
    if (a.at("layers").size() == 3)
    {
      deep.push_back({ a.at("pixel").at(0).get<int>(), a.at("pixel").at(1).get<int>() });
      break;
    }
  }
  ASSERT_EQ(error, "");
  ASSERT_FALSE(deep.empty());
  args.insert(
    args.end(), { "--pixel", std::to_string(deep[0][0]) + "," + std::to_string(deep[0][1]) });
  const RunResult r = RunShadelab(args);
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  std::size_t leftOut = 0;
  for (std::size_t at = r.Stdout.find("beyond --peels"); at != std::string::npos;
       at = r.Stdout.find("beyond --peels", at + 1))
  {
    ++leftOut;
  }
  EXPECT_EQ(leftOut, 2u) << r.Stdout;
  EXPECT_NE(r.Stdout.find("composited = "), std::string::npos) << r.Stdout;
}
