// shadelab-bench-subdivide: the large meshes of scripts/bench-large, made
// from a small one: welded and Loop-subdivided (LoopSubdivided, as the other
// benchmarks subdivide) and written as binary PLY with float x y z and no
// normals by VTK's own writer, the kind of file a scanner or another tool
// gives (the bunny, 4 levels: 17.8M triangles, 338 MB).
//
//   shadelab-bench-subdivide MESH --levels N -o OUT.ply
#include "scene/mesh_input.h"
#include "vtkShadelabMeshReader.h"

#include <vtkExecutive.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <CLI/CLI.hpp>

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
  CLI::App app("A mesh Loop-subdivided into a binary PLY", "shadelab-bench-subdivide");
  std::string meshFile, out;
  int levels = 4;
  app.add_option("MESH", meshFile, "Mesh file (the Stanford bunny)")->required();
  app.add_option("--levels", levels, "Loop subdivision levels")->check(CLI::Range(0, 5));
  app.add_option("-o", out, "The PLY file to write")->required();
  CLI11_PARSE(app, argc, argv);

  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(meshFile.c_str());
  reader->ReadNormalsOff();
  if (!reader->GetExecutive()->Update())
  {
    std::fprintf(stderr, "bench-subdivide: %s cannot be read\n", meshFile.c_str());
    return 1;
  }
  vtkSmartPointer<vtkPolyData> mesh = shadelab::LoopSubdivided(reader->GetOutput(), levels);
  auto writer = vtkSmartPointer<vtkPLYWriter>::New();
  writer->SetInputData(mesh);
  writer->SetFileTypeToBinary();
  writer->SetFileName(out.c_str());
  if (!writer->Write())
  {
    std::fprintf(stderr, "bench-subdivide: %s cannot be written\n", out.c_str());
    return 1;
  }
  std::printf("%s: %lld points, %lld triangles\n", out.c_str(),
    static_cast<long long>(mesh->GetNumberOfPoints()),
    static_cast<long long>(mesh->GetNumberOfPolys()));
  return 0;
}
