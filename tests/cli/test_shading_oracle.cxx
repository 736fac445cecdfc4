// The lecture's illumination model, pixel by pixel: orthographic renders of
// planar meshes by `shadelab render` against the double-precision CPU oracle,
// interior pixels only. The scenes and the oracle's pictures are
// oracle_scene.h's; this file lists the cases.
#include "oracle_scene.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <sstream>

using namespace shadelab_test;

namespace
{
std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);

  // `none`: one fixed colour, kd, exactly; with the background check this
  // also pins down the pixel mapping.
  {
    Scene s;
    s.Rule = Shading::None;
    add("none", s, { 0, 0, true });
  }

  // Each rule x each reflection model: a tilted bowl, one point light.
  for (Shading r : LitRules)
  {
    for (Reflection m : { Reflection::BlinnPhong, Reflection::Phong })
    {
      Scene s;
      s.Rule = r;
      s.Model = m;
      add(std::string(ToString(r)) + "_" + ToString(m), s);
    }
  }

  // Each light kind (point is above); a spot whose cone holds the whole mesh.
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Lights = { Directional({ -0.3, -0.2, -1 }) };
    add("directional_" + std::string(ToString(r)), s);
    s.Lights = { Spot({ 0.2, 0.1, 3 }, { -0.05, 0, -1 }, 40, 3) };
    add("spot_" + std::string(ToString(r)), s);
  }

  // Several coloured lights at once (ColouredLights), in float and 8 bits.
  const Scene coloured = ColouredLights();
  for (Shading r : LitRules)
  {
    Scene s = coloured;
    s.Rule = r;
    add("coloured_lights_" + std::string(ToString(r)), s);
    s.EightBit = true;
    add("coloured_lights_" + std::string(ToString(r)) + "_png", s);
  }
  {
    Scene s;
    s.EightBit = true;
    add("phong_blinn_png", s);
    s.Rule = Shading::Gouraud;
    s.Model = Reflection::Phong;
    add("gouraud_phong_png", s);
  }

  // Vertex colours (PLY red, green, blue) as kd under every rule: flat
  // takes the provoking vertex's, gouraud lights each vertex with its own,
  // phong and none interpolate them; --kd given overrides them.
  for (Shading r : { Shading::None, Shading::Flat, Shading::Gouraud, Shading::Phong })
  {
    Scene s = coloured;
    s.Rule = r;
    s.Geometry.VertexColors = true;
    add("vertex_colors_" + std::string(ToString(r)), s);
    s.OverrideKd = true;
    add("vertex_colors_overridden_" + std::string(ToString(r)), s);
  }

  // A mesh of three parts, each with its own material from its MTL file (one
  // without specular), under every rule and both reflection models; --kd
  // replaces the kd of every part and keeps the rest of each.
  for (Shading r : LitRules)
  {
    for (Reflection m : { Reflection::BlinnPhong, Reflection::Phong })
    {
      Scene s;
      s.Rule = r;
      s.Model = m;
      s.Parts = ThreeParts();
      add("parts_" + std::string(ToString(r)) + "_" + ToString(m), s);
    }
    Scene s = coloured;
    s.Rule = r;
    s.Parts = ThreeParts();
    s.OverrideKd = true;
    add("parts_kd_overridden_" + std::string(ToString(r)), s);
  }
  {
    Scene s;
    s.Rule = Shading::None;
    s.Parts = ThreeParts();
    add("parts_none", s, { 0, 0, true });
  }

  // A spot cone whose boundary crosses the mesh: pixels inside and outside,
  // a hard edge (exponent 0) and a soft fall-off.
  for (Shading r : LitRules)
  {
    for (double exponent : { 0.0, 4.0 })
    {
      Scene s;
      s.Rule = r;
      s.Lights = { Spot({ 0.1, -0.2, 2 }, { 0, 0, -1 }, 15, exponent) };
      add("spot_cone_" + std::string(exponent == 0 ? "hard_" : "soft_") + std::string(ToString(r)),
        s);
    }
  }

  // ns = 0 (S = ks wherever the base is positive) and ns = 1e-3, with the
  // light high enough that the specular base stays positive on the whole mesh
  // for both models (no cliff where it changes sign).
  for (double ns : { 0.0, 1e-3 })
  {
    for (Shading r : { Shading::Gouraud, Shading::Phong })
    {
      for (Reflection m : { Reflection::BlinnPhong, Reflection::Phong })
      {
        Scene s;
        s.Rule = r;
        s.Model = m;
        s.Surface = TestMaterial(ns);
        s.Lights = { Point({ 0.1, 0.2, 3 }) };
        add(
          std::string(ns == 0 ? "ns0_" : "ns0p001_") + std::string(ToString(r)) + "_" + ToString(m),
          s);
      }
    }
  }

  // ns = 1e6 on the tilted plane, its normals tilting by 2e-3 per unit off
  // the centre, under a directional light mirrored about the normal at
  // (-0.25, -0.125) (so that H and R meet N there): the highlight's 1%
  // contour is some 60 (Blinn) and 30 (Phong) pixels across.
  for (Shading r : LitRules)
  {
    for (Reflection m : { Reflection::BlinnPhong, Reflection::Phong })
    {
      Scene s;
      s.Rule = r;
      s.Model = m;
      s.Surface = TestMaterial(1e6);
      s.Geometry.Bump = -2e-3;
      const Vec3 n = GridNormal(s.Geometry, -0.25, -0.125);
      s.Lights = { Directional(Vec3{ 0, 0, 1 } - 2 * n[2] * n) }; // -(2(N.V)N - V)
      add("ns1e6_" + std::string(ToString(r)) + "_" + ToString(m), s, HighExponent);
    }
  }

  // Grazing light: N.L = 1e-4 on a flat plane with the face normal.
  for (Shading r : LitRules)
  {
    for (Reflection m : { Reflection::BlinnPhong, Reflection::Phong })
    {
      Scene s;
      s.Rule = r;
      s.Model = m;
      s.Surface = TestMaterial(2);
      s.Geometry.SlopeX = s.Geometry.SlopeY = s.Geometry.Bump = 0;
      s.Lights = { Directional({ -std::sqrt(1 - 1e-8), 0, -1e-4 }) };
      add("grazing_" + std::string(ToString(r)) + "_" + ToString(m), s);
    }
  }

  // Lights in the surface's plane (N.L = 0 exactly): ambient only, no
  // specular, for a point and a directional light.
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Geometry.SlopeX = s.Geometry.SlopeY = s.Geometry.Bump = 0;
    s.Lights = { Point({ 1.5, 0.25, 0 }), Directional({ -1, 0.5, 0 }) };
    add("light_in_plane_" + std::string(ToString(r)), s);
  }

  // The same on the tilted plane, whose normal (-0.25, 0.125, 1) is not an
  // axis: N.L = 0 is no longer exact in floating point.
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Geometry.Bump = 0;
    s.Lights = { Point({ 1.5, 0.25, 0.25 * 1.5 - 0.125 * 0.25 }), Directional({ -1, 0, -0.25 }) };
    add("light_in_tilted_plane_" + std::string(ToString(r)), s);
  }

  // A point light exactly at a grid vertex, (0.5, 0.5) on the tilted bowl:
  // it adds nothing there (no direction), and lights the bowl around it.
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Lights = { Point({ 0.5, 0.5, 0.25 * 0.5 - 0.125 * 0.5 }) };
    add("light_at_vertex_" + std::string(ToString(r)), s);
  }

  // Zero-length vertex normals: one lone vertex, a corner, and the four
  // corners of cell (3, 3), whose two triangles' interpolated normal is 0
  // everywhere (phong: the geometric normal; gouraud: ambient at those
  // vertices; flat: unaffected).
  Scene zeroNormals;
  zeroNormals.Geometry.ZeroNormals = { { 1, 2 }, { 0, 0 }, { 3, 3 }, { 4, 3 }, { 3, 4 }, { 4, 4 } };
  for (Shading r : LitRules)
  {
    Scene s = zeroNormals;
    s.Rule = r;
    add("zero_normals_" + std::string(ToString(r)), s,
      r == Shading::Phong ? DerivativeNormal : Standard);
  }
  // The same, the camera ten times farther away: where the geometric normal
  // is used it must not lose accuracy with the distance (orthographic: the
  // picture is otherwise the same).
  {
    Scene s = zeroNormals;
    s.CameraDistance = 100;
    add("zero_normals_far_camera_phong", s, DerivativeNormal);
  }

  // Back faces: the same bowl wound clockwise with normals pointing away;
  // two-sided lighting lights them as the front.
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Geometry.BackFaces = true;
    add("back_faces_" + std::string(ToString(r)), s);
  }

  // The coloured scene at 1e-6 and 1e6 and offset by 1e5 from the origin
  // lights as at unit scale (the oracle's answers agree to double precision).
  for (Shading r : LitRules)
  {
    Scene s = coloured;
    s.Rule = r;
    s.Scale = 1e-6;
    add("scale_1em6_" + std::string(ToString(r)), s);
    s.Scale = 1e6;
    add("scale_1e6_" + std::string(ToString(r)), s);
    s.Scale = 1;
    s.Offset = { 1e5, 1e5, 1e5 };
    add("offset_1e5_" + std::string(ToString(r)), s);
  }

  // Distance attenuation: each rule and reflection model with a point light
  // whose Il falls to about a quarter across the mesh; every light kind at
  // once, one point light with attenuation of its own and the directional
  // light unaffected; in 8 bits; and at 1e-6 and 1e6 world units, the
  // coefficients scaled so that the picture stays the same.
  for (Shading r : LitRules)
  {
    for (Reflection m : { Reflection::BlinnPhong, Reflection::Phong })
    {
      Scene s;
      s.Rule = r;
      s.Model = m;
      s.Attenuation = { 0.25, 0.5, 0.75 };
      add("attenuation_" + std::string(ToString(r)) + "_" + ToString(m), s);
    }
    Scene s = coloured;
    s.Rule = r;
    s.Attenuation = { 1, 0.5, 0.25 };
    s.Lights.back().Attenuation = Vec3{ 0.125, 0, 2 };
    add("attenuation_light_kinds_" + std::string(ToString(r)), s);
    if (r != Shading::Gouraud)
    {
      for (double scale : { 1e-6, 1e6 })
      {
        s.Scale = scale;
        add("attenuation_scale_" + std::string(scale < 1 ? "1em6_" : "1e6_") + ToString(r), s);
      }
    }
  }
  {
    Scene s = coloured;
    s.Attenuation = { 0.25, 0.5, 0.75 };
    s.EightBit = true;
    add("attenuation_png", s);
  }

  // Fog, per fragment under every rule: each mode over the tilted bowl,
  // whose depth runs from about 9.6 to 10.4 (the camera 10 above it), so
  // that the factor changes across the picture; towards the background
  // (black) and towards a colour of its own; in 8 bits; and at 1e-6 and 1e6
  // units with depths and density scaled alike.
  shadelab::Fog linear, exp, exp2;
  linear.Mode = shadelab::FogMode::Linear;
  linear.Start = 9.5;
  linear.End = 10.75;
  exp.Mode = shadelab::FogMode::Exp;
  exp.Density = 0.1;
  exp2.Mode = shadelab::FogMode::Exp2;
  exp2.Density = 0.09;
  exp2.Color = Rgb{ 0.5, 0.625, 0.75 };
  for (Shading r : LitRules)
  {
    for (const auto& [name, fog] : { std::pair{ "linear", linear }, std::pair{ "exp", exp },
           std::pair{ "exp2_coloured", exp2 } })
    {
      Scene s = coloured;
      s.Rule = r;
      s.Fog = fog;
      add("fog_" + std::string(name) + "_" + ToString(r), s);
    }
  }
  {
    Scene s = coloured;
    s.Rule = Shading::Gouraud;
    s.Fog = linear;
    s.EightBit = true;
    add("fog_linear_gouraud_png", s);
    s.EightBit = false;
    s.Rule = Shading::Phong;
    for (double scale : { 1e-6, 1e6 })
    {
      s.Scale = scale;
      s.Fog = exp2;
      add("fog_exp2_scale_" + std::string(scale < 1 ? "1em6" : "1e6"), s);
    }
  }

  return cases;
}

class ShadingOracle : public testing::TestWithParam<Case>
{
};
}

TEST_P(ShadingOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, ShadingOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });

// True per-vertex lighting: a point light close above the middle of one large
// quad (two triangles) makes a highlight in the middle of a Phong render; the
// Gouraud render interpolates the corners' colours, which the highlight does
// not reach, so its middle is no brighter than its corners.
TEST(ShadingShape, GouraudHasNoHighlightInTheMiddleOfALargeQuadWherePhongHasOne)
{
  Scene s;
  s.Geometry.Cells = 1;
  s.Geometry.SlopeX = s.Geometry.SlopeY = s.Geometry.Bump = 0;
  s.Surface.Kd = { 0.3, 0.3, 0.3 };
  s.Surface.Ks = { 0.8, 0.8, 0.8 };
  s.Surface.Ns = 50;
  s.Lights = { Point({ 0, 0, 0.5 }) };
  s.Size = 97; // odd: pixel (48, 48) is centred on the quad's middle
  // Pixels 6 and 90 are centred at -/+0.953, 2 pixels inside the quad's corners.
  const std::array<std::array<int, 2>, 4> corners{ { { 6, 6 }, { 90, 6 }, { 6, 90 }, { 90, 90 } } };
  std::map<Shading, std::pair<double, double>> middleAndCorner; // green channel
  for (Shading rule : { Shading::Gouraud, Shading::Phong })
  {
    s.Rule = rule;
    TempDir dir;
    std::string error;
    const Image image = Render(s, dir, error);
    ASSERT_EQ(error, "");
    double corner = 0;
    for (const auto& xy : corners)
    {
      corner = std::max(corner, Got(image, xy[0], xy[1])[1]);
    }
    middleAndCorner[rule] = { Got(image, 48, 48)[1], corner };
  }
  const auto [gouraudMiddle, gouraudCorner] = middleAndCorner[Shading::Gouraud];
  const auto [phongMiddle, phongCorner] = middleAndCorner[Shading::Phong];
  std::ostringstream numbers;
  numbers << "middle/brightest corner: gouraud " << gouraudMiddle << "/" << gouraudCorner
          << ", phong " << phongMiddle << "/" << phongCorner;
  std::cout << "[oracle] shape: " << numbers.str() << std::endl;
  // Phong: ka*Ia + kd + ks = 1.16 in the middle against 0.17 at the corners.
  EXPECT_GT(phongMiddle, 3 * phongCorner) << numbers.str();
  // Gouraud: the middle interpolates two corners' colours (the diagonal);
  // 1e-4 relative for float rounding.
  EXPECT_LE(gouraudMiddle, gouraudCorner * (1 + 1e-4)) << numbers.str();
}