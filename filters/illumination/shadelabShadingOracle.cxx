#include "shadelabShadingOracle.h"
#include "shadelabVec3.h"

#include <cmath>

namespace shadelab
{
namespace
{
Rgb Mul(const Rgb& a, const Rgb& b)
{
  return { a[0] * b[0], a[1] * b[1], a[2] * b[2] };
}
// Below this length a normal or a direction is taken as undefined.
constexpr double TinyLength = 1e-20;
// An interpolated normal shorter than this falls back to the geometric one.
constexpr double ShortNormal = 1e-6;
// The lecture lights a point when N.L > 0. Where N.L is exactly 0 (a light
// in the surface's plane, or at one of a triangle's vertices), float
// rounding in view coordinates gives N.L about +-1e-6 and would switch the
// specular term on and off at random; lighting only N.L > 1e-5 keeps the
// case rule deterministic at a cost of at most kd*1e-5 of diffuse light.
constexpr double GrazingLimit = 1e-5;

bool Usable(double len, double shortest)
{
  return len > shortest && std::isfinite(len);
}

// The light's direction L (unit, towards the light) and its colour as it
// reaches P, with the spot's cone and fall-off; false if it adds nothing.
bool LightAt(const FrameLight& light, const Vec3& P, Vec3& L, Rgb& Il)
{
  Il = light.Color;
  if (light.Kind == LightKind::Directional)
  {
    L = -light.Direction;
    return true;
  }
  const Vec3 toLight = light.Position - P;
  const double distance = length(toLight);
  if (!(distance > TinyLength))
  {
    return false; // the light is at P: no direction
  }
  L = (1 / distance) * toLight;
  if (light.Kind == LightKind::Spot)
  {
    const double cosAngle = dot(-L, light.Direction);
    if (cosAngle < light.CosCutoff)
    {
      return false;
    }
    const double falloff =
      light.Exponent == 0 ? 1.0 : (cosAngle > 0 ? std::pow(cosAngle, light.Exponent) : 0.0);
    Il = falloff * Il;
  }
  return true;
}

// d = 1 - cos of the specular angle, or a negative value when the lecture's
// case rules give no specular term (base <= 0 or undefined H).
double SpecularD(const IlluminationInputs& in, const Vec3& N, const Vec3& L, const Vec3& V)
{
  if (in.Model == Reflection::BlinnPhong)
  {
    const Vec3 sum = L + V;
    const double len = length(sum);
    if (!(len > TinyLength))
    {
      return -1; // L = -V: H undefined
    }
    const Vec3 H = (1 / len) * sum;
    return dot(N, H) > 0 ? 0.5 * dot(N - H, N - H) : -1;
  }
  const Vec3 R = (2 * dot(N, L)) * N - L;
  return dot(V, R) > 0 ? 0.5 * dot(V - R, V - R) : -1;
}
}

FrameLight ToFrame(const Light& light, const double r[3][3], const Vec3& t)
{
  auto rotate = [r](const Vec3& v) -> Vec3
  {
    return { r[0][0] * v[0] + r[0][1] * v[1] + r[0][2] * v[2],
      r[1][0] * v[0] + r[1][1] * v[1] + r[1][2] * v[2],
      r[2][0] * v[0] + r[2][1] * v[1] + r[2][2] * v[2] };
  };
  FrameLight f;
  f.Kind = light.Kind;
  f.Position = rotate(light.Position) + t;
  const Vec3 d = rotate(light.Direction);
  const double len = length(d);
  f.Direction = len > 0 ? (1 / len) * d : d;
  f.Color = light.Color;
  f.CosCutoff = std::cos(light.HalfAngleDeg * 3.14159265358979323846 / 180);
  f.Exponent = light.Exponent;
  return f;
}

double SpecularFalloff(double d, double ns)
{
  if (d < 0.01)
  {
    // ln(1 - d) = -(d + d^2/2 + d^3/3 + d^4/4 + ...); what is left out
    // changes the result by a factor exp(-ns*d^5/5), and the result is
    // exp(-ns*d) or less, so by under 1e-9 in absolute terms for d < 0.01.
    return std::exp(-ns * d * (1 + d * (0.5 + d * (1.0 / 3 + d * 0.25))));
  }
  return std::pow(1 - d, ns);
}

Rgb Illuminate(const IlluminationInputs& in, const Vec3& P, const Vec3& N)
{
  const Material& m = in.Surface;
  Rgb I = Mul(m.Ka, in.Ambient);
  Vec3 V = -in.ViewDirection;
  if (!in.Orthographic)
  {
    const Vec3 toEye = in.Eye - P;
    const double len = length(toEye);
    V = len > TinyLength ? (1 / len) * toEye : Vec3{ 0, 0, 0 };
  }
  for (const FrameLight& light : in.Lights)
  {
    Vec3 L;
    Rgb Il;
    if (!LightAt(light, P, L, Il))
    {
      continue;
    }
    const double NdotL = dot(N, L);
    if (!(NdotL > GrazingLimit))
    {
      continue; // no diffuse and, by the lecture's cases, no specular
    }
    Rgb term = NdotL * m.Kd;
    const double d = SpecularD(in, N, L, V);
    if (d >= 0)
    {
      term = term + SpecularFalloff(d, m.Ns) * m.Ks;
    }
    I = I + Mul(Il, term);
  }
  return I;
}

Rgb ShadeFragment(const IlluminationInputs& in, const Vec3& P, const Vec3& interpolatedN,
  const Vec3& geometricN, bool frontFacing)
{
  const double len = length(interpolatedN);
  Vec3 N;
  if (Usable(len, ShortNormal))
  {
    N = (1 / len) * interpolatedN;
    if (!frontFacing)
    {
      N = -N;
    }
  }
  else
  {
    N = (1 / length(geometricN)) * geometricN; // already facing the viewer
  }
  return Illuminate(in, P, N);
}

Rgb ShadeVertex(const IlluminationInputs& in, const Vec3& P, const Vec3& N, bool front)
{
  const double len = length(N);
  if (!Usable(len, TinyLength))
  {
    return Mul(in.Surface.Ka, in.Ambient);
  }
  const Vec3 unit = (1 / len) * N;
  return Illuminate(in, P, front ? unit : -unit);
}

Rgb ShadeFlat(
  const IlluminationInputs& in, const Vec3& P0, const Vec3& P1, const Vec3& P2, bool frontFacing)
{
  const Vec3 face = cross(P1 - P0, P2 - P0);
  return ShadeVertex(in, P2, face, frontFacing);
}
}
