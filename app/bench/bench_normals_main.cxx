// shadelab-bench-normals: vtkShadelabMeshNormals against vtkPolyDataNormals,
// side by side in one run: time and peak memory on a mesh and its
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
#include "bench/bench_normals.h"
#include "core/report_text.h"
#include "scene/mesh_input.h"
#include "vtkShadelabMeshReader.h"

#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkVersion.h>

#include <CLI/CLI.hpp>

#include <sched.h>

#include <cstdio>
#include <ctime>
#include <string>
#include <thread>
#include <vector>

namespace
{
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

// The run's heading: the date and the machine.
void PrintHeading(int runs)
{
  char date[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%F", std::gmtime(&now));
  std::printf("# bench-normals, %s\n\n%d processors (%s), VTK %s, SMP backend %s with %d threads; "
              "%d runs per configuration\n",
    date, Processors(), shadelab::CpuModel().c_str(), vtkVersion::GetVTKVersion(),
    vtkSMPTools::GetBackend(), vtkSMPTools::GetEstimatedNumberOfThreads(), runs);
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
  PrintHeading(runs);

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
    shadelab::bench_normals::SpeedTable(
      mesh, baseName + (level > 0 ? ", Loop subdivision x" + std::to_string(level) : ""), runs);
  }
  shadelab::bench_normals::AccuracyTable();
  return 0;
}
