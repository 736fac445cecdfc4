// shadelab-bench-peels: translucency's speed-accuracy trade, side by side in
// one run with VTK's own dual depth peeling (the compositor a VTK user gets
// with SetUseDepthPeeling), both drawing our shaders on the same scene:
// every part at --translucency A, under the gold material.
//
//   shadelab-bench-peels MESH [--size WxH] [--translucency A] [--frames N]
//                        [--rounds R] [--camera-position X,Y,Z] [--csv FILE]
//
// Variants: the scene opaque; our peeling pass (vtkShadelabPeelingPass) at
// --peels 1, 2, 3, 4, 6 and every layer; VTK's vtkDualDepthPeelingPass in
// its place at 1, 2, 3, 4, 6 peels and "every layer" (MaxPeels, with
// SetOcclusionRatio(0): VTK takes 0 peels literally, as none). Each variant
// gets a fresh OpenGL context and one unmeasured frame (its programs
// compiled), then --frames frames of the same camera; the whole list runs
// --rounds times, alternated, and the time is the median of all its frames.
// Each picture's error is against ours with every layer, which the oracle
// tests hold within 1.5e-6 of the double-precision composite: the RMSE and
// the largest and mean |difference| over the R, G and B values of the
// pixels that picture covers, and the share of those pixels whose 8-bit
// value changes. A markdown table goes to stdout; --csv writes the rows for
// the chart (scripts/bench-peels draws it).
#include "core/errors.h"
#include "core/milliseconds.h"
#include "core/options.h"
#include "core/output_file.h"
#include "headless/headless_renderer.h"
#include "headless/vtkShadelabCapturePass.h"
#include "image/image_pixels.h"
#include "scene/mesh_input.h"
#include "scene/scene.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkDualDepthPeelingPass.h>
#include <vtkLogger.h>
#include <vtkPolyData.h>
#include <vtkRenderStepsPass.h>
#include <vtkRenderer.h>
#include <vtkTranslucentPass.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace shadelab;

namespace
{
struct Variant
{
  std::string Compositor; // opaque, shadelab, vtk-ddp
  int Peels = 0;          // 0: every layer
  std::vector<double> Times;
  FloatImage Picture;
};

struct Error
{
  double Rmse = 0, Max = 0, Mean = 0, Changed = 0; // Changed: share of covered pixels
};

// picture against reference over the pixels picture covers (any channel
// above 0 on the black background).
Error Against(const FloatImage& picture, const FloatImage& reference)
{
  double sum = 0, squares = 0, largest = 0;
  long long values = 0, pixels = 0, changed = 0;
  for (std::size_t p = 0; p + 3 < picture.Rgba.size(); p += 4)
  {
    const float* a = &picture.Rgba[p];
    const float* b = &reference.Rgba[p];
    if (a[0] <= 0 && a[1] <= 0 && a[2] <= 0)
    {
      continue;
    }
    ++pixels;
    bool differs = false;
    for (int c = 0; c < 3; ++c)
    {
      const double d = std::abs(double(a[c]) - b[c]);
      sum += d;
      squares += d * d;
      largest = std::max(largest, d);
      ++values;
      differs = differs || Quantised(a[c], 255) != Quantised(b[c], 255);
    }
    changed += differs;
  }
  if (values == 0)
  {
    return {};
  }
  return { std::sqrt(squares / values), largest, sum / values, double(changed) / pixels };
}

double Median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

std::string PeelsText(const Variant& v)
{
  return v.Compositor == "opaque" ? "" : v.Peels == 0 ? "every" : std::to_string(v.Peels);
}
}

int main(int argc, char** argv)
{
  vtkShadelabOutputWindow::Install();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app("translucency's time and error against the number of peels, ours against VTK's",
    "shadelab-bench-peels");
  SceneOptions o;
  o.MaterialName = "gold";
  o.MaterialGiven = true;
  std::string size = "1920x1080", camera, csv;
  double translucency = 0.4;
  int frames = 5, rounds = 3;
  app.add_option("MESH", o.Mesh)->required();
  app.add_option("--size", size);
  app.add_option("--translucency", translucency)->check(CLI::Range(0.0, 1.0));
  app.add_option("--frames", frames)->check(CLI::Range(1, 1000));
  app.add_option("--rounds", rounds)->check(CLI::Range(1, 100));
  app.add_option("--camera-position", camera, "X,Y,Z");
  app.add_option("--csv", csv, "The rows for the chart");
  CLI11_PARSE(app, argc, argv);
  try
  {
    o.Size = ParseSize(size);
    if (!camera.empty())
    {
      o.CameraPosition = ParseVec3(camera);
    }
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

  std::vector<Variant> variants(1);
  variants[0].Compositor = "opaque";
  for (const char* compositor : { "shadelab", "vtk-ddp" })
  {
    for (int peels : { 1, 2, 3, 4, 6, 0 })
    {
      variants.emplace_back().Compositor = compositor;
      variants.back().Peels = peels;
    }
  }
  for (int round = 0; round < rounds; ++round)
  {
    for (Variant& v : variants)
    {
      SceneOptions scene = o;
      if (v.Compositor != "opaque")
      {
        scene.Translucency = translucency;
      }
      HeadlessRenderer renderer;
      if (const std::string error = renderer.Start(o.Size.Width, o.Size.Height); !error.empty())
      {
        return ReportError("render", error);
      }
      const BuiltScene built = BuildScene(scene, loaded.Mesh, renderer.GetRenderer());
      if (!built.Error.empty())
      {
        return ReportError("scene", built.Error);
      }
      renderer.SetMaximumNumberOfPeels(v.Peels);
      if (v.Compositor == "vtk-ddp")
      {
        auto ddp = vtkSmartPointer<vtkDualDepthPeelingPass>::New();
        ddp->SetTranslucentPass(vtkSmartPointer<vtkTranslucentPass>::New());
        ddp->SetMaximumNumberOfPeels(v.Peels == 0 ? MaxPeels : v.Peels);
        ddp->SetOcclusionRatio(0);
        auto* capture = vtkShadelabCapturePass::SafeDownCast(renderer.GetRenderer()->GetPass());
        vtkRenderStepsPass::SafeDownCast(capture->GetDelegatePass())->SetTranslucentPass(ddp);
      }
      FloatImage picture = renderer.Render();
      if (!renderer.GetError().empty())
      {
        return ReportError(v.Compositor, renderer.GetError());
      }
      if (round == 0)
      {
        v.Picture = std::move(picture);
      }
      for (int i = 0; i < frames; ++i)
      {
        const Clock::time_point start = Clock::now();
        renderer.Render();
        v.Times.push_back(Milliseconds(start));
      }
    }
  }

  const FloatImage& every = variants[6].Picture; // ours, every layer
  const double everyMs = Median(variants[6].Times);
  std::ostringstream rows;
  rows << "compositor,peels,ms,x_every,rmse,max,mean,changed\n";
  std::printf("| compositor | --peels | frame ms (median) | x ours, every layer | RMSE | max abs "
              "error | mean abs error | 8-bit pixels changed |\n"
              "|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (const Variant& v : variants)
  {
    const double ms = Median(v.Times);
    const Error e = Against(v.Picture, every);
    const bool opaque = v.Compositor == "opaque";
    std::printf(opaque ? "| %s | %s | %.0f | %.2f | | | | |\n"
                       : "| %s | %s | %.0f | %.2f | %.3g | %.3g | %.3g | %.1f%% |\n",
      v.Compositor.c_str(), PeelsText(v).c_str(), ms, ms / everyMs, e.Rmse, e.Max, e.Mean,
      100 * e.Changed);
    if (!opaque)
    {
      rows << v.Compositor << ',' << PeelsText(v) << ',' << ms << ',' << ms / everyMs << ','
           << e.Rmse << ',' << e.Max << ',' << e.Mean << ',' << e.Changed << '\n';
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
