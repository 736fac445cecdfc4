#include "commands/view_command.h"

#include "core/errors.h"
#include "core/sibling_executable.h"
#include "scene/camera.h"
#include "scene/comparison_panels.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <cstring>
#include <iostream>

namespace shadelab
{
const char* const ViewKeysHelp =
  "Keys:\n"
  "  0 1 2 3   shading none, flat, gouraud, phong\n"
  "  b         Blinn-Phong / Phong reflection\n"
  "  m M       next / previous material\n"
  "  l         lights: point at camera, directional, spot\n"
  "  + -       shininess up / down\n"
  "  a d s     ambient, diffuse, specular term on / off\n"
  "  w         normal weighting (computed once each)\n"
  "  n         normal glyphs\n"
  "  e         edges\n"
  "  c         comparison layout (as compare's options), linked cameras\n"
  "  r         reset the camera\n"
  "  p         screenshot (its name is printed)\n"
  "  h         this help\n"
  "  q Esc     quit\n"
  "Mouse: left rotate, middle pan, right or wheel zoom.";

CLI::App* AddViewCommand(CLI::App& program, ViewOptions& o)
{
  CLI::App* view =
    program.add_subcommand("view", "Open MESH in a window (needs a display) and inspect it live");
  AddSceneOptions(*view, o.Scene);
  view->get_option("MESH")->required();
  view->get_option("--size")->description("Window size in pixels (default 1024x768)");
  view
    ->add_option("--interactive-shading", o.InteractiveShading,
      "A cheaper rule while the mouse drags; the full rule returns on release")
    ->transform(CLI::CheckedTransformer(NamedValues<Shading>()))
    ->option_text(JoinedNames<Shading>("|"));
  view->add_flag("--compare", o.Compare, "Start in the comparison layout (key c)");
  view->add_flag("-q,--quiet", o.Quiet, "No warnings");
  AddComparisonOptions(*view, o.Panels);
  view
    ->add_option("--measure-drag", o.MeasureDrag,
      "Time N frames of a simulated mouse drag and N still frames, print them and exit "
      "(scripts/bench-view)")
    ->check(CLI::Range(1, 100000))
    ->option_text("N");
  view->footer(std::string(ViewKeysHelp) + "\n\n" + CameraHelp);
  return view;
}

int ExecViewer(int argc, char** argv)
{
  const std::string viewer = SiblingExecutable("shadelab-view");
  std::vector<char*> args(argv, argv + argc);
  args[0] = const_cast<char*>(viewer.c_str());
  args.push_back(nullptr);
  execv(viewer.c_str(), args.data());
  return ReportError(viewer, std::string("cannot start the viewer: ") + std::strerror(errno));
}
}
