// shadelab-bench-readers: how fast shadelab reads OFF, glTF and GLB, against
// the readers a user would take instead, on the same files: OpenMesh's OFF
// reader (VTK has none; OpenMesh builds its halfedge structure as it reads)
// and VTK's vtkGLTFReader (a multiblock of the primitives, node transforms
// applied); and against assimp, which reads all three and which shadelab
// uses for the formats it has no reader of its own for (Importer::ReadFile
// with the post-processing of shadelab's assimp reader, in process: the
// parse alone, no VTK mesh made). Then what running assimp in a child
// process costs shadelab's assimp reader: the child's start and end, and
// the mesh's bytes through the pipe. The files are the mesh given (the bunny) and its Loop
// subdivisions, with vertex normals, written into --out by
// bench_readers_files; they are in the page cache when timed, so this
// measures parsing, not the disk.
//
//   shadelab-bench-readers MESH --out DIR [--runs N] [--levels 0,1,2]
//
// Each time is the median of N reads, each by a fresh reader. MB/s counts
// every byte the reader takes in (a .gltf's .bin too). Markdown to stdout,
// progress to stderr.
#include "bench/bench_readers_files.h"
#include "core/milliseconds.h"
#include "core/process_memory.h"
#include "core/report_text.h"
#include "scene/mesh_input.h"
#include "shadelabAssimpMeshBytes.h"
#include "shadelabIsolatedRead.h"
#include "vtkShadelabMeshReader.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <vtkExecutive.h>
#include <vtkGLTFReader.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkVersion.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace
{
using shadelab::FormatNumber;

// The median of `runs` calls of `read`, in milliseconds; a failed read
// stops the bench.
double MedianMs(int runs, const std::function<bool()>& read, const std::string& what)
{
  std::vector<double> times;
  for (int r = 0; r < runs; ++r)
  {
    const auto start = shadelab::Clock::now();
    if (!read())
    {
      std::fprintf(stderr, "bench-readers: %s failed\n", what.c_str());
      std::exit(1);
    }
    times.push_back(shadelab::Milliseconds(start));
  }
  std::sort(times.begin(), times.end());
  return times[times.size() / 2];
}

bool ReadOurs(const std::string& path)
{
  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(path.c_str());
  return reader->GetExecutive()->Update() != 0;
}

bool ReadVtkGltf(const std::string& path)
{
  auto reader = vtkSmartPointer<vtkGLTFReader>::New();
  reader->SetFileName(path.c_str());
  return reader->GetExecutive()->Update() != 0;
}

bool ReadOpenMesh(const std::string& path)
{
  OpenMesh::TriMesh_ArrayKernelT<> mesh;
  return OpenMesh::IO::read_mesh(mesh, path);
}

bool ReadAssimp(const std::string& path)
{
  Assimp::Importer importer;
  return importer.ReadFile(path,
           aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType |
             aiProcess_ValidateDataStructure | aiProcess_PreTransformVertices) != nullptr;
}

// The bunny or its subdivision, with smooth vertex normals (no splitting,
// so that every format holds the same points).
vtkSmartPointer<vtkPolyData> MeshAtLevel(vtkPolyData* base, int level)
{
  vtkSmartPointer<vtkPolyData> mesh =
    level > 0 ? shadelab::LoopSubdivided(base, level) : vtkSmartPointer<vtkPolyData>(base);
  auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
  normals->SetInputData(mesh);
  normals->SplittingOff();
  normals->Update();
  return normals->GetOutput();
}

std::uintmax_t Bytes(const std::string& path)
{
  std::uintmax_t bytes = std::filesystem::file_size(path);
  if (path.size() > 5 && path.substr(path.size() - 5) == ".gltf")
  {
    bytes += std::filesystem::file_size(path.substr(0, path.size() - 5) + ".bin");
  }
  return bytes;
}

void Row(const std::string& path, vtkIdType triangles, int runs)
{
  const std::string name = path.substr(path.find_last_of('/') + 1);
  const bool off = name.substr(name.size() - 4) == ".off";
  const double megabytes = static_cast<double>(Bytes(path)) / 1e6;
  std::fprintf(stderr, "bench-readers: %s\n", name.c_str());
  const double ours = MedianMs(
    runs, [&] { return ReadOurs(path); }, "shadelab on " + name);
  const double peer = off ? MedianMs(
                              runs, [&] { return ReadOpenMesh(path); }, "OpenMesh on " + name)
                          : MedianMs(
                              runs, [&] { return ReadVtkGltf(path); }, "vtkGLTFReader on " + name);
  const double assimp = MedianMs(
    runs, [&] { return ReadAssimp(path); }, "assimp on " + name);
  std::printf("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", name.c_str(),
    FormatNumber("%.0f", static_cast<double>(triangles)).c_str(),
    FormatNumber("%.1f", megabytes).c_str(), FormatNumber("%.1f", ours).c_str(),
    FormatNumber("%.0f", megabytes / (ours / 1000)).c_str(),
    FormatNumber("%.1f", static_cast<double>(triangles) / (ours / 1000) / 1e6).c_str(),
    off ? "OpenMesh" : "vtkGLTFReader", FormatNumber("%.1f", peer).c_str(),
    FormatNumber("%.1f", peer / ours).c_str(), FormatNumber("%.1f", assimp).c_str(),
    FormatNumber("%.1f", assimp / ours).c_str());
  std::fflush(stdout);
}

// The child process of shadelab's assimp reader, on its own: started and
// ended empty, then handed back an AssimpMesh of `mesh`'s size (points,
// normals, triangles, parts; none without a mesh), encoded, piped and
// decoded. fork() copies the page tables, so the start costs in proportion
// to the process's resident memory, which the row gives.
std::string IsolationRow(vtkPolyData* mesh, int runs)
{
  shadelab::AssimpMesh sized;
  const vtkIdType points = mesh ? mesh->GetNumberOfPoints() : 0;
  const vtkIdType triangles = mesh ? mesh->GetNumberOfPolys() : 0;
  sized.Mesh.Points.assign(3 * points, 0.5);
  sized.Mesh.Normals.assign(3 * points, 0.5f);
  sized.Mesh.FaceIds.assign(3 * triangles, 0);
  sized.Mesh.FaceOffsets.assign(triangles + 1, 0);
  sized.Mesh.Parts.assign(triangles, 0);
  const double megabytes = static_cast<double>(shadelab::EncodeAssimpMesh(sized).size()) / 1e6;
  const double resident = shadelab::StatusMiB("VmRSS:");
  const double empty = MedianMs(
    runs, [] { return shadelab::ReadIsolated("bench", [] { return std::string(); }).empty(); },
    "an empty child");
  const double full = MedianMs(
    runs,
    [&]
    {
      shadelab::DecodeAssimpMesh(
        shadelab::ReadIsolated("bench", [&] { return shadelab::EncodeAssimpMesh(sized); }));
      return true;
    },
    "a child with the mesh");
  char row[256];
  std::snprintf(row, sizeof row, "| %s | %s | %s | %s | %s |\n",
    FormatNumber("%.0f", static_cast<double>(triangles)).c_str(),
    FormatNumber("%.1f", megabytes).c_str(), FormatNumber("%.0f", resident).c_str(),
    FormatNumber("%.1f", empty).c_str(), FormatNumber("%.1f", full).c_str());
  return row;
}
}

int main(int argc, char** argv)
{
  CLI::App app(
    "shadelab's OFF, glTF and GLB readers against OpenMesh's and VTK's", "shadelab-bench-readers");
  std::string meshFile, out;
  int runs = 5;
  std::vector<int> levels{ 0, 1, 2 };
  app.add_option("MESH", meshFile, "Mesh file (the Stanford bunny)")->required();
  app.add_option("--out", out, "Folder for the files read")->required();
  app.add_option("--runs", runs, "Reads per reader and file (median)")->check(CLI::Range(1, 100));
  app.add_option("--levels", levels, "Loop subdivision levels")
    ->delimiter(',')
    ->check(CLI::Range(0, 3));
  CLI11_PARSE(app, argc, argv);
  // Before any mesh: the resident memory of a program that has just started.
  const std::string isolationAtStart = IsolationRow(nullptr, runs);

  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(meshFile.c_str());
  reader->ReadNormalsOff();
  if (!reader->GetExecutive()->Update())
  {
    std::fprintf(stderr, "bench-readers: %s cannot be read\n", meshFile.c_str());
    return 1;
  }
  std::filesystem::create_directories(out);
  char date[16];
  const std::time_t now = std::time(nullptr);
  std::strftime(date, sizeof date, "%F", std::gmtime(&now));
  std::printf("# bench-readers, %s\n\n%s, VTK %s; median of %d reads per reader and file, files "
              "in the page cache\n\n",
    date, shadelab::CpuModel().c_str(), vtkVersion::GetVTKVersion(), runs);
  std::printf("| file | triangles | MB | shadelab ms | MB/s | M triangles/s | peer | peer ms | "
              "peer / shadelab | assimp ms | assimp / shadelab |\n"
              "|---|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|\n");
  const std::string stem = std::filesystem::path(meshFile).stem().string();
  std::vector<vtkSmartPointer<vtkPolyData>> meshes;
  for (const int level : levels)
  {
    vtkSmartPointer<vtkPolyData> mesh = MeshAtLevel(reader->GetOutput(), level);
    meshes.push_back(mesh);
    const std::string path = out + "/" + stem + (level ? "-loop" + std::to_string(level) : "");
    for (const std::string& error : { shadelab::bench_readers::WriteOff(mesh, path),
           shadelab::bench_readers::WriteGltf(mesh, path, false),
           shadelab::bench_readers::WriteGltf(mesh, path, true) })
    {
      if (!error.empty())
      {
        std::fprintf(stderr, "bench-readers: %s: %s\n", path.c_str(), error.c_str());
        return 1;
      }
    }
    for (const char* extension : { ".off", ".gltf", ".glb" })
    {
      Row(path + extension, mesh->GetNumberOfPolys(), runs);
    }
  }
  std::printf("\nThe child process of shadelab's assimp reader, median of %d: started and ended "
              "empty, and handing back a mesh of the file's size (points, normals, triangles, "
              "parts), encoded, piped and decoded; the process's resident memory when it "
              "starts the child (fork copies its page tables)\n\n"
              "| triangles | MB piped | resident MiB | empty child ms | child with the mesh "
              "ms |\n|---:|---:|---:|---:|---:|\n%s",
    runs, isolationAtStart.c_str());
  for (vtkPolyData* mesh : meshes)
  {
    std::printf("%s", IsolationRow(mesh, runs).c_str());
  }
  return 0;
}
