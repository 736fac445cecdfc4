// The picture of `shadelab profile`: the luminance along the line for each
// rule, with the oracle's smooth (phong) curve dashed, over its first and
// second differences, the triangles' edges the line crosses as grey
// verticals; beside them the picture with the line drawn over it.
#ifndef shadelab_profile_chart_h
#define shadelab_profile_chart_h

#include "headless/chart_style.h"
#include "profile/line_profile.h"

#include <string>

namespace shadelab
{
/**
 * The chart of profile; `picture` is what the inset shows the line on,
 * `title` the chart's first line (the mesh and the line).
 */
ChartImage DrawProfileChart(const LineProfile& profile, const FloatImage& picture,
  const std::string& title, int width = 1400, int height = 1000);
}

#endif
