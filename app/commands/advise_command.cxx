#include "commands/advise_command.h"

#include "bench/speed_accuracy.h"
#include "core/errors.h"
#include "scene/mesh_input.h"
#include "settings/command_line.h"
#include "shadelabSpeedAccuracyCsv.h" // generated from data/speed_accuracy.csv

#include <vtkPolyData.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <sstream>

namespace shadelab
{
CLI::App* AddAdviseCommand(CLI::App& program, AdviseOptions& o)
{
  CLI::App* advise = program.add_subcommand("advise",
    "Name the cheapest shading rule that keeps MESH's shading error under E at a picture "
    "size, and whether more triangles or a better rule is the better buy");
  advise->add_option("MESH", o.Mesh, MeshFileHelp())->required();
  advise
    ->add_option("--max-error", o.MaxError,
      "Largest acceptable RMSE against the exact picture, intensities 0..1 (1/255 = 0.0039 "
      "is one 8-bit step)")
    ->required()
    ->check(CLI::PositiveNumber)
    ->option_text("E");
  advise
    ->add_option_function<std::string>(
      "--size", [&o](const std::string& text) { o.Size = ParseSize(text); },
      "Picture size (default 1920x1080)")
    ->option_text("WxH");
  advise
    ->add_option("--measurements", o.Measurements,
      "speed_accuracy.csv from `shadelab bench` on this machine (default: the measurements "
      "shadelab ships, BENCHMARKS.md)")
    ->option_text("CSV");
  AddSettings(*advise, o.Scene, Command::Advise);
  return advise;
}

namespace
{
// y at x through the points (x_i, y_i), linear in log-log, extended beyond
// the ends along the end segments: errors follow power laws in the edge
// angle (first order for flat, second for Gouraud and Phong).
double LogLogInterpolate(std::vector<std::pair<double, double>> points, double x)
{
  std::sort(points.begin(), points.end());
  if (points.size() == 1)
  {
    return points[0].second;
  }
  std::size_t k = 1;
  while (k + 1 < points.size() && points[k].first < x)
  {
    ++k;
  }
  const auto [x0, y0] = points[k - 1];
  const auto [x1, y1] = points[k];
  const double slope = std::log(y1 / y0) / std::log(x1 / x0);
  return y0 * std::exp(slope * std::log(x / x0));
}

// y at x from the least-squares line a + b x through the points, a and b
// at least 0: a frame costs a fixed part (the pixels, the read-back) and a
// part per triangle, and a line keeps the timings' noise from making more
// triangles look faster.
double AffineFit(const std::vector<std::pair<double, double>>& points, double x)
{
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(points.size());
  for (const auto& [px, py] : points)
  {
    sx += px;
    sy += py;
    sxx += px * px;
    sxy += px * py;
  }
  const double d = n * sxx - sx * sx;
  double b = d > 0 ? std::max(0.0, (n * sxy - sx * sy) / d) : 0;
  double a = (sy - b * sx) / n;
  if (a < 0)
  {
    a = 0;
    b = sxx > 0 ? sxy / sxx : 0;
  }
  return a + b * x;
}

struct Prediction
{
  double Rmse = 0;
  double Ms = 0;
};

class Model
{
public:
  Model(const std::vector<SpeedAccuracyRow>& rows, ImageSize size, const std::string& weighting)
  {
    // The measured size nearest the asked one (by pixel count, on a log scale).
    const double pixels = static_cast<double>(size.Width) * size.Height;
    double best = std::numeric_limits<double>::infinity();
    for (const SpeedAccuracyRow& r : rows)
    {
      const double distance = std::abs(std::log(static_cast<double>(r.Width) * r.Height / pixels));
      if (distance < best)
      {
        best = distance;
        this->Width = r.Width;
        this->Height = r.Height;
      }
    }
    for (const SpeedAccuracyRow& r : rows)
    {
      const bool usable = r.Rmse > 0 && r.MsPerFrame > 0 && r.EdgeAngle > 0 &&
        r.Width == this->Width && r.Height == this->Height;
      if (usable && (r.Weighting == weighting || r.Weighting == "face"))
      {
        this->Errors[r.Shading][r.Surface].push_back({ r.EdgeAngle, r.Rmse });
        this->Times[r.Shading][r.Surface].push_back(
          { static_cast<double>(r.Triangles), r.MsPerFrame });
      }
    }
  }

  bool Has(const std::string& rule) const { return this->Errors.count(rule) > 0; }

  // The worse of the measured surfaces' errors (a mesh may curve like
  // either), and their mean time.
  Prediction Predict(const std::string& rule, double edgeAngle, double triangles) const
  {
    Prediction p;
    for (const auto& [surface, points] : this->Errors.at(rule))
    {
      p.Rmse = std::max(p.Rmse, LogLogInterpolate(points, edgeAngle));
    }
    const auto& times = this->Times.at(rule);
    for (const auto& [surface, points] : times)
    {
      p.Ms += AffineFit(points, triangles) / times.size();
    }
    return p;
  }

  int Width = 0, Height = 0;

private:
  using Curves = std::map<std::string, std::vector<std::pair<double, double>>>;
  std::map<std::string, Curves> Errors, Times;
};

// The measurements: the file given, else the ones shadelab ships; "" or
// the problem.
std::string ReadMeasurements(const AdviseOptions& o, std::vector<SpeedAccuracyRow>& rows)
{
  if (o.Measurements.empty())
  {
    std::istringstream shipped(ShippedSpeedAccuracyCsv);
    return ParseSpeedAccuracyCsv(shipped, rows);
  }
  return ReadSpeedAccuracyCsv(o.Measurements, rows);
}

// What one could do: a rule on this mesh (level 0), or on a mesh with 4^level
// times the triangles.
struct Option
{
  std::string Rule;
  int Level;
  Prediction P;
};

// Each rule on this mesh, and on meshes with 4^k times the triangles (k
// Loop subdivisions, or a finer export), whose edges turn by a 2^k-th of
// the angle.
std::vector<Option> Options(const Model& model, double angle, double triangles)
{
  std::vector<Option> options;
  for (int level = 0; level <= 3; ++level)
  {
    for (const Shading lit : LitRules)
    {
      const char* rule = ToString(lit);
      options.push_back(
        { rule, level, model.Predict(rule, angle / (1 << level), triangles * (1 << (2 * level))) });
    }
  }
  return options;
}

void PrintTable(const std::vector<Option>& options, const AdviseOptions& o, double triangles)
{
  std::printf(
    "| triangles | rule | RMSE | ms/frame | under %g |\n|---:|---|---:|---:|---|\n", o.MaxError);
  for (const Option& c : options)
  {
    std::printf("| %s | %s | %.2g | %.1f | %s |\n",
      TriangleCountText(triangles * (1 << (2 * c.Level))).c_str(), c.Rule.c_str(), c.P.Rmse, c.P.Ms,
      c.P.Rmse <= o.MaxError ? "yes" : "no");
  }
}

// The fastest option that keeps the error under maxError and that keep()
// accepts; null when there is none.
template <typename Keep>
const Option* Cheapest(const std::vector<Option>& options, double maxError, Keep keep)
{
  const Option* cheapest = nullptr;
  for (const Option& c : options)
  {
    if (c.P.Rmse <= maxError && keep(c) && (!cheapest || c.P.Ms < cheapest->P.Ms))
    {
      cheapest = &c;
    }
  }
  return cheapest;
}

// The buy, when the mesh as it is needs more than flat: a better rule on
// these triangles, or more triangles.
void PrintWhy(const std::vector<Option>& options, const Option& cheapest, double maxError)
{
  // The cheapest that reaches E on these triangles.
  const Option* here = Cheapest(options, maxError, [](const Option& c) { return c.Level == 0; });
  // The cheapest that reaches E on more triangles with a cheaper rule than here's.
  const Option* finer = Cheapest(options, maxError,
    [here](const Option& c) { return c.Level > 0 && (!here || c.Rule != here->Rule); });
  std::printf("Why: flat on this mesh comes to %.2g. ", options[0].P.Rmse);
  if (here && finer && here == &cheapest)
  {
    std::printf("A better rule is the better buy: %s on these triangles (%.1f ms) is cheaper "
                "than %s on %dx of them (%.1f ms).\n",
      here->Rule.c_str(), here->P.Ms, finer->Rule.c_str(), 1 << (2 * finer->Level), finer->P.Ms);
  }
  else if (here == &cheapest)
  {
    std::printf(
      "A better rule is the better buy: %s reaches it on these triangles.\n", here->Rule.c_str());
  }
  else if (here)
  {
    std::printf("More triangles are the better buy: %s on %dx the triangles (%.1f ms) is "
                "cheaper than %s on these (%.1f ms).\n",
      cheapest.Rule.c_str(), 1 << (2 * cheapest.Level), cheapest.P.Ms, here->Rule.c_str(),
      here->P.Ms);
  }
  else
  {
    std::printf("No rule reaches it on these triangles: more triangles are needed, and %s is "
                "the cheapest rule that gets there.\n",
      cheapest.Rule.c_str());
  }
}

// The verdict: the cheapest option under the error, and why.
void PrintAdvice(const std::vector<Option>& options, double maxError)
{
  const Option* cheapest = Cheapest(options, maxError, [](const Option&) { return true; });
  std::printf("\n");
  if (!cheapest)
  {
    std::printf("Nothing measured reaches %g: phong on 64x the triangles comes to %.2g. The "
                "error falls fastest with triangles under phong; a finer mesh and phong is the "
                "way there.\n",
      maxError, options.back().P.Rmse);
    return;
  }
  if (cheapest->Level == 0)
  {
    std::printf("Use %s: %.2g <= %g at %.1f ms/frame on this mesh as it is.\n",
      cheapest->Rule.c_str(), cheapest->P.Rmse, maxError, cheapest->P.Ms);
  }
  else
  {
    std::printf("Use %s on %dx the triangles: %.2g <= %g at %.1f ms/frame.\n",
      cheapest->Rule.c_str(), 1 << (2 * cheapest->Level), cheapest->P.Rmse, maxError,
      cheapest->P.Ms);
  }
  if (options[0].P.Rmse > maxError)
  {
    PrintWhy(options, *cheapest, maxError);
  }
}
}

int RunAdvise(const AdviseOptions& o)
{
  std::vector<SpeedAccuracyRow> rows;
  const std::string source = o.Measurements.empty() ? "shadelab's measurements" : o.Measurements;
  if (const std::string problem = ReadMeasurements(o, rows); !problem.empty())
  {
    return ReportError(source, problem);
  }
  const Model model(rows, o.Size, o.Scene.Computed.Weighting);
  for (const Shading lit : LitRules)
  {
    const char* rule = ToString(lit);
    if (!model.Has(rule))
    {
      return ReportError(source,
        std::string("no measurements of ") + rule + " with " + o.Scene.Computed.Weighting +
          " weighting");
    }
  }

  SceneOptions scene;
  scene.Mesh = o.Mesh;
  scene.Computed = o.Scene.Computed;
  const LoadedMesh loaded = LoadMesh(scene);
  if (!loaded.Mesh)
  {
    return ReportError(o.Mesh, loaded.Error);
  }
  const double triangles = static_cast<double>(loaded.Mesh->GetNumberOfPolys());
  const double angle = MeanEdgeNormalAngle(loaded.Mesh);
  if (!(angle > 0))
  {
    return ReportError(
      o.Mesh, "has no edges between differing normals: every rule shades it alike");
  }

  const std::vector<Option> options = Options(model, angle, triangles);
  std::printf("%s: %s triangles, edges turn by %.2f degrees on average (%s normals)\n",
    o.Mesh.c_str(), TriangleCountText(triangles).c_str(), angle,
    loaded.NormalsFromFile ? "the file's" : o.Scene.Computed.Weighting.c_str());
  std::printf("predicted from %s at %dx%d (RMSE: the worse of sphere and torus; ms/frame: "
              "OSMesa llvmpipe)\n\n",
    source.c_str(), model.Width, model.Height);
  PrintTable(options, o, triangles);
  PrintAdvice(options, o.MaxError);
  return 0;
}
}
