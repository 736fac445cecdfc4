// `shadelab bench`'s measurements: tessellations of a sphere and a torus
// rendered through the headless backend under each shading rule and normal
// weighting, each against the exact picture of its surface
// (shadelabExactImage.h). Compiled into the headless library, as the chart.
#ifndef shadelab_speed_accuracy_run_h
#define shadelab_speed_accuracy_run_h

#include "bench/speed_accuracy.h"
#include "core/options.h"

#include <optional>
#include <string>
#include <vector>

namespace shadelab
{
class ProgressBar;

/** What a run measures. */
struct SpeedAccuracyPlan
{
  int Levels = 8;                      // tessellation levels 0 to Levels - 1
  std::vector<ImageSize> Sizes;        // picture sizes
  std::vector<std::string> Weightings; // gouraud's and phong's normals (flat has "face")
  int Frames = 5;                      // timed frames per measurement, after the first
};

/** The full plan, or the quick one: four levels, 640x480, angle weighting. */
SpeedAccuracyPlan MakeSpeedAccuracyPlan(bool quick, int frames);

/** How many rows the plan measures. */
long long SpeedAccuracyRowCount(const SpeedAccuracyPlan& plan);

/** A measurement that failed: what failed and why. */
struct MeasurementFailure
{
  std::string Input;
  std::string Problem;
};

/**
 * Measures the plan, appending a row per measurement to rows and showing
 * each on progress; the failure that ended it, if one did.
 */
std::optional<MeasurementFailure> MeasureSpeedAccuracy(
  const SpeedAccuracyPlan& plan, ProgressBar& progress, std::vector<SpeedAccuracyRow>& rows);
}

#endif
