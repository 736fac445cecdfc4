#include "shadelabFog.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{
namespace
{
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
}

FogAt FogOver(const Fog& fog, const Rgb& C, const Vec3& P, const Vec3& eye,
  const Vec3& viewDirection, const std::optional<Rgb>& background)
{
  FogAt at;
  at.Mode = fog.Mode;
  for (int c = 0; c < 3; ++c)
  {
    at.Depth += (P[c] - eye[c]) * viewDirection[c];
  }
  at.Factor = FogFactor(fog, at.Depth);
  at.Transparent = !fog.Color && !background;
  at.Color = fog.Color.value_or(background.value_or(Rgb{}));
  at.Before = C;
  for (int c = 0; c < 3; ++c)
  {
    at.After[c] = at.Transparent ? C[c] : at.Factor * C[c] + (1 - at.Factor) * at.Color[c];
  }
  return at;
}
}
