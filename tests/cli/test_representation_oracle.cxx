// The lecture's cheaper pictures against the double-precision oracle
// (doc/design.md, "Representations"): the grid's edges and points, each
// drawn once, lit by each rule with the normal turned towards the viewer
// (flat: the owning triangle's face normal); compared at the centres of the
// pixels drawn, away from where an element's coverage ends (ElementMargin),
// and the background away from every element.
#include "oracle_scene.h"

#include <gtest/gtest.h>

using namespace shadelab_test;
using shadelab::Representation;

namespace
{
std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);
  const Scene coloured = ColouredLights();
  for (Shading r : LitRules)
  {
    for (Representation d : { Representation::Wireframe, Representation::Points })
    {
      Scene s = coloured;
      s.Rule = r;
      s.Drawn = d;
      s.Pixels = d == Representation::Points ? 9 : 3;
      add(std::string(ToString(d)) + "_" + ToString(r), s);
      // Normals pointing away from the camera: turned towards it, as a
      // back face's are.
      s.Geometry.BackFaces = true;
      add(std::string(ToString(d)) + "_back_" + ToString(r), s);
    }
  }
  {
    Scene s = coloured;
    s.Drawn = Representation::Wireframe;
    s.Rule = Shading::None;
    add("wireframe_none", s, { 0, 0, true });
    s.Rule = Shading::Phong;
    s.Pixels = 1;
    s.Size = 256; // enough pixels on lines one wide
    add("wireframe_1px_phong", s);
    s.Size = Scene{}.Size;
    s.Pixels = 2;
    s.Model = Reflection::Phong;
    s.EightBit = true;
    add("wireframe_2px_phong_png", s);
    // A vertex of no normal: its points and the phong fragments near it
    // are lit by ka*Ia alone.
    s = coloured;
    s.Drawn = Representation::Points;
    s.Pixels = 9;
    s.Geometry.ZeroNormals = { { 2, 2 }, { 1, 3 } };
    add("points_zero_normals_phong", s);
    s.Rule = Shading::Gouraud;
    add("points_zero_normals_gouraud", s);
    // Vertex colours and a texture, per fragment on an edge too.
    s = coloured;
    s.Drawn = Representation::Wireframe;
    s.Geometry.VertexColors = true;
    s.Rule = Shading::Flat;
    add("wireframe_vertex_colours_flat", s);
    s.Geometry.VertexColors = false;
    s.Textured = true;
    s.Rule = Shading::Gouraud;
    add("wireframe_textured_gouraud", s);
  }
  return cases;
}

class RepresentationOracle : public testing::TestWithParam<Case>
{
};
}

TEST_P(RepresentationOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, RepresentationOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });
