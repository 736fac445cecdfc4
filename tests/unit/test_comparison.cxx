// The comparison's pieces: modes parsed onto the base scene,
// terms split by zeroing coefficients, --diff resolved, the difference of
// two pictures and its heat map, and the layout.
#include "image/comparison_picture.h"
#include "scene/comparison_panels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace shadelab;

TEST(Comparison, ModesChangeTheBaseSceneAndSayHowInTheirLabels)
{
  SceneOptions base;
  base.MaterialName = "brass";
  base.Ns = 5;
  const std::vector<Panel> panels =
    ParseModes("flat,phong:material=gold:reflection=phong,weighting=area,gouraud:ns=2", base);
  ASSERT_EQ(panels.size(), 4u);
  EXPECT_EQ(panels[0].Scene.ShadingRule, Shading::Flat);
  EXPECT_EQ(panels[0].Scene.MaterialName, "brass");
  EXPECT_EQ(panels[0].Label, "flat");
  EXPECT_EQ(panels[1].Scene.MaterialName, "gold");
  EXPECT_EQ(panels[1].Scene.ReflectionModel, Reflection::Phong);
  EXPECT_EQ(panels[1].Label, "phong, material gold, reflection phong");
  EXPECT_EQ(panels[2].Scene.ShadingRule, base.ShadingRule) << "no rule: the base's";
  EXPECT_EQ(panels[2].Scene.Computed.Weighting, "area");
  EXPECT_EQ(panels[3].Scene.Ns, 2);
  EXPECT_EQ(panels[3].Mode, "gouraud:ns=2");
}

TEST(Comparison, BadModesSayWhichAndWhy)
{
  const SceneOptions base;
  for (const auto& [modes, says] :
    std::vector<std::pair<std::string, std::string>>{ { "phong,", "mode '': is empty" },
      { "shiny", "mode 'shiny'" }, { "phong:ka=1", "'ka=1' is not KEY=VALUE" },
      { "phong:material", "is not KEY=VALUE" }, { "phong:ns=-1", "negative" },
      { "phong:weighting=heavy", "mode 'phong:weighting=heavy'" } })
  {
    try
    {
      ParseModes(modes, base);
      ADD_FAILURE() << modes << " was taken";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
}

TEST(Comparison, TermsZeroTheOtherCoefficients)
{
  SceneOptions base;
  base.MaterialName = "gold";
  const std::vector<Panel> split = SplitIntoTerms(ParseModes("phong", base));
  ASSERT_EQ(split.size(), 4u);
  const Material gold = base.EffectiveMaterial();
  const Rgb zero{ 0, 0, 0 };
  const Material ambient = split[0].Scene.EffectiveMaterial();
  EXPECT_EQ(ambient.Ka, gold.Ka);
  EXPECT_EQ(ambient.Kd, zero);
  EXPECT_EQ(ambient.Ks, zero);
  const Material diffuse = split[1].Scene.EffectiveMaterial();
  EXPECT_EQ(diffuse.Ka, zero);
  EXPECT_EQ(diffuse.Kd, gold.Kd);
  EXPECT_EQ(diffuse.Ks, zero);
  const Material specular = split[2].Scene.EffectiveMaterial();
  EXPECT_EQ(specular.Kd, zero);
  EXPECT_EQ(specular.Ks, gold.Ks);
  const Material total = split[3].Scene.EffectiveMaterial();
  EXPECT_EQ(total.Ka, gold.Ka);
  EXPECT_EQ(total.Kd, gold.Kd);
  EXPECT_EQ(total.Ks, gold.Ks);
  EXPECT_EQ(split[2].Label, "phong: specular");
  EXPECT_EQ(split[3].Label, "phong: total");
}

TEST(Comparison, DifferenceNamesModesByTextOrNumber)
{
  ComparisonOptions o;
  o.Modes = "flat,gouraud,phong";
  o.Difference = "phong,1";
  Comparison c = PlanComparison(o, SceneOptions{});
  EXPECT_EQ(c.DifferenceA, 2);
  EXPECT_EQ(c.DifferenceB, 0);
  EXPECT_EQ(c.DifferenceLabel, "|phong - flat|");
  o.Components = true;
  c = PlanComparison(o, SceneOptions{});
  EXPECT_EQ(c.Panels.size(), 12u);
  EXPECT_EQ(c.Columns, 4);
  EXPECT_EQ(c.DifferenceA, 11) << "phong's total";
  EXPECT_EQ(c.DifferenceB, 3) << "flat's total";
  for (const std::string bad :
    { "phong", "phong,gouraud,flat", "phong,4", "phong,0", "phong,Phong" })
  {
    o.Difference = bad;
    EXPECT_THROW(PlanComparison(o, SceneOptions{}), std::invalid_argument) << bad;
  }
}

TEST(Comparison, DifferenceIsTheLargestChannelOfWhatEightBitPicturesShow)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  FloatImage a{ 4, 1,
    { 0.5f, 0.5f, 0.5f, 1, /**/ 2.0f, 0, 0, 1, /**/ nan, 0, 0, 1, /**/ 0.1f, 0.9f, 0.2f, 1 } };
  FloatImage b{ 4, 1,
    { 0.5f, 0.5f, 0.5f, 1, /**/ 1.0f, 0, 0, 1, /**/ 0, 0, 0, 1, /**/ 0.1f, 0.5f, 0.0f, 1 } };
  const Difference d = CompareImages(a, b);
  EXPECT_EQ(d.Largest, std::fabs(0.9f - 0.5f)) << "the green channel of the last pixel";
  EXPECT_EQ(d.Differing, 1) << "2 and 1 both show as 1; NaN shows as 0";
  EXPECT_NEAR(d.Mean, 0.4 / 4, 1e-7);
  const Rgb black{ 0, 0, 0 }, white{ 1, 1, 1 };
  EXPECT_EQ(HeatColour(0), black);
  EXPECT_EQ(HeatColour(1), white);
  double previous = -1;
  for (int i = 0; i <= 100; ++i) // brightness rises with the difference
  {
    const Rgb c = HeatColour(i / 100.0);
    EXPECT_GT(c[0] + c[1] + c[2], previous) << i;
    previous = c[0] + c[1] + c[2];
  }
  EXPECT_EQ(d.Heat.Rgba[0], 0) << "no difference: black";
  EXPECT_EQ(d.Heat.Rgba[12], 1) << "the largest: white";
}

TEST(Comparison, LayoutRowUpToFourThenAGrid)
{
  const ComparisonLayout three = LayOut(3, 100, 50, 0, false);
  EXPECT_EQ(three.Columns, 3);
  EXPECT_EQ(three.Rows, 1);
  EXPECT_EQ(three.Width, 3 * (100 + CellGap) + CellGap);
  EXPECT_EQ(three.Height, LabelStripHeight + 50 + CellGap);
  EXPECT_EQ(three.PanelX(2), CellGap + 2 * (100 + CellGap));
  const ComparisonLayout five = LayOut(5, 100, 50, 0, true);
  EXPECT_EQ(five.Columns, 3);
  EXPECT_EQ(five.Rows, 2);
  EXPECT_EQ(five.PanelY(4), LabelStripHeight + 50 + CellGap + LabelStripHeight);
  EXPECT_EQ(five.Height, 2 * (LabelStripHeight + 50 + CellGap) + ColourBarStripHeight);
  EXPECT_EQ(LayOut(9, 10, 10, 4, false).Rows, 3);
}
