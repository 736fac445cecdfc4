// `shadelab render` end to end through the OSMesa backend, DISPLAY unset.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

using namespace shadelab_test;

namespace
{
std::string Bytes(const std::filesystem::path& path)
{
  std::ifstream in(path, std::ios::binary);
  return { std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
}

struct MeshAndShading
{
  std::string Mesh;
  std::string Shading;
};

void PrintTo(const MeshAndShading& c, std::ostream* os)
{
  *os << c.Mesh << " " << c.Shading;
}

class EveryMeshEveryShading : public testing::TestWithParam<MeshAndShading>
{
};
}

TEST_P(EveryMeshEveryShading, RendersAPicture)
{
  TempDir dir;
  const auto out = dir / "picture.png";
  const RunResult r = RunShadelab({ "render", SharedMesh(GetParam().Mesh).string(), "-o",
    out.string(), "--size", "160x120", "--shading", GetParam().Shading });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(r.Stderr, "");
  const Image image = ReadImage(out);
  ASSERT_EQ(image.Width, 160);
  ASSERT_EQ(image.Height, 120);
  // The fitted camera puts the whole mesh in view: it covers a good part of
  // the picture but not all of it (the bounding sphere fits inside).
  const size_t covered = CountCovered(image);
  EXPECT_GT(covered, 160u * 120u / 50) << "the mesh is (nearly) invisible";
  EXPECT_LT(covered, 160u * 120u * 9 / 10) << "the mesh fills the frame: camera not fitted";
  EXPECT_EQ(dir.Files().size(), 1u) << "a temporary file was left behind";
}

// Every mesh file in the shared folder, so that a mesh added there is tested
// too; at least the eight that the folder's README lists.
static std::vector<MeshAndShading> EveryCase()
{
  std::vector<std::string> meshes;
  for (const auto& entry : std::filesystem::directory_iterator(SharedMesh("")))
  {
    const std::string ext = entry.path().extension().string();
    if (ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".vtp" || ext == ".vtk")
    {
      meshes.push_back(entry.path().filename().string());
    }
  }
  std::sort(meshes.begin(), meshes.end());
  std::vector<MeshAndShading> cases;
  for (const std::string& mesh : meshes)
  {
    for (const char* shading : { "none", "flat", "gouraud", "phong" })
    {
      cases.push_back({ mesh, shading });
    }
  }
  return cases;
}

TEST(SharedMeshes, AllEightAreThere)
{
  EXPECT_GE(EveryCase().size(), 8u * 4u);
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, EveryMeshEveryShading, testing::ValuesIn(EveryCase()),
  [](const testing::TestParamInfo<MeshAndShading>& info)
  {
    std::string name = info.param.Mesh + "_" + info.param.Shading;
    for (char& c : name)
    {
      c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    }
    return name;
  });

// The metadata names the output file, so both renders go to the same name.
TEST(Render, IsDeterministic)
{
  TempDir dir;
  for (const char* name : { "same.png", "same.exr" })
  {
    std::string first;
    for (int run = 0; run < 2; ++run)
    {
      const RunResult r = RunShadelab({ "render", SharedMesh("stanford-bunny.ply").string(), "-o",
        (dir / name).string(), "--size", "320x240", "--light", "point:1,1,1:1,0.8,0.6", "--light",
        "directional:0,-1,-1:0.2,0.3,0.9" });
      ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
      if (run == 0)
      {
        first = Bytes(dir / name);
      }
    }
    EXPECT_TRUE(first == Bytes(dir / name)) << name << " differs between two runs";
  }
}

// With --shading none every covered pixel is kd exactly, which pins the
// contract's output rule: float files store I, 8-bit files round(255*clamp(I)).
TEST(Render, FloatKeepsValuesAboveOneAndEightBitClamps)
{
  TempDir dir;
  for (const char* name : { "flat.exr", "flat.png", "flat.tif" })
  {
    std::vector<std::string> args = { "render", SharedMesh("spot.obj").string(), "-o",
      (dir / name).string(), "--size", "64x64", "--shading", "none", "--kd", "0.5,0.25,2.5" };
    if (std::string(name) == "flat.tif")
    {
      args.insert(args.end(), { "--pixel-type", "float" });
    }
    const RunResult r = RunShadelab(args);
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  }
  const Image exr = ReadImage(dir / "flat.exr");
  const Image tif = ReadImage(dir / "flat.tif");
  const Image png = ReadImage(dir / "flat.png");
  EXPECT_EQ(exr.Format, "float");
  EXPECT_EQ(tif.Format, "float");
  EXPECT_EQ(png.Format, "uint8");
  // The centre of the picture is on the cow-like spot mesh.
  const size_t centre = (32 * 64 + 32) * 3;
  for (const Image* f : { &exr, &tif })
  {
    EXPECT_FLOAT_EQ(f->Pixels[centre + 0], 0.5f);
    EXPECT_FLOAT_EQ(f->Pixels[centre + 1], 0.25f);
    EXPECT_FLOAT_EQ(f->Pixels[centre + 2], 2.5f) << "a float image must keep values above 1";
  }
  EXPECT_EQ(png.Pixels[centre + 0], 128); // round(127.5)
  EXPECT_EQ(png.Pixels[centre + 1], 64);  // round(63.75)
  EXPECT_EQ(png.Pixels[centre + 2], 255); // clamped
}

TEST(Render, LitFloatPictureExceedsOneWhereTheLightIsStrong)
{
  TempDir dir;
  const RunResult r =
    RunShadelab({ "render", SharedMesh("cow.obj").string(), "-o", (dir / "bright.exr").string(),
      "--size", "96x96", "--shading", "phong", "--ambient", "4,4,4", "--ka", "1,1,1" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const Image exr = ReadImage(dir / "bright.exr");
  float peak = 0;
  for (float v : exr.Pixels)
  {
    peak = std::max(peak, v);
  }
  EXPECT_GE(peak, 4.0f);
}

TEST(Render, PictureCarriesItsParameters)
{
  TempDir dir;
  for (const char* name : { "m.png", "m.exr", "m.jpg", "m.tif" })
  {
    const RunResult r = RunShadelab({ "render", SharedMesh("suzanne.obj").string(), "-o",
      (dir / name).string(), "--size", "64x48", "--shading", "gouraud", "--material", "brass",
      "--light", "spot:0,0,5:0,0,-1:30:2:1,0.5,0.5", "--orthographic" });
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    const Image image = ReadImage(dir / name);
    for (const char* expected : { "\"shading\":\"gouraud\"", "\"name\":\"brass\"",
           "\"kind\":\"spot\"", "\"half_angle_deg\":30.0", "\"projection\":\"orthographic\"",
           "\"parallel_scale\":", "\"shadelab\":\"", "--material brass", "suzanne.obj" })
    {
      EXPECT_NE(image.Description.find(expected), std::string::npos)
        << name << " lacks " << expected << " in: " << image.Description;
    }
  }
}

TEST(Render, HelpDocumentsTheCameraConventions)
{
  const RunResult r = RunShadelab({ "render", "--help" });
  EXPECT_EQ(r.ExitCode, 0);
  for (const char* expected : { "--camera-position", "--parallel-scale", "half the view height",
         "bounding sphere", "--orthographic", "--light" })
  {
    EXPECT_NE(r.Stdout.find(expected), std::string::npos) << expected;
  }
}

// The teapot has degenerate (zero-area) triangles at its poles, and a
// zero-area triangle and a zero normal here: no rule may turn them into NaN
// or Inf anywhere in the float picture (issue 3, numerical safety).
TEST(Render, DegenerateTrianglesGiveNoNaN)
{
  TempDir dir;
  WriteText(dir / "odd.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nvn 0 0 1\nvn 0 0 0\n"
    "f 1//1 2//1 3//2\nf 2//1 4//1 5//1\n");
  for (const std::string& mesh : { SharedMesh("teapot.obj").string(), (dir / "odd.obj").string() })
  {
    for (const char* shading : { "none", "flat", "gouraud", "phong" })
    {
      const RunResult r = RunShadelab({ "render", mesh, "-o", (dir / "odd.exr").string(), "--size",
        "96x96", "--shading", shading, "--light", "point:0,0,0.5" });
      ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
      const Image image = ReadImage(dir / "odd.exr");
      ASSERT_GT(image.Width, 0);
      for (float v : image.Pixels)
      {
        ASSERT_TRUE(std::isfinite(v)) << mesh << " " << shading;
      }
    }
  }
}
