#include "commands/render_command.h"

#include "core/errors.h"
#include "core/output_path.h"
#include "headless/batch.h"
#include "scene/camera.h"
#include "scene/mesh_arguments.h"
#include "scene/scene_file.h"
#include "settings/command_line.h"
#include "vtkShadelabMeshReader.h"

#include <CLI/CLI.hpp>

#include <iostream>
#include <map>
#include <tuple>

namespace shadelab
{
CLI::App* AddRenderCommand(CLI::App& program, RenderOptions& o)
{
  CLI::App* render = program.add_subcommand(
    "render", "Render MESH headless into the image OUT, or every shot of a scene file (--scene)");
  // render takes many meshes (files, folders, globs), rendered in one process.
  render->add_option("MESH", o.Meshes,
    std::string("Mesh files (") + vtkShadelabMeshReader::GetKnownExtensions() +
      "), folders of them, or quoted globs; with more than one, -o is a template such as "
      "'thumbs/{mesh}.png'");
  AddSettings(*render, o.Scene, Command::Render);
  render->get_option("--fps")->needs("--orbit");
  // With a scene file, the file says all that these say.
  std::vector<CLI::Option*> sceneSettings =
    render->get_options([](const CLI::Option* option) { return option->get_name() != "--help"; });
  render
    ->add_option("-o,--output", o.Output,
      "Image file; its extension picks the format. With --scene: an output name template for "
      "every shot, replacing the file's")
    ->option_text("OUT");
  render
    ->add_option("--dump-shaders", o.DumpShaders,
      "Write the final GLSL of each shader program into DIR (RULE-REFLECTION.vert/.frag)")
    ->option_text("DIR");
  render->add_flag("-v,--verbose", o.Verbose, "Print each phase's time and VTK's messages");
  CLI::Option* scene = render
                         ->add_option("--scene", o.SceneFile,
                           "Every shot of a scene file, in one process (--print-schema shows "
                           "its format)")
                         ->option_text("FILE.json");
  for (CLI::Option* setting : sceneSettings)
  {
    setting->excludes(scene);
  }
  render->get_option("--dump-shaders")->excludes(scene);
  render->add_flag("--print-schema", o.PrintSchema, "Print the scene files' JSON Schema and exit");
  render
    ->add_option_function<std::string>(
      "--shard",
      [&o](const std::string& text)
      {
        try
        {
          std::tie(o.ShardIndex, o.ShardCount) = ParseShard(text);
        }
        catch (const std::invalid_argument& e)
        {
          throw CLI::ValidationError("--shard", e.what());
        }
      },
      "With --scene: render only the shots whose index (from 0) mod N is I, so that N jobs "
      "share a batch")
    ->option_text("I/N")
    ->needs(scene);
  render->add_flag("--skip-existing", o.SkipExisting,
    "Leave shots whose output file exists (outputs appear whole, by rename): finishes an "
    "interrupted batch");
  render->add_flag("-q,--quiet", o.Quiet,
    "No warnings and no progress bar (none either when output is not a terminal)");
  render->footer(CameraHelp);
  return render;
}

namespace
{
// The command line's shots: one mesh file to OUT as it is (with --orbit, as
// a template for its frames); many meshes (or a folder, or a glob) each to
// OUT as a template, sharing one process. An exit status on error, else 0.
int CommandLineShots(const RenderOptions& o, std::vector<Shot>& shots)
{
  Shot shot{ o.Scene, o.Output, "", false, false };
  if (IsOneMeshFile(o.Meshes) && o.Scene.Orbit == 0)
  {
    shot.Scene.Mesh = o.Meshes[0];
    shots.push_back(shot);
    return 0;
  }
  std::vector<std::string> meshes;
  if (const std::string error = ExpandMeshArguments(o.Meshes, meshes); !error.empty())
  {
    std::cerr << "shadelab: error: " << error << std::endl;
    return ExitFailure;
  }
  std::map<std::string, std::string> outputs; // output -> the mesh that writes it
  shot.MakeFolders = true;
  for (std::size_t i = 0; i < meshes.size(); ++i)
  {
    shot.Scene.Mesh = meshes[i];
    std::vector<Shot> expanded;
    if (const std::string error = ExpandShot(o.Output, shot, "", i, meshes.size(), expanded);
        !error.empty())
    {
      ReportError("--output", error);
      return ExitUsage;
    }
    for (const Shot& one : expanded)
    {
      if (const auto [other, added] = outputs.emplace(OutputIdentity(one.Output), meshes[i]);
          !added)
      {
        ReportError("--output",
          "\"" + one.Output + "\" is the output of " + other->second + " and " + meshes[i] +
            ": name each mesh's, as with {mesh} or {index}");
        return ExitUsage;
      }
      shots.push_back(one);
    }
  }
  return 0;
}
}

int RunRender(const RenderOptions& o, const std::string& commandLine)
{
  if (o.PrintSchema)
  {
    std::cout << SceneSchema();
    return 0;
  }
  BatchOptions batch;
  batch.DumpShaders = o.DumpShaders;
  batch.Verbose = o.Verbose;
  batch.Quiet = o.Quiet;
  batch.ShardIndex = o.ShardIndex;
  batch.ShardCount = o.ShardCount;
  batch.SkipExisting = o.SkipExisting;
  std::vector<Shot> shots;
  if (!o.SceneFile.empty())
  {
    if (const std::string error = ReadSceneFile(o.SceneFile, o.Output, shots); !error.empty())
    {
      return ReportError(o.SceneFile, error);
    }
    for (Shot& shot : shots)
    {
      shot.Scene.AllowOutsideReferences = o.Scene.AllowOutsideReferences;
    }
  }
  else
  {
    for (const auto& [missing, what] :
      { std::pair{ o.Meshes.empty(), "MESH" }, std::pair{ o.Output.empty(), "--output" } })
    {
      if (missing)
      {
        std::cerr << "shadelab: error: render: " << what
                  << " is required unless --scene gives the shots (see shadelab --help)"
                  << std::endl;
        return ExitUsage;
      }
    }
    if (const int status = CommandLineShots(o, shots); status != 0)
    {
      return status;
    }
  }
  return RenderShots(shots, batch, commandLine);
}
}
