// `shadelab bench --quick` end to end: the files it writes and
// what its measurements must show.
#include "bench/speed_accuracy.h"
#include "cli_test_support.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace shadelab_test;

namespace
{
std::string ReadAll(const std::filesystem::path& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}
}

// phong < gouraud < flat at every level: the expectation, and what
// the full run shows too (BENCHMARKS.md).
TEST(BenchCommand, QuickRunWritesTheFilesAndErrorFallsWithTessellation)
{
  TempDir dir;
  const auto out = dir / "results";
  const RunResult run = RunShadelab({ "bench", "--quick", "--frames", "1", "--out", out.string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Stderr;
  EXPECT_EQ(run.Stderr, "") << "no progress bar when stderr is not a terminal";

  std::vector<shadelab::SpeedAccuracyRow> rows;
  ASSERT_EQ(shadelab::ReadSpeedAccuracyCsv((out / "speed_accuracy.csv").string(), rows), "");
  // 2 surfaces x 4 levels x 3 rules, at 640x480.
  ASSERT_EQ(rows.size(), 24u);
  std::ifstream json(out / "speed_accuracy.json");
  EXPECT_EQ(nlohmann::json::parse(json).size(), rows.size());
  const std::string summary = ReadAll(out / "speed_accuracy.md");
  EXPECT_NE(summary.find("## sphere, 640x480"), std::string::npos);
  EXPECT_NE(summary.find("## torus, 640x480"), std::string::npos);

  // surface -> rule -> RMSE by increasing triangle count
  std::map<std::string, std::map<std::string, std::vector<double>>> errors;
  for (const auto& r : rows)
  {
    EXPECT_TRUE(std::isfinite(r.Rmse) && std::isfinite(r.MaxError) && r.MsPerFrame > 0);
    EXPECT_GT(r.Pixels, 40000) << "most of the object is compared";
    errors[r.Surface][r.Shading].push_back(r.Rmse);
  }
  for (const auto& [surface, byRule] : errors)
  {
    for (const auto& [rule, rmse] : byRule)
    {
      ASSERT_EQ(rmse.size(), 4u);
      // Each level halves the edges: flat's error is first order in the
      // edge length (about x0.5 a level), Gouraud's and Phong's second
      // order (about x0.25-0.5 here). 0.75 (0.95 from the coarsest level,
      // whose highlights fall unevenly) fails a rule that does not converge
      // at all, as flat under a rotated camera once did.
      for (std::size_t k = 1; k < rmse.size(); ++k)
      {
        EXPECT_LT(rmse[k], (k == 1 ? 0.95 : 0.75) * rmse[k - 1])
          << surface << " " << rule << " level " << k;
      }
      if (rule != "phong")
      {
        continue;
      }
      for (std::size_t k = 0; k < rmse.size(); ++k)
      {
        EXPECT_LT(rmse[k], byRule.at("gouraud")[k]) << surface << " level " << k;
        EXPECT_LT(byRule.at("gouraud")[k], byRule.at("flat")[k]) << surface << " level " << k;
      }
    }
  }

  const Image chart = ReadImage(out / "speed_accuracy.png");
  ASSERT_EQ(chart.Width, 1600);
  ASSERT_EQ(chart.Height, 1000);
  // The three rules' line colours are drawn (flat red, gouraud green, phong blue).
  int red = 0, green = 0, blue = 0;
  for (std::size_t p = 0; p + 2 < chart.Pixels.size(); p += chart.Channels)
  {
    const float r = chart.Pixels[p], g = chart.Pixels[p + 1], b = chart.Pixels[p + 2];
    red += r > 180 && g < 80 && b < 80;
    green += g > 130 && r < 80 && b < 80;
    blue += b > 150 && r < 60 && g > 90 && g < 140;
  }
  EXPECT_GT(red, 500);
  EXPECT_GT(green, 500);
  EXPECT_GT(blue, 500);
}

TEST(BenchCommand, BadOutputFolderIsOneLine)
{
  const RunResult run = RunShadelab({ "bench", "--quick", "--out", "/proc/no/such/folder" });
  EXPECT_EQ(run.ExitCode, 1);
  EXPECT_NE(run.Stderr.find("shadelab: error: /proc/no/such/folder: cannot make the folder"),
    std::string::npos)
    << run.Stderr;
  EXPECT_EQ(std::count(run.Stderr.begin(), run.Stderr.end(), '\n'), 1);
  EXPECT_EQ(RunShadelab({ "bench", "--frames", "0" }).ExitCode, 2);
}
