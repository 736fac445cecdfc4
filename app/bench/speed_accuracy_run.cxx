#include "bench/speed_accuracy_run.h"

#include "core/milliseconds.h"
#include "core/progress_bar.h"
#include "headless/headless_renderer.h"
#include "scene/mesh_input.h"
#include "scene/scene.h"

#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <map>

namespace shadelab
{
namespace
{
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
  return WorldIllumination(RenderScene(b, Shading::Phong, {}), { b.Lamp });
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

// The rules with their normals' weightings: gouraud and phong with each of
// the plan's, flat with the faces' own.
std::vector<Candidate> Candidates(const SpeedAccuracyPlan& plan)
{
  std::vector<Candidate> candidates;
  for (const std::string& w : plan.Weightings)
  {
    candidates.push_back({ Shading::Gouraud, w });
    candidates.push_back({ Shading::Phong, w });
  }
  candidates.push_back({ Shading::Flat, "face" });
  return candidates;
}

// The measurements of one bench scene, appended to rows.
class SceneMeasurements
{
public:
  SceneMeasurements(const BenchScene& scene, const SpeedAccuracyPlan& plan, ProgressBar& progress,
    std::vector<SpeedAccuracyRow>& rows)
    : Scene(scene)
    , Sizes(plan.Sizes)
    , Frames(plan.Frames)
    , Progress(progress)
    , Rows(rows)
  {
  }

  // Every level and candidate at every size; a failure ends it.
  std::optional<MeasurementFailure> Run(int levels, const std::vector<Candidate>& candidates)
  {
    this->RenderExactImages();
    for (int level = 0; level < levels; ++level)
    {
      const vtkSmartPointer<vtkPolyData> tessellation = this->Scene.Surface.Tessellate(level);
      this->WithNormals.clear();
      this->EdgeAngle = 0;
      for (const Candidate& c : candidates)
      {
        if (auto failure = this->MeasureCandidate(tessellation, level, c))
        {
          return failure;
        }
      }
    }
    return std::nullopt;
  }

private:
  // The measurements made so far, for the progress bar.
  long long Done() const { return static_cast<long long>(this->Rows.size()); }

  void RenderExactImages()
  {
    for (const ImageSize& size : this->Sizes)
    {
      this->Progress.Show(this->Done(),
        std::string(this->Scene.Surface.GetName()) + ": exact picture " +
          std::to_string(size.Width) + "x" + std::to_string(size.Height));
      this->Exact.push_back(RenderExactImage(this->Scene.Surface, this->Scene.Camera, size.Width,
        size.Height, ExactInputs(this->Scene)));
    }
  }

  // The tessellation with the candidate's vertex normals (computed once per
  // weighting and level, and timed), or as it is for flat.
  std::optional<MeasurementFailure> MeshFor(
    vtkPolyData* tessellation, const Candidate& c, SpeedAccuracyRow& row, vtkPolyData*& mesh)
  {
    mesh = tessellation;
    if (c.Rule == Shading::Flat)
    {
      row.EdgeAngle =
        this->EdgeAngle; // the mesh's coarseness, as its angle-weighted normals see it
      return std::nullopt;
    }
    auto& [computed, ms] = this->WithNormals[c.Weighting];
    if (!computed)
    {
      NormalsSettings settings;
      settings.Weighting = c.Weighting;
      const auto t0 = Clock::now();
      const ComputedNormals normals = ComputeNormals(tessellation, settings);
      ms = Milliseconds(t0, Clock::now());
      if (!normals.Mesh)
      {
        return MeasurementFailure{ row.Surface, "normals: " + normals.Error };
      }
      computed = normals.Mesh;
    }
    mesh = computed;
    row.NormalsMs = ms;
    row.EdgeAngle = MeanEdgeNormalAngle(computed);
    this->EdgeAngle = c.Weighting == "angle" ? row.EdgeAngle : this->EdgeAngle;
    return std::nullopt;
  }

  // One candidate on one level, at every size.
  std::optional<MeasurementFailure> MeasureCandidate(
    vtkPolyData* tessellation, int level, const Candidate& c)
  {
    SpeedAccuracyRow row;
    row.Surface = this->Scene.Surface.GetName();
    row.Shading = ToString(c.Rule);
    row.Weighting = c.Weighting;
    row.Triangles = this->Scene.Surface.TriangleCount(level);
    vtkPolyData* mesh = nullptr;
    if (auto failure = this->MeshFor(tessellation, c, row, mesh))
    {
      return failure;
    }
    for (std::size_t s = 0; s < this->Sizes.size(); ++s)
    {
      row.Width = this->Sizes[s].Width;
      row.Height = this->Sizes[s].Height;
      this->Progress.Show(this->Done(),
        row.Surface + " " + std::to_string(row.Triangles) + " " + row.Shading + "/" +
          row.Weighting + " " + std::to_string(row.Width) + "x" + std::to_string(row.Height));
      if (std::string problem = Measure(RenderScene(this->Scene, c.Rule, this->Sizes[s]), mesh,
            this->Frames, this->Exact[s], row);
          !problem.empty())
      {
        return MeasurementFailure{ "render", problem };
      }
      this->Rows.push_back(row);
    }
    return std::nullopt;
  }

  const BenchScene& Scene;
  const std::vector<ImageSize>& Sizes;
  const int Frames;
  ProgressBar& Progress;
  std::vector<SpeedAccuracyRow>& Rows;
  std::vector<ExactImage> Exact; // one per size
  // The current level's meshes with normals, and their time, by weighting.
  std::map<std::string, std::pair<vtkSmartPointer<vtkPolyData>, double>> WithNormals;
  double EdgeAngle = 0; // the current level's, with angle-weighted normals
};
}

SpeedAccuracyPlan MakeSpeedAccuracyPlan(bool quick, int frames)
{
  SpeedAccuracyPlan plan;
  plan.Levels = quick ? 4 : 8;
  plan.Sizes = quick ? std::vector<ImageSize>{ { 640, 480 } }
                     : std::vector<ImageSize>{ { 640, 480 }, { 1920, 1080 } };
  plan.Weightings = quick ? std::vector<std::string>{ "angle" }
                          : std::vector<std::string>{ "angle", "uniform", "max" };
  plan.Frames = frames;
  return plan;
}

long long SpeedAccuracyRowCount(const SpeedAccuracyPlan& plan)
{
  return static_cast<long long>(
    Scenes().size() * plan.Levels * Candidates(plan).size() * plan.Sizes.size());
}

std::optional<MeasurementFailure> MeasureSpeedAccuracy(
  const SpeedAccuracyPlan& plan, ProgressBar& progress, std::vector<SpeedAccuracyRow>& rows)
{
  const std::vector<Candidate> candidates = Candidates(plan);
  for (const BenchScene& scene : Scenes())
  {
    SceneMeasurements measurements(scene, plan, progress, rows);
    if (auto failure = measurements.Run(plan.Levels, candidates))
    {
      return failure;
    }
  }
  return std::nullopt;
}
}
