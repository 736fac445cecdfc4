// The executables of scripts/bench-scaling: shadelab-bench-meshes makes the
// bunny at each size in the format the curves assume, and
// shadelab-bench-vtk-pipeline prints the phases the script parses and writes
// a picture; both fail as shadelab does on bad input.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <regex>
#include <sstream>

using namespace shadelab_test;

namespace
{
// The PLY header, up to and including end_header.
std::string Header(const std::filesystem::path& path)
{
  const std::string bytes = Slurp(path);
  return bytes.substr(0, bytes.find("end_header"));
}

// The last line, without its newline.
std::string LastLine(const std::string& text)
{
  const std::string trimmed = text.substr(0, text.find_last_not_of('\n') + 1);
  return trimmed.substr(trimmed.find_last_of('\n') + 1);
}

long FaceCount(const std::string& header)
{
  std::smatch m;
  return std::regex_search(header, m, std::regex("element face ([0-9]+)")) ? std::stol(m[1]) : -1;
}
}

TEST(BenchMeshes, TheBunnyAtEachSizeAsBinaryFloatPlyWithoutNormals)
{
  TempDir out;
  const RunResult r = RunProgram(SHADELAB_BENCH_MESHES,
    { TestMesh("teapot-fine.ply").string(), "--out", out.path().string(), "--sizes",
      "10k,69k,278k" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(
    out.Files(), (std::vector<std::string>{ "bunny-10k.ply", "bunny-278k.ply", "bunny-69k.ply" }));
  // The input itself (the benchmarks give the bunny; the test the fine
  // teapot, 65,280 triangles), as it was read.
  EXPECT_EQ(FaceCount(Header(out / "bunny-69k.ply")), 65280);
  // One Loop subdivision splits every triangle in four.
  const std::string loop = Header(out / "bunny-278k.ply");
  EXPECT_EQ(FaceCount(loop), 4 * 65280);
  EXPECT_NE(loop.find("format binary_little_endian"), std::string::npos) << loop;
  EXPECT_NE(loop.find("property float x"), std::string::npos) << loop;
  EXPECT_EQ(loop.find("property float nx"), std::string::npos) << loop;
  // vtkQuadricDecimation stops at its target reduction, give or take a few
  // triangles (it removes two at an edge collapse, fewer at a boundary): 1%.
  EXPECT_NEAR(FaceCount(Header(out / "bunny-10k.ply")), 10000, 100);

  // The folder is the cache: a file already there is kept as it is.
  WriteText(out / "bunny-10k.ply", "kept");
  const RunResult again = RunProgram(SHADELAB_BENCH_MESHES,
    { TestMesh("teapot-fine.ply").string(), "--out", out.path().string(), "--sizes", "10k" });
  ASSERT_EQ(again.ExitCode, 0) << again.Stderr;
  EXPECT_TRUE(Slurp(out / "bunny-10k.ply") == "kept") << Header(out / "bunny-10k.ply");
}

TEST(BenchMeshes, AnUnknownSizeIsAUsageErrorAndWritesNothing)
{
  TempDir out;
  const RunResult r = RunProgram(SHADELAB_BENCH_MESHES,
    { TestMesh("teapot-fine.ply").string(), "--out", out.path().string(), "--sizes", "69k,5k" });
  EXPECT_EQ(r.ExitCode, 2);
  EXPECT_EQ(r.Stderr, "shadelab: error: --sizes: unknown size '5k'\n");
  EXPECT_TRUE(out.Files().empty());
}

TEST(BenchMeshes, AnUnreadableBunnyGetsOneLineAndNoFile)
{
  TempDir out;
  WriteText(out / "not-a-mesh.ply", "ply\nformat nonsense\n");
  const RunResult r = RunProgram(SHADELAB_BENCH_MESHES,
    { (out / "not-a-mesh.ply").string(), "--out", (out / "meshes").string(), "--sizes", "69k" });
  EXPECT_EQ(r.ExitCode, 1);
  EXPECT_EQ(r.Stderr.rfind("shadelab: error: " + (out / "not-a-mesh.ply").string() + ": ", 0), 0u)
    << r.Stderr;
  EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
  EXPECT_TRUE(FilesIn(out / "meshes").empty());
}

TEST(BenchVtkPipeline, PrintsItsPhasesInOrderAndWritesThePicture)
{
  TempDir out;
  const RunResult r = RunProgram(SHADELAB_BENCH_VTK_PIPELINE,
    { TestMesh("teapot-fine.ply").string(), "-o", (out / "vtk.png").string(), "--size", "160x90" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  // The lines bench-common.sh's phase_lines parses (scripts/bench-scaling),
  // every phase once, in order, the peak never falling.
  EXPECT_EQ(VerbosePhases(r.Stderr, "shadelab-bench-vtk-pipeline"),
    (std::vector<std::string>{ "read", "normals", "context", "upload", "frame", "write" }))
    << r.Stderr;

  const Image picture = ReadImage(out / "vtk.png");
  ASSERT_EQ(picture.Width, 160);
  ASSERT_EQ(picture.Height, 90);
  // The bunny drawn, framed by ResetCamera: it covers about a fifth of a
  // 16:9 picture (measured: 17%). Between 5% and 50% tells a drawn bunny from
  // an empty picture or the 1x1 viewport of the upload pass left in place.
  const double covered = static_cast<double>(CountCovered(picture)) / (160 * 90);
  EXPECT_GT(covered, 0.05);
  EXPECT_LT(covered, 0.5);
}

TEST(BenchVtkPipeline, BadInputGetsOneLineAndNoPicture)
{
  TempDir out;
  const RunResult size = RunProgram(SHADELAB_BENCH_VTK_PIPELINE,
    { TestMesh("teapot-fine.ply").string(), "-o", (out / "vtk.png").string(), "--size", "0x90" });
  EXPECT_EQ(size.ExitCode, 2);
  EXPECT_EQ(size.Stderr.rfind("shadelab: error: --size: ", 0), 0u) << size.Stderr;
  EXPECT_EQ(std::count(size.Stderr.begin(), size.Stderr.end(), '\n'), 1) << size.Stderr;

  WriteText(out / "not-a-mesh.ply", "ply\nformat nonsense\n");
  const RunResult mesh = RunProgram(SHADELAB_BENCH_VTK_PIPELINE,
    { (out / "not-a-mesh.ply").string(), "-o", (out / "vtk.png").string() });
  EXPECT_EQ(mesh.ExitCode, 1);
  EXPECT_EQ(
    mesh.Stderr.rfind("shadelab: error: " + (out / "not-a-mesh.ply").string() + ": ", 0), 0u)
    << mesh.Stderr;
  EXPECT_EQ(std::count(mesh.Stderr.begin(), mesh.Stderr.end(), '\n'), 1) << mesh.Stderr;

  const RunResult unwritable = RunProgram(SHADELAB_BENCH_VTK_PIPELINE,
    { TestMesh("teapot-fine.ply").string(), "-o", (out / "no-folder" / "vtk.png").string(),
      "--size", "16x9" });
  EXPECT_EQ(unwritable.ExitCode, 1);
  // After the phases it went through, the error as the last line.
  EXPECT_EQ(LastLine(unwritable.Stderr)
              .rfind("shadelab: error: " + (out / "no-folder" / "vtk.png").string() + ": ", 0),
    0u)
    << unwritable.Stderr;
  EXPECT_EQ(out.Files(), (std::vector<std::string>{ "not-a-mesh.ply" }));
}
