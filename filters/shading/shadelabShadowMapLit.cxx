// ShadowMap::Lit, the shaders' test of a map redone on the CPU in double
// (probe's shadow_map_agrees, the shadows benchmark's mismatch).
#include "shadelabShadowMaps.h"

#include "shadelabVec3.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{
bool ShadowMap::Lit(const Vec3& P, double slopeCos, double fromEye) const
{
  if (this->Texels.empty())
  {
    for (int f = 0; f < (this->Cube ? 6 : 1); ++f)
    {
      this->Texels.push_back(this->ReadFace(f));
    }
  }
  const std::array<double, 16>& m = this->WorldToMap;
  Vec3 q;
  for (int r = 0; r < 3; ++r)
  {
    q[r] = m[r * 4] * P[0] + m[r * 4 + 1] * P[1] + m[r * 4 + 2] * P[2] + m[r * 4 + 3];
  }
  const std::array<float, 4> b = this->GetBias();
  const double most = b[2];
  const double slope = slopeCos > 0
    ? std::min(std::sqrt(std::max(1 - slopeCos * slopeCos, 0.0)) / slopeCos, most)
    : most;
  const auto texel = [this](int face, double x, double y) -> double
  {
    const int i = std::clamp(static_cast<int>(std::floor(x)), 0, this->Size - 1);
    const int j = std::clamp(static_cast<int>(std::floor(y)), 0, this->Size - 1);
    return this->Texels[face][static_cast<std::size_t>(j) * this->Size + i];
  };
  if (this->Cube)
  {
    // The face whose forward axis q leans along most, as OpenGL picks it.
    int face = 0;
    for (int f = 1; f < 6; ++f)
    {
      if (dot(q, CubeFaces[f].Forward) > dot(q, CubeFaces[face].Forward))
      {
        face = f;
      }
    }
    const CubeFace& f = CubeFaces[face];
    const double ahead = dot(q, f.Forward), n = this->Size;
    const double x = (dot(q, cross(f.Forward, f.Up)) / ahead + 1) / 2 * n;
    const double y = (dot(q, f.Up) / ahead + 1) / 2 * n;
    const double d = length(q);
    return d <= texel(face, x, y) + b[0] * (d + fromEye) + b[1] * d * (1 + slope);
  }
  const double x = q[0] * this->Size, y = q[1] * this->Size;
  if (x < 0 || y < 0 || x >= this->Size || y >= this->Size)
  {
    return true;
  }
  return q[2] <= texel(0, x, y) + b[0] * (std::abs(q[2]) + fromEye) + b[1] * (1 + slope);
}
}
