#include "shadelabShadingOracle.h"
#include "shadelabVec3.h"

#include <cmath>

namespace shadelab
{
namespace
{
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
// reaches P, with the distance attenuation and the spot's cone and
// fall-off: the first fields of terms.
void LightAt(const FrameLight& light, const Vec3& P, LightTerms& t)
{
  t.Il = light.Color;
  const LightGeometry g = GeometryOf(light.Kind);
  if (!g.Position)
  {
    t.L = -light.Direction;
    t.Reaches = true;
    return;
  }
  const Vec3 toLight = light.Position - P;
  const double distance = length(toLight);
  if (!(distance > TinyLength))
  {
    t.Il = { 0, 0, 0 };
    return; // the light is at P: no direction
  }
  t.L = (1 / distance) * toLight;
  t.Reaches = true;
  t.Distance = distance;
  if (light.Attenuation != NoAttenuation)
  {
    const Vec3& c = light.Attenuation;
    t.Attenuation = 1 / (c[0] + distance * (c[1] + distance * c[2]));
    t.Il = t.Attenuation * t.Il;
  }
  if (g.Cone)
  {
    t.SpotCos = dot(-t.L, light.Direction);
    t.Reaches = t.SpotCos >= light.CosCutoff;
    t.SpotFactor = !t.Reaches ? 0.0
      : light.Exponent == 0   ? 1.0
                              : (t.SpotCos > 0 ? std::pow(t.SpotCos, light.Exponent) : 0.0);
    t.Il = t.SpotFactor * t.Il;
  }
}

// H or R and the specular base; returns d = 1 - cos of the specular angle,
// or a negative value when the lecture's case rules give no specular term
// (base <= 0 or undefined H).
double SpecularD(const IlluminationInputs& in, const Vec3& N, const Vec3& V, LightTerms& t)
{
  if (UsesHalfVector(in.Model))
  {
    const Vec3 sum = t.L + V;
    const double len = length(sum);
    if (!(len > TinyLength))
    {
      return -1; // L = -V: H undefined
    }
    t.HR = (1 / len) * sum;
    t.Base = dot(N, t.HR);
    return t.Base > 0 ? 0.5 * dot(N - t.HR, N - t.HR) : -1;
  }
  t.HR = (2 * t.NdotL) * N - t.L;
  t.Base = dot(V, t.HR);
  return t.Base > 0 ? 0.5 * dot(V - t.HR, V - t.HR) : -1;
}

// One light's terms at P, lit with unit normal N seen along V.
LightTerms LightTermsAt(
  const IlluminationInputs& in, std::size_t l, const Vec3& P, const Vec3& N, const Vec3& V)
{
  const FrameLight& light = in.Lights[l];
  const Material& m = in.Surface;
  LightTerms t;
  LightAt(light, P, t);
  t.NdotL = dot(N, t.L);
  const double d = SpecularD(in, N, V, t);
  // "N.L <= 0": no diffuse and, by the lecture's cases, no specular.
  t.Lit = t.Reaches && t.NdotL > GrazingLimit;
  // The shadow ray only where the light would add a term, as the shaders
  // read their maps.
  t.Shadowed = t.Lit && light.Shadows && in.Reaches && !in.Reaches(l, P, N);
  t.Lit = t.Lit && !t.Shadowed;
  t.Specular = t.Lit && d >= 0;
  if (t.Lit)
  {
    t.DiffuseTerm = t.Il * (t.NdotL * m.Kd);
  }
  if (t.Specular)
  {
    t.Power = SpecularFalloff(d, m.Ns);
    t.SpecularTerm = t.Il * (t.Power * m.Ks);
  }
  return t;
}
}

FrameLight ToFrame(const Light& light, const double r[3][3], const Vec3& t)
{
  FrameLight f;
  f.Kind = light.Kind;
  f.Position = Rotate(r, light.Position) + t;
  const Vec3 d = Rotate(r, light.Direction);
  const double len = length(d);
  f.Direction = len > 0 ? (1 / len) * d : d;
  f.Color = light.Color;
  f.CosCutoff = std::cos(light.HalfAngleDeg * 3.14159265358979323846 / 180);
  f.Exponent = light.Exponent;
  f.Shadows = CastsShadows(light);
  if (Attenuated(light))
  {
    f.Attenuation = *light.Attenuation;
  }
  return f;
}

FrameLight ToFrame(const Light& light)
{
  const double identity[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
  return ToFrame(light, identity, { 0, 0, 0 });
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

Rgb IlluminationTerms::Total() const
{
  Rgb I = this->Ambient;
  for (const LightTerms& light : this->Lights)
  {
    I = I + (light.DiffuseTerm + light.SpecularTerm);
  }
  if (this->Environment)
  {
    I = I + this->Environment->Term;
  }
  return I;
}

IlluminationTerms IlluminateTerms(const IlluminationInputs& in, const Vec3& P, const Vec3& N)
{
  IlluminationTerms terms;
  terms.P = P;
  terms.N = N;
  terms.Ambient = in.Surface.Ka * in.Ambient;
  terms.V = -in.ViewDirection;
  if (!in.Orthographic)
  {
    const Vec3 toEye = in.Eye - P;
    const double len = length(toEye);
    terms.V = len > TinyLength ? (1 / len) * toEye : Vec3{ 0, 0, 0 };
  }
  for (std::size_t l = 0; l < in.Lights.size(); ++l)
  {
    terms.Lights.push_back(LightTermsAt(in, l, P, N, terms.V));
  }
  // N = 0 lights as ambient only (ShadeVertex): nothing is reflected.
  if (in.Environment && length(N) > 0)
  {
    terms.Environment = EnvironmentAt(*in.Environment, N, terms.V, in.Surface.Ks);
  }
  return terms;
}

Rgb Illuminate(const IlluminationInputs& in, const Vec3& P, const Vec3& N)
{
  return IlluminateTerms(in, P, N).Total();
}

bool UsableInterpolatedNormal(const Vec3& interpolatedN)
{
  return Usable(length(interpolatedN), ShortNormal);
}

bool UsableVertexNormal(const Vec3& N)
{
  return Usable(length(N), TinyLength);
}

IlluminationTerms ShadeFragment(const IlluminationInputs& in, const Vec3& P,
  const Vec3& interpolatedN, const Vec3& geometricN, bool frontFacing)
{
  Vec3 N;
  if (UsableInterpolatedNormal(interpolatedN))
  {
    N = (1 / length(interpolatedN)) * interpolatedN;
    if (!frontFacing)
    {
      N = -N;
    }
  }
  else
  {
    N = (1 / length(geometricN)) * geometricN; // already facing the viewer
  }
  return IlluminateTerms(in, P, N);
}

IlluminationTerms ShadeVertex(
  const IlluminationInputs& in, const Vec3& P, const Vec3& N, bool front)
{
  // No usable normal: N = 0 makes N.L = 0 for every light, ambient only.
  const Vec3 unit = UsableVertexNormal(N) ? (1 / length(N)) * N : Vec3{ 0, 0, 0 };
  return IlluminateTerms(in, P, front ? unit : -unit);
}

IlluminationTerms ShadeFlat(
  const IlluminationInputs& in, const Vec3& P0, const Vec3& P1, const Vec3& P2, bool frontFacing)
{
  const Vec3 face = cross(P1 - P0, P2 - P0);
  return ShadeVertex(in, P2, face, frontFacing);
}
}
