// `shadelab probe MESH --pixel X,Y [options] [--json]`: explains how the
// lecture's equation gives the colour of pixel (X, Y) of the picture
// `render` makes with the same options, headless.
#ifndef shadelab_probe_command_h
#define shadelab_probe_command_h

#include "core/options.h"

#include <vector>

namespace CLI
{
class App;
}

namespace shadelab
{
struct ProbeOptions
{
  SceneOptions Scene;
  std::vector<Pixel> Pixels; // each explained in turn
  bool Json = false;         // one JSON object per pixel and line instead of text
  bool Quiet = false;        // no warnings
};

/** Declares the probe command and its options on the program. */
CLI::App* AddProbeCommand(CLI::App& program, ProbeOptions& options);

/** Runs it; returns the exit code. */
int RunProbe(const ProbeOptions& options);
}

#endif
