// The option-value parsers of the command line (app/core/options.h).
#include "core/options.h"
#include "settings/command_line.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using namespace shadelab;

namespace
{
// Each text refused by parse with a message holding its words.
template <typename Parse>
void ExpectRefused(Parse parse, const std::vector<std::pair<std::string, std::string>>& cases)
{
  for (const auto& [text, words] : cases)
  {
    try
    {
      parse(text);
      ADD_FAILURE() << text << " was accepted";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << text << ": " << e.what();
    }
  }
}
}

TEST(Options, NumbersAreFiniteAndWhole)
{
  EXPECT_DOUBLE_EQ(ParseNumber("1e-3"), 1e-3);
  EXPECT_DOUBLE_EQ(ParseNumber("+2.5"), 2.5);
  EXPECT_DOUBLE_EQ(ParseNumber("-0.25"), -0.25);
  for (const char* bad : { "", "nan", "inf", "-inf", "1.5x", "x", "1,2", " 1", "1e999" })
  {
    EXPECT_THROW(ParseNumber(bad), std::invalid_argument) << bad;
  }
}

TEST(Options, ColoursAreThreeNonNegativeNumbers)
{
  EXPECT_EQ(ParseRgb("0.5,1,2.5"), (Rgb{ 0.5, 1, 2.5 }));
  for (const char* bad : { "1,2", "1,2,3,4", "1,-1,0", "a,b,c", "1,,2", "nan,0,0" })
  {
    EXPECT_THROW(ParseRgb(bad), std::invalid_argument) << bad;
  }
  EXPECT_EQ(ParseVec3("-1,0,1e5"), (Vec3{ -1, 0, 1e5 }));
}

TEST(Options, SizesAreBounded)
{
  const ImageSize s = ParseSize("1920x1080");
  EXPECT_EQ(s.Width, 1920);
  EXPECT_EQ(s.Height, 1080);
  EXPECT_EQ(ParseSize("1X1").Width, 1);
  EXPECT_EQ(ParseSize("8192x8192").Height, 8192);
  for (const char* bad : { "0x10", "10x0", "-5x5", "16385x1", "16384x16384", "1920", "x", "1920x",
         "19.5x10", "1920x1080x3", "axb" })
  {
    EXPECT_THROW(ParseSize(bad), std::invalid_argument) << bad;
  }
}

TEST(Options, Pixel)
{
  const Pixel p = ParsePixel("12,0");
  EXPECT_EQ(p.X, 12);
  EXPECT_EQ(p.Y, 0);
  EXPECT_EQ(ParsePixel("16383,16383").Y, 16383);
  for (const char* bad : { "", "1", "1,", ",1", "-1,3", "3,-1", "+1,2", "1.5,2", "1,2,3", "a,b",
         " 1,2", "1,2 ", "99999999999,1" })
  {
    EXPECT_THROW(ParsePixel(bad), std::invalid_argument) << bad;
  }
}

TEST(Options, PointAndDirectionalLights)
{
  const Light p = ParseLight("point:1,2,3");
  EXPECT_EQ(p.Kind, LightKind::Point);
  EXPECT_EQ(p.Position, (Vec3{ 1, 2, 3 }));
  EXPECT_EQ(p.Color, (Rgb{ 1, 1, 1 })) << "a light's colour defaults to white";
  const Light d = ParseLight("directional:0,-1,0:0.5,0.5,1");
  EXPECT_EQ(d.Kind, LightKind::Directional);
  EXPECT_EQ(d.Direction, (Vec3{ 0, -1, 0 }));
  EXPECT_EQ(d.Color, (Rgb{ 0.5, 0.5, 1 }));
}

TEST(Options, SpotLights)
{
  const Light s = ParseLight("spot:0,0,5:0,0,-1:30");
  EXPECT_EQ(s.Kind, LightKind::Spot);
  EXPECT_EQ(s.Position, (Vec3{ 0, 0, 5 }));
  EXPECT_EQ(s.Direction, (Vec3{ 0, 0, -1 }));
  EXPECT_DOUBLE_EQ(s.HalfAngleDeg, 30);
  EXPECT_DOUBLE_EQ(s.Exponent, 0) << "a spot's exponent defaults to 0 (hard-edged cone)";
  const Light e = ParseLight("spot:0,0,5:0,0,-1:45:8:1,0,0");
  EXPECT_DOUBLE_EQ(e.Exponent, 8);
  EXPECT_EQ(e.Color, (Rgb{ 1, 0, 0 }));
}

TEST(Options, AttenuationIsTheScenesOrALightsOwn)
{
  EXPECT_EQ(ParseAttenuation("1,0.5,0.25"), (Vec3{ 1, 0.5, 0.25 }));
  EXPECT_EQ(ParseAttenuation("0,0,1e-6"), (Vec3{ 0, 0, 1e-6 })) << "one coefficient suffices";
  EXPECT_FALSE(ParseLight("point:1,2,3").Attenuation) << "none of its own: the scene's";
  EXPECT_EQ(ParseLight("point:1,2,3@1,0,2").Attenuation, (Vec3{ 1, 0, 2 }));
  const Light spot = ParseLight("spot:0,0,5:0,0,-1:45:8:1,0,0@0,1,0");
  EXPECT_EQ(spot.Color, (Rgb{ 1, 0, 0 }));
  EXPECT_EQ(spot.Attenuation, (Vec3{ 0, 1, 0 }));
  const std::vector<std::pair<std::string, std::string>> bad{
    { "1,0", "C0,C1,C2" },
    { "1,-1,0", "negative" },
    { "0,0,0", "all zero" },
    { "1,nan,0", "not a finite number" },
  };
  ExpectRefused(ParseAttenuation, bad);
  std::vector<std::pair<std::string, std::string>> own;
  for (const auto& [text, words] : bad)
  {
    own.emplace_back("point:1,2,3@" + text, words);
  }
  ExpectRefused(ParseLight, own);
}

TEST(Options, FogModesAndTheirNumbers)
{
  EXPECT_EQ(ParseFog("none").Mode, FogMode::None);
  const Fog linear = ParseFog("linear:2,10");
  EXPECT_EQ(linear.Mode, FogMode::Linear);
  EXPECT_EQ(linear.Start, 2);
  EXPECT_EQ(linear.End, 10);
  EXPECT_FALSE(linear.Color) << "no colour: the background's";
  const Fog exp2 = ParseFog("exp2:0.25:0.5,0.5,1");
  EXPECT_EQ(exp2.Mode, FogMode::Exp2);
  EXPECT_EQ(exp2.Density, 0.25);
  EXPECT_EQ(exp2.Color, (Rgb{ 0.5, 0.5, 1 }));
  EXPECT_EQ(ParseFog("exp:0").Density, 0) << "no fog at all, but a valid one";
  ExpectRefused(ParseFog,
    {
      { "mist:1", "unknown fog 'mist'" },
      { "linear:10,2", "fog END '2' is not beyond START '10'" },
      { "linear:3,3", "not beyond" },
      { "linear:1", "START,END" },
      { "exp:-0.1", "fog density '-0.1' is negative" },
      { "exp2", "exp2:DENSITY" },
      { "exp:1:1,1", "R,G,B" },
      { "none:1", "is not none" },
      { "exp:1:1,1,1:extra", "is not none" },
    });
}

TEST(Options, BadLightsNameTheProblem)
{
  ExpectRefused(ParseLight,
    {
      { "laser:1,2,3", "unknown light kind" },
      { "point", "point:X,Y,Z" },
      { "point:1,2", "X,Y,Z" },
      { "point:1,2,3:1,1", "R,G,B" },
      { "directional:0,0,0", "zero length" },
      { "spot:0,0,5:0,0,-1", "HALF_ANGLE" },
      { "spot:0,0,5:0,0,-1:0", "half-angle" },
      { "spot:0,0,5:0,0,-1:91", "half-angle" },
      { "spot:0,0,5:0,0,-1:30:-1", "negative" },
      { "spot:0,0,5:0,0,-1:30:1:1,1,1:extra", "spot:" },
      { "directional:0,0,-1@1,0,1", "no attenuation" },
    });
}

TEST(Options, OverridesReplaceOnlyWhatTheyName)
{
  SceneOptions o;
  o.MaterialName = "gold";
  o.Ks = Rgb{ 0, 0, 0 };
  o.Ns = 5;
  const Material m = o.EffectiveMaterial();
  const Material* gold = FindLectureMaterial("gold");
  ASSERT_NE(gold, nullptr);
  EXPECT_EQ(m.Ka, gold->Ka);
  EXPECT_EQ(m.Kd, gold->Kd);
  EXPECT_EQ(m.Ks, (Rgb{ 0, 0, 0 }));
  EXPECT_DOUBLE_EQ(m.Ns, 5);
}

// The inspector's Copy command: SceneArguments parsed back gives the same
// scene, to the last bit of every number (0.1 + 0.2 and 1/3 print with 17
// digits), and the defaults write nothing but the size.
TEST(Options, SceneArgumentsParseBackToTheSameScene)
{
  SceneOptions s;
  s.ShadingRule = Shading::Gouraud;
  s.ReflectionModel = Reflection::Phong;
  s.MaterialName = "brass";
  s.Ka = Rgb{ 0.1 + 0.2, 1.0 / 3, 0 };
  s.Kd = Rgb{ 0, 0, 0 };
  s.Ks = Rgb{ 2, 0.5, 1e-7 };
  s.Ns = 1.0 / 7;
  s.Ambient = { 0.3, 0.25, 1.0 / 9 };
  Light spot;
  spot.Kind = LightKind::Spot;
  spot.Position = { 1.0 / 3, -2, 5 };
  spot.Direction = { 0, -1.0 / 3, -1 };
  spot.HalfAngleDeg = 12.5;
  spot.Exponent = 2.0 / 3;
  spot.Color = { 0.9, 0.8, 0.7 };
  Light sun;
  sun.Kind = LightKind::Directional;
  sun.Direction = { 1, 2, 3 };
  s.Lights = { spot, sun, Light{} };
  s.Size = { 321, 123 };
  s.CameraPosition = Vec3{ 3.9, 1.5, -2.2 + 1e-12 };
  s.CameraFocalPoint = Vec3{ 0.1, 0.2, 0.3 };
  s.CameraViewUp = Vec3{ 0, 0, 1 };
  s.ViewAngle = 100.0 / 3;
  s.Orthographic = true;
  s.ParallelScale = 0.7;
  s.Background = { 0.5, 0.5, 1 };
  s.Edges = true;
  s.EdgeColor = { 1, 0, 0 };
  s.EdgeWidth = 2.5;
  s.NormalGlyphs = true;
  s.Normals = NormalsMode::Compute;
  s.Computed.Weighting = "area";
  s.Computed.FeatureAngle = 45.5;
  s.Computed.Orient = true;
  const std::vector<std::string> words = SceneArguments(s);
  SceneOptions back;
  ApplySceneArguments(back, words);
  EXPECT_EQ(SceneArguments(back), words);
  EXPECT_EQ(*back.Ka, *s.Ka);
  EXPECT_EQ(*back.Ns, *s.Ns);
  EXPECT_EQ(back.Ambient, s.Ambient);
  EXPECT_EQ(back.Lights.size(), 3u);
  EXPECT_EQ(back.Lights[0].Direction, spot.Direction);
  EXPECT_EQ(back.Lights[0].Exponent, spot.Exponent);
  EXPECT_EQ(*back.CameraPosition, *s.CameraPosition);
  EXPECT_EQ(back.ViewAngle, s.ViewAngle);
  EXPECT_EQ(*back.Computed.FeatureAngle, 45.5);
  EXPECT_EQ(SceneArguments(SceneOptions{}), (std::vector<std::string>{ "--size", "1024x768" }));
}
