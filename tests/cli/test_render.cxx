// `shadelab render` end to end through the OSMesa backend, DISPLAY unset.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace shadelab_test;

namespace
{
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
  // Coverage is read from alpha: a file's own material may draw black (the
  // Khronos box's, a metal of kd 0, under none).
  const RunResult r =
    RunShadelab({ "render", TestMesh(GetParam().Mesh).string(), "-o", out.string(), "--size",
      "160x120", "--shading", GetParam().Shading, "--background", "transparent" });
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

// Every mesh file in tests/data/meshes, so that a mesh added there is tested
// too; at least the eight that the folder's README lists.
static std::vector<MeshAndShading> EveryCase()
{
  std::vector<std::string> meshes;
  for (const auto& entry : std::filesystem::directory_iterator(TestMesh("")))
  {
    const std::string ext = entry.path().extension().string();
    if (ext == ".obj" || ext == ".ply" || ext == ".stl" || ext == ".off" || ext == ".gltf" ||
      ext == ".glb" || ext == ".vtp" || ext == ".vtk")
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

TEST(TestMeshes, AllEightAreThere)
{
  EXPECT_GE(EveryCase().size(), 8u * 4u);
}

INSTANTIATE_TEST_SUITE_P(TestMeshes, EveryMeshEveryShading, testing::ValuesIn(EveryCase()),
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
      const RunResult r = RunShadelab({ "render", TestMesh("teapot-fine.ply").string(), "-o",
        (dir / name).string(), "--size", "320x240", "--light", "point:1,1,1:1,0.8,0.6", "--light",
        "directional:0,-1,-1:0.2,0.3,0.9" });
      ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
      if (run == 0)
      {
        first = Slurp(dir / name);
      }
    }
    EXPECT_TRUE(first == Slurp(dir / name)) << name << " differs between two runs";
  }
}

// -v: one line a phase, `shadelab: PHASE MS ms, peak MIB MiB` (benchmark
// scripts parse it), the mesh's reading and normals apart, and the peak
// resident memory (VmHWM) never falling.
TEST(Render, VerboseTimesEachPhaseWithItsPeakMemory)
{
  TempDir dir;
  const RunResult r = RunShadelab({ "render", TestMesh("teapot-fine.ply").string(), "-o",
    (dir / "out.png").string(), "--size", "64x48", "-v" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(VerbosePhases(r.Stderr, "shadelab"),
    (std::vector<std::string>{ "read", "normals", "context", "frame", "write" }))
    << r.Stderr;
}

// With --shading none every covered pixel is kd exactly, which pins the
// contract's output rule: float files store I, 8-bit files round(255*clamp(I)).
TEST(Render, FloatKeepsValuesAboveOneAndEightBitClamps)
{
  TempDir dir;
  for (const char* name : { "flat.exr", "flat.png", "flat.tif" })
  {
    std::vector<std::string> args = { "render", TestMesh("teapot.obj").string(), "-o",
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
  // The centre of the picture is on the teapot.
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

// The way to an 8-bit file (the read-back, the quantisation, the encoder)
// must not change a pixel: every pixel of a detailed picture (a texture,
// flat-shaded facets, a specular highlight) decodes to round(255*clamp(I))
// of the same render stored as float. Exact: no bound. (The PNG encoder's
// zlib level and row filter cannot fail this: PNG is lossless.)
// An 8-bit file's picture is rendered into an 8-bit target (the capture
// pass's exact quantisation step), an EXR's into floats: each 8-bit picture
// must be its EXR quantised, byte for byte, whatever it shows: textures,
// each rule, VTK's own line shaders (edges, normal glyphs), a background on
// a tie (0.5: 127.5), a transparent one, and --ssaa (quantised after the
// average).
TEST(Render, EightBitPictureIsTheFloatRenderQuantised)
{
  TempDir dir;
  const std::vector<std::vector<std::string>> scenes = {
    { TestMesh("teapot-textured.obj").string(), "--size", "480x270", "--shading", "flat", "--zoom",
      "1.6" },
    { TestMesh("torus.obj").string(), "--size", "200x150", "--shading", "phong", "--edges",
      "--edge-color", "0.5,0.5,0.5", "--normal-glyphs", "--background", "0.5,0.5,0.5" },
    { TestMesh("teapot-quads.obj").string(), "--size", "160x120", "--shading", "gouraud",
      "--ambient", "3,3,3", "--background", "transparent" },
    { TestMesh("teapot-quads.obj").string(), "--size", "100x80", "--shading", "flat", "--ssaa",
      "3" },
  };
  for (std::size_t s = 0; s < scenes.size(); ++s)
  {
    for (const char* name : { "picture.exr", "picture.png" })
    {
      std::vector<std::string> args = { "render", "-o", (dir / name).string() };
      args.insert(args.end(), scenes[s].begin(), scenes[s].end());
      const RunResult r = RunShadelab(args);
      ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    }
    const Image exr = ReadImage(dir / "picture.exr");
    const Image png = ReadImage(dir / "picture.png");
    ASSERT_EQ(png.Format, "uint8");
    ASSERT_EQ(exr.Pixels.size(), png.Pixels.size()) << "scene " << s;
    size_t differing = 0;
    for (size_t i = 0; i < png.Pixels.size(); ++i)
    {
      const double clamped = std::clamp(static_cast<double>(exr.Pixels[i]), 0.0, 1.0);
      differing += png.Pixels[i] != std::floor(255 * clamped + 0.5);
    }
    EXPECT_EQ(differing, 0u) << "scene " << s;
    if (s == 0)
    {
      size_t distinct = 0;
      std::vector<bool> seen(256 * 256 * 256);
      for (size_t i = 0; i + 2 < png.Pixels.size(); i += 3)
      {
        const size_t colour = static_cast<size_t>(png.Pixels[i]) * 65536 +
          static_cast<size_t>(png.Pixels[i + 1]) * 256 + static_cast<size_t>(png.Pixels[i + 2]);
        distinct += !seen[colour];
        seen[colour] = true;
      }
      EXPECT_GT(distinct, 1000u)
        << "the picture is meant to have detail for the encoder to work on";
    }
  }
}

TEST(Render, LitFloatPictureExceedsOneWhereTheLightIsStrong)
{
  TempDir dir;
  const RunResult r =
    RunShadelab({ "render", TestMesh("torus.obj").string(), "-o", (dir / "bright.exr").string(),
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
    const RunResult r = RunShadelab({ "render", TestMesh("teapot-quads.obj").string(), "-o",
      (dir / name).string(), "--size", "64x48", "--shading", "gouraud", "--material", "brass",
      "--light", "spot:0,0,5:0,0,-1:30:2:1,0.5,0.5", "--orthographic" });
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    const Image image = ReadImage(dir / name);
    for (const char* expected : { "\"shading\":\"gouraud\"", "\"name\":\"brass\"",
           "\"kind\":\"spot\"", "\"half_angle_deg\":30.0", "\"projection\":\"orthographic\"",
           "\"parallel_scale\":", "\"shadelab\":\"", "--material brass", "teapot-quads.obj" })
    {
      EXPECT_NE(image.Description.find(expected), std::string::npos)
        << name << " lacks " << expected << " in: " << image.Description;
    }
  }
}

// A mesh's vertex colours are kd unless --material or --kd replaces them;
// the picture says which.
TEST(Render, PictureSaysWhereKdCameFrom)
{
  TempDir dir;
  const auto mesh = dir / "rgb.ply";
  WriteRgbTriangle(mesh);
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases{
    { {}, "\"kd_from\":\"vertex colors\"" },
    { { "--material", "chrome" }, "\"kd_from\":\"material\"" },
    { { "--kd", "0.5,0.5,0.5" }, "\"kd_from\":\"material\"" },
  };
  for (const auto& [options, expected] : cases)
  {
    std::vector<std::string> args{ "render", mesh.string(), "-o", (dir / "m.png").string(),
      "--size", "32x32" };
    args.insert(args.end(), options.begin(), options.end());
    const RunResult r = RunShadelab(args);
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    const Image image = ReadImage(dir / "m.png");
    EXPECT_NE(image.Description.find(expected), std::string::npos)
      << expected << " not in: " << image.Description;
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
// or Inf anywhere in the float picture (numerical safety).
TEST(Render, DegenerateTrianglesGiveNoNaN)
{
  TempDir dir;
  WriteText(dir / "odd.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nvn 0 0 1\nvn 0 0 0\n"
    "f 1//1 2//1 3//2\nf 2//1 4//1 5//1\n");
  for (const std::string& mesh : { TestMesh("teapot.obj").string(), (dir / "odd.obj").string() })
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

// Flat's face normals reach view coordinates through a normal matrix of its
// own. Under an orthographic camera and a directional light, N, L, V and H
// are constant over a planar face, so flat and phong must give the same
// colour inside each face of a cube with per-face normals, from a camera
// that is not on an axis (a transposed normal matrix once turned flat's
// normals the wrong way under any camera but one looking down -Z).
TEST(FlatShading, AgreesWithPhongOnPlanarFacesFromAnObliqueCamera)
{
  TempDir dir;
  std::string obj = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                    "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n";
  // Outward, counter-clockwise quads as two triangles, each with its face's vn.
  const int faces[6][5] = { { 1, 4, 3, 2, 1 }, { 5, 6, 7, 8, 2 }, { 1, 2, 6, 5, 3 },
    { 4, 8, 7, 3, 4 }, { 1, 5, 8, 4, 5 }, { 2, 3, 7, 6, 6 } };
  for (const auto& f : faces)
  {
    const std::string n = "//" + std::to_string(f[4]);
    obj += "f " + std::to_string(f[0]) + n + " " + std::to_string(f[1]) + n + " " +
      std::to_string(f[2]) + n + "\nf " + std::to_string(f[0]) + n + " " + std::to_string(f[2]) +
      n + " " + std::to_string(f[3]) + n + "\n";
  }
  WriteText(dir / "cube.obj", obj);
  std::map<std::string, Image> pictures;
  for (const std::string rule : { "flat", "phong" })
  {
    const auto out = dir / (rule + ".exr");
    const RunResult r = RunShadelab(
      { "render", (dir / "cube.obj").string(), "-o", out.string(), "--size", "96x96", "--shading",
        rule, "--orthographic", "--camera-position", "3,2,4", "--camera-focal-point", "0,0,0",
        "--camera-view-up", "0,1,0", "--light", "directional:-1,-2,-3", "--material", "gold" });
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    pictures[rule] = ReadImage(out);
  }
  const Image& flat = pictures["flat"];
  const Image& phong = pictures["phong"];
  ASSERT_EQ(flat.Pixels.size(), phong.Pixels.size());
  // Float rounding of the same equation by two routes: 1e-5 is 100 ulps of
  // intensities about 0.1-1; a face normal off by degrees changes them by 1e-2.
  std::size_t compared = 0;
  double worst = 0;
  for (std::size_t p = 0; p < flat.Pixels.size(); ++p)
  {
    if (flat.Pixels[p] > 0 && phong.Pixels[p] > 0)
    {
      ++compared;
      worst = std::max(worst, static_cast<double>(std::abs(flat.Pixels[p] - phong.Pixels[p])));
    }
  }
  EXPECT_GT(compared, 3000u);
  EXPECT_LT(worst, 1e-5);
}
