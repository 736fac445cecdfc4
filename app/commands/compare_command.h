// `shadelab compare MESH -o OUT [--modes ...] [--diff A,B] [--components]`
// the side-by-side comparison: one picture with a panel per mode, one shared camera, a label
// in each panel, and optionally the difference of two as a heat map.
#ifndef shadelab_compare_command_h
#define shadelab_compare_command_h

#include "core/options.h"
#include "scene/comparison_panels.h"

#include <string>

namespace CLI
{
class App;
}

namespace shadelab
{
struct CompareOptions
{
  SceneOptions Scene; // every panel's, before its mode's changes; Size is a panel's
  std::string Output;
  ComparisonOptions Panels;
  bool Quiet = false; // no warnings
};

/** Declares the compare command and its options on the program. */
CLI::App* AddCompareCommand(CLI::App& program, CompareOptions& options);

/** Runs it; returns the exit code. */
int RunCompare(const CompareOptions& options, const std::string& commandLine);
}

#endif
