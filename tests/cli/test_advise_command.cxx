// `shadelab advise` end to end: its verdicts from measurements
// whose power laws are known exactly, and its errors.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace shadelab_test;

namespace
{
// Measurements of one surface at 640x480 that follow exact laws in the edge
// angle t (degrees) and the triangle count T:
//   flat RMSE 0.01 t, gouraud 0.001 t^2, phong 0.0001 t^2;
//   ms/frame flat 10 + T, gouraud 12 + T, phong 20 + T (a triangle costs
// a millisecond, so that more of them are no free lunch for a mesh of 2).
std::string LawCsv()
{
  std::ostringstream csv;
  csv << "surface,shading,weighting,triangles,width,height,ms_per_frame,rmse,max_error,psnr,"
         "normals_ms,compile_ms,edge_angle_deg,pixels\n";
  const double angles[] = { 8, 4, 2, 1 };
  const double triangles[] = { 1, 4, 16, 64 };
  for (int k = 0; k < 4; ++k)
  {
    const double t = angles[k], n = triangles[k];
    csv << "sphere,flat,face," << n << ",640,480," << 10 + n << "," << 0.01 * t << ",1,1,0,0," << t
        << ",1000\n";
    csv << "sphere,gouraud,angle," << n << ",640,480," << 12 + n << "," << 0.001 * t * t
        << ",1,1,0,0," << t << ",1000\n";
    csv << "sphere,phong,angle," << n << ",640,480," << 20 + n << "," << 0.0001 * t * t
        << ",1,1,0,0," << t << ",1000\n";
  }
  return csv.str();
}

// Two triangles over a square, the normal at one corner tilted by 10
// degrees: the edges turn by 3 x 10 / 5 = 6 degrees on average.
std::string SquareObj()
{
  const double tilt = 10 * 3.14159265358979323846 / 180;
  std::ostringstream obj;
  obj.precision(17);
  obj << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      << "vn 0 0 1\nvn 0 0 1\nvn " << std::sin(tilt) << " 0 " << std::cos(tilt) << "\nvn 0 0 1\n"
      << "f 1//1 2//2 3//3\nf 1//1 3//3 4//4\n";
  return obj.str();
}

struct Advice
{
  RunResult Run;
  std::string Verdict; // the "Use ..." line
  std::string Why;     // the "Why: ..." line, if any
};

Advice Advise(const TempDir& dir, const std::string& maxError)
{
  Advice a;
  a.Run = RunShadelab({ "advise", (dir / "square.obj").string(), "--max-error", maxError, "--size",
    "640x480", "--measurements", (dir / "laws.csv").string() });
  std::istringstream lines(a.Run.Stdout);
  for (std::string line; std::getline(lines, line);)
  {
    if (line.rfind("Use ", 0) == 0 || line.rfind("Nothing", 0) == 0)
    {
      a.Verdict = line;
    }
    if (line.rfind("Why: ", 0) == 0)
    {
      a.Why = line;
    }
  }
  return a;
}

class AdviseCommand : public testing::Test
{
protected:
  void SetUp() override
  {
    WriteText(this->Dir / "laws.csv", LawCsv());
    WriteText(this->Dir / "square.obj", SquareObj());
  }
  TempDir Dir;
};
}

TEST_F(AdviseCommand, ReportsTheMeshAndEveryOption)
{
  const Advice a = Advise(this->Dir, "0.1");
  ASSERT_EQ(a.Run.ExitCode, 0) << a.Run.Stderr;
  EXPECT_NE(a.Run.Stdout.find("2 triangles, edges turn by 6.00 degrees"), std::string::npos)
    << a.Run.Stdout;
  // flat at t = 6: 0.06; phong on 64x the triangles (t = 0.75): 5.6e-05.
  EXPECT_NE(a.Run.Stdout.find("| 2 | flat | 0.06 | 12.0 | yes |"), std::string::npos)
    << a.Run.Stdout;
  EXPECT_NE(a.Run.Stdout.find("| 128 | phong | 5.6e-05 | 148.0 | yes |"), std::string::npos)
    << a.Run.Stdout;
}

TEST_F(AdviseCommand, LooseTargetsTakeFlatAsItIs)
{
  const Advice a = Advise(this->Dir, "0.1");
  EXPECT_EQ(a.Verdict, "Use flat: 0.06 <= 0.1 at 12.0 ms/frame on this mesh as it is.");
  EXPECT_EQ(a.Why, "");
}

TEST_F(AdviseCommand, MoreTrianglesWhenTheyCostLessThanABetterRule)
{
  // phong here: 0.0036 at 22 ms; gouraud on 4x (t = 3, T = 8): 0.009 at 20 ms.
  const Advice a = Advise(this->Dir, "0.01");
  EXPECT_EQ(a.Verdict, "Use gouraud on 4x the triangles: 0.009 <= 0.01 at 20.0 ms/frame.");
  EXPECT_NE(a.Why.find("More triangles are the better buy"), std::string::npos) << a.Why;
}

TEST_F(AdviseCommand, ABetterRuleWhenItCostsLessThanMoreTriangles)
{
  // phong here: 0.0036 at 22 ms; gouraud needs 16x (t = 1.5: 0.00225) at
  // 44 ms: phong as it is.
  const Advice a = Advise(this->Dir, "0.004");
  EXPECT_EQ(a.Verdict, "Use phong: 0.0036 <= 0.004 at 22.0 ms/frame on this mesh as it is.");
  EXPECT_NE(a.Why.find("A better rule is the better buy"), std::string::npos) << a.Why;
}

TEST_F(AdviseCommand, SaysWhenNothingMeasuredReaches)
{
  const Advice a = Advise(this->Dir, "1e-6");
  EXPECT_EQ(a.Run.ExitCode, 0);
  EXPECT_EQ(a.Verdict.rfind("Nothing measured reaches 1e-06", 0), 0u) << a.Run.Stdout;
}

TEST_F(AdviseCommand, ShippedMeasurementsGiveAnAnswerForARealMesh)
{
  const RunResult r =
    RunShadelab({ "advise", TestMesh("teapot-fine.ply").string(), "--max-error", "0.002" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_NE(r.Stdout.find("from shadelab's measurements at 1920x1080"), std::string::npos);
  EXPECT_NE(r.Stdout.find("\nUse "), std::string::npos) << r.Stdout;
}

TEST_F(AdviseCommand, BadInputIsOneLine)
{
  const auto expectError =
    [](const std::vector<std::string>& args, int code, const std::string& text)
  {
    const RunResult r = RunShadelab(args);
    EXPECT_EQ(r.ExitCode, code) << r.Stderr;
    EXPECT_NE(r.Stderr.find(text), std::string::npos) << r.Stderr;
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
    EXPECT_EQ(r.Stdout, "");
  };
  const std::string mesh = (this->Dir / "square.obj").string();
  const std::string missing = (this->Dir / "missing.csv").string();
  expectError({ "advise", mesh, "--max-error", "0.01", "--measurements", missing }, 1,
    "shadelab: error: " + missing + ": cannot read the measurements");
  WriteText(this->Dir / "flat-only.csv", LawCsv().substr(0, LawCsv().find("sphere,gouraud")));
  expectError({ "advise", mesh, "--max-error", "0.01", "--measurements",
                (this->Dir / "flat-only.csv").string() },
    1, "no measurements of gouraud with angle weighting");
  expectError({ "advise", (this->Dir / "none.obj").string(), "--max-error", "0.01" }, 1,
    "none.obj: cannot open");
  expectError({ "advise", mesh, "--max-error", "-1" }, 2, "--max-error");
  expectError({ "advise", mesh }, 2, "--max-error is required");
}
