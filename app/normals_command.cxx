#include "normals_command.h"

#include "errors.h"
#include "mesh_input.h"
#include "output_path.h"
#include "vtkShadelabMeshReader.h"
#include "vtkShadelabOutputWindow.h"
#include "vtkShadelabPLYWriter.h"

#include <vtkExecutive.h>
#include <vtkOBJWriter.h>
#include <vtkOutputWindow.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace shadelab
{
CLI::App* AddNormalsCommand(CLI::App& program, NormalsOptions& o)
{
  CLI::App* normals = program.add_subcommand(
    "normals", "Write MESH with computed vertex normals (and face normals where OUT has room)");
  normals->add_option("MESH", o.Mesh, "Mesh file: .obj .ply .stl .vtp .vtk")->required();
  normals->add_option("-o,--output", o.Output, "Output mesh: .ply .vtp .obj")
    ->required()
    ->option_text("OUT");
  AddNormalsSettings(*normals, o.Settings);
  return normals;
}

namespace
{
// Writes mesh to path in the format that ext names; errors go to VTK's
// output window.
template <typename Writer>
void Write(vtkPolyData* mesh, const std::string& path)
{
  auto writer = vtkSmartPointer<Writer>::New();
  writer->SetInputData(mesh);
  writer->SetFileName(path.c_str());
  writer->Write();
}
}

int RunNormals(const NormalsOptions& o)
{
  const std::string ext = LowerExtension(o.Output);
  if (ext != ".ply" && ext != ".vtp" && ext != ".obj")
  {
    return ReportError(o.Output, "unknown mesh format \"" + ext + "\" (known: .ply .vtp .obj)");
  }
  if (const std::string error = CheckWritableFolder(o.Output); !error.empty())
  {
    return ReportError(o.Output, error);
  }

  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(o.Mesh.c_str());
  reader->ReadNormalsOff(); // computed, and not split at the file's vn seams
  if (!reader->GetExecutive()->Update())
  {
    return ReportError(o.Mesh, FirstVtkError("cannot be read"));
  }
  const ComputedNormals normals = ComputeNormals(reader->GetOutput(), o.Settings);
  if (!normals.Mesh)
  {
    return ReportError(o.Mesh, "normals: " + FirstVtkError("cannot be computed"));
  }
  if (normals.DuplicatedFaces > 0)
  {
    std::cerr << "shadelab: note: " << o.Mesh << ": " << normals.DuplicatedFaces
              << " faces are non-manifold or repeat a vertex: they got vertices of their own"
              << std::endl;
  }

  // Written to a temporary name beside OUT and renamed: no partial file.
  const std::string temporary = TemporaryName(o.Output);
  auto* window = vtkShadelabOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  window->Clear();
  vtkPolyData* mesh = normals.Mesh;
  if (ext == ".ply")
  {
    Write<vtkShadelabPLYWriter>(mesh, temporary);
  }
  else if (ext == ".vtp")
  {
    Write<vtkXMLPolyDataWriter>(mesh, temporary);
  }
  else
  {
    Write<vtkOBJWriter>(mesh, temporary);
  }
  if (!window->GetFirstError().empty() || std::rename(temporary.c_str(), o.Output.c_str()) != 0)
  {
    const std::string why =
      window->GetFirstError().empty() ? std::strerror(errno) : window->GetFirstError();
    std::remove(temporary.c_str());
    return ReportError(o.Output, "cannot write: " + why);
  }
  return 0;
}
}
