// speed_accuracy.md, the summary `shadelab bench` writes beside its
// measurements: what a reader wants from them without a spreadsheet.
#ifndef shadelab_speed_accuracy_summary_h
#define shadelab_speed_accuracy_summary_h

#include "bench/speed_accuracy.h"

#include <string>
#include <vector>

namespace shadelab
{
/**
 * The markdown summary: per surface and size, each rule's error and speed
 * at each level (angle weighting), the weightings side by side, the checks
 * (CheckSpeedAccuracyOrder). commandLine and seconds say how they were made.
 */
std::string SpeedAccuracySummary(
  const std::vector<SpeedAccuracyRow>& rows, const std::string& commandLine, double seconds);
}

#endif
