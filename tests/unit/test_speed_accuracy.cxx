// The pieces of `shadelab bench` that need no renderer: the error metrics,
// the mesh-coarseness measure, the CSV and JSON files, the checks, the
// progress line.
#include "bench/speed_accuracy.h"
#include "core/progress_bar.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace shadelab;

namespace
{
// A width x height pair: the exact picture covers the square [x0, x1)^2 with
// 0.5; the rendered one covers the same square with 0.5 + error.
std::pair<FloatImage, ExactImage> Square(int size, int x0, int x1, float error)
{
  FloatImage rendered{ size, size, std::vector<float>(4 * size * size, 0.f) };
  ExactImage exact;
  exact.Width = exact.Height = size;
  exact.Rgb.assign(3 * size * size, 0.0);
  exact.Covered.assign(size * size, 0);
  for (int j = x0; j < x1; ++j)
  {
    for (int i = x0; i < x1; ++i)
    {
      const int p = j * size + i;
      exact.Covered[p] = 1;
      for (int k = 0; k < 3; ++k)
      {
        exact.Rgb[3 * p + k] = 0.5;
        rendered.Rgba[4 * p + k] = 0.5f + error;
      }
      rendered.Rgba[4 * p + 3] = 1;
    }
  }
  return { rendered, exact };
}

std::filesystem::path TempFile(const std::string& name)
{
  return std::filesystem::temp_directory_path() /
    (name + "-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
      std::to_string(getpid()));
}
}

TEST(CompareWithExact, MeasuresTheInteriorOnly)
{
  auto [rendered, exact] = Square(20, 5, 15, 0.125f);
  // Outside the square (and in the band) a wrong pixel is not compared.
  rendered.Rgba[4 * (5 * 20 + 5)] = 100;
  rendered.Rgba[4 * (0 * 20 + 0)] = 100;
  const AccuracyMetrics m = CompareWithExact(rendered, exact);
  EXPECT_EQ(m.Pixels, (10 - 2 * SilhouetteBand) * (10 - 2 * SilhouetteBand));
  EXPECT_NEAR(m.Rmse, 0.125, 1e-7);
  EXPECT_NEAR(m.MaxError, 0.125, 1e-7);
  EXPECT_NEAR(m.Psnr, -10 * std::log10(0.125 * 0.125), 1e-5);
}

TEST(CompareWithExact, OnlyPixelsBothCoverCount)
{
  auto [rendered, exact] = Square(20, 2, 18, 0.f);
  // The mesh leaves a hole where the exact surface is: its band goes too.
  rendered.Rgba[4 * (10 * 20 + 10) + 3] = 0;
  const AccuracyMetrics m = CompareWithExact(rendered, exact);
  EXPECT_EQ(m.Pixels, 12 * 12 - 5 * 5);
  EXPECT_EQ(m.Rmse, 0);
  EXPECT_TRUE(std::isinf(m.Psnr));
}

TEST(CompareWithExact, NaNIsNeverHidden)
{
  auto [rendered, exact] = Square(20, 2, 18, 0.f);
  rendered.Rgba[4 * (10 * 20 + 10) + 1] = NAN;
  const AccuracyMetrics m = CompareWithExact(rendered, exact);
  EXPECT_TRUE(std::isnan(m.MaxError));
  EXPECT_TRUE(std::isnan(m.Rmse));
}

TEST(MeanEdgeNormalAngle, IsTheMeanOverEdgesOfTheAngleBetweenTheirNormals)
{
  // Two triangles over a square: 5 edges. Vertex 2's normal is tilted by 10
  // degrees, so the three edges at it measure 10, the other two 0.
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(1, 1, 0);
  points->InsertNextPoint(0, 1, 0);
  mesh->SetPoints(points);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType a[3] = { 0, 1, 2 }, b[3] = { 0, 2, 3 };
  cells->InsertNextCell(3, a);
  cells->InsertNextCell(3, b);
  mesh->SetPolys(cells);
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetNumberOfComponents(3);
  const double tilt = 10 * 3.14159265358979323846 / 180;
  for (int p = 0; p < 4; ++p)
  {
    normals->InsertNextTuple3(p == 2 ? std::sin(tilt) : 0, 0, p == 2 ? std::cos(tilt) : 1);
  }
  mesh->GetPointData()->SetNormals(normals);
  EXPECT_NEAR(MeanEdgeNormalAngle(mesh), 3 * 10.0 / 5, 1e-5);
}

TEST(SpeedAccuracyFiles, CsvAndJsonCarryEveryColumn)
{
  SpeedAccuracyRow r;
  r.Surface = "torus";
  r.Shading = "gouraud";
  r.Weighting = "max";
  r.Triangles = 1638400;
  r.Width = 1920;
  r.Height = 1080;
  r.MsPerFrame = 123.456789;
  r.Rmse = 1.25e-4;
  r.MaxError = 0.0625;
  r.Psnr = 78.0618;
  r.NormalsMs = 2345.5;
  r.CompileMs = 150.25;
  r.EdgeAngle = 0.4375;
  r.Pixels = 654321;
  const auto csv = TempFile("rows.csv"), json = TempFile("rows.json");
  ASSERT_EQ(WriteSpeedAccuracyCsv(csv.string(), { r, r }), "");
  ASSERT_EQ(WriteSpeedAccuracyJson(json.string(), { r }), "");
  std::vector<SpeedAccuracyRow> back;
  ASSERT_EQ(ReadSpeedAccuracyCsv(csv.string(), back), "");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1].Surface, r.Surface);
  EXPECT_EQ(back[1].Shading, r.Shading);
  EXPECT_EQ(back[1].Weighting, r.Weighting);
  EXPECT_EQ(back[1].Triangles, r.Triangles);
  EXPECT_EQ(back[1].Height, r.Height);
  EXPECT_DOUBLE_EQ(back[1].MsPerFrame, r.MsPerFrame);
  EXPECT_DOUBLE_EQ(back[1].Rmse, r.Rmse);
  EXPECT_DOUBLE_EQ(back[1].EdgeAngle, r.EdgeAngle);
  EXPECT_EQ(back[1].Pixels, r.Pixels);
  std::ifstream in(json);
  const auto parsed = nlohmann::json::parse(in);
  ASSERT_EQ(parsed.size(), 1u);
  EXPECT_EQ(parsed[0]["shading"], "gouraud");
  EXPECT_EQ(parsed[0]["triangles"], 1638400);
  EXPECT_DOUBLE_EQ(parsed[0]["psnr"].get<double>(), r.Psnr);
  std::filesystem::remove(csv);
  std::filesystem::remove(json);
}

TEST(SpeedAccuracyFiles, ReadingSaysWhatIsWrong)
{
  const auto csv = TempFile("bad.csv");
  std::ofstream(csv) << "surface,shading\nsphere,flat\n";
  std::vector<SpeedAccuracyRow> rows;
  EXPECT_EQ(
    ReadSpeedAccuracyCsv(csv.string(), rows), "not speed_accuracy.csv: no column \"weighting\"");
  SpeedAccuracyRow r;
  ASSERT_EQ(WriteSpeedAccuracyCsv(csv.string(), { r }), "");
  std::ofstream(csv, std::ios::app) << "sphere,flat\n";
  EXPECT_EQ(ReadSpeedAccuracyCsv(csv.string(), rows), "line 3: 2 fields, not 14");
  EXPECT_EQ(
    ReadSpeedAccuracyCsv((csv.string() + "-missing"), rows), "cannot read the measurements");
  std::filesystem::remove(csv);
}

TEST(CheckSpeedAccuracyOrder, NamesEachException)
{
  auto row = [](const char* shading, const char* weighting, long long triangles, double rmse)
  {
    SpeedAccuracyRow r;
    r.Surface = "sphere";
    r.Shading = shading;
    r.Weighting = weighting;
    r.Triangles = triangles;
    r.Width = 64;
    r.Height = 48;
    r.Rmse = rmse;
    return r;
  };
  std::vector<SpeedAccuracyRow> rows = { row("flat", "face", 80, 0.3),
    row("gouraud", "angle", 80, 0.2), row("phong", "angle", 80, 0.1), row("flat", "face", 320, 0.2),
    row("gouraud", "angle", 320, 0.1), row("phong", "angle", 320, 0.01) };
  EXPECT_TRUE(CheckSpeedAccuracyOrder(rows).empty());
  rows[4].Rmse = 0.25; // gouraud no better than before, and worse than flat
  const auto exceptions = CheckSpeedAccuracyOrder(rows);
  ASSERT_EQ(exceptions.size(), 2u);
  EXPECT_EQ(exceptions[0],
    "sphere 64x48 at 320 triangles: gouraud/angle RMSE 0.25 is not below the coarser level's 0.2");
  EXPECT_NE(exceptions[1].find("not in the order phong < gouraud < flat"), std::string::npos);
}

TEST(ProgressBar, LineShowsCountsEtaAndLabel)
{
  EXPECT_EQ(ProgressBar::Line(6, 24, "sphere 80 flat", 30, 200),
    "[######..................] 6/24 ETA 1:30  sphere 80 flat");
  EXPECT_EQ(ProgressBar::Line(24, 24, "done", 30, 200), "[########################] 24/24  done");
  EXPECT_EQ(ProgressBar::Line(0, 24, "start", 0, 12).size(), 12u);
}
