// shadelab-bench-shadows: what --shadows costs and how far its shadow maps
// stray from the oracle's shadow rays, in one run. The mesh stands on a
// square floor twice its width (added under its bounding box, along -Y),
// seen from the iso view (front, right and above), lit by one light at a
// time: a point light above and to the side, a
// spot light there aimed at the mesh's centre (30 degrees), a directional
// light from the same side; phong, the gold material.
//
//   shadelab-bench-shadows MESH [--size WxH] [--frames N] [--rounds R]
//                          [--step S] [--csv FILE]
//
// Variants: each light without shadows and with them at --shadow-map-size
// 2048, then the point light's shadows at 256 to 4096 texels (8192, 1.5 GiB a
// cube, is more than llvmpipe gives). Each variant
// gets a fresh OpenGL context; its first frame (programs compiled, maps
// baked) is timed apart, then --frames frames of the same camera (the maps
// kept); the list runs --rounds times, alternated, and a frame's time is
// the median of all. A variant's mismatch: the share of pixels (every S-th
// in each direction, over the mesh and floor) where the map decides
// otherwise than the oracle's ray at a point the rule lit (probe's
// ShadowCheck), and the share in a shadow by the rays. A markdown table
// goes to stdout; --csv writes the size sweep's rows for the chart
// (scripts/bench-shadows draws it).
#include "core/errors.h"
#include "core/milliseconds.h"
#include "core/options.h"
#include "core/output_file.h"
#include "headless/headless_renderer.h"
#include "probe/pixel_probe.h"
#include "scene/mesh_input.h"
#include "scene/scene.h"
#include "shadelabVec3.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkLogger.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace shadelab;
using namespace shadelab::vec3;

namespace
{
struct Variant
{
  std::string Light; // point, spot, directional
  bool Shadows = false;
  int Size = DefaultShadowMapSize;
  std::vector<double> First, Times;
  double Mismatch = 0, Shadowed = 0;
};

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// mesh on a floor: a square under its bounding box, twice its larger
// width, facing +Y, with the mesh's point arrays where it has normals.
vtkSmartPointer<vtkPolyData> OnAFloor(vtkPolyData* mesh)
{
  double b[6];
  mesh->GetBounds(b);
  const double cx = (b[0] + b[1]) / 2, cz = (b[4] + b[5]) / 2;
  const double half = std::max(b[1] - b[0], b[5] - b[4]);
  auto floor = vtkSmartPointer<vtkPolyData>::New();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->InsertNextPoint(cx - half, b[2], cz + half);
  points->InsertNextPoint(cx + half, b[2], cz + half);
  points->InsertNextPoint(cx + half, b[2], cz - half);
  points->InsertNextPoint(cx - half, b[2], cz - half);
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType first[3] = { 0, 1, 2 }, second[3] = { 0, 2, 3 };
  polys->InsertNextCell(3, first);
  polys->InsertNextCell(3, second);
  floor->SetPoints(points);
  floor->SetPolys(polys);
  if (vtkDataArray* normals = mesh->GetPointData()->GetNormals())
  {
    auto up = vtkSmartPointer<vtkFloatArray>::New();
    up->SetName(normals->GetName());
    up->SetNumberOfComponents(3);
    up->SetNumberOfTuples(4);
    for (vtkIdType i = 0; i < 4; ++i)
    {
      up->SetTuple3(i, 0, 1, 0);
    }
    floor->GetPointData()->SetNormals(up);
  }
  auto append = vtkSmartPointer<vtkAppendPolyData>::New();
  append->AddInputData(mesh);
  append->AddInputData(floor);
  append->Update();
  return append->GetOutput();
}

// The variant's light, placed from the mesh's bounds (the floor's excluded).
Light LightOf(const std::string& kind, const double b[6])
{
  const Vec3 centre{ (b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2 };
  const double size = length(Vec3{ b[1] - b[0], b[3] - b[2], b[5] - b[4] });
  const Vec3 from = centre + size * Vec3{ -1, 1.5, 0.8 };
  Light l;
  if (kind == "directional")
  {
    l.Kind = LightKind::Directional;
    l.Direction = centre - from;
  }
  else
  {
    l.Kind = kind == "spot" ? LightKind::Spot : LightKind::Point;
    l.Position = from;
    l.Direction = centre - from;
    l.HalfAngleDeg = 30;
  }
  return l;
}
}

int main(int argc, char** argv)
{
  vtkShadelabOutputWindow::Install();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app(
    "what --shadows costs, and its maps against the oracle's rays", "shadelab-bench-shadows");
  SceneOptions o;
  o.MaterialName = "gold";
  o.MaterialGiven = true;
  o.View = ViewPreset::Iso;
  std::string size = "1920x1080", csv;
  int frames = 5, rounds = 3, step = 4;
  app.add_option("MESH", o.Mesh)->required();
  app.add_option("--size", size);
  app.add_option("--frames", frames)->check(CLI::Range(1, 1000));
  app.add_option("--rounds", rounds)->check(CLI::Range(1, 100));
  app.add_option("--step", step, "Probe every S-th pixel each way")->check(CLI::Range(1, 64));
  app.add_option("--csv", csv, "The size sweep's rows for the chart");
  CLI11_PARSE(app, argc, argv);
  try
  {
    o.Size = ParseSize(size);
  }
  catch (const std::invalid_argument& e)
  {
    return ReportError("option", e.what());
  }
  LoadedMesh loaded = LoadMesh(o);
  if (!loaded.Mesh)
  {
    return ReportError(o.Mesh, loaded.Error);
  }
  double bounds[6];
  loaded.Mesh->GetBounds(bounds);
  const vtkSmartPointer<vtkPolyData> scene = OnAFloor(loaded.Mesh);

  std::vector<Variant> variants;
  for (const char* light : { "point", "spot", "directional" })
  {
    for (bool shadows : { false, true })
    {
      Variant& v = variants.emplace_back();
      v.Light = light;
      v.Shadows = shadows;
    }
  }
  for (int texels : { 256, 512, 1024, 4096 })
  {
    Variant& v = variants.emplace_back();
    v.Light = "point";
    v.Shadows = true;
    v.Size = texels;
  }
  for (int round = 0; round < rounds; ++round)
  {
    for (Variant& v : variants)
    {
      SceneOptions s = o;
      s.Lights = { LightOf(v.Light, bounds) };
      s.Shadows = v.Shadows;
      s.ShadowMapSize = v.Size;
      HeadlessRenderer renderer;
      if (const std::string error = renderer.Start(o.Size.Width, o.Size.Height); !error.empty())
      {
        return ReportError("render", error);
      }
      const BuiltScene built = BuildScene(s, scene, renderer.GetRenderer());
      if (!built.Error.empty())
      {
        return ReportError("scene", built.Error);
      }
      Clock::time_point start = Clock::now();
      renderer.Render();
      v.First.push_back(Milliseconds(start));
      if (!renderer.GetError().empty())
      {
        return ReportError(v.Light, renderer.GetError());
      }
      for (int i = 0; i < frames; ++i)
      {
        start = Clock::now();
        renderer.Render();
        v.Times.push_back(Milliseconds(start));
      }
      if (round > 0 || !v.Shadows)
      {
        continue;
      }
      const PixelProber prober(s, built.Mesh, renderer.GetRenderer()->GetActiveCamera(), o.Size,
        built.Images, built.Casters.get());
      long long asked = 0, differs = 0, shadowed = 0;
      for (int y = 0; y < o.Size.Height; y += step)
      {
        for (int x = 0; x < o.Size.Width; x += step)
        {
          const PixelProbe p = prober.Probe({ x, y });
          if (!p.Hit || p.Shadows.empty() || p.Shadows[0].Rays == 0)
          {
            continue;
          }
          ++asked;
          differs += p.Shadows[0].MapDisagrees > 0;
          shadowed += p.Shaded.Terms.Lights[0].Shadowed;
        }
      }
      v.Mismatch = asked ? double(differs) / asked : 0;
      v.Shadowed = asked ? double(shadowed) / asked : 0;
    }
  }

  std::ostringstream rows;
  rows << "texels,ms,first_ms,mismatch\n";
  std::printf("| light | shadows | map texels | frame ms (median) | x without | first frame ms | "
              "pixels in shadow | map against ray: pixels that differ |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const Variant& v : variants)
  {
    const double ms = Median(v.Times);
    const auto without = std::find_if(variants.begin(), variants.end(),
      [&v](const Variant& w) { return w.Light == v.Light && !w.Shadows; });
    if (!v.Shadows)
    {
      std::printf("| %s | no | | %.0f | 1 | %.0f | | |\n", v.Light.c_str(), ms, Median(v.First));
      continue;
    }
    std::printf("| %s | yes | %d | %.0f | %.2f | %.0f | %.1f%% | %.3f%% |\n", v.Light.c_str(),
      v.Size, ms, ms / Median(without->Times), Median(v.First), 100 * v.Shadowed, 100 * v.Mismatch);
    if (v.Light == "point")
    {
      rows << v.Size << ',' << ms << ',' << Median(v.First) << ',' << v.Mismatch << '\n';
    }
  }
  if (!csv.empty())
  {
    if (const std::string error = WriteFile(csv, rows.str()); !error.empty())
    {
      return ReportError(csv, error);
    }
  }
  return 0;
}
