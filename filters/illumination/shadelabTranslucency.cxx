#include "shadelabTranslucency.h"

#include <algorithm>

namespace shadelab
{
Covered Composite(const std::vector<Layer>& nearestFirst, const Covered& behind, int peels)
{
  const std::size_t drawn = peels > 0
    ? std::min(nearestFirst.size(), static_cast<std::size_t>(peels))
    : nearestFirst.size();
  Covered c = behind;
  for (std::size_t k = drawn; k-- > 0;)
  {
    const Layer& layer = nearestFirst[k];
    for (int channel = 0; channel < 3; ++channel)
    {
      c.Color[channel] =
        layer.Opacity * layer.Color[channel] + (1 - layer.Opacity) * c.Color[channel];
    }
    c.Alpha = layer.Opacity + (1 - layer.Opacity) * c.Alpha;
  }
  return c;
}
}
