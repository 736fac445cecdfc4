// `shadelab view MESH [options]`: the desktop inspector, a real
// window through VTK's native backend. shadelab itself links OSMesa first
// (the headless backend), so the window runs in an executable of its own,
// shadelab-view, which shadelab becomes (exec) after checking the command
// line; both declare the options through AddViewCommand.
#ifndef shadelab_view_command_h
#define shadelab_view_command_h

#include "core/options.h"
#include "scene/comparison_panels.h"

#include <optional>
#include <string>

namespace CLI
{
class App;
}

namespace shadelab
{
struct ViewOptions
{
  SceneOptions Scene;
  std::optional<Shading> InteractiveShading; // the rule while the mouse drags
  bool Compare = false;                      // start in the comparison layout
  ComparisonOptions Panels;                  // its panels, as compare's
  bool SizeGiven = false; // --size was given: the window keeps it even where the screen is smaller
  int MeasureDrag = 0;    // frames of a simulated drag to time, then exit (scripts/bench-view)
  bool Quiet = false;     // no warnings
};

/** Declares the view command and its options on the program. */
CLI::App* AddViewCommand(CLI::App& program, ViewOptions& options);

/**
 * Replaces this process by shadelab-view with the same arguments (argv[0]
 * aside). Returns only on failure, with the exit code.
 */
int ExecViewer(int argc, char** argv);

/** Opens the window and runs until it is closed (shadelab-view); the exit code. */
int RunView(const ViewOptions& options, const std::string& commandLine);

/** The key table (desktop/view_keys.h) as `h` shows it and --help lists it. */
std::string ViewKeysHelp();
}

#endif
