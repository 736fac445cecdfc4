// Textures through the lecture's equation, pixel by pixel: orthographic
// renders by `shadelab render --texture` of a planar grid with texture
// coordinates (an OFF) and a 4 x 4 8-bit image (a PNG) against the
// double-precision oracle, which looks the texel up as OpenGL defines it
// (filters/illumination/shadelabTexture.h). Every rule, both filters, every
// wrap mode, and the same image as a mesh file's own texture on some of its
// parts; the scenes and the comparison are oracle_scene.h's.
//
// The tolerance is the standard one (1e-4 relative, oracle_scene.h) with
// nothing added for the texture. OpenGL lets bilinear filtering compute its
// weights with limited precision, and llvmpipe keeps 8 bits of the position
// between texel centres for 8-bit textures: a weight off by up to 2^-8 per
// axis would put the texel off by up to 2 * 2^-8 of the texture's range
// and the pixel by that times ka*Ia + kd*sum(Il), some 0.004 here, forty
// times the bound. But the texture is uploaded as 32-bit floats (the decoded
// linear values), and for float textures llvmpipe filters in float: the
// largest deviation measured over these cases was 1.1e-6 absolute, float
// rounding of the equation, as untextured. So a texel off by a fraction of
// 1/256 still fails here.
#include "oracle_scene.h"

#include <gtest/gtest.h>

using namespace shadelab_test;
using shadelab::TextureFilter;
using shadelab::TextureWrap;

namespace
{
std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);
  for (Shading r : { Shading::None, Shading::Flat, Shading::Gouraud, Shading::Phong })
  {
    for (TextureFilter filter : { TextureFilter::Nearest, TextureFilter::Bilinear })
    {
      for (TextureWrap wrap : { TextureWrap::Repeat, TextureWrap::Clamp, TextureWrap::Mirror })
      {
        Scene s;
        s.Rule = r;
        s.Textured = true;
        s.Filter = filter;
        s.Wrap = wrap;
        add(std::string(ToString(r)) + "_" + ToString(filter) + "_" + ToString(wrap), s);
      }
    }
  }
  // The file's own textures, per part: an OBJ of three parts whose MTL
  // gives parts 0 and 2 the image as map_Kd and map_Ka (Kd, Ka the factors),
  // part 1 none; repeating and clamped (-clamp on).
  for (Shading r : { Shading::None, Shading::Flat, Shading::Gouraud, Shading::Phong })
  {
    for (TextureWrap wrap : { TextureWrap::Repeat, TextureWrap::Clamp })
    {
      Scene s;
      s.Rule = r;
      s.Textured = true;
      s.Parts = ThreeParts();
      s.Wrap = wrap;
      add("file_parts_" + std::string(ToString(r)) + "_" + ToString(wrap), s);
    }
  }
  // Several coloured lights of every kind, and the 8-bit picture.
  for (Shading r : LitRules)
  {
    Scene s;
    s.Rule = r;
    s.Textured = true;
    s.Lights = { Point({ -0.8, 0.6, 1.2 }, { 1, 0.2, 0.1 }),
      Directional({ 0.4, -0.3, -1 }, { 0.1, 0.9, 0.2 }),
      Spot({ 0.5, -0.5, 2 }, { 0, 0, -1 }, 60, 2, { 0.2, 0.3, 1 }) };
    add("coloured_lights_" + std::string(ToString(r)), s);
    s.EightBit = true;
    add("coloured_lights_" + std::string(ToString(r)) + "_png", s);
  }
  return cases;
}

class TextureOracle : public testing::TestWithParam<Case>
{
};
}

TEST_P(TextureOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, TextureOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });

// A batch keeps a rule's actor from shot to shot (SceneCache) and with it
// the uploaded texture when the image is the same: the next shot's wrap and
// filter must still apply. And it decodes a new image while the picture
// before is being written (the writer's answers must not mix). Each shot of
// a scene file equals its own render.
TEST(TextureBatch, EachShotSamplesAsItsOwnRender)
{
  TempDir dir;
  Scene s;
  s.Textured = true;
  WriteText(dir / "mesh.off", OffText(s, Grid(s.Geometry)));
  WriteImage8(dir / "texture.png", TextureSide, TextureSide, TextureBytes());
  std::vector<unsigned char> inverted = TextureBytes();
  for (unsigned char& v : inverted)
  {
    v = static_cast<unsigned char>(255 - v);
  }
  WriteImage8(dir / "inverted.png", TextureSide, TextureSide, inverted);
  WriteText(dir / "scene.json",
    R"({ "mesh": "mesh.off", "texture": "texture.png", "size": [64, 64],
         "shots": [ { "texture_filter": "nearest", "texture_wrap": "clamp" },
                    { "texture_filter": "bilinear", "texture_wrap": "repeat" },
                    { "texture": "inverted.png" } ] })");
  const RunResult batch = RunShadelab({ "render", "--scene", (dir / "scene.json").string(), "-o",
    (dir / "shot{index}.exr").string() });
  ASSERT_EQ(batch.ExitCode, 0) << batch.Stderr;
  const char* settings[][3] = { { "texture.png", "nearest", "clamp" },
    { "texture.png", "bilinear", "repeat" }, { "inverted.png", "bilinear", "repeat" } };
  for (int shot = 0; shot < 3; ++shot)
  {
    SCOPED_TRACE(std::to_string(shot));
    const auto alone = dir / ("alone" + std::to_string(shot) + ".exr");
    const RunResult r = RunShadelab({ "render", (dir / "mesh.off").string(), "-o", alone.string(),
      "--size", "64x64", "--texture", (dir / settings[shot][0]).string(), "--texture-filter",
      settings[shot][1], "--texture-wrap", settings[shot][2] });
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    EXPECT_EQ(
      ReadImage(dir / ("shot" + std::to_string(shot) + ".exr")).Pixels, ReadImage(alone).Pixels);
  }
}
