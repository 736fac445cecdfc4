// Translucency against the double-precision oracle (doc/design.md,
// "Translucency"): every surface under a pixel composited as a*I +
// (1-a)*behind in depth order. Three sheets of the grid one behind the
// other, written in every order (the picture must not depend on it); a
// closed cube whose far faces show through its near ones, lit as back
// faces; translucent parts (MTL d) beside and in front of opaque ones;
// --peels keeping only the nearest layers; each rule, 8 bits too; a
// transparent background's alpha, the coverage; and fog towards it, which
// takes coverage away and is composited the same way.
#include "oracle_scene.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

namespace
{
std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);
  Scene sheets = ColouredLights();
  sheets.Geometry.VertexColors = true; // each sheet its own colours: a wrong order shows
  sheets.Translucency = 0.5;
  std::vector<int> order{ 0, 1, 2 };
  do
  {
    Scene s = sheets;
    s.Geometry.Sheets = order;
    add("sheets_" + std::to_string(order[0]) + std::to_string(order[1]) + std::to_string(order[2]) +
        "_phong",
      s);
  } while (std::next_permutation(order.begin(), order.end()));
  sheets.Geometry.Sheets = { 2, 0, 1 };
  for (Shading r : { Shading::None, Shading::Flat, Shading::Gouraud })
  {
    Scene s = sheets;
    s.Rule = r;
    add(std::string("sheets_") + ToString(r), s);
  }
  {
    Scene s = sheets;
    s.Translucency = 0.2;
    s.Model = Reflection::Phong;
    add("sheets_a02_phong_reflection", s);
    s.Translucency = 0;
    add("sheets_a0_background", s); // nothing shows
    s.Translucency = 0.5;
    s.EightBit = true;
    add("sheets_png", s);
  }
  for (int peels : { 1, 2 })
  {
    Scene s = sheets;
    s.Peels = peels;
    add("sheets_" + std::to_string(peels) + "_peels", s);
  }
  for (Shading r : LitRules)
  {
    Scene s = ColouredLights();
    s.Geometry.Box = true;
    s.Rule = r;
    s.Translucency = 0.4;
    add(std::string("box_") + ToString(r), s);
  }
  {
    Scene s = ColouredLights();
    s.Geometry.Box = true;
    s.Geometry.VertexColors = true;
    s.Translucency = 0.7;
    add("box_vertex_colours_phong", s);
  }
  {
    // Parts of their own a (MTL d) beside opaque ones, on two sheets: the
    // near sheet's translucent cells over the far sheet's opaque and
    // translucent ones.
    Scene s = ColouredLights();
    s.Parts = ThreeParts();
    s.Parts[0].Translucency = 0.5;
    s.Parts[2].Translucency = 0.25;
    s.Geometry.Sheets = { 1, 0 };
    add("parts_beside_opaque_phong", s);
    s.Rule = Shading::Gouraud;
    add("parts_beside_opaque_gouraud", s);
  }
  {
    // A transparent background: the alpha is the coverage, 1 - (1-a)^n.
    Scene s = sheets;
    s.TransparentBackground = true;
    add("sheets_transparent_background", s);
    // Fog towards it: each fragment's a times the fog's factor (an opaque
    // cube's far faces then show through its near ones), composited in
    // depth order.
    s.Fog.Mode = shadelab::FogMode::Linear;
    s.Fog.Start = 9;
    s.Fog.End = 13;
    s.Rule = Shading::Gouraud;
    add("sheets_fog_towards_transparent_gouraud", s);
    Scene box = ColouredLights();
    box.Geometry.Box = true;
    box.TransparentBackground = true;
    box.Fog.Mode = shadelab::FogMode::Exp;
    box.Fog.Density = 0.08;
    for (Shading r : LitRules)
    {
      box.Rule = r;
      add(std::string("opaque_box_fog_towards_transparent_") + ToString(r), box);
    }
  }
  return cases;
}

class TranslucencyOracle : public testing::TestWithParam<Case>
{
};
}

TEST_P(TranslucencyOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, TranslucencyOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });
