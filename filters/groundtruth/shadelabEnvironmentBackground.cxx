#include "shadelabEnvironmentBackground.h"

#include "shadelabParallelRows.h"

namespace shadelab
{
EnvironmentTerm EnvironmentBehind(
  const EnvironmentMap& e, const PinholeCamera& camera, int width, int height, double x, double y)
{
  return EnvironmentAlong(e, PictureRay(camera, width, height, x, y).Direction);
}

void OverEnvironment(std::vector<float>& rgba, int width, int height, const PinholeCamera& camera,
  const EnvironmentMap& e)
{
  ForEachRow(0, height,
    [&](int row)
    {
      // Row `row` from the bottom: its centres lie height - row - 0.5 from the top.
      float* out = rgba.data() + static_cast<std::size_t>(row) * width * 4;
      for (int x = 0; x < width; ++x, out += 4)
      {
        const double uncovered = 1.0 - out[3];
        if (uncovered == 0)
        {
          continue;
        }
        const Rgb E =
          EnvironmentBehind(e, camera, width, height, x + 0.5, height - row - 0.5).Texel;
        for (int c = 0; c < 3; ++c)
        {
          out[c] = static_cast<float>(out[c] + uncovered * E[c]);
        }
        out[3] = 1;
      }
    });
}
}
