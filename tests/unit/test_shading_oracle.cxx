// The double-precision oracle (filters/illumination/shadelabShadingOracle) against the
// lecture's equations written out independently here, in their plainest
// form, and its case rules and guards.
#include "shadelabShadingOracle.h"
#include "shadelabTriangleFragment.h"

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

// The lecture's terms, one directional light: ka Ia, Il kd (N.L) and
// Il ks (N.H)^ns (or (V.R)^ns) with their cases, and the vectors they use.
struct Terms
{
  Vec3 L, HR;
  Real NdotL = 0, Base = 0;
  Rgb Ambient, Diffuse, Specular;
};

// The lecture: I = ka Ia + sum Il [kd (N.L) + ks (N.H)^ns] with its cases,
// for one directional light, straight from the slides.
Terms Lecture(const IlluminationInputs& in, const Vec3& P, const Vec3& N, const FrameLight& light)
{
  Terms t;
  t.L = Unit({ -light.Direction[0], -light.Direction[1], -light.Direction[2] });
  const Vec3& L = t.L;
  const Vec3 V = Unit({ in.Eye[0] - P[0], in.Eye[1] - P[1], in.Eye[2] - P[2] });
  t.NdotL = Dot(N, L);
  const Real NL = t.NdotL;
  if (in.Model == Reflection::BlinnPhong)
  {
    t.HR = Unit({ L[0] + V[0], L[1] + V[1], L[2] + V[2] });
    t.Base = Dot(N, t.HR);
  }
  else
  {
    t.HR = { static_cast<double>(2 * NL * N[0] - L[0]), static_cast<double>(2 * NL * N[1] - L[1]),
      static_cast<double>(2 * NL * N[2] - L[2]) };
    t.Base = Dot(V, t.HR);
  }
  for (int c = 0; c < 3; ++c)
  {
    t.Ambient[c] = static_cast<double>(static_cast<Real>(in.Surface.Ka[c]) * in.Ambient[c]);
    t.Diffuse[c] = NL > 0 ? static_cast<double>(light.Color[c] * in.Surface.Kd[c] * NL) : 0;
    t.Specular[c] = NL > 0 && t.Base > 0
      ? static_cast<double>(light.Color[c] * in.Surface.Ks[c] * std::pow(t.Base, in.Surface.Ns))
      : 0;
  }
  return t;
}
}

// Random unit normals and light directions over the hemisphere of
// interest, both reflection models, shininess from 0 to 1e6: the robust
// specular form agrees with pow(N.H, ns) to 1e-9 relative (the series'
// remainder is below 1e-8 * ns * d^4, double rounding far below), term by
// term, and so do the vectors and dot products the terms come from.
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
        const Terms want = Lecture(in, P, N, light);
        const IlluminationTerms got = IlluminateTerms(in, P, N);
        ASSERT_EQ(got.Lights.size(), 1u);
        const LightTerms& l = got.Lights[0];
        const auto close = [](double a, double b)
        { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); };
        for (int c = 0; c < 3; ++c)
        {
          ASSERT_TRUE(close(got.Ambient[c], want.Ambient[c])) << c;
          ASSERT_TRUE(close(l.DiffuseTerm[c], want.Diffuse[c]))
            << "diffuse, ns " << ns << " model " << ToString(model) << " sample " << i;
          ASSERT_TRUE(close(l.SpecularTerm[c], want.Specular[c]))
            << "specular, ns " << ns << " model " << ToString(model) << " sample " << i;
          ASSERT_TRUE(
            close(Illuminate(in, P, N)[c], want.Ambient[c] + want.Diffuse[c] + want.Specular[c]));
          ASSERT_TRUE(close(l.L[c], want.L[c]));
          ASSERT_TRUE(close(l.HR[c], want.HR[c]));
        }
        ASSERT_TRUE(close(l.NdotL, static_cast<double>(want.NdotL)));
        ASSERT_TRUE(close(l.Base, static_cast<double>(want.Base)));
        // The terms add up to the intensity, as Illuminate adds them.
        EXPECT_EQ(got.Total(), Illuminate(in, P, N));
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
  const LightTerms t = IlluminateTerms(in, { x, 0, 0 }, N).Lights[0];
  EXPECT_TRUE(t.Reaches);
  EXPECT_NEAR(t.SpotCos, cosA, 1e-15);
  EXPECT_NEAR(t.SpotFactor, std::pow(cosA, 4), 1e-15);
  EXPECT_EQ(t.Il, (Rgb{ t.SpotFactor, t.SpotFactor, t.SpotFactor }));
  // Outside the 30-degree cone: ambient only, the cone's angle still told.
  const double far = 5 * std::tan(31 * 3.14159265358979323846 / 180);
  EXPECT_DOUBLE_EQ(Illuminate(in, { far, 0, 0 }, N)[0], 0.05);
  const LightTerms out = IlluminateTerms(in, { far, 0, 0 }, N).Lights[0];
  EXPECT_FALSE(out.Reaches);
  EXPECT_FALSE(out.Lit);
  EXPECT_NEAR(out.SpotCos, std::cos(31 * 3.14159265358979323846 / 180), 1e-15);
  EXPECT_EQ(out.SpotFactor, 0);
  EXPECT_EQ(out.DiffuseTerm, (Rgb{ 0, 0, 0 }));
}

TEST(ShadingOracle, RulesFallBackAndFlip)
{
  IlluminationInputs in = Inputs(Reflection::BlinnPhong, 10);
  in.Lights = { Directional({ 0, 0, -1 }) };
  const Vec3 P{ 0, 0, 0 };
  // A zero interpolated normal falls back to the geometric normal.
  EXPECT_EQ(
    ShadeFragment(in, P, { 0, 0, 0 }, { 0, 0, 2 }, true).Total(), Illuminate(in, P, { 0, 0, 1 }));
  // Back faces are lit with the normal flipped.
  EXPECT_EQ(
    ShadeFragment(in, P, { 0, 0, 3 }, { 0, 0, 1 }, false).Total(), Illuminate(in, P, { 0, 0, -1 }));
  // Gouraud: a zero vertex normal lights as ambient only.
  EXPECT_EQ(ShadeVertex(in, P, { 0, 0, 0 }, true).Total(), (Rgb{ 0.05, 0.1, 0.15 }));
  // Flat: the face normal from the winding, evaluated at the last vertex.
  const Rgb flat = ShadeFlat(in, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, true).Total();
  EXPECT_EQ(flat, Illuminate(in, { 0, 1, 0 }, { 0, 0, 1 }));
  EXPECT_EQ(ShadeFlat(in, { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, false).Total(),
    Illuminate(in, { 0, 1, 0 }, { 0, 0, -1 }));
}

// A triangle's fragment under each rule: where the equation runs, with which
// normal, and how gouraud mixes its vertices' colours (term by term too).
TEST(ShadingOracle, TriangleFragmentUnderEachRule)
{
  IlluminationInputs in = Inputs(Reflection::BlinnPhong, 10);
  FrameLight point;
  point.Kind = LightKind::Point;
  point.Position = { 0.3, 0.2, 2 };
  in.Lights = { point, Directional({ 0.2, -0.1, -1 }, { 0.5, 0.4, 0.3 }) };
  TriangleFragment f;
  f.Positions = { Vec3{ 0, 0, 0 }, Vec3{ 1, 0, 0.2 }, Vec3{ 0, 1, -0.1 } };
  f.Normals = { Unit({ -0.1, 0, 1 }), Unit({ 0.2, 0.1, 1 }), Unit({ 0, 0.3, 1 }) };
  f.Weights = { 0.2, 0.5, 0.3 };
  Vec3 point3{ 0, 0, 0 }, interpolated{ 0, 0, 0 };
  for (int k = 0; k < 3; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      point3[c] += f.Weights[k] * f.Positions[k][c];
      interpolated[c] += f.Weights[k] * f.Normals[k][c];
    }
  }
  const Vec3 face = Unit({ -0.2, 0.1, 1 }); // (P1 - P0) x (P2 - P0) = (-0.2, 0.1, 1)
  for (bool front : { true, false })
  {
    f.Front = front;
    const double side = front ? 1 : -1;
    // none: kd, nothing lit.
    const ShadedFragment none = ShadeTriangleFragment(in, Shading::None, f);
    EXPECT_EQ(none.Color, in.Surface.Kd);
    EXPECT_TRUE(none.Terms.Lights.empty());
    // flat: at the last vertex with the face normal, facing.
    const ShadedFragment flat = ShadeTriangleFragment(in, Shading::Flat, f);
    EXPECT_EQ(flat.Terms.P, f.Positions[2]);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(flat.FaceNormal[c], face[c], 1e-15);
      EXPECT_NEAR(flat.Terms.N[c], side * face[c], 1e-15);
      EXPECT_NEAR(flat.Point[c], point3[c], 1e-15);
    }
    EXPECT_EQ(flat.Color, flat.Terms.Total());
    // phong: at the fragment with the interpolated normal renormalised.
    const ShadedFragment phong = ShadeTriangleFragment(in, Shading::Phong, f);
    const Vec3 N = Unit(interpolated);
    const Rgb want = Illuminate(in, point3, { side * N[0], side * N[1], side * N[2] });
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(phong.Color[c], want[c], 1e-15);
    }
    EXPECT_FALSE(phong.FaceNormalFallback);
    // Normals that cancel at the fragment: the face normal, facing the viewer.
    TriangleFragment cancelling = f;
    cancelling.Normals = { Vec3{ 0, 0, 1 }, Vec3{ 0, 0, -1 }, Vec3{ 0, 0, 0 } };
    cancelling.Weights = { 0.5, 0.5, 0 };
    const ShadedFragment fallback = ShadeTriangleFragment(in, Shading::Phong, cancelling);
    EXPECT_TRUE(fallback.FaceNormalFallback);
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(fallback.Terms.N[c], side * face[c], 1e-15);
    }
    // gouraud: each vertex's colour, mixed by the weights; so are its terms.
    const ShadedFragment gouraud = ShadeTriangleFragment(in, Shading::Gouraud, f);
    Rgb mixed{ 0, 0, 0 }, diffuse{ 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      const Vec3& n = f.Normals[k];
      const IlluminationTerms vertex =
        IlluminateTerms(in, f.Positions[k], { side * n[0], side * n[1], side * n[2] });
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(gouraud.Vertices[k].Total()[c], vertex.Total()[c], 1e-15);
        mixed[c] += f.Weights[k] * vertex.Total()[c];
        diffuse[c] += f.Weights[k] * vertex.Lights[1].DiffuseTerm[c];
      }
    }
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(gouraud.Color[c], mixed[c], 1e-15);
      EXPECT_NEAR(gouraud.Terms.Total()[c], gouraud.Color[c], 1e-15);
      EXPECT_NEAR(gouraud.Terms.Lights[1].DiffuseTerm[c], diffuse[c], 1e-15);
    }
  }
}
