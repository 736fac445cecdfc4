#include "commands/normals_command.h"

#include "core/errors.h"
#include "core/output_file.h"
#include "core/output_path.h"
#include "scene/mesh_input.h"
#include "settings/command_line.h"
#include "vtkShadelabOutputWindow.h"
#include "vtkShadelabPLYWriter.h"

#include <vtkOBJWriter.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataWriter.h>

#include <CLI/CLI.hpp>

#include <iostream>

namespace shadelab
{
CLI::App* AddNormalsCommand(CLI::App& program, NormalsOptions& o)
{
  CLI::App* normals = program.add_subcommand(
    "normals", "Write MESH with computed vertex normals (and face normals where OUT has room)");
  normals->add_option("MESH", o.Mesh, MeshFileHelp())->required();
  normals->add_option("-o,--output", o.Output, "Output mesh: .ply .vtp .obj")
    ->required()
    ->option_text("OUT");
  AddSettings(*normals, o.Scene, Command::Normals);
  normals->add_flag("-q,--quiet", o.Quiet, "No warnings");
  return normals;
}

namespace
{
// Writes mesh as Writer does, into a file that WriteFileThroughMemory names:
// VTK's writers open their files themselves, and vtkOBJWriter checks none
// of its writes. "" or the writer's first error.
template <typename Writer>
std::string Write(vtkPolyData* mesh, const std::string& fileName)
{
  const MessageScope messages;
  auto writer = vtkSmartPointer<Writer>::New();
  writer->SetInputData(mesh);
  writer->SetFileName(fileName.c_str());
  const bool written = writer->Write() != 0;
  return written && messages.FirstError().empty() ? std::string()
                                                  : "cannot write: " + messages.ErrorOr("failed");
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

  // The same reading and normals as render's, without the file's normals:
  // they are computed, and not split at the file's vn seams.
  SceneOptions input;
  input.Mesh = o.Mesh;
  input.ShadingRule = Shading::Phong; // a lit rule: LoadMesh computes normals for those
  input.Normals = NormalsMode::Compute;
  input.Computed = o.Scene.Computed;
  input.AllowOutsideReferences = o.Scene.AllowOutsideReferences;
  const LoadedMesh loaded = LoadMesh(input, nullptr, true); // with face normals: files have room
  if (!loaded.Mesh)
  {
    return ReportError(o.Mesh, loaded.Error);
  }
  if (loaded.DuplicatedFaces > 0)
  {
    std::cerr << "shadelab: note: " << o.Mesh << ": " << loaded.DuplicatedFaces
              << " faces are non-manifold or repeat a vertex: they got vertices of their own"
              << std::endl;
  }

  vtkPolyData* mesh = loaded.Mesh;
  const std::string error = WriteFileThroughMemory(o.Output,
    [&](const std::string& name)
    {
      return ext == ".ply" ? Write<vtkShadelabPLYWriter>(mesh, name)
        : ext == ".vtp"    ? Write<vtkXMLPolyDataWriter>(mesh, name)
                           : Write<vtkOBJWriter>(mesh, name);
    });
  return error.empty() ? 0 : ReportError(o.Output, error);
}
}
