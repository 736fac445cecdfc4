// What a comparison shows (issue 5): one panel per mode of --modes, each the
// command line's scene with the mode's changes, optionally split into the
// illumination's ambient, diffuse and specular terms. Shared by `compare`
// (one picture) and `view --compare` (a window).
#ifndef shadelab_comparison_panels_h
#define shadelab_comparison_panels_h

#include "options.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

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
 * (RULE: none|flat|gouraud|phong; KEY: shading, reflection, material,
 * weighting, ns, normals, as their options), each applied to base.
 * Throws std::invalid_argument naming the mode and the problem.
 */
std::vector<Panel> ParseModes(const std::string& text, const SceneOptions& base);

/**
 * Leaves only the chosen terms of the illumination in scene, by zeroing the
 * others' coefficients: the shaders then hold no code for them (DESIGN.md,
 * generated for what the scene needs).
 */
void ShowTerms(SceneOptions& scene, bool ambient, bool diffuse, bool specular);

/** Each panel as four: its ambient, diffuse and specular terms and their total. */
std::vector<Panel> SplitIntoTerms(const std::vector<Panel>& panels);

/**
 * The two panels of "A,B" (--diff): each a mode as written in --modes or
 * its number from 1. Throws std::invalid_argument.
 */
std::pair<int, int> ParseDifference(const std::string& text, const std::vector<Panel>& modes);

/** The help text of --modes. */
extern const char* const ModesHelp;

const char* ToString(Terms terms);
}

#endif
