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
/** r v: v rotated (or otherwise mapped) by the 3x3 matrix r. */
inline Vec3 Rotate(const double r[3][3], const Vec3& v)
{
  return { r[0][0] * v[0] + r[0][1] * v[1] + r[0][2] * v[2],
    r[1][0] * v[0] + r[1][1] * v[1] + r[1][2] * v[2],
    r[2][0] * v[0] + r[2][1] * v[1] + r[2][2] * v[2] };
}
/** a / |a|; unlike GLSL's, a zero vector stays zero. */
inline Vec3 normalize(const Vec3& a)
{
  const double l = length(a);
  return l > 0 ? (1 / l) * a : a;
}
/**
 * The unit normal of the triangle p0 p1 p2, (p1 - p0) x (p2 - p0) divided by
 * its length, into `unit`; returns that length, the doubled area. A cross
 * product of no usable length (zero, or overflowing) gives (0, 0, 0) and 0.
 * The one face normal: flat shading's, the oracle's and the summed vertex
 * normals' weights.
 */
inline double FaceNormal(const Vec3& p0, const Vec3& p1, const Vec3& p2, Vec3& unit)
{
  const Vec3 n = cross(p1 - p0, p2 - p0);
  const double l = length(n);
  const bool usable = l > 0 && std::isfinite(l);
  unit = usable ? Vec3{ n[0] / l, n[1] / l, n[2] / l } : Vec3{ 0, 0, 0 };
  return usable ? l : 0;
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
