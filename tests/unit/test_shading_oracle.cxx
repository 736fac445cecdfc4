// The double-precision oracle (filters/illumination/shadelabShadingOracle) against the
// lecture's equations written out independently here, in their plainest
// form, and its case rules and guards.
#include "shadelabShadingOracle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace shadelab;

namespace
{
using Real = long double;

Vec3 Unit(Vec3 v)
{
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return { v[0] / n, v[1] / n, v[2] / n };
}

Real Dot(const Vec3& a, const Vec3& b)
{
  return static_cast<Real>(a[0]) * b[0] + static_cast<Real>(a[1]) * b[1] +
    static_cast<Real>(a[2]) * b[2];
}

IlluminationInputs Inputs(Reflection model, double ns)
{
  IlluminationInputs in;
  in.Surface = { "test", { 0.1, 0.2, 0.3 }, { 0.5, 0.4, 0.3 }, { 0.9, 0.8, 0.7 }, ns, 1 };
  in.Ambient = { 0.5, 0.5, 0.5 };
  in.Model = model;
  in.Orthographic = false;
  in.Eye = { 0, 0, 10 };
  return in;
}

FrameLight Directional(const Vec3& shinesAlong, Rgb color = { 1, 1, 1 })
{
  FrameLight l;
  l.Kind = LightKind::Directional;
  l.Direction = Unit(shinesAlong);
  l.Color = color;
  return l;
}

// The lecture: I = ka Ia + sum Il [kd (N.L) + ks (N.H)^ns] with its cases,
// for one directional light, straight from the slides.
Rgb Lecture(const IlluminationInputs& in, const Vec3& P, const Vec3& N, const FrameLight& light)
{
  const Vec3 L = Unit({ -light.Direction[0], -light.Direction[1], -light.Direction[2] });
  const Vec3 V = Unit({ in.Eye[0] - P[0], in.Eye[1] - P[1], in.Eye[2] - P[2] });
  const Real NL = Dot(N, L);
  Real base = 0;
  if (in.Model == Reflection::BlinnPhong)
  {
    base = Dot(N, Unit({ L[0] + V[0], L[1] + V[1], L[2] + V[2] }));
  }
  else
  {
    const Vec3 R = { static_cast<double>(2 * NL * N[0] - L[0]),
      static_cast<double>(2 * NL * N[1] - L[1]), static_cast<double>(2 * NL * N[2] - L[2]) };
    base = Dot(V, R);
  }
  Rgb I;
  for (int c = 0; c < 3; ++c)
  {
    Real v = static_cast<Real>(in.Surface.Ka[c]) * in.Ambient[c];
    if (NL > 0)
    {
      v += light.Color[c] *
        (in.Surface.Kd[c] * NL + (base > 0 ? in.Surface.Ks[c] * std::pow(base, in.Surface.Ns) : 0));
    }
    I[c] = static_cast<double>(v);
  }
  return I;
}
}

// Random unit normals and light directions over the hemisphere of
// interest, both reflection models, shininess from 0 to 1e6: the robust
// specular form agrees with pow(N.H, ns) to 1e-9 relative (the series'
// remainder is below 1e-8 * ns * d^4, double rounding far below).
TEST(ShadingOracle, MatchesTheLecturesEquation)
{
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const Vec3 P{ 0.1, -0.2, 0.05 };
  for (Reflection model : { Reflection::BlinnPhong, Reflection::Phong })
  {
    for (double ns : { 0.0, 1e-3, 1.0, 27.8974, 1e3, 1e6 })
    {
      IlluminationInputs in = Inputs(model, ns);
      for (int i = 0; i < 2000; ++i)
      {
        const Vec3 N = Unit({ u(random), u(random), std::abs(u(random)) + 0.2 });
        // Near the mirror direction often, so that large ns is exercised.
        const Vec3 L =
          Unit({ N[0] + 0.02 * u(random), N[1] + 0.02 * u(random), N[2] + 0.02 * u(random) });
        const FrameLight light = Directional({ -L[0], -L[1], -L[2] });
        in.Lights = { light };
        const Rgb got = Illuminate(in, P, N);
        const Rgb want = Lecture(in, P, N, light);
        for (int c = 0; c < 3; ++c)
        {
          ASSERT_NEAR(got[c], want[c], 1e-9 * std::max(1.0, std::abs(want[c])))
            << "ns " << ns << " model " << ToString(model) << " sample " << i;
        }
      }
    }
  }
}

TEST(ShadingOracle, CaseRules)
{
  IlluminationInputs in = Inputs(Reflection::BlinnPhong, 10);
  const Vec3 P{ 0, 0, 0 }, N{ 0, 0, 1 };
  const Rgb ambient{ 0.05, 0.1, 0.15 };
  // Light behind the surface: N.L <= 0 gives ambient only, no specular.
  in.Lights = { Directional({ 0, 0, 1 }) };
  EXPECT_EQ(Illuminate(in, P, N), ambient);
  // Light in the surface's plane: N.L = 0, ambient only.
  in.Lights = { Directional({ 1, 0, 0 }) };
  EXPECT_EQ(Illuminate(in, P, N), ambient);
  // ns = 0 with a positive base gives ks.
  in.Surface.Ns = 0;
  in.Lights = { Directional({ 0, 0, -1 }) };
  const Rgb head = Illuminate(in, P, N);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_DOUBLE_EQ(head[c], ambient[c] + in.Surface.Kd[c] + in.Surface.Ks[c]);
  }
}

TEST(ShadingOracle, UndefinedDirectionsAddNothingUndefined)
{
  IlluminationInputs in = Inputs(Reflection::BlinnPhong, 10);
  const Rgb ambient{ 0.05, 0.1, 0.15 };
  // A point light exactly at P: no direction, no contribution.
  FrameLight atP;
  atP.Kind = LightKind::Point;
  atP.Position = { 1, 2, 3 };
  in.Lights = { atP };
  EXPECT_EQ(Illuminate(in, { 1, 2, 3 }, { 0, 0, 1 }), ambient);
  // L = -V: H is undefined; diffuse only if N.L > 0, never NaN.
  in.Lights = { Directional({ 0, 0, 1 }) }; // shines away from the eye: L = (0,0,-1) = -V
  const Rgb r = Illuminate(in, { 0, 0, 0 }, Unit({ 0, 1, -1 }));
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_TRUE(std::isfinite(r[c]));
    EXPECT_NEAR(r[c], ambient[c] + in.Surface.Kd[c] * std::sqrt(0.5), 1e-12);
  }
}

TEST(ShadingOracle, SpotConeAndFalloff)
{
  IlluminationInputs in = Inputs(Reflection::BlinnPhong, 10);
  in.Surface.Ks = { 0, 0, 0 };
  FrameLight spot;
  spot.Kind = LightKind::Spot;
  spot.Position = { 0, 0, 5 };
  spot.Direction = { 0, 0, -1 };
  spot.CosCutoff = std::cos(30 * 3.14159265358979323846 / 180);
  spot.Exponent = 4;
  in.Lights = { spot };
  const Vec3 N{ 0, 0, 1 };
  // Inside: at angle a from the axis, Il (cos a)^4 and N.L = cos a.
  const double x = 5 * std::tan(20 * 3.14159265358979323846 / 180);
  const double cosA = std::cos(20 * 3.14159265358979323846 / 180);
  const Rgb inside = Illuminate(in, { x, 0, 0 }, N);
  EXPECT_NEAR(inside[0], 0.05 + 0.5 * std::pow(cosA, 4) * cosA, 1e-12);
  // Outside the 30-degree cone: ambient only.
  const double far = 5 * std::tan(31 * 3.14159265358979323846 / 180);
  EXPECT_DOUBLE_EQ(Illuminate(in, { far, 0, 0 }, N)[0], 0.05);
}

TEST(ShadingOracle, RulesFallBackAndFlip)
{
  IlluminationInputs in = Inputs(Reflection::BlinnPhong, 10);
  in.Lights = { Directional({ 0, 0, -1 }) };
  const Vec3 P{ 0, 0, 0 };
  // A zero interpolated normal falls back to the geometric normal.
  EXPECT_EQ(ShadeFragment(in, P, { 0, 0, 0 }, { 0, 0, 2 }, true), Illuminate(in, P, { 0, 0, 1 }));
  // Back faces are lit with the normal flipped.
  EXPECT_EQ(ShadeFragment(in, P, { 0, 0, 3 }, { 0, 0, 1 }, false), Illuminate(in, P, { 0, 0, -1 }));
  // Gouraud: a zero vertex normal lights as ambient only.
  EXPECT_EQ(ShadeVertex(in, P, { 0, 0, 0 }, true), (Rgb{ 0.05, 0.1, 0.15 }));
  // Flat: the face normal from the winding, evaluated at the last vertex.
  const Rgb flat = ShadeFlat(in, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, true);
  EXPECT_EQ(flat, Illuminate(in, { 0, 1, 0 }, { 0, 0, 1 }));
  EXPECT_EQ(ShadeFlat(in, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, false),
    Illuminate(in, { 0, 1, 0 }, { 0, 0, -1 }));
}
