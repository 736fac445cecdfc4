// shadelab-bench-meshes: the meshes of the scaling curves (scripts/
// bench-scaling), one object from 10k to 17.8M triangles, so that every size
// covers the same pixels and only the triangle count changes:
//
//   10k, 30k   the bunny decimated (vtkQuadricDecimation)
//   69k        the bunny itself
//   278k, 1.1M, 4.4M, 17.8M   the bunny Loop-subdivided 1 to 4 times
//              (vtkCleanPolyData, vtkLoopSubdivisionFilter)
//
//   shadelab-bench-meshes BUNNY.ply --out DIR [--sizes 10k,30k,...]
//
// Writes DIR/bunny-SIZE.ply for each size not already there: binary PLY,
// float xyz, no normals (vtkPLYWriter), so every tool computes its own. A
// file already there is kept: the folder is the cache.
#include "core/errors.h"
#include "core/output_file.h"
#include "scene/mesh_input.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkLogger.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>

#include <CLI/CLI.hpp>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using namespace shadelab;

namespace
{
struct Recipe
{
  const char* Size;
  int Triangles = 0;    // decimated to about this many; 0: not decimated
  int Subdivisions = 0; // Loop subdivision levels
};

constexpr std::array<Recipe, 7> Recipes{ { { "10k", 10000 }, { "30k", 30000 }, { "69k" },
  { "278k", 0, 1 }, { "1.1M", 0, 2 }, { "4.4M", 0, 3 }, { "17.8M", 0, 4 } } };

vtkSmartPointer<vtkPolyData> Made(vtkPolyData* bunny, const Recipe& recipe)
{
  if (recipe.Subdivisions > 0)
  {
    return LoopSubdivided(bunny, recipe.Subdivisions);
  }
  if (recipe.Triangles == 0)
  {
    return bunny;
  }
  auto decimate = vtkSmartPointer<vtkQuadricDecimation>::New();
  decimate->SetInputData(bunny);
  decimate->SetTargetReduction(
    1.0 - static_cast<double>(recipe.Triangles) / static_cast<double>(bunny->GetNumberOfPolys()));
  decimate->Update();
  return decimate->GetOutput();
}

// "" or the problem. vtkPLYWriter opens its file itself, unchecked, and adds
// ".ply" to a name without it, so it writes through a link named *.ply to
// the memory file whose bytes then go to path through an OutputFile. Not
// WriteToOutputStringOn(): VTK 9.1's vtkPLY::ply_open_for_writing_to_string
// writes into a stream of its own and never copies it back, so
// GetOutputString() stays empty (checked: a sphere gives 0 bytes).
std::string WritePly(vtkPolyData* mesh, const std::string& path)
{
  return WriteFileThroughMemory(path,
    [mesh](const std::string& name) -> std::string
    {
      std::string folder = std::filesystem::temp_directory_path() / "shadelab-bench-meshes-XXXXXX";
      if (!mkdtemp(folder.data()))
      {
        return std::string("cannot make a temporary folder: ") + std::strerror(errno);
      }
      const std::string link = folder + "/mesh.ply";
      std::error_code error;
      std::filesystem::create_symlink(name, link, error);
      std::string problem = error ? "cannot link the memory file: " + error.message() : "";
      if (problem.empty())
      {
        const MessageScope messages;
        auto writer = vtkSmartPointer<vtkPLYWriter>::New();
        writer->SetInputData(mesh);
        writer->SetFileTypeToBinary();
        writer->SetFileName(link.c_str());
        if (!writer->Write() || !messages.FirstError().empty())
        {
          problem = "cannot write: " + messages.ErrorOr("vtkPLYWriter failed");
        }
      }
      std::filesystem::remove_all(folder, error);
      return problem;
    });
}
}

int main(int argc, char** argv)
{
  vtkShadelabOutputWindow::Install();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  CLI::App app("the bunny from 10k to 17.8M triangles, as binary PLY", "shadelab-bench-meshes");
  std::string bunnyPath, outDir, sizes = "10k,30k,69k,278k,1.1M,4.4M,17.8M";
  app.add_option("BUNNY", bunnyPath, "The Stanford bunny, PLY")->required();
  app.add_option("--out", outDir, "Folder of the meshes (made if missing)")->required();
  app.add_option("--sizes", sizes, "Comma-separated, of 10k 30k 69k 278k 1.1M 4.4M 17.8M");
  CLI11_PARSE(app, argc, argv);

  std::vector<const Recipe*> wanted;
  std::stringstream list(sizes);
  for (std::string size; std::getline(list, size, ',');)
  {
    const Recipe* found = nullptr;
    for (const Recipe& r : Recipes)
    {
      found = size == r.Size ? &r : found;
    }
    if (!found)
    {
      ReportError("--sizes", "unknown size '" + size + "'");
      return ExitUsage;
    }
    wanted.push_back(found);
  }
  std::error_code error;
  std::filesystem::create_directories(outDir, error);
  if (error)
  {
    return ReportError(outDir, "cannot make the folder: " + error.message());
  }

  vtkSmartPointer<vtkPolyData> bunny;
  for (const Recipe* recipe : wanted)
  {
    const std::string path = outDir + "/bunny-" + recipe->Size + ".ply";
    if (std::filesystem::exists(path))
    {
      continue; // made by an earlier run
    }
    if (!bunny)
    {
      const MessageScope messages;
      auto reader = vtkSmartPointer<vtkPLYReader>::New();
      reader->SetFileName(bunnyPath.c_str());
      reader->Update();
      bunny = reader->GetOutput();
      if (bunny->GetNumberOfPolys() == 0)
      {
        return ReportError(bunnyPath, messages.ErrorOr("no triangles read"));
      }
    }
    const vtkSmartPointer<vtkPolyData> mesh = Made(bunny, *recipe);
    if (const std::string problem = WritePly(mesh, path); !problem.empty())
    {
      return ReportError(path, problem);
    }
    std::fprintf(stderr, "shadelab-bench-meshes: %s: %lld triangles, %lld points\n", path.c_str(),
      static_cast<long long>(mesh->GetNumberOfPolys()),
      static_cast<long long>(mesh->GetNumberOfPoints()));
  }
  return 0;
}
