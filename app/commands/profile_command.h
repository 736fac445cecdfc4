// `shadelab profile MESH --line X0,Y0,X1,Y1 [--modes flat,gouraud,phong]
// -o profile.png [-o profile.csv]`: Mach bands as a measurement. Each
// mode's picture is read along the line (luminance and channels, with
// first and second differences) beside the double-precision oracle's phong,
// drawn as a chart with the line over the picture in an inset, or written
// as CSV.
#ifndef shadelab_profile_command_h
#define shadelab_profile_command_h

#include "core/options.h"

#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace shadelab
{
struct ProfileOptions
{
  SceneOptions Scene; // every mode's, before its changes
  std::string Line;   // "X0,Y0,X1,Y1"
  std::string Modes = "flat,gouraud,phong";
  std::vector<std::string> Outputs; // a chart (an image) or CSV (.csv), by extension
  bool Quiet = false;               // no warnings
};

/** Declares the profile command and its options on the program. */
CLI::App* AddProfileCommand(CLI::App& program, ProfileOptions& options);

/** Runs it; returns the exit code. */
int RunProfile(const ProfileOptions& options, const std::string& commandLine);
}

#endif
