// What the probe tests share: the teapots, their lights and background,
// `shadelab probe --json` on many pixels, and reading its answers.
#ifndef shadelab_probe_support_h
#define shadelab_probe_support_h

#include "cli_test_support.h"
#include "oracle_scene.h" // the oracle tests' tolerance and edge margin
#include "vtkShadelabMeshReader.h"

#include <vtkCellArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace shadelab_test
{
using nlohmann::json;

inline const std::string Fine = TestMesh("teapot-fine.obj").string();
inline const std::string Teapot = TestMesh("teapot.obj").string();
inline const Rgb Background{ 0.1, 0.2, 0.3 };

// The teapot spans 6.4 x 3.2 x 4 units from the origin up. Two points (one
// behind, so that N.L <= 0 happens), a directional light, a soft and a
// hard-edged spot whose cones' edges cross it.
inline const std::vector<std::string> TeapotLights{ "--light", "point:4,6,5", "--light",
  "point:-5,1,-4:0.4,0.2,0.2", "--light", "directional:0.3,-1,-0.5:0.5,0.6,0.5", "--light",
  "spot:0,8,0:0,-1,0:20:2:0.8,0.8,1", "--light", "spot:-6,3,6:1,-0.3,-1:6:0:1,0.4,0.2" };

// Every fourth pixel each way that the oracle compares (Expected::Interior).
inline std::vector<std::array<int, 2>> ComparedPixels(const Scene& s, const Oracle& oracle)
{
  std::vector<std::array<int, 2>> pixels;
  for (int y = 0; y < s.Size; y += 4)
  {
    for (int x = 0; x < s.Size; x += 4)
    {
      if (oracle.At(x, y).What == Expected::Interior)
      {
        pixels.push_back({ x, y });
      }
    }
  }
  return pixels;
}

// `shadelab probe` on pixels, --json: one object per pixel.
inline std::vector<json> Probe(const std::vector<std::string>& common,
  const std::vector<std::array<int, 2>>& pixels, std::string& error)
{
  std::vector<std::string> args{ "probe", "--json" };
  args.insert(args.end(), common.begin(), common.end());
  for (const auto& [x, y] : pixels)
  {
    args.push_back("--pixel");
    args.push_back(std::to_string(x) + "," + std::to_string(y));
  }
  // Spawned with its words as they are: thousands of pixels are more than
  // a shell's command string holds.
  TempDir dir;
  const int status = WaitShadelab(StartShadelab(args, dir / "out", dir / "err"));
  std::vector<json> lines;
  std::ifstream out(dir / "out"), err(dir / "err");
  if (status != 0)
  {
    error = "probe failed (" + std::to_string(status) +
      "): " + std::string(std::istreambuf_iterator<char>(err), {});
    return lines;
  }
  for (std::string line; std::getline(out, line);)
  {
    lines.push_back(json::parse(line)); // throws, failing the test, on malformed JSON
  }
  return lines;
}

inline void ExpectNear(const Vec3& got, const Vec3& want, double tolerance, const std::string& what)
{
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(got[c], want[c], tolerance) << what << " " << Show(got) << " " << Show(want);
  }
}

// The rendered value within the oracle tests' bound of the oracle, per
// channel (oracle_scene.h's Standard, reasoned there); the largest
// deviation in units of the bound.
inline double ExpectWithinTheBound(const Rgb& got, const Rgb& oracle)
{
  double worst = 0;
  for (int k = 0; k < 3; ++k)
  {
    const double bound = Standard.Relative * std::max(std::abs(oracle[k]), Standard.Floor);
    EXPECT_LE(std::abs(got[k] - oracle[k]), bound)
      << "channel " << k << ": rendered " << got[k] << ", oracle " << oracle[k];
    worst = std::max(worst, std::abs(got[k] - oracle[k]) / bound);
  }
  return worst;
}

inline Rgb Vec(const json& v)
{
  return { v.at(0).get<double>(), v.at(1).get<double>(), v.at(2).get<double>() };
}

// ambient + the lights' diffuse and specular terms (+ the environment's).
inline Rgb TermsSum(const json& at)
{
  Rgb sum = Vec(at.at("ambient"));
  for (const json& light : at.at("lights"))
  {
    sum = sum + Vec(light.at("diffuse")) + Vec(light.at("specular"));
  }
  if (at.contains("environment"))
  {
    sum = sum + Vec(at.at("environment").at("term"));
  }
  return sum;
}

// Whether a light's case at a point is within 1e-5 of switching where a
// term jumps (N.L against the oracle's 1e-5, a spot's cosine against its
// cut-off): the GPU's float N.L and cosine are some 1e-6 off the oracle's,
// so there the case, and the term, may go the other way. (The specular
// base's case, base > 0, moves nothing for ns > 0: base^ns is 0 there.)
inline bool NearACase(const json& lights)
{
  constexpr double Near = 1e-5;
  for (const json& l : lights)
  {
    bool near = std::abs(l.at("n_dot_l").get<double>() - 1e-5) < Near;
    if (l.at("kind") == "spot")
    {
      const double cutoff = std::cos(l.at("half_angle_deg").get<double>() * Pi / 180);
      near = near || std::abs(l.at("cos_angle").get<double>() - cutoff) < Near;
    }
    if (near)
    {
      return true;
    }
  }
  return false;
}

// The triangles of the mesh as shadelab's reader gives them, to hold the
// probe's triangle against.
inline vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& path)
{
  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

inline std::array<vtkIdType, 3> Corners(vtkPolyData* mesh, vtkIdType cell)
{
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  mesh->GetPolys()->GetCellAtId(cell, n, ids);
  return { ids[0], ids[1], ids[2] };
}

inline Vec3 PointOf(vtkPolyData* mesh, vtkIdType id)
{
  Vec3 p;
  mesh->GetPoint(id, p.data());
  return p;
}
}

#endif
