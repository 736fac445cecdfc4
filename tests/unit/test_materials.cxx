// The lecture's material table, compiled in from data/materials.json, must
// carry the lecture's numbers verbatim (the course text, class 6).
#include "shadelabIllumination.h"

#include <gtest/gtest.h>

using namespace shadelab;

TEST(Materials, TheLecturesTableInItsOrder)
{
  const auto& table = LectureMaterials();
  std::vector<std::string> names;
  for (const Material& m : table)
  {
    names.push_back(m.Name);
  }
  EXPECT_EQ(names,
    (std::vector<std::string>{ "brass", "bronze", "polished-bronze", "chrome", "copper",
      "polished-copper", "gold", "polished-gold" }));
}

TEST(Materials, NumbersVerbatim)
{
  // Spot checks across the table, typed in from the lecture independently.
  const Material* brass = FindLectureMaterial("brass");
  ASSERT_NE(brass, nullptr);
  EXPECT_EQ(brass->Ka, (Rgb{ 0.329412, 0.223529, 0.027451 }));
  EXPECT_EQ(brass->Kd, (Rgb{ 0.780392, 0.568627, 0.113725 }));
  EXPECT_EQ(brass->Ks, (Rgb{ 0.992157, 0.941176, 0.807843 }));
  EXPECT_EQ(brass->Ns, 27.8974);
  const Material* copper = FindLectureMaterial("polished-copper");
  ASSERT_NE(copper, nullptr);
  EXPECT_EQ(copper->Ks, (Rgb{ 0.580594, 0.223257, 0.0695701 }));
  EXPECT_EQ(copper->Ns, 51.2);
  const Material* gold = FindLectureMaterial("polished-gold");
  ASSERT_NE(gold, nullptr);
  EXPECT_EQ(gold->Kd, (Rgb{ 0.34615, 0.3143, 0.0903 }));
  EXPECT_EQ(gold->Ns, 83.2);
  for (const Material& m : LectureMaterials())
  {
    EXPECT_EQ(m.Translucency, 1.0) << m.Name;
  }
  EXPECT_EQ(FindLectureMaterial("unobtainium"), nullptr);
}
