// `shadelab normals`: the mesh written back with its computed normals, in
// each output format, read back through the project's own reader.
#include "cli_test_support.h"
#include "vtkShadelabMeshReader.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

using namespace shadelab_test;

namespace
{
// A unit cube, 8 vertices, 12 outward triangles.
const char* const Cube = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                         "f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
                         "f 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

vtkSmartPointer<vtkPolyData> ReadBack(const std::filesystem::path& path)
{
  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}
}

TEST(NormalsCommand, CubeSplitsAtItsEdgesInEveryFormat)
{
  TempDir dir;
  WriteText(dir / "cube.obj", Cube);
  for (const char* name : { "split.ply", "split.vtp", "split.obj" })
  {
    const RunResult r = RunShadelab({ "normals", (dir / "cube.obj").string(), "-o",
      (dir / name).string(), "--feature-angle", "30" });
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    vtkSmartPointer<vtkPolyData> mesh = ReadBack(dir / name);
    ASSERT_EQ(mesh->GetNumberOfPolys(), 12) << name;
    vtkDataArray* normals = mesh->GetPointData()->GetNormals();
    ASSERT_NE(normals, nullptr) << name;
    // Each corner becomes three points, one per face it touches: 24, each
    // normal along an axis.
    EXPECT_EQ(mesh->GetNumberOfPoints(), 24) << name;
    for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
    {
      const double* n = normals->GetTuple3(i);
      const double largest = std::max({ std::abs(n[0]), std::abs(n[1]), std::abs(n[2]) });
      EXPECT_NEAR(largest, 1.0, 1e-6) << name << " point " << i;
    }
  }
}

TEST(NormalsCommand, WithoutSplittingTheVerticesStayAsTheyAre)
{
  TempDir dir;
  WriteText(dir / "cube.obj", Cube);
  const RunResult r = RunShadelab({ "normals", (dir / "cube.obj").string(), "-o",
    (dir / "smooth.ply").string(), "--weighting", "uniform" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  vtkSmartPointer<vtkPolyData> mesh = ReadBack(dir / "smooth.ply");
  ASSERT_EQ(mesh->GetNumberOfPoints(), 8);
  // Corner (1,1,1) touches two triangles of the x = 1 face, two of z = 1 and
  // one of y = 1: uniform weighting (the plain average of the five unit face
  // normals) gives (2,1,2)/3.
  const double* n = mesh->GetPointData()->GetNormals()->GetTuple3(6);
  EXPECT_NEAR(n[0], 2.0 / 3, 1e-6);
  EXPECT_NEAR(n[1], 1.0 / 3, 1e-6);
  EXPECT_NEAR(n[2], 2.0 / 3, 1e-6);

  // The faces keep their normals too: a mesh file has room for them, where
  // render's meshes go without.
  std::ifstream file(dir / "smooth.ply", std::ios::binary);
  const std::string text{ std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>() };
  const std::string header = text.substr(0, text.find("end_header"));
  EXPECT_NE(header.find("element face 12\nproperty list uchar int vertex_indices\n"
                        "property float nx\nproperty float ny\nproperty float nz\n"),
    std::string::npos)
    << header;
}

TEST(NormalsCommand, BadInputAndOptions)
{
  TempDir dir;
  WriteText(dir / "cube.obj", Cube);
  const std::string cube = (dir / "cube.obj").string();
  const std::vector<std::pair<std::vector<std::string>, int>> cases = {
    { { "normals", cube, "-o", (dir / "out.stl").string() }, 1 },
    { { "normals", (dir / "missing.obj").string(), "-o", (dir / "out.ply").string() }, 1 },
    { { "normals", cube, "-o", (dir / "no" / "dir" / "out.ply").string() }, 1 },
    { { "normals", cube, "-o", (dir / "out.ply").string(), "--weighting", "best" }, 2 },
    { { "normals", cube, "-o", (dir / "out.ply").string(), "--feature-angle", "200" }, 2 },
  };
  for (const auto& [args, code] : cases)
  {
    const RunResult r = RunShadelab(args);
    EXPECT_EQ(r.ExitCode, code) << args[3];
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
    EXPECT_EQ(r.Stderr.rfind("shadelab: error: ", 0), 0u) << r.Stderr;
  }
  EXPECT_EQ(dir.Files(), std::vector<std::string>{ "cube.obj" }) << "output left behind";
}

TEST(NormalsCommand, NonManifoldFacesAreKeptAndReported)
{
  TempDir dir;
  // Three triangles on one edge.
  WriteText(dir / "fin.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"
    "f 1 2 3\nf 2 1 4\nf 1 2 5\n");
  // Splitting gives the refused face points of its own, and says so; plain
  // sums need no connectivity, so the output's points are the file's and
  // there is nothing to report.
  const RunResult split = RunShadelab({ "normals", (dir / "fin.obj").string(), "-o",
    (dir / "split.vtp").string(), "--feature-angle", "30" });
  ASSERT_EQ(split.ExitCode, 0) << split.Stderr;
  EXPECT_NE(split.Stderr.find("non-manifold"), std::string::npos) << split.Stderr;
  EXPECT_EQ(ReadBack(dir / "split.vtp")->GetNumberOfPolys(), 3);
  const RunResult r =
    RunShadelab({ "normals", (dir / "fin.obj").string(), "-o", (dir / "fin.vtp").string() });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(r.Stderr.find("non-manifold"), std::string::npos) << r.Stderr;
  vtkSmartPointer<vtkPolyData> mesh = ReadBack(dir / "fin.vtp");
  EXPECT_EQ(mesh->GetNumberOfPoints(), 5);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 3);
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_TRUE(std::isfinite(normals->GetComponent(i, c)));
    }
  }
}

TEST(NormalsCommand, ComputedNormalsIgnoreTheFilesNormalSeams)
{
  TempDir dir;
  // Two triangles sharing the edge 1-2, each corner carrying its own face's
  // vn: read with its normals the mesh has 6 points (a seam along 1-2);
  // computed, it keeps its 4 vertices and one smooth normal across the edge.
  WriteText(dir / "seam.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvn 0 0 1\nvn 0.577 0.577 -0.577\n"
    "f 1//1 2//1 3//1\nf 2//2 4//2 3//2\n");
  ASSERT_EQ(ReadBack(dir / "seam.obj")->GetNumberOfPoints(), 6);
  const RunResult r =
    RunShadelab({ "normals", (dir / "seam.obj").string(), "-o", (dir / "seam.vtp").string() });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  vtkSmartPointer<vtkPolyData> mesh = ReadBack(dir / "seam.vtp");
  EXPECT_EQ(mesh->GetNumberOfPoints(), 4);
  // Vertex 2 (index 1) is on both faces, with normals (0,0,1) and
  // (-1,-1,1)/sqrt(3): its normal lies strictly between the two.
  const double* n = mesh->GetPointData()->GetNormals()->GetTuple3(1);
  const double first = n[2];
  const double second = (-n[0] - n[1] + n[2]) / std::sqrt(3.0);
  EXPECT_GT(first, 0.5);
  EXPECT_LT(first, 0.99);
  EXPECT_GT(second, 0.5);
  EXPECT_LT(second, 0.99);
}

TEST(NormalsCommand, RenderSplitsComputedNormalsAtTheFeatureAngle)
{
  TempDir dir;
  WriteText(dir / "cube.obj", Cube);
  // A cube seen from a corner, lit by a directional light, orthographic:
  // with its corners split, each face has one normal and, per fragment, one
  // colour (N, L and V are the same everywhere on it); smoothed, the corner
  // normals point diagonally and each face shades in a gradient.
  auto distinctColours = [&](const std::vector<std::string>& extra)
  {
    std::vector<std::string> args = { "render", (dir / "cube.obj").string(), "-o",
      (dir / "cube.png").string(), "--shading", "phong", "--orthographic", "--size", "160x160",
      "--camera-position", "3,4,5", "--camera-focal-point", "0.5,0.5,0.5", "--light",
      "directional:-1,-2,-3" };
    args.insert(args.end(), extra.begin(), extra.end());
    const RunResult r = RunShadelab(args);
    EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
    const Image image = ReadImage(dir / "cube.png");
    std::set<std::array<float, 3>> colours;
    for (size_t i = 0; i + 2 < image.Pixels.size(); i += image.Channels)
    {
      const std::array<float, 3> c{ image.Pixels[i], image.Pixels[i + 1], image.Pixels[i + 2] };
      if (c != std::array<float, 3>{ 0, 0, 0 })
      {
        colours.insert(c);
      }
    }
    return std::make_pair(colours.size(), image.Description);
  };
  const auto [split, description] = distinctColours({ "--feature-angle", "30" });
  const auto [smooth, unused] = distinctColours({});
  // Three faces in view, and a colour or two more where rasterisation
  // rounds a face's own normal differently: at most 6.
  EXPECT_LE(split, 6u);
  EXPECT_GT(smooth, 50u);
  EXPECT_NE(description.find("\"feature_angle\":30"), std::string::npos) << description;
}
