#include "shadelabFog.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{
double FogDepth(const Vec3& P, const Vec3& eye, const Vec3& viewDirection)
{
  return (P[0] - eye[0]) * viewDirection[0] + (P[1] - eye[1]) * viewDirection[1] +
    (P[2] - eye[2]) * viewDirection[2];
}

double FogFactor(const Fog& fog, double depth)
{
  switch (fog.Mode)
  {
    case FogMode::None:
      return 1;
    case FogMode::Linear:
      return std::clamp((fog.End - depth) / (fog.End - fog.Start), 0.0, 1.0);
    case FogMode::Exp:
      return std::exp(-fog.Density * depth);
    case FogMode::Exp2:
    {
      const double x = fog.Density * depth;
      return std::exp(-x * x);
    }
  }
  return 1;
}

Rgb Fogged(const Rgb& colour, double factor, const Rgb& fogColour)
{
  Rgb out{};
  for (int c = 0; c < 3; ++c)
  {
    out[c] = factor * colour[c] + (1 - factor) * fogColour[c];
  }
  return out;
}
}
