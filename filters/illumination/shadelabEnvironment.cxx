#include "shadelabEnvironment.h"

#include "shadelabVec3.h"

#include <cmath>

namespace shadelab
{
namespace
{
constexpr double Pi = 3.14159265358979323846;
}

std::array<double, 2> EnvironmentTexCoord(const Vec3& d)
{
  return { 0.5 + std::atan2(d[0], -d[2]) / (2 * Pi),
    0.5 + std::atan2(d[1], std::hypot(d[0], d[2])) / Pi };
}

EnvironmentTerm EnvironmentAlong(const EnvironmentMap& e, const Vec3& d)
{
  EnvironmentTerm t;
  t.R = d;
  t.Direction = Rotate(e.Frame, t.R);
  t.TexCoord = EnvironmentTexCoord(t.Direction);
  t.Texel = SampleTexture(e.Map, t.TexCoord[0], t.TexCoord[1]);
  return t;
}

EnvironmentTerm EnvironmentAt(const EnvironmentMap& e, const Vec3& N, const Vec3& V, const Rgb& ks)
{
  EnvironmentTerm t = EnvironmentAlong(e, (2 * dot(N, V)) * N - V);
  t.Term = ks * t.Texel;
  return t;
}
}
