// `shadelab probe` on edges and points (doc/design.md, "Representations"):
// the element drawn at a pixel, its terms, the oracle against the render.
#include "probe_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

using namespace shadelab_test;

namespace
{
// Edges and points, in perspective: the element drawn at the pixel (an
// edge of the triangle that owns it, or a corner of it), its terms adding
// up to the oracle, and the oracle the rendered value away from where an
// element's coverage may change; the background elsewhere.
class ProbeElements : public testing::TestWithParam<std::tuple<Shading, bool>>
{
};
}

TEST_P(ProbeElements, AgreeWithRenderAndTheOracle)
{
  const auto [rule, points] = GetParam();
  std::vector<std::string> common{ Teapot, "--size", "480x400", "--background", Triple(Background),
    "--shading", ToString(rule), "--material", "polished-copper", "--view", "iso", "--zoom", "1.6",
    "--representation", points ? "points" : "wireframe", points ? "--point-size" : "--line-width",
    points ? "5" : "2" };
  common.insert(common.end(), TeapotLights.begin(), TeapotLights.end());
  TempDir dir;
  std::vector<std::string> render{ "render", "-o", (dir / "out.exr").string() };
  render.insert(render.end(), common.begin(), common.end());
  const RunResult rendered = RunShadelab(render);
  ASSERT_EQ(rendered.ExitCode, 0) << rendered.Stderr;
  const Image picture = ReadImage(dir / "out.exr");
  std::vector<std::array<int, 2>> pixels;
  for (int y = 0; y < 400; y += 4)
  {
    for (int x = 1; x < 480; x += 4)
    {
      pixels.push_back({ x, y });
    }
  }
  std::string error;
  const std::vector<json> probes = Probe(common, pixels, error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(probes.size(), pixels.size());
  const auto mesh = ReadMesh(Teapot);
  constexpr double Margin = 0.25; // as the oracle tests' ElementMargin
  std::size_t compared = 0, background = 0;
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const json& p = probes[i];
    SCOPED_TRACE(PixelName(pixels[i][0], pixels[i][1]));
    const Rgb got = Got(picture, pixels[i][0], pixels[i][1]);
    const double margin = p.at("edge_distance").get<double>();
    if (!p.at("hit").get<bool>())
    {
      if (margin > Margin)
      {
        ++background;
        EXPECT_EQ(got, (Rgb{ float(Background[0]), float(Background[1]), float(Background[2]) }));
      }
      continue;
    }
    const json& element = p.at("element");
    EXPECT_EQ(element.at("representation"), points ? "points" : "wireframe");
    const auto corners = Corners(mesh, p.at("triangle").get<vtkIdType>());
    const auto ends = element.at("points").get<std::vector<vtkIdType>>();
    ASSERT_EQ(ends.size(), points ? 1u : 2u);
    for (vtkIdType end : ends)
    {
      EXPECT_NE(std::find(corners.begin(), corners.end(), end), corners.end())
        << "not the owning triangle's";
    }
    const Rgb oracle = Vec(p.at("oracle"));
    ExpectNear(TermsSum(p), oracle, 1e-12, "ambient + terms against the oracle");
    if (margin <= Margin || NearACase(p.at("lights")))
    {
      continue;
    }
    ++compared;
    ExpectWithinTheBound(got, oracle);
  }
  std::cout << "[probe] " << ToString(rule) << (points ? " points: " : " wireframe: ") << compared
            << " compared with the oracle, " << background << " background" << std::endl;
  EXPECT_GE(compared, 300u);
  EXPECT_GE(background, 5000u);
}

INSTANTIATE_TEST_SUITE_P(Probe, ProbeElements,
  testing::Combine(testing::ValuesIn(LitRules), testing::Bool()),
  [](const testing::TestParamInfo<std::tuple<Shading, bool>>& info)
  {
    return std::string(ToString(std::get<0>(info.param))) +
      (std::get<1>(info.param) ? "_points" : "_wireframe");
  });
