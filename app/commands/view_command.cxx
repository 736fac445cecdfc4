#include "commands/view_command.h"

#include "core/errors.h"
#include "core/sibling_executable.h"
#include "desktop/view_keys.h"
#include "scene/camera.h"
#include "scene/comparison_panels.h"
#include "settings/command_line.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>

namespace shadelab
{
std::string ViewKeysHelp()
{
  std::size_t width = 0;
  for (const ViewKey& key : ViewKeys)
  {
    width = std::max(width, std::strlen(key.Keys));
  }
  std::string help = "Keys:\n";
  for (const ViewKey& key : ViewKeys)
  {
    help += "  " + std::string(key.Keys) + std::string(width + 3 - std::strlen(key.Keys), ' ') +
      key.Help + "\n";
  }
  return help + ViewMouseHelp;
}

CLI::App* AddViewCommand(CLI::App& program, ViewOptions& o)
{
  CLI::App* view =
    program.add_subcommand("view", "Open MESH in a window (needs a display) and inspect it live");
  view->add_option("MESH", o.Scene.Mesh, MeshFileHelp())->required();
  AddSettings(*view, o.Scene, Command::View);
  view->get_option("--size")->description(
    "The 3D view's size in pixels (default 1024x768, made smaller in the same shape where the "
    "window with its controls would not fit the screen; a given size is kept)");
  std::map<std::string, Shading> raster = NamedValues<Shading>(); // the rules the window draws
  raster.erase(ToString(Shading::Raytrace));
  std::string rules;
  for (const auto& [name, rule] : raster)
  {
    rules += (rules.empty() ? "" : "|") + name;
  }
  view
    ->add_option("--interactive-shading", o.InteractiveShading,
      "A cheaper rule while the mouse drags; the full rule returns on release")
    ->transform(CLI::CheckedTransformer(raster))
    ->option_text(rules);
  view->add_flag("--compare", o.Compare, "Start in the comparison layout (key c)");
  view->add_flag("-q,--quiet", o.Quiet, "No warnings");
  AddComparisonOptions(*view, o.Panels);
  view
    ->add_option("--measure-drag", o.MeasureDrag,
      "Time N frames of a simulated mouse drag and N still frames, print them and exit "
      "(scripts/bench-view)")
    ->check(CLI::Range(1, 100000))
    ->option_text("N");
  view->footer(ViewKeysHelp() + "\n\n" + CameraHelp);
  return view;
}

int ExecViewer(int argc, char** argv)
{
  const std::string viewer = SiblingExecutable("shadelab-view");
  // The window runs shadelab itself (the profile's chart): this one.
  std::error_code error;
  const std::string self = std::filesystem::read_symlink("/proc/self/exe", error).string();
  if (!error)
  {
    setenv("SHADELAB_EXECUTABLE", self.c_str(), 1);
  }
  std::vector<char*> args(argv, argv + argc);
  args[0] = const_cast<char*>(viewer.c_str());
  args.push_back(nullptr);
  execv(viewer.c_str(), args.data());
  return ReportError(viewer, std::string("cannot start the viewer: ") + std::strerror(errno));
}
}
