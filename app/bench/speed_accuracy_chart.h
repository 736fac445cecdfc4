// The picture of `shadelab bench`: error against time per frame, drawn with
// VTK's charts through the headless backend.
#ifndef shadelab_speed_accuracy_chart_h
#define shadelab_speed_accuracy_chart_h

#include "bench/speed_accuracy.h"
#include "headless/chart_style.h"

#include <vector>

namespace shadelab
{
/**
 * RMSE against median ms/frame on log-log axes: a line per surface and rule
 * (angle weighting for gouraud and phong, at the largest picture size
 * measured), each point labelled with its triangle count.
 */
ChartImage DrawSpeedAccuracyChart(
  const std::vector<SpeedAccuracyRow>& rows, int width = 1600, int height = 1000);
}

#endif
