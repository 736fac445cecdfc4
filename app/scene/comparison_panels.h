// What a comparison shows: one panel per mode of --modes, each the
// command line's scene with the mode's changes, optionally split into the
// illumination's ambient, diffuse and specular terms. Shared by `compare`
// (one picture) and `view --compare` (a window).
#ifndef shadelab_comparison_panels_h
#define shadelab_comparison_panels_h

#include "core/options.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace CLI
{
class App;
}

namespace shadelab
{
/** The terms of the illumination that a panel shows (--components). */
enum class Terms
{
  All,
  Ambient,
  Diffuse,
  Specular
};

struct Panel
{
  SceneOptions Scene; // the base scene with the mode's changes and the terms' material
  std::string Mode;   // the mode as written in --modes
  std::string Label;  // what the panel's label says
  Terms Shown = Terms::All;
};

/**
 * The modes of text, "MODE[,MODE...]" with MODE = "[RULE][:KEY=VALUE]..."
 * (RULE: none|flat|gouraud|phong|raytrace; KEY: shading, reflection, material,
 * weighting, ns, normals, as their options), each applied to base.
 * Throws std::invalid_argument naming the mode and the problem.
 */
std::vector<Panel> ParseModes(const std::string& text, const SceneOptions& base);

/** --modes's help: the modes' syntax (compare, view, profile). */
extern const char* const ModesHelp;

/**
 * Leaves only the chosen terms of the illumination in scene, by zeroing the
 * others' coefficients (and the environment, with the background that shows
 * it, by dropping it), and the normal maps, the options' and the file's,
 * only where chosen (else --normal-map none): the shaders then hold no code for them
 * (doc/design.md, generated for what the scene needs).
 */
void ShowTerms(SceneOptions& scene, bool ambient, bool diffuse, bool specular,
  bool environment = true, bool normalMap = true);

/** Each panel as four: its ambient, diffuse and specular terms and their total. */
std::vector<Panel> SplitIntoTerms(const std::vector<Panel>& panels);

/**
 * The two panels of "A,B" (--diff): each a mode as written in --modes or
 * its number from 1. Throws std::invalid_argument.
 */
std::pair<int, int> ParseDifference(const std::string& text, const std::vector<Panel>& modes);

/** What a comparison shows: --modes, --diff and --components of compare and view. */
struct ComparisonOptions
{
  std::string Modes = "flat,gouraud,phong";
  std::string Difference; // "A,B" or empty
  bool Components = false;
};

/** Declares --modes, --diff and --components on command. */
void AddComparisonOptions(CLI::App& command, ComparisonOptions& options);

/** The panels of a comparison, in layout order. */
struct Comparison
{
  std::vector<Panel> Modes;  // one per mode
  std::vector<Panel> Panels; // the modes, or with --components four per mode
  int Columns = 0;           // 4 with --components (a row per mode), else 0: LayOut's choice
  int DifferenceA = -1;      // the panels whose difference is shown, or -1
  int DifferenceB = -1;
  std::string DifferenceLabel; // "|A - B|"
};

/** The comparison options ask for on base. Throws std::invalid_argument. */
Comparison PlanComparison(const ComparisonOptions& options, const SceneOptions& base);

const char* ToString(Terms terms);
}

#endif
