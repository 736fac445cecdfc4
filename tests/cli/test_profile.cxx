// `shadelab profile`: Mach bands as a measurement. Along a line across the
// torus (orthographic, so that screen-space interpolation is linear), flat's
// luminance is constant within each triangle and steps at its edges,
// gouraud's is linear within each triangle (second difference at float's
// rounding) and kinks at the edges, and phong's is the oracle's; the chart
// plots the CSV's numbers; bad lines and outputs are one-line errors.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

using namespace shadelab_test;

namespace
{
// A CSV without quoted fields, by column name; an empty field is NaN.
std::map<std::string, std::vector<double>> ReadCsv(const std::string& text)
{
  std::istringstream in(text);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  std::istringstream header(line);
  for (std::string name; std::getline(header, name, ',');)
  {
    names.push_back(name);
  }
  std::map<std::string, std::vector<double>> columns;
  while (std::getline(in, line))
  {
    std::istringstream row(line + ",");
    std::string field;
    for (const std::string& name : names)
    {
      std::getline(row, field, ',');
      columns[name].push_back(field.empty() ? std::nan("") : std::stod(field));
    }
  }
  return columns;
}

const std::vector<std::string> TorusLine{ "profile", "", "--size", "320x240", "--orthographic",
  "--line", "0,120,319,120" };

std::vector<std::string> Profile(const std::vector<std::string>& outputs)
{
  std::vector<std::string> args = TorusLine;
  args[1] = TestMesh("torus.obj").string();
  for (const std::string& output : outputs)
  {
    args.push_back("-o");
    args.push_back(output);
  }
  return args;
}
}

TEST(Profile, FlatStepsGouraudKinksAndPhongIsTheOracle)
{
  const TempDir dir;
  const RunResult r = RunShadelab(Profile({ (dir / "p.csv").string() }));
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_NE(r.Stdout.find("triangle edges crossed"), std::string::npos) << r.Stdout;
  auto c = ReadCsv(Slurp(dir / "p.csv"));
  const std::vector<double>& triangle = c["triangle"];
  const std::size_t n = triangle.size();
  ASSERT_EQ(n, 320u) << "a sample per column";
  // Compared where the pixel centre is half a pixel or more inside its
  // triangle: there every rule's rasteriser takes the triangle the probe
  // took (check-shader's margin).
  const auto inside = [&](std::size_t i) { return triangle[i] >= 0 && c["edge"][i] >= 0.5; };
  const auto same = [&](std::size_t i, std::size_t j)
  { return inside(i) && inside(j) && triangle[i] == triangle[j]; };

  // Flat: one value per triangle (the same inputs at every fragment), and
  // steps where the line crosses an edge.
  const std::vector<double>& flat = c["flat luminance"];
  int withinFlat = 0, steps = 0;
  for (std::size_t i = 0; i + 1 < n; ++i)
  {
    if (same(i, i + 1))
    {
      ++withinFlat;
      EXPECT_LE(std::abs(flat[i + 1] - flat[i]), 1e-7) << "sample " << i;
    }
    else if (triangle[i] >= 0 && triangle[i + 1] >= 0)
    {
      steps += std::abs(c["flat first"][i]) > 1e-3;
    }
  }
  EXPECT_GT(withinFlat, 50);
  EXPECT_GE(steps, 6);

  // Gouraud: linear in screen space within a triangle, so its second
  // difference is float's rounding of three values near 1 (about 1e-7);
  // at the edges the slope changes: a kink a thousand times that.
  const std::vector<double>& second = c["gouraud second"];
  int withinGouraud = 0;
  double kink = 0;
  for (std::size_t i = 1; i + 1 < n; ++i)
  {
    if (same(i - 1, i) && same(i, i + 1))
    {
      ++withinGouraud;
      EXPECT_LE(std::abs(second[i]), 1e-6) << "sample " << i;
    }
    else if (!std::isnan(second[i]))
    {
      kink = std::max(kink, std::abs(second[i]));
    }
  }
  EXPECT_GT(withinGouraud, 40);
  EXPECT_GT(kink, 1e-3);

  // Phong: the oracle's, within the oracle tests' bound.
  int compared = 0;
  double gouraudFromOracle = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (inside(i))
    {
      ++compared;
      const double oracle = c["oracle luminance"][i];
      EXPECT_LE(std::abs(c["phong luminance"][i] - oracle), 1e-4 * std::max(oracle, 0.01))
        << "sample " << i;
      gouraudFromOracle = std::max(gouraudFromOracle, std::abs(c["gouraud luminance"][i] - oracle));
    }
  }
  EXPECT_GT(compared, 60);
  EXPECT_GT(gouraudFromOracle, 0.05) << "gouraud misses the highlight's peak";
}

// The chart plots the CSV's numbers: in the luminance chart (the top third,
// left of the inset), flat's red spans the columns of the samples on the
// mesh, and its highest plateau lies over the samples where the CSV's flat
// luminance is largest.
TEST(Profile, TheChartPlotsTheCsvsNumbers)
{
  const TempDir dir;
  std::vector<std::string> args = Profile({ (dir / "p.png").string(), (dir / "p.csv").string() });
  args.insert(args.end(), { "--modes", "flat" });
  const RunResult r = RunShadelab(args);
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  auto c = ReadCsv(Slurp(dir / "p.csv"));
  const std::vector<double>& triangle = c["triangle"];
  const std::vector<double>& flat = c["flat luminance"];
  std::size_t first = triangle.size(), last = 0;
  double largest = 0;
  for (std::size_t i = 0; i < triangle.size(); ++i)
  {
    if (triangle[i] >= 0)
    {
      first = std::min(first, i);
      last = i;
      largest = std::max(largest, flat[i]);
    }
  }
  ASSERT_LT(first, last);
  std::size_t plateauFirst = last, plateauLast = first;
  for (std::size_t i = first; i <= last; ++i)
  {
    if (triangle[i] >= 0 && flat[i] >= largest - 1e-9)
    {
      plateauFirst = std::min(plateauFirst, i);
      plateauLast = i;
    }
  }

  const Image chart = ReadImage(dir / "p.png");
  ASSERT_EQ(chart.Width, 1400);
  ASSERT_EQ(chart.Height, 1000);
  const auto red = [&](int x, int y)
  {
    const float* p =
      &chart.Pixels[(static_cast<std::size_t>(y) * chart.Width + x) * chart.Channels];
    return std::abs(p[0] - 214) < 40 && std::abs(p[1] - 39) < 40 && std::abs(p[2] - 40) < 40;
  };
  int left = chart.Width, right = -1, top = chart.Height;
  for (int y = 40; y < 40 + 320; ++y)
  {
    for (int x = 0; x < 1000; ++x)
    {
      if (red(x, y))
      {
        left = std::min(left, x);
        right = std::max(right, x);
        top = std::min(top, y);
      }
    }
  }
  ASSERT_LT(left, right) << "flat's curve in the luminance chart";
  int topLeft = right, topRight = left;
  for (int x = left; x <= right; ++x)
  {
    for (int y = top; y <= top + 2; ++y)
    {
      if (red(x, y))
      {
        topLeft = std::min(topLeft, x);
        topRight = std::max(topRight, x);
      }
    }
  }
  // Samples to columns, as the red span's ends say; within 3 pixels (the
  // line's width and its joins).
  const auto column = [&](std::size_t i)
  {
    return left +
      (right - left) * (static_cast<double>(i) - static_cast<double>(first)) / (last - first);
  };
  EXPECT_NEAR(topLeft, column(plateauFirst), 3);
  EXPECT_NEAR(topRight, column(plateauLast), 3);
  // And the axis runs from sample 0 at the plot's left to the last sample
  // at its right: the charts fill the picture's width left of the inset
  // (1010 of 1400 pixels), their axis labels left of the plot.
  const std::size_t n = triangle.size();
  EXPECT_GT(column(0), 30);
  EXPECT_LT(column(0), 110);
  EXPECT_GT(column(n - 1), 960);
  EXPECT_LT(column(n - 1), 1010);
}

// A line that is not four numbers, or leaves the picture, is a usage error
// naming --line; an output whose folder is missing names the output; no
// output is written.
TEST(Profile, BadLinesAndOutputsAreOneLineErrors)
{
  const TempDir dir;
  const std::string out = (dir / "p.csv").string();
  struct Case
  {
    std::string Line;
    std::string Output;
    int Exit;
    std::string Says;
  };
  for (const Case& k : { Case{ "0,120,319", out, 2, "--line: '0,120,319' is not X0,Y0,X1,Y1" },
         Case{ "0,120,320,120", out, 2, "--line: the end 320,120 is outside the 320x240 picture" },
         Case{ "-1,0,5,5", out, 2, "the end -1,0 is outside" },
         Case{ "0,120,319,120", (dir / "no" / "p.csv").string(), 1, "p.csv" } })
  {
    SCOPED_TRACE(k.Line);
    std::vector<std::string> args = Profile({ k.Output });
    args[6] = k.Line;
    const RunResult r = RunShadelab(args);
    EXPECT_EQ(r.ExitCode, k.Exit);
    EXPECT_NE(r.Stderr.find(k.Says), std::string::npos) << r.Stderr;
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
    EXPECT_TRUE(dir.Files().empty());
  }
}
