// shadelab-bench-normals: vtkShadelabMeshNormals against vtkPolyDataNormals,
// side by side in one run (issue 4): time and peak memory on a mesh and its
// Loop subdivisions, and each weighting's accuracy against the exact normals
// of a sphere and a torus, regular and irregular.
//
//   shadelab-bench-normals MESH [--runs N] [--quick]
//
// Times are medians of N runs of Update(), each on a fresh filter except for
// the cached re-weighting rows. Peak memory is how far the process's peak
// resident size rose above its resident size before a run (Linux resets the
// peak when "5" is written to /proc/self/clear_refs), the largest over a
// configuration's runs, with the input mesh already in memory. Markdown to
// stdout, progress to stderr.
#include "core/milliseconds.h"
#include "scene/mesh_input.h"
#include "shadelabVec3.h"
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabMeshReader.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkVersion.h>

#include <CLI/CLI.hpp>

#include <malloc.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
using Vec = shadelab::Vec3;
using namespace shadelab::vec3;
using shadelab::Clock;
using shadelab::Milliseconds;

const char* WeightingName(int weighting)
{
  return shadelab::ToString(static_cast<vtkShadelabMeshNormals::Weightings>(weighting));
}

// ---------------------------------------------------------------------------
// The machine.

int Processors()
{
  // What nproc prints: the processors this process may run on.
  cpu_set_t set;
  if (sched_getaffinity(0, sizeof set, &set) == 0)
  {
    return CPU_COUNT(&set);
  }
  return static_cast<int>(std::thread::hardware_concurrency());
}

std::string CpuModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      const size_t start = line.find_first_not_of(" \t", line.find(':') + 1);
      return start == std::string::npos ? "" : line.substr(start);
    }
  }
  return "unknown CPU";
}

// ---------------------------------------------------------------------------
// Time and memory.

// A field of /proc/self/status ("VmRSS:", "VmHWM:") in MiB.
double StatusMiB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind(field, 0) == 0)
    {
      return std::stod(line.substr(std::strlen(field))) / 1024;
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

// Resets VmHWM to the current resident size; false where the kernel refuses.
bool ResetPeak()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
  clear.flush();
  return static_cast<bool>(clear);
}

struct Measured
{
  double Median = 0;
  double Min = 0;
  double Max = 0;
  double PeakMiB = 0; // NaN if the peak could not be reset
};

// `prepare` (untimed, unmeasured) then `run` (timed), `runs` times.
Measured Measure(int runs, const std::function<void()>& prepare, const std::function<void()>& run)
{
  std::vector<double> ms;
  double peak = 0;
  for (int i = 0; i < runs; ++i)
  {
    prepare();
    // Give freed memory back first: otherwise a run reuses heap pages that
    // are already resident and its allocations do not show in the peak.
    malloc_trim(0);
    const bool reset = ResetPeak();
    const double before = StatusMiB("VmRSS:");
    const auto start = Clock::now();
    run();
    ms.push_back(Milliseconds(start));
    peak = reset ? std::max(peak, StatusMiB("VmHWM:") - before)
                 : std::numeric_limits<double>::quiet_NaN();
  }
  std::sort(ms.begin(), ms.end());
  return { ms[ms.size() / 2], ms.front(), ms.back(), peak };
}

vtkSmartPointer<vtkPolyDataNormals> VtkNormals(vtkPolyData* mesh, bool defaults)
{
  auto filter = vtkSmartPointer<vtkPolyDataNormals>::New();
  filter->SetInputData(mesh);
  if (!defaults)
  {
    filter->SplittingOff();
    filter->ConsistencyOff();
    filter->ComputeCellNormalsOff();
  }
  return filter;
}

vtkSmartPointer<vtkShadelabMeshNormals> OurNormals(
  vtkPolyData* mesh, int weighting, bool splitting, bool consistency)
{
  auto filter = vtkSmartPointer<vtkShadelabMeshNormals>::New();
  filter->SetInputData(mesh);
  filter->SetWeighting(weighting);
  filter->SetSplitting(splitting);
  filter->SetFeatureAngle(30);
  filter->SetConsistency(consistency);
  return filter;
}

// A timed configuration whose output has no point normals measured nothing.
bool HasPointNormals(vtkAlgorithm* filter)
{
  vtkPolyData* output = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  return output && output->GetPointData()->GetNormals() &&
    output->GetPointData()->GetNormals()->GetNumberOfTuples() == output->GetNumberOfPoints();
}

std::string Number(double value, const char* format)
{
  if (std::isnan(value))
  {
    return "n/a";
  }
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

void SpeedTable(vtkPolyData* mesh, const std::string& name, int runs)
{
  struct Row
  {
    std::string Name;
    Measured M;
    bool Ok = true;
  };
  std::vector<Row> rows;
  vtkSmartPointer<vtkAlgorithm> filter;
  auto add = [&](const std::string& row, const std::function<void()>& prepare,
               const std::function<void()>& run, vtkAlgorithm* checked)
  {
    std::fprintf(stderr, "bench-normals: %s: %s\n", name.c_str(), row.c_str());
    const Measured m = Measure(runs, prepare, run);
    rows.push_back({ row, m, HasPointNormals(checked ? checked : filter.Get()) });
  };
  // A fresh filter for every run; the previous one (and its output) is freed
  // before the run, so it does not count in the next run's memory either.
  auto fresh = [&](const std::string& row, std::function<vtkSmartPointer<vtkAlgorithm>()> make)
  {
    add(
      row, [&filter, make] { filter = make(); }, [&filter] { filter->Update(); }, nullptr);
  };
  using N = vtkShadelabMeshNormals;

  fresh("vtkPolyDataNormals, defaults (split at 30, consistency)",
    [mesh] { return VtkNormals(mesh, true); });
  fresh(
    "vtkPolyDataNormals, no splitting, no consistency", [mesh] { return VtkNormals(mesh, false); });
  fresh("ours, angle, split at 30", [mesh] { return OurNormals(mesh, N::Angle, true, false); });
  const size_t oursSplit = rows.size() - 1;
  fresh("ours, angle, split at 30, consistency",
    [mesh] { return OurNormals(mesh, N::Angle, true, true); });
  fresh("ours, angle, no splitting", [mesh] { return OurNormals(mesh, N::Angle, false, false); });
  const size_t freshAngle = rows.size() - 1;
  filter = nullptr;

  // Re-weighting a filter that has already run on this input, without
  // splitting: each run first switches to another weighting (untimed), then
  // only SetWeighting + Update is timed. The other weighting is max, or
  // angle for max, because the cache keeps the corner weights of the last
  // of those two it computed: each timed Update really recomputes.
  auto cached = OurNormals(mesh, N::Angle, false, false);
  cached->Update();
  size_t reweightedTo[N::Loop + 1];
  for (int w = N::Uniform; w <= N::Loop; ++w)
  {
    const int other = w == N::Max ? N::Angle : N::Max;
    add(
      std::string("ours, cached mesh, re-weighted ") + WeightingName(other) + " -> " +
        WeightingName(w),
      [&, other]
      {
        cached->SetWeighting(other);
        cached->Update();
      },
      [&, w]
      {
        cached->SetWeighting(w);
        cached->Update();
      },
      cached);
    reweightedTo[w] = rows.size() - 1;
  }
  add(
    "ours, cached mesh, angle, split at 30 -> 40",
    [&]
    {
      cached->SetWeighting(N::Angle);
      cached->SplittingOn();
      cached->SetFeatureAngle(30);
      cached->Update();
    },
    [&]
    {
      cached->SetFeatureAngle(40);
      cached->Update();
    },
    cached);
  const int builds = cached->GetNumberOfConnectivityBuilds();
  cached = nullptr;

  std::printf("\n### %s: %lld points, %lld triangles\n\n", name.c_str(),
    static_cast<long long>(mesh->GetNumberOfPoints()),
    static_cast<long long>(mesh->GetNumberOfPolys()));
  std::printf("| configuration | median ms | min ms | max ms | peak MiB | x VTK defaults | x VTK "
              "no split |\n|---|---:|---:|---:|---:|---:|---:|\n");
  const double vtkDefaults = rows[0].M.Median;
  const double vtkPlain = rows[1].M.Median;
  for (const Row& row : rows)
  {
    const bool goal = &row == &rows[oursSplit] || &row == &rows[reweightedTo[N::Angle]];
    std::printf("| %s%s%s%s | %s | %s | %s | %s | %.2f | %.2f |\n", goal ? "**" : "",
      row.Name.c_str(), goal ? "**" : "", row.Ok ? "" : " (NO POINT NORMALS IN THE OUTPUT)",
      Number(row.M.Median, "%.1f").c_str(), Number(row.M.Min, "%.1f").c_str(),
      Number(row.M.Max, "%.1f").c_str(), Number(row.M.PeakMiB, "%.0f").c_str(),
      row.M.Median / vtkDefaults, row.M.Median / vtkPlain);
  }

  const double split = rows[oursSplit].M.Median / vtkDefaults;
  std::printf("\n- goal: ours split at 30 <= 0.6 x vtkPolyDataNormals defaults: **%.2f**, %s\n",
    split, split <= 0.6 ? "met" : "NOT met");
  std::string met;
  std::string missed;
  for (int w = N::Uniform; w <= N::Loop; ++w)
  {
    std::string& list = rows[reweightedTo[w]].M.Median <= 0.3 * vtkPlain ? met : missed;
    list += (list.empty() ? "" : ", ") + std::string(WeightingName(w));
  }
  std::printf("- goal: cached re-weighting <= 0.3 x vtkPolyDataNormals without splitting and "
              "consistency: to angle (the default) **%.2f**, %s; met for %s; NOT met for %s\n",
    rows[reweightedTo[N::Angle]].M.Median / vtkPlain,
    rows[reweightedTo[N::Angle]].M.Median <= 0.3 * vtkPlain ? "met" : "NOT met",
    met.empty() ? "none" : met.c_str(), missed.empty() ? "none" : missed.c_str());
  // The filter does not time its phases; this difference is the one-off
  // cost that the cache saves.
  std::printf("- fresh minus cached (angle, no splitting): %.1f ms, building OpenMesh's "
              "connectivity and the face geometry\n",
    rows[freshAngle].M.Median - rows[reweightedTo[N::Angle]].M.Median);
  std::printf("- connectivity builds by the cached filter over all its updates: %d%s\n", builds,
    builds == 1 ? "" : " (1 EXPECTED: the cache did not hold)");
  std::fflush(stdout);
}

// ---------------------------------------------------------------------------
// Accuracy against exact normals.

// A surface by its parameters: the point at (u, v) in [0,1]^2 and the exact
// unit normal at a point on it.
struct Surface
{
  std::string Name;
  int Columns; // u divisions (periodic)
  int Rows;    // v divisions
  bool Sphere; // poles at v = 0 and v = 1; otherwise periodic in v (torus)
  std::function<Vec(double, double)> Point;
  std::function<Vec(const Vec&)> Normal;
};

// A triangulated grid on the surface. With jitter > 0 each grid vertex moves
// by up to `jitter` of a cell in u and in v (a tangential move), so the
// triangles vary in shape and size while every vertex stays exactly on the
// surface.
vtkSmartPointer<vtkPolyData> Tessellate(const Surface& s, double jitter, unsigned seed)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> offset(-jitter, jitter);
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  const int rings = s.Sphere ? s.Rows - 1 : s.Rows; // rows of vertices, poles aside
  for (int j = 0; j < rings; ++j)
  {
    for (int i = 0; i < s.Columns; ++i)
    {
      const double u = (i + offset(random)) / s.Columns;
      const double v = (j + (s.Sphere ? 1 : 0) + offset(random)) / s.Rows;
      points->InsertNextPoint(s.Point(u, v).data());
    }
  }
  auto at = [&](int i, int j) -> vtkIdType
  { return ((j + rings) % rings) * s.Columns + (i + s.Columns) % s.Columns; };
  auto triangle = [&](vtkIdType a, vtkIdType b, vtkIdType c)
  {
    const vtkIdType ids[3] = { a, b, c };
    polys->InsertNextCell(3, ids);
  };
  const int quadRows = s.Sphere ? rings - 1 : rings;
  for (int j = 0; j < quadRows; ++j)
  {
    for (int i = 0; i < s.Columns; ++i)
    {
      // The diagonal alternates, so that vertices have 4 or 8 neighbours:
      // uniform weighting is then visibly biased even on the regular grid.
      if ((i + j) % 2)
      {
        triangle(at(i, j), at(i + 1, j), at(i + 1, j + 1));
        triangle(at(i, j), at(i + 1, j + 1), at(i, j + 1));
      }
      else
      {
        triangle(at(i, j), at(i + 1, j), at(i, j + 1));
        triangle(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
    }
  }
  if (s.Sphere)
  {
    const vtkIdType south = points->InsertNextPoint(s.Point(0, 0).data());
    const vtkIdType north = points->InsertNextPoint(s.Point(0, 1).data());
    for (int i = 0; i < s.Columns; ++i)
    {
      triangle(south, at(i + 1, 0), at(i, 0));
      triangle(north, at(i, rings - 1), at(i + 1, rings - 1));
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

// Calls visit(id, nextId, p, next, previous) for every corner of every
// cell: the corner's point id, the next one's, and the three positions.
template <typename Visit>
void ForEachCorner(vtkPolyData* mesh, Visit visit)
{
  vtkIdType size;
  const vtkIdType* ids;
  for (auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
       !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    cells->GetCurrentCell(size, ids);
    for (vtkIdType k = 0; k < size; ++k)
    {
      Vec p, next, previous;
      mesh->GetPoint(ids[k], p.data());
      mesh->GetPoint(ids[(k + 1) % size], next.data());
      mesh->GetPoint(ids[(k + size - 1) % size], previous.data());
      visit(ids[k], ids[(k + 1) % size], p, next, previous);
    }
  }
}

// Moves each vertex of a mesh on the unit sphere tangentially, in a random
// direction, by up to `jitter` of its shortest edge, and back onto the
// sphere. Relative to the shortest edge, so that the thin cells by a UV
// sphere's poles get irregular without folding or turning into slivers.
void JitterOnSphere(vtkPolyData* mesh, double jitter, unsigned seed)
{
  const vtkIdType count = mesh->GetNumberOfPoints();
  std::vector<double> shortest(count, std::numeric_limits<double>::infinity());
  ForEachCorner(mesh,
    [&](vtkIdType id, vtkIdType nextId, const Vec& p, const Vec& next, const Vec&)
    {
      const double l = length(next - p);
      shortest[id] = std::min(shortest[id], l);
      shortest[nextId] = std::min(shortest[nextId], l);
    });
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  for (vtkIdType i = 0; i < count; ++i)
  {
    Vec p;
    mesh->GetPoint(i, p.data());
    // A tangent basis at p: t1 across the axis p is least aligned with.
    const int least = std::fabs(p[0]) < std::fabs(p[1])
      ? (std::fabs(p[0]) < std::fabs(p[2]) ? 0 : 2)
      : (std::fabs(p[1]) < std::fabs(p[2]) ? 1 : 2);
    Vec axis = { 0, 0, 0 };
    axis[least] = 1;
    const Vec t1 = normalize(cross(p, axis));
    const Vec t2 = cross(p, t1);
    const double direction = 2 * M_PI * unit(random);
    const double distance = jitter * shortest[i] * unit(random);
    p = normalize(p + distance * (std::cos(direction) * t1 + std::sin(direction) * t2));
    mesh->GetPoints()->SetPoint(i, p.data());
  }
}

// Angle between two vectors in degrees; atan2 stays accurate for tiny
// angles, where acos does not.
double Degrees(const Vec& a, const Vec& b)
{
  return std::atan2(length(cross(a, b)), dot(a, b)) * 180 / M_PI;
}

struct Error
{
  double Mean = 0;
  double Max = 0;
};

// Angles in degrees between the output's point normals and the exact ones.
// A missing or zero normal counts as 180 degrees: wrong, not exempt.
Error AngleError(vtkPolyData* output, const Surface& s)
{
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  const vtkIdType count = output->GetNumberOfPoints();
  Error e;
  for (vtkIdType i = 0; i < count; ++i)
  {
    Vec p;
    output->GetPoint(i, p.data());
    Vec n = { 0, 0, 0 };
    if (normals)
    {
      normals->GetTuple(i, n.data());
    }
    const double degrees = n == Vec{ 0, 0, 0 } ? 180 : Degrees(n, s.Normal(p));
    e.Mean += degrees / count;
    e.Max = std::max(e.Max, degrees);
  }
  return e;
}

// The smallest and largest inner angle of the mesh's triangles, degrees:
// slivers (angles near 180) are where the weightings differ most.
std::pair<double, double> TriangleAngles(vtkPolyData* mesh)
{
  std::pair<double, double> range{ 180, 0 };
  ForEachCorner(mesh,
    [&](vtkIdType, vtkIdType, const Vec& p, const Vec& next, const Vec& previous)
    {
      const double degrees = Degrees(next - p, previous - p);
      range.first = std::min(range.first, degrees);
      range.second = std::max(range.second, degrees);
    });
  return range;
}

void AccuracyTable()
{
  const double R = 1;
  const double r = 0.35;
  const Surface sphere{ "sphere", 48, 32, true,
    [](double u, double v)
    {
      const double theta = 2 * M_PI * u;
      const double phi = M_PI * v;
      return Vec{ std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
        -std::cos(phi) };
    },
    [](const Vec& p) { return normalize(p); } };
  const Surface torus{ "torus", 64, 24, false,
    [R, r](double u, double v)
    {
      const double a = 2 * M_PI * u;
      const double b = 2 * M_PI * v;
      return Vec{ (R + r * std::cos(b)) * std::cos(a), (R + r * std::cos(b)) * std::sin(a),
        r * std::sin(b) };
    },
    [R](const Vec& p)
    {
      // Away from the nearest point of the core circle.
      const double l = std::hypot(p[0], p[1]);
      return normalize({ p[0] - R * p[0] / l, p[1] - R * p[1] / l, p[2] });
    } };

  // How irregular: tangential moves up to 0.3 of a vertex's shortest edge
  // on the sphere, 0.2 of a cell in each parameter on the torus, so that
  // both meshes' worst triangles are alike (about 140 degrees at most) and
  // neither turns into slivers, which would measure the slivers instead.
  const double sphereJitter = 0.3;
  const double torusJitter = 0.2;
  struct Column
  {
    std::string Name;
    std::vector<Error> Errors;        // the weightings in order, then vtkPolyDataNormals
    std::pair<double, double> Angles; // the triangles' smallest and largest angles
  };
  std::vector<Column> columns;
  for (const Surface* s : { &sphere, &torus })
  {
    for (const bool irregular : { false, true })
    {
      const double j = irregular ? (s->Sphere ? sphereJitter : torusJitter) : 0;
      std::fprintf(
        stderr, "bench-normals: accuracy: %s%s\n", s->Name.c_str(), j > 0 ? ", jittered" : "");
      // The sphere as the issue asks (tangential moves projected back), as a
      // move in its parameters would make slivers of the thin cells at its
      // poles; the torus's cells are near square, so it moves in its own.
      vtkSmartPointer<vtkPolyData> mesh = Tessellate(*s, s->Sphere ? 0 : j, 1999);
      if (s->Sphere && j > 0)
      {
        JitterOnSphere(mesh, j, 1999);
      }
      Column c;
      c.Name = s->Name + " " + std::to_string(s->Columns) + "x" + std::to_string(s->Rows) +
        (j > 0 ? " irregular" : " regular") + " (" + std::to_string(mesh->GetNumberOfPolys()) +
        " tri)";
      for (int w = vtkShadelabMeshNormals::Uniform; w <= vtkShadelabMeshNormals::Loop; ++w)
      {
        auto ours = OurNormals(mesh, w, false, false);
        ours->Update();
        c.Errors.push_back(AngleError(ours->GetOutput(), *s));
      }
      auto vtk = VtkNormals(mesh, false);
      vtk->Update();
      c.Errors.push_back(AngleError(vtk->GetOutput(), *s));
      c.Angles = TriangleAngles(mesh);
      columns.push_back(c);
    }
  }

  std::printf("\n### Accuracy: mean / largest angle to the exact normal, degrees\n\n");
  std::printf("Irregular sphere: every vertex moved tangentially, in a random direction, by up "
              "to %.1f of its shortest edge, then projected back onto the sphere. Irregular "
              "torus (R = %g, r = %g): every grid vertex moved by up to %.1f of a cell in each "
              "parameter, so exactly on the surface. Uniform random, seed 1999.\n\n",
    sphereJitter, R, r, torusJitter);
  std::printf("| weighting |");
  for (const Column& c : columns)
  {
    std::printf(" %s |", c.Name.c_str());
  }
  std::printf("\n|---|");
  for (size_t i = 0; i < columns.size(); ++i)
  {
    std::printf("---:|");
  }
  std::printf("\n");
  for (int k = 0; k <= vtkShadelabMeshNormals::Loop + 1; ++k)
  {
    std::printf("| %s |",
      k <= vtkShadelabMeshNormals::Loop ? WeightingName(k)
                                        : "vtkPolyDataNormals (no splitting, no consistency)");
    for (const Column& c : columns)
    {
      std::printf(" %.3f / %.3f |", c.Errors[k].Mean, c.Errors[k].Max);
    }
    std::printf("\n");
  }
  std::printf("| (the triangles' smallest / largest angle) |");
  for (const Column& c : columns)
  {
    std::printf(" %.1f / %.1f |", c.Angles.first, c.Angles.second);
  }
  std::printf("\n");
  std::fflush(stdout);
}
}

int main(int argc, char** argv)
{
  CLI::App app("vtkShadelabMeshNormals against vtkPolyDataNormals", "shadelab-bench-normals");
  std::string meshFile;
  int runs = 5;
  bool quick = false;
  app.add_option("MESH", meshFile, "Mesh file (the Stanford bunny)")->required();
  app.add_option("--runs", runs, "Runs per configuration (median)")->check(CLI::Range(1, 100));
  app.add_flag("--quick", quick, "Skip the 3-level subdivision (4.4M triangles for the bunny)");
  CLI11_PARSE(app, argc, argv);

  char date[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%F", std::gmtime(&now));
  std::printf("# bench-normals, %s\n\n%d processors (%s), VTK %s, SMP backend %s with %d threads; "
              "%d runs per configuration\n",
    date, Processors(), CpuModel().c_str(), vtkVersion::GetVTKVersion(), vtkSMPTools::GetBackend(),
    vtkSMPTools::GetEstimatedNumberOfThreads(), runs);
  std::fflush(stdout);

  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(meshFile.c_str());
  reader->ReadNormalsOff();
  if (!reader->GetExecutive()->Update())
  {
    std::fprintf(stderr, "bench-normals: %s cannot be read\n", meshFile.c_str());
    return 1;
  }
  const std::string baseName = meshFile.substr(meshFile.find_last_of('/') + 1);
  std::vector<int> levels{ 0, 2 };
  if (!quick)
  {
    levels.push_back(3);
  }
  for (const int level : levels)
  {
    vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
    if (level > 0)
    {
      std::fprintf(stderr, "bench-normals: Loop subdivision x%d\n", level);
      // Double points, as for the bunny itself, so that neither filter
      // pays for a conversion.
      mesh = shadelab::LoopSubdivided(mesh, level);
      std::fprintf(stderr, "bench-normals: %lld triangles, points in %s\n",
        static_cast<long long>(mesh->GetNumberOfPolys()),
        mesh->GetPoints()->GetData()->GetDataTypeAsString());
    }
    SpeedTable(
      mesh, baseName + (level > 0 ? ", Loop subdivision x" + std::to_string(level) : ""), runs);
  }
  AccuracyTable();
  return 0;
}
