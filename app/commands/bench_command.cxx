#include "commands/bench_command.h"

#include "bench/speed_accuracy_chart.h"
#include "core/errors.h"
#include "core/milliseconds.h"
#include "core/output_file.h"
#include "core/output_path.h"
#include "core/progress_bar.h"
#include "headless/headless_renderer.h"
#include "image/image_writer_process.h"
#include "scene/mesh_input.h"
#include "scene/scene.h"

#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

namespace shadelab
{
CLI::App* AddBenchCommand(CLI::App& program, BenchOptions& o)
{
  CLI::App* bench = program.add_subcommand("bench",
    "Measure speed against accuracy: tessellated sphere and torus under each shading rule "
    "against their exact pictures; writes speed_accuracy.{csv,json,png,md} into DIR");
  bench->add_option("--out", o.Out, "Folder for the results (made if missing)")
    ->option_text("DIR")
    ->capture_default_str();
  bench->add_flag("--quick", o.Quick,
    "Four levels (80 to 7680 triangles), 640x480, angle weighting: under a minute");
  bench->add_option("--frames", o.Frames, "Timed frames per measurement, after the first")
    ->check(CLI::Range(1, 1000))
    ->capture_default_str();
  bench->add_flag("-q,--quiet", o.Quiet, "No warnings and no progress bar");
  return bench;
}

namespace
{

// What each surface is seen with: a camera that shows all of it with room
// to spare, and a point light above and to the left, so that the highlight
// sits off the middle and crosses triangle edges.
struct BenchScene
{
  AnalyticSurface Surface;
  PinholeCamera Camera;
  Light Lamp;
};

std::vector<BenchScene> Scenes()
{
  BenchScene sphere{ AnalyticSurface(AnalyticSurface::Kind::Sphere), {}, {} };
  sphere.Camera.Position = { 0, 0, 5 };
  sphere.Lamp.Position = { -2, 2.5, 5 };
  BenchScene torus{ AnalyticSurface(AnalyticSurface::Kind::Torus), {}, {} };
  torus.Camera.Position = { 0, -4.8, 3.6 };
  torus.Camera.ViewUp = { 0, 0, 1 };
  torus.Lamp.Position = { -2, -3, 5 };
  return { sphere, torus };
}

// The render command's scene for a bench scene: every camera option given,
// the default material (chrome) and ambient light.
SceneOptions RenderScene(const BenchScene& b, Shading rule, ImageSize size)
{
  SceneOptions o;
  o.ShadingRule = rule;
  o.Size = size;
  o.CameraPosition = b.Camera.Position;
  o.CameraFocalPoint = b.Camera.FocalPoint;
  o.CameraViewUp = b.Camera.ViewUp;
  o.ViewAngle = b.Camera.ViewAngle;
  o.Lights = { b.Lamp };
  return o;
}

IlluminationInputs ExactInputs(const BenchScene& b)
{
  const SceneOptions o = RenderScene(b, Shading::Phong, {});
  IlluminationInputs in;
  in.Surface = o.EffectiveMaterial();
  in.Ambient = o.Ambient;
  const double identity[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  in.Lights = { ToFrame(b.Lamp, identity, { 0, 0, 0 }) };
  in.Model = o.ReflectionModel;
  return in;
}

struct Candidate
{
  Shading Rule;
  std::string Weighting; // "face" for flat
};

// Renders mesh as scene says in a fresh context (so the first frame
// compiles its programs) and measures it.
std::string Measure(const SceneOptions& scene, vtkPolyData* mesh, int frames,
  const ExactImage& exact, SpeedAccuracyRow& row)
{
  HeadlessRenderer renderer;
  if (std::string error = renderer.Start(scene.Size.Width, scene.Size.Height); !error.empty())
  {
    return error;
  }
  const BuiltScene built = BuildScene(scene, mesh, renderer.GetRenderer());
  if (!built.Error.empty())
  {
    return built.Error;
  }
  const auto t0 = Clock::now();
  FloatImage image = renderer.Render();
  const double first = Milliseconds(t0, Clock::now());
  std::vector<double> times;
  for (int f = 0; f < frames; ++f)
  {
    const auto a = Clock::now();
    image = renderer.Render();
    times.push_back(Milliseconds(a, Clock::now()));
  }
  std::sort(times.begin(), times.end());
  row.MsPerFrame = times[times.size() / 2];
  row.CompileMs = std::max(0.0, first - row.MsPerFrame);
  const AccuracyMetrics m = CompareWithExact(image, exact);
  row.Rmse = m.Rmse;
  row.MaxError = m.MaxError;
  row.Psnr = m.Psnr;
  row.Pixels = m.Pixels;
  return {};
}

std::string Format(const char* format, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string CpuModel()
{
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);)
  {
    if (line.rfind("model name", 0) == 0)
    {
      return line.substr(line.find(':') + 2);
    }
  }
  return "unknown CPU";
}

// The markdown summary: per surface and size, each rule's error and speed
// at each level (angle weighting), the weightings side by side, the checks.
std::string Summary(
  const std::vector<SpeedAccuracyRow>& rows, const std::string& commandLine, double seconds)
{
  std::ostringstream md;
  md << "# Speed against accuracy\n\n"
     << "`" << commandLine << "`: " << Format("%.0f", seconds) << " s on " << CpuModel() << " ("
     << std::thread::hardware_concurrency() << " threads), OSMesa llvmpipe.\n\n"
     << "Error: |rendered - exact| of R, G, B over the object's pixels, less a " << SilhouetteBand
     << "-pixel band at the silhouette; exact = the lecture's equation at the ray's hit on the "
        "analytic surface with its exact normal, in double precision. Chrome, Blinn-Phong, one "
        "point light. ms/frame: median of the timed frames, read-back included.\n\n";
  std::map<std::tuple<std::string, int, int>,
    std::map<long long, std::map<std::string, const SpeedAccuracyRow*>>>
    tables;
  for (const SpeedAccuracyRow& r : rows)
  {
    if (r.Weighting == "angle" || r.Weighting == "face")
    {
      tables[{ r.Surface, r.Width, r.Height }][r.Triangles][r.Shading] = &r;
    }
  }
  for (const auto& [key, levels] : tables)
  {
    md << "## " << std::get<0>(key) << ", " << std::get<1>(key) << "x" << std::get<2>(key)
       << "\n\n| triangles | edge angle | flat RMSE | gouraud RMSE | phong RMSE | flat ms | "
          "gouraud ms | phong ms | phong PSNR |\n|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const auto& [triangles, byRule] : levels)
    {
      md << "| " << triangles << " | " << Format("%.2f", byRule.begin()->second->EdgeAngle) << " |";
      for (const Shading rule : LitRules)
      {
        const auto it = byRule.find(ToString(rule));
        md << " " << (it == byRule.end() ? "" : Format("%.2e", it->second->Rmse)) << " |";
      }
      for (const Shading rule : LitRules)
      {
        const auto it = byRule.find(ToString(rule));
        md << " " << (it == byRule.end() ? "" : Format("%.1f", it->second->MsPerFrame)) << " |";
      }
      const auto phong = byRule.find("phong");
      md << " " << (phong == byRule.end() ? "" : Format("%.1f", phong->second->Psnr)) << " |\n";
    }
    md << "\n";
  }
  std::map<std::string, std::map<long long, std::map<std::string, double>>> weightings;
  std::set<std::string> weightingNames;
  for (const SpeedAccuracyRow& r : rows)
  {
    if (r.Weighting != "face" && r.Width == rows.back().Width)
    {
      weightings[r.Surface + " " + r.Shading][r.Triangles][r.Weighting] = r.Rmse;
      weightingNames.insert(r.Weighting);
    }
  }
  if (weightingNames.size() > 1)
  {
    md << "## Normal weightings (RMSE at " << rows.back().Width << "x" << rows.back().Height
       << ")\n\n| surface, rule | triangles |";
    for (const std::string& w : weightingNames)
    {
      md << " " << w << " |";
    }
    md << "\n|---|---:|";
    for (std::size_t k = 0; k < weightingNames.size(); ++k)
    {
      md << "---:|";
    }
    md << "\n";
    for (const auto& [name, levels] : weightings)
    {
      for (const auto& [triangles, byWeighting] : levels)
      {
        md << "| " << name << " | " << triangles << " |";
        for (const std::string& w : weightingNames)
        {
          const auto it = byWeighting.find(w);
          md << " " << (it == byWeighting.end() ? "" : Format("%.2e", it->second)) << " |";
        }
        md << "\n";
      }
    }
    md << "\n";
  }
  const std::vector<std::string> exceptions = CheckSpeedAccuracyOrder(rows);
  md << "## Checks\n\nError falls with tessellation for every rule, and phong < gouraud < flat "
        "at every level: "
     << (exceptions.empty() ? "yes, everywhere.\n" : "no:\n\n");
  for (const std::string& e : exceptions)
  {
    md << "- " << e << "\n";
  }
  md << "\n![error against ms/frame](speed_accuracy.png)\n";
  return md.str();
}
}

int RunBench(const BenchOptions& o, const std::string& commandLine)
{
  std::error_code error;
  std::filesystem::create_directories(o.Out, error);
  const std::string csv = (std::filesystem::path(o.Out) / "speed_accuracy.csv").string();
  if (error)
  {
    return ReportError(o.Out, "cannot make the folder: " + error.message());
  }
  if (std::string problem = CheckWritableFolder(csv); !problem.empty())
  {
    return ReportError(o.Out, problem);
  }
  ImageWriterProcess writer;
  // Compilation is measured, so Mesa's shader cache must not answer for it.
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
  const auto start = Clock::now();

  const int levels = o.Quick ? 4 : 8;
  const std::vector<ImageSize> sizes = o.Quick
    ? std::vector<ImageSize>{ { 640, 480 } }
    : std::vector<ImageSize>{ { 640, 480 }, { 1920, 1080 } };
  const std::vector<std::string> weightings = o.Quick
    ? std::vector<std::string>{ "angle" }
    : std::vector<std::string>{ "angle", "uniform", "max" };
  std::vector<Candidate> candidates;
  for (const std::string& w : weightings)
  {
    candidates.push_back({ Shading::Gouraud, w });
    candidates.push_back({ Shading::Phong, w });
  }
  candidates.push_back({ Shading::Flat, "face" });

  const std::vector<BenchScene> scenes = Scenes();
  ProgressBar progress(
    static_cast<long long>(scenes.size() * levels * candidates.size() * sizes.size()), o.Quiet);
  long long done = 0;
  std::vector<SpeedAccuracyRow> rows;
  for (const BenchScene& scene : scenes)
  {
    std::vector<ExactImage> exact;
    for (const ImageSize& size : sizes)
    {
      progress.Show(done,
        std::string(scene.Surface.GetName()) + ": exact picture " + std::to_string(size.Width) +
          "x" + std::to_string(size.Height));
      exact.push_back(
        RenderExactImage(scene.Surface, scene.Camera, size.Width, size.Height, ExactInputs(scene)));
    }
    for (int level = 0; level < levels; ++level)
    {
      const vtkSmartPointer<vtkPolyData> tessellation = scene.Surface.Tessellate(level);
      std::map<std::string, std::pair<vtkSmartPointer<vtkPolyData>, double>> withNormals;
      double edgeAngle = 0;
      for (const Candidate& c : candidates)
      {
        SpeedAccuracyRow row;
        row.Surface = scene.Surface.GetName();
        row.Shading = ToString(c.Rule);
        row.Weighting = c.Weighting;
        row.Triangles = scene.Surface.TriangleCount(level);
        vtkPolyData* mesh = tessellation;
        if (c.Rule != Shading::Flat)
        {
          auto& [computed, ms] = withNormals[c.Weighting];
          if (!computed)
          {
            NormalsSettings settings;
            settings.Weighting = c.Weighting;
            const auto t0 = Clock::now();
            const ComputedNormals normals = ComputeNormals(tessellation, settings);
            ms = Milliseconds(t0, Clock::now());
            if (!normals.Mesh)
            {
              return ReportError(row.Surface, "normals: " + normals.Error);
            }
            computed = normals.Mesh;
          }
          mesh = computed;
          row.NormalsMs = ms;
          row.EdgeAngle = MeanEdgeNormalAngle(computed);
          edgeAngle = c.Weighting == "angle" ? row.EdgeAngle : edgeAngle;
        }
        else
        {
          row.EdgeAngle = edgeAngle; // the mesh's coarseness, as its angle-weighted normals see it
        }
        for (std::size_t s = 0; s < sizes.size(); ++s)
        {
          row.Width = sizes[s].Width;
          row.Height = sizes[s].Height;
          progress.Show(done,
            row.Surface + " " + std::to_string(row.Triangles) + " " + row.Shading + "/" +
              row.Weighting + " " + std::to_string(row.Width) + "x" + std::to_string(row.Height));
          if (std::string problem =
                Measure(RenderScene(scene, c.Rule, sizes[s]), mesh, o.Frames, exact[s], row);
              !problem.empty())
          {
            return ReportError("render", problem);
          }
          rows.push_back(row);
          ++done;
        }
      }
    }
  }
  progress.Show(done, "chart");
  const ChartImage chart = DrawSpeedAccuracyChart(rows);
  progress.Finish();
  if (!chart.Error.empty())
  {
    return ReportError("chart", chart.Error);
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  // Each output is tried and each failure reported: one that fits may
  // follow one that does not.
  const std::filesystem::path out(o.Out);
  const std::string json = (out / "speed_accuracy.json").string();
  const std::string md = (out / "speed_accuracy.md").string();
  const std::string png = (out / "speed_accuracy.png").string();
  int status = 0;
  for (const auto& [path, problem] : { std::pair{ csv, WriteSpeedAccuracyCsv(csv, rows) },
         std::pair{ json, WriteSpeedAccuracyJson(json, rows) },
         std::pair{ md, WriteFile(md, Summary(rows, commandLine, seconds)) },
         std::pair{ png,
           writer.Write(png, chart.Image, PixelType::UInt8,
             { { "ImageDescription", "shadelab bench: RMSE against ms/frame" } }) } })
  {
    if (!problem.empty())
    {
      status = ReportError(path, problem);
    }
  }
  if (status != 0)
  {
    return status;
  }
  std::printf("%s: %zu measurements in %.0f s; speed_accuracy.{csv,json,png,md}\n", o.Out.c_str(),
    rows.size(), seconds);
  return 0;
}
}
