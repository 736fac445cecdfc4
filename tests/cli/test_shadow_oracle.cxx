// Shadows against the double-precision oracle (doc/design.md, "Shadows"):
// a square over the grid casts a shadow on it under each kind of light and
// every rule that lights, and the picture drawn with shadow maps equals the
// oracle's, whose shadow rays (shadelabRayScene) decide each light's
// visibility at the point the rule lights: the fragment (phong), each
// vertex (gouraud), the provoking vertex (flat). Pixels lit at a point in
// the band around a shadow's edge, where a map's texel may decide
// otherwise, are left out and counted; each case must show a shadow.
// A wall's shadow starting at its foot (peter-panning); a torus shadowing
// itself; a closed box lit from behind. Three lights at once; scenes far from the origin,
// tiny and huge; a small map, whose wider band is left out.
#include "oracle_scene.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

namespace
{
Scene Shadowed(const Light& light, Shading rule)
{
  Scene s;
  s.Geometry.Cells = 12;
  s.Size = 192; // cells of 16 pixels: enough of each lies away from its edges
  s.Geometry.Occluder = true;
  s.Shadows = true;
  s.Lights = { light };
  s.Rule = rule;
  return s;
}

std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);
  // Oblique enough that the camera, looking straight down, sees much of
  // each shadow beside the square.
  const std::pair<const char*, Light> lights[] = { { "point", Point({ 0.6, 0.6, 1.4 }) },
    { "directional", Directional({ -0.9, -0.7, -1 }) },
    { "spot", Spot({ 0.6, 0.6, 1.4 }, { -0.5, -0.5, -1 }, 50, 1) } };
  for (const auto& [name, light] : lights)
  {
    for (Shading r : LitRules)
    {
      add(std::string(name) + "_" + ToString(r), Shadowed(light, r));
    }
  }
  {
    Scene s = Shadowed(Point({ 0.6, 0.6, 1.4 }, { 1, 0.2, 0.1 }), Shading::Phong);
    s.Lights.push_back(Directional({ -0.9, -0.7, -1 }, { 0.1, 0.9, 0.2 }));
    s.Lights.push_back(Spot({ -0.5, 0.7, 1.6 }, { 0.3, -0.4, -1 }, 60, 2, { 0.2, 0.3, 1 }));
    add("coloured_lights_phong", s);
    s.Rule = Shading::Gouraud;
    add("coloured_lights_gouraud", s);
  }
  for (const auto& [name, scale, offset] :
    { std::tuple{ "far_from_origin", 1.0, Vec3{ 1e5, -2e5, 5e4 } },
      std::tuple{ "tiny", 1e-4, Vec3{ 0, 0, 0 } }, std::tuple{ "huge", 1e4, Vec3{ 0, 0, 0 } } })
  {
    Scene s = Shadowed(Point({ 0.6, 0.6, 1.4 }), Shading::Phong);
    s.Scale = scale;
    s.Offset = offset;
    add(std::string(name) + "_phong", s);
  }
  for (Shading r : LitRules)
  {
    // Peter-panning: the shadow of a wall starts at its foot.
    Scene s = Shadowed(Point({ -0.1, 1.0, 0.9 }), r);
    s.Geometry.Occluder = false;
    s.Geometry.Wall = true;
    add(std::string("wall_") + ToString(r), s);
  }
  for (Shading r : { Shading::Flat, Shading::Gouraud, Shading::Phong })
  {
    // Self-shadowing: the torus's upper half shadows the inside of its
    // lower half. Under phong, at the terminator the interpolated normal
    // leans towards the light where the faces turn away from it: the
    // map's slope bias must be the face's (doc/design.md, "Shadows").
    Scene s = Shadowed(Directional({ 0.4, -1, -0.15 }), r);
    s.Geometry.Occluder = false;
    s.Geometry.Torus = true;
    s.ShadowedAtLeast = 50; // a smaller shadow than the square's
    add(std::string("torus_") + ToString(r), s);
  }
  {
    // A closed mesh lit from behind: the faces the camera sees face away
    // from the light, and nothing of it comes through.
    Scene s = Shadowed(Point({ 0.3, 0.2, -2.5 }), Shading::Phong);
    s.Geometry.Occluder = false;
    s.Geometry.Box = true;
    s.ShadowedAtLeast = 0; // N.L < 0 already: no light, and no shadow
    add("box_lit_from_behind_phong", s);
  }
  {
    Scene s = Shadowed(Directional({ -0.9, -0.7, -1 }), Shading::Phong);
    s.ShadowMapSize = 256;
    add("small_map_phong", s);
  }
  return cases;
}

class ShadowOracle : public testing::TestWithParam<Case>
{
};
}

TEST_P(ShadowOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, ShadowOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });
