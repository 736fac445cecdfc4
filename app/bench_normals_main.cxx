// shadelab-bench-normals: vtkShadelabMeshNormals against vtkPolyDataNormals,
// side by side in one run (issue 4): time and peak memory on a mesh and its
// Loop subdivisions, and the accuracy of each weighting against the exact
// normals of an irregular sphere and torus.
//
//   shadelab-bench-normals MESH [--runs N] [--levels 0,2,3]
//
// Times are medians of N runs, each on a fresh filter except the cached
// re-weighting. Peak memory is the growth of the process's peak resident
// size during one run of a configuration (Linux resets the peak when "5" is
// written to /proc/self/clear_refs), with the input mesh already loaded.
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabMeshReader.h"

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkExecutive.h>
#include <vtkLoopSubdivisionFilter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <CLI/CLI.hpp>

#include <malloc.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;
using Vec = std::array<double, 3>;

// The process's resident and peak resident size in MiB, from /proc.
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
  return 0;
}

struct Measured
{
  double MedianMs = 0;
  double PeakMiB = 0;
};

// Runs `prepare` (untimed) then `run` (timed) `runs` times: the median time,
// and the peak memory growth of the first run.
Measured Measure(int runs, const std::function<void()>& prepare, const std::function<void()>& run)
{
  std::vector<double> ms;
  double peak = 0;
  for (int i = 0; i < runs; ++i)
  {
    prepare();
    // Freed memory back to the system first, so that what a run allocates
    // shows in the resident size rather than reusing the heap's free space.
    malloc_trim(0);
    std::ofstream("/proc/self/clear_refs") << "5";
    const double before = StatusMiB("VmRSS:");
    const auto start = Clock::now();
    run();
    ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    if (i == 0)
    {
      peak = StatusMiB("VmHWM:") - before;
    }
  }
  std::sort(ms.begin(), ms.end());
  return { ms[ms.size() / 2], peak };
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

void SpeedTable(vtkPolyData* mesh, const std::string& name, int runs)
{
  std::printf("\n### %s: %lld points, %lld triangles\n\n", name.c_str(),
    static_cast<long long>(mesh->GetNumberOfPoints()),
    static_cast<long long>(mesh->GetNumberOfPolys()));
  std::printf("| configuration | median ms | peak MiB | x VTK defaults | x VTK no split |\n");
  std::printf("|---|---:|---:|---:|---:|\n");

  vtkSmartPointer<vtkAlgorithm> filter;
  auto fresh = [&](std::function<vtkSmartPointer<vtkAlgorithm>()> make)
  { return [&filter, make] { filter = make(); }; };
  auto update = [&filter] { filter->GetExecutive()->Update(); };

  struct Row
  {
    std::string Name;
    Measured M;
  };
  std::vector<Row> rows;
  rows.push_back({ "vtkPolyDataNormals, defaults (split at 30, consistency)",
    Measure(runs, fresh([mesh] { return VtkNormals(mesh, true); }), update) });
  rows.push_back({ "vtkPolyDataNormals, no splitting, no consistency",
    Measure(runs, fresh([mesh] { return VtkNormals(mesh, false); }), update) });
  rows.push_back({ "ours, angle, split at 30",
    Measure(runs,
      fresh([mesh] { return OurNormals(mesh, vtkShadelabMeshNormals::Angle, true, false); }),
      update) });
  rows.push_back({ "ours, angle, split at 30, consistency",
    Measure(runs,
      fresh([mesh] { return OurNormals(mesh, vtkShadelabMeshNormals::Angle, true, true); }),
      update) });
  rows.push_back({ "ours, angle, no splitting",
    Measure(runs,
      fresh([mesh] { return OurNormals(mesh, vtkShadelabMeshNormals::Angle, false, false); }),
      update) });

  // Re-weighting a cached mesh: the filter has run with another weighting
  // (so the corner weights in its cache are not the ones asked for), then
  // only the weighting changes.
  auto cached = OurNormals(mesh, vtkShadelabMeshNormals::Uniform, false, false);
  cached->Update();
  const char* const names[] = { "uniform", "area", "angle", "max", "loop" };
  for (int w = vtkShadelabMeshNormals::Uniform; w <= vtkShadelabMeshNormals::Loop; ++w)
  {
    const int other = w == vtkShadelabMeshNormals::Max ? vtkShadelabMeshNormals::Angle
                                                       : vtkShadelabMeshNormals::Max;
    rows.push_back({ std::string("ours, cached mesh, re-weighted to ") + names[w],
      Measure(
        runs,
        [&]
        {
          cached->SetWeighting(other);
          cached->Update();
        },
        [&]
        {
          cached->SetWeighting(w);
          cached->Update();
        }) });
  }
  rows.push_back({ "ours, cached mesh, feature angle 30 -> 40 (angle weights cached)",
    Measure(
      runs,
      [&]
      {
        cached->SetWeighting(vtkShadelabMeshNormals::Angle);
        cached->SplittingOn();
        cached->SetFeatureAngle(30);
        cached->Update();
      },
      [&]
      {
        cached->SetFeatureAngle(40);
        cached->Update();
      }) });

  const double vtkDefaults = rows[0].M.MedianMs;
  const double vtkPlain = rows[1].M.MedianMs;
  for (const Row& row : rows)
  {
    std::printf("| %s | %.0f | %.0f | %.2f | %.2f |\n", row.Name.c_str(), row.M.MedianMs,
      row.M.PeakMiB, row.M.MedianMs / vtkDefaults, row.M.MedianMs / vtkPlain);
  }
  std::fflush(stdout);
}

// ---------------------------------------------------------------------------
// Accuracy against exact normals.

// A surface given by its parameters: the point at (u, v) in [0,1]^2 and the
// exact unit normal at a point on it.
struct Surface
{
  std::string Name;
  int Columns; // u divisions (around, periodic)
  int Rows;    // v divisions
  bool Sphere; // poles at v = 0 and 1; otherwise periodic in v too (torus)
  std::function<Vec(double, double)> Point;
  std::function<Vec(const Vec&)> Normal;
};

// A triangulated grid on the surface; with jitter > 0 each inner vertex
// moves by up to jitter of a cell in u and v, so the triangles vary in shape
// and size while every vertex stays exactly on the surface.
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
      const double v = s.Sphere ? (j + 1 + offset(random)) / s.Rows : (j + offset(random)) / s.Rows;
      const Vec p = s.Point(u, v);
      points->InsertNextPoint(p.data());
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
      // Alternate the diagonal for more varied triangles.
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
    const Vec south = s.Point(0, 0);
    const Vec north = s.Point(0, 1);
    const vtkIdType bottom = points->InsertNextPoint(south.data());
    const vtkIdType top = points->InsertNextPoint(north.data());
    for (int i = 0; i < s.Columns; ++i)
    {
      triangle(bottom, at(i + 1, 0), at(i, 0));
      triangle(top, at(i, rings - 1), at(i + 1, rings - 1));
    }
  }
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  return mesh;
}

// Mean and largest angle in degrees between the filter's point normals and
// the exact ones.
std::pair<double, double> AngleError(vtkPolyData* normals, const Surface& s)
{
  vtkDataArray* n = normals->GetPointData()->GetNormals();
  double sum = 0;
  double largest = 0;
  const vtkIdType count = normals->GetNumberOfPoints();
  for (vtkIdType i = 0; i < count; ++i)
  {
    Vec p;
    normals->GetPoint(i, p.data());
    const Vec exact = s.Normal(p);
    const double* got = n->GetTuple3(i);
    const Vec cross = { got[1] * exact[2] - got[2] * exact[1],
      got[2] * exact[0] - got[0] * exact[2], got[0] * exact[1] - got[1] * exact[0] };
    const double dot = got[0] * exact[0] + got[1] * exact[1] + got[2] * exact[2];
    const double degrees =
      std::atan2(std::sqrt(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2]), dot) *
      180 / M_PI;
    sum += degrees;
    largest = std::max(largest, degrees);
  }
  return { sum / count, largest };
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
    [](const Vec& p)
    {
      const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
      return Vec{ p[0] / l, p[1] / l, p[2] / l };
    } };
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
      // From the nearest point of the core circle.
      const double l = std::hypot(p[0], p[1]);
      const Vec d = { p[0] - R * p[0] / l, p[1] - R * p[1] / l, p[2] };
      const double dl = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      return Vec{ d[0] / dl, d[1] / dl, d[2] / dl };
    } };

  std::printf("\n### Accuracy: mean / largest angle to the exact normal, degrees\n\n");
  std::printf("| mesh | uniform | area | angle | max | loop | vtkPolyDataNormals |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|\n");
  for (const Surface* s : { &sphere, &torus })
  {
    for (const double jitter : { 0.0, 0.3 })
    {
      vtkSmartPointer<vtkPolyData> mesh = Tessellate(*s, jitter, 1999);
      std::ostringstream row;
      row << "| " << s->Name << " " << s->Columns << "x" << s->Rows
          << (jitter > 0 ? ", jittered 0.3 cell" : ", regular") << " (" << mesh->GetNumberOfPolys()
          << " triangles)";
      char cell[64];
      for (int w = vtkShadelabMeshNormals::Uniform; w <= vtkShadelabMeshNormals::Loop; ++w)
      {
        auto filter = OurNormals(mesh, w, false, false);
        filter->Update();
        const auto [mean, largest] = AngleError(filter->GetOutput(), *s);
        std::snprintf(cell, sizeof cell, " | %.3f / %.3f", mean, largest);
        row << cell;
      }
      auto vtk = VtkNormals(mesh, false);
      vtk->Update();
      const auto [mean, largest] = AngleError(vtk->GetOutput(), *s);
      std::snprintf(cell, sizeof cell, " | %.3f / %.3f |", mean, largest);
      row << cell;
      std::printf("%s\n", row.str().c_str());
    }
  }
}
}

int main(int argc, char** argv)
{
  CLI::App app("vtkShadelabMeshNormals against vtkPolyDataNormals");
  std::string meshFile;
  int runs = 5;
  std::vector<int> levels{ 0, 2, 3 };
  app.add_option("MESH", meshFile, "Mesh file")->required();
  app.add_option("--runs", runs, "Runs per configuration (median)")->check(CLI::Range(1, 100));
  app.add_option("--levels", levels, "Loop subdivision levels to measure")->delimiter(',');
  CLI11_PARSE(app, argc, argv);

  std::printf("# bench-normals: %d threads (VTK SMP backend %s)\n",
    vtkSMPTools::GetEstimatedNumberOfThreads(), vtkSMPTools::GetBackend());
  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(meshFile.c_str());
  reader->ReadNormalsOff();
  if (!reader->GetExecutive()->Update())
  {
    std::fprintf(stderr, "bench-normals: %s cannot be read\n", meshFile.c_str());
    return 1;
  }
  for (const int level : levels)
  {
    vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
    if (level > 0)
    {
      auto clean = vtkSmartPointer<vtkCleanPolyData>::New();
      clean->SetInputData(mesh);
      auto loop = vtkSmartPointer<vtkLoopSubdivisionFilter>::New();
      loop->SetInputConnection(clean->GetOutputPort());
      loop->SetNumberOfSubdivisions(level);
      loop->Update();
      mesh = loop->GetOutput();
      // Double points, as shadelab's readers give.
      auto xyz = vtkSmartPointer<vtkDoubleArray>::New();
      xyz->DeepCopy(mesh->GetPoints()->GetData());
      mesh->GetPoints()->SetData(xyz);
    }
    SpeedTable(mesh,
      meshFile.substr(meshFile.find_last_of('/') + 1) +
        (level > 0 ? ", Loop subdivision x" + std::to_string(level) : ""),
      runs);
  }
  AccuracyTable();
  return 0;
}
