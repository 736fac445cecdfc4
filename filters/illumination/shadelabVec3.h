// GLSL's vector operations on shadelab::Vec3, in double: what the oracle
// computes with, so that it reads like the shaders, and what tests use to
// write the equations out.
#ifndef shadelabVec3_h
#define shadelabVec3_h

#include "shadelabIllumination.h"

#include <cmath>

namespace shadelab
{
inline Vec3 operator+(const Vec3& a, const Vec3& b)
{
  return { a[0] + b[0], a[1] + b[1], a[2] + b[2] };
}
inline Vec3 operator-(const Vec3& a, const Vec3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}
inline Vec3 operator-(const Vec3& a)
{
  return { -a[0], -a[1], -a[2] };
}
inline Vec3 operator*(double s, const Vec3& a)
{
  return { s * a[0], s * a[1], s * a[2] };
}
/** Component by component, as GLSL's vec3 * vec3: colours times colours. */
inline Vec3 operator*(const Vec3& a, const Vec3& b)
{
  return { a[0] * b[0], a[1] * b[1], a[2] * b[2] };
}
inline double dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline double length(const Vec3& a)
{
  return std::sqrt(dot(a, a));
}
inline Vec3 cross(const Vec3& a, const Vec3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
/** a / |a|; unlike GLSL's, a zero vector stays zero. */
inline Vec3 normalize(const Vec3& a)
{
  const double l = length(a);
  return l > 0 ? (1 / l) * a : a;
}

/**
 * Vec3 is a std::array, so these are not found by argument-dependent lookup
 * outside namespace shadelab: `using namespace shadelab::vec3;` brings them.
 */
namespace vec3
{
using shadelab::operator+;
using shadelab::operator-;
using shadelab::operator*;
using shadelab::cross;
using shadelab::dot;
using shadelab::length;
using shadelab::normalize;
}
}

#endif
