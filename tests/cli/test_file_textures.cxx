// The mesh files' own textures drawn, per part: real files (teapot-textured.obj
// with its MTL and PNG, Khronos' BoxTextured as .gltf and .glb) rendered
// against the oracle under every rule, pixel by pixel through `probe`; a
// mesh of a textured and an untextured part; which options keep or drop the
// file's textures, as the picture's metadata lists them.
#include "cli_test_support.h"
#include "probe_oracle_check.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace shadelab_test;
using nlohmann::json;

namespace
{
using Rgb = std::array<double, 3>;

// `shadelab probe MESH --json` at every 12th pixel of a 240x240 picture
// seen from "iso" at `zoom`, under `rule`: one JSON object per pixel.
std::vector<json> ProbeGrid(const std::filesystem::path& mesh, const char* rule, double zoom)
{
  std::vector<std::string> args{ "probe", mesh.string(), "--json", "--shading", rule, "--size",
    "240x240", "--view", "iso", "--zoom", std::to_string(zoom) };
  for (int y = 4; y < 240; y += 12)
  {
    for (int x = 4; x < 240; x += 12)
    {
      args.insert(args.end(), { "--pixel", std::to_string(x) + "," + std::to_string(y) });
    }
  }
  const RunResult r = RunShadelab(args);
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  std::vector<json> probes;
  std::istringstream lines(r.Stdout);
  for (std::string line; std::getline(lines, line);)
  {
    probes.push_back(json::parse(line));
  }
  return probes;
}

// The pixels probe compared, at least half a pixel inside their triangle
// (as the oracle tests skip the edges, where the rasteriser and the ray may
// meet different triangles), each rendered as the oracle lights it within
// the oracle tests' standard bound (1e-4 relative, floor 0.01;
// oracle_scene.h's Standard says why) plus `texelSlack` absolute; each
// kd a texel's (kd_from "texture"), and not all the same texel (so the
// image is looked up, not one colour of it); ks the texel's too where
// ksTextured (not all the same, nor all the pictures' pixels), else the
// material's alone.
void ExpectTexturedAsTheOracle(const std::filesystem::path& mesh, double texelSlack,
  std::size_t atLeast, bool ksTextured, double zoom = 1)
{
  for (const char* rule : { "none", "flat", "gouraud", "phong" })
  {
    std::size_t compared = 0;
    std::set<std::vector<double>> texels, ks, rendered;
    for (const json& p : ProbeGrid(mesh, rule, zoom))
    {
      if (!p.at("hit") || p.at("edge_distance").get<double>() < 0.5)
      {
        continue;
      }
      ++compared;
      ASSERT_EQ(p.at("kd_from"), "texture") << rule << " " << p.at("pixel");
      texels.insert(p.at("texel").get<std::vector<double>>());
      ks.insert(p.at("ks").get<std::vector<double>>());
      rendered.insert(p.at("rendered").get<std::vector<double>>());
      ExpectRenderedIsOracle(
        p, mesh.filename().string() + ", " + rule + ", pixel " + p.at("pixel").dump(), texelSlack);
    }
    EXPECT_GE(compared, atLeast) << mesh.filename() << ", " << rule;
    EXPECT_GT(texels.size(), 1u) << mesh.filename() << ", " << rule;
    // The picture shows the texture, but for none on a metal (kd = 0: black).
    const bool unlitMetal = ksTextured && std::string(rule) == "none";
    EXPECT_EQ(rendered.size() > 1, !unlitMetal) << mesh.filename() << ", " << rule;
    EXPECT_EQ(ks.size() > 1, ksTextured) << mesh.filename() << ", " << rule;
  }
}
}

// The teapot's texture coordinates lie in [0, 1], where a float's ulp is
// 6e-8: 1.5e-5 of a texel of the 256-texel texture. Across its squares'
// edges the texel changes by up to 0.775 per texel (blue: 0.9 to 0.125), so
// each ulp that the interpolated coordinate is off moves the texel by up to
// 1.2e-5 and the pixel by that times ka Ia + kd Il (1.2 here): 1e-4 allows
// about seven ulps. The largest deviation measured was 3.3e-5. Seen at zoom
// 2, its triangles are a few pixels across, enough of them away from edges.
TEST(FileTextures, TexturedObjMatchesTheOracleUnderEveryRule)
{
  ExpectTexturedAsTheOracle(TestMesh("teapot-textured.obj"), 1e-4, 40, false, 2);
}

// BoxTextured as Debian ships it (metallic 0: kd = ka = 1 x texel).
// The box's texture coordinates reach s = 6, where a float's ulp is 4.8e-7:
// 1e-4 of a texel of the 211-texel logo. Across the logo's sharp edges the
// texel changes by up to 1 per texel, so each ulp that the interpolated s
// is off moves the texel by up to 1e-4 and the pixel by that times
// ka Ia + kd Il (1.2 here): 6e-4 allows about five ulps. The largest
// deviation measured was 7e-5; a wrong texel (another image, wrap, filter
// or orientation) is off by tenths.
TEST(FileTextures, BoxTexturedGltfAndGlbMatchTheOracleUnderEveryRule)
{
  for (const char* name :
    { "BoxTextured-glTF/BoxTextured.gltf", "BoxTextured-glTF-Binary/BoxTextured.glb" })
  {
    ExpectTexturedAsTheOracle(DebianModel(std::string("glTF2/") + name), 6e-4, 100, false);
  }
}

// The box made a metal (metallic 1, kd = ka = 0): the texel is in ks alone,
// ks = texel, and the pixel moves by up to ks's texel times the specular
// sum (1 here, ns 0): the bound above holds. Under none a metal is black
// (kd = 0).
TEST(FileTextures, BoxTexturedMetalShowsItsTextureThroughKs)
{
  const TempDir dir;
  for (const bool binary : { false, true })
  {
    ExpectTexturedAsTheOracle(MetalBoxTextured(dir.path(), binary), 6e-4, 100, true);
  }
}

namespace
{
// The square [-1, 1]^2 of test_parts in two parts: part 0 ("tex", below the
// diagonal) with map_Kd and map_Ka, part 1 ("plain") without. The texture is
// one colour, 8-bit 188, so every lookup gives it (188/255, as stored).
constexpr const char* TwoPartObj = "mtllib two.mtl\n"
                                   "v -1 -1 0\nv 1 -1 0\nv -1 1 0\nv 1 1 0\n"
                                   "vt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n"
                                   "usemtl tex\nf 1/1 2/2 3/3\n"
                                   "usemtl plain\nf 2/2 4/4 3/3\n";
constexpr const char* TwoPartMtl = "newmtl tex\nKa 0.5 0.5 0.5\nKd 0.5 0.25 1\nKs 0.5 0.5 0.5\n"
                                   "Ns 16\nmap_Kd tex.png\nmap_Ka tex.png\n"
                                   "newmtl plain\nKa 0 0 0\nKd 0.75 0.125 0.0625\nKs 0 0 0\nNs 1\n";
const std::vector<unsigned char> TexRgb{ 188, 188, 188 };

const std::vector<std::string> View{ "--size", "100x100", "--orthographic", "--camera-position",
  "0,0,5", "--camera-focal-point", "0,0,0", "--camera-view-up", "0,1,0", "--parallel-scale",
  "1.1" };
// Pixels well inside each part: (-0.5, -0.5) and (0.5, 0.5).
constexpr std::array<int, 2> InPart0{ 27, 72 }, InPart1{ 72, 27 };

struct TwoParts
{
  TempDir Dir;
  std::string Obj = (Dir / "two.obj").string();
  TwoParts()
  {
    WriteText(Dir / "two.obj", TwoPartObj);
    WriteText(Dir / "two.mtl", TwoPartMtl);
    WriteImage8(Dir / "tex.png", 1, 1, TexRgb);
  }

  // The parts as the picture's metadata lists them, rendered with options
  // under `none`, and the picture (a float EXR: kd exactly).
  Image Render(const std::vector<std::string>& options) const
  {
    const auto out = this->Dir / "out.exr";
    std::vector<std::string> args{ "render", this->Obj, "-o", out.string(), "--shading", "none",
      "--pixel-type", "float" };
    args.insert(args.end(), View.begin(), View.end());
    args.insert(args.end(), options.begin(), options.end());
    const RunResult r = RunShadelab(args);
    EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
    return ReadImage(out);
  }
};

json PartsOf(const Image& image)
{
  return json::parse(image.Description).at("parts");
}

Rgb At(const Image& image, const std::array<int, 2>& xy)
{
  const size_t i = (static_cast<size_t>(xy[1]) * image.Width + xy[0]) * image.Channels;
  return { image.Pixels[i], image.Pixels[i + 1], image.Pixels[i + 2] };
}

// 188 of 255, as the texture decoding takes it: the stored value.
double TexValue()
{
  return 188 / 255.0;
}

// Each value of `got` within float's rounding of `want` (the picture is float).
void ExpectRgb(const Rgb& got, const Rgb& want, const std::string& what)
{
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(got[c], want[c], 1e-6) << what << ", channel " << c;
  }
}
}

// Part 0 is Kd x texel, part 1 its own Kd: under `none` exactly, under the
// lit rules as the oracle lights each part (probe, the standard bound).
// The colour pipeline (doc/design.md, "Colour"): texels are display values
// taken as stored, and pictures are written as computed, so a texture shown
// as kd itself (--shading none, --texture alone) comes out as its file
// stores it: the same bytes in an 8-bit picture, each byte / 255 in a float
// one (its float rounding apart).
TEST(FileTextures, ATextureShownAsItIsComesOutAsItsFileStoresIt)
{
  TempDir dir;
  WriteText(dir / "square.off",
    "STNOFF\n4 2 0\n0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n"
    "0 1 0 0 0 1 0 1\n3 0 1 2\n3 0 2 3\n");
  const std::vector<unsigned char> texel{ 3, 128, 250 };
  WriteImage8(dir / "texel.png", 1, 1, texel);
  for (const std::string out : { "out.png", "out.exr" })
  {
    SCOPED_TRACE(out);
    const RunResult r =
      RunShadelab({ "render", (dir / "square.off").string(), "-o", (dir / out).string(), "--size",
        "32x32", "--shading", "none", "--texture", (dir / "texel.png").string() });
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    const Image image = ReadImage(dir / out);
    ASSERT_EQ(image.Width, 32);
    const std::size_t centre = (16 * 32 + 16) * static_cast<std::size_t>(image.Channels);
    for (int c = 0; c < 3; ++c)
    {
      if (out == "out.png")
      {
        EXPECT_EQ(image.Pixels[centre + c], texel[c]) << "channel " << c;
      }
      else
      {
        EXPECT_NEAR(image.Pixels[centre + c], texel[c] / 255.0, 1e-7) << "channel " << c;
      }
    }
  }
}

TEST(FileTextures, TexturedAndUntexturedPartsOfOneMesh)
{
  const TwoParts files;
  const Image none = files.Render({});
  const double t = TexValue();
  ExpectRgb(At(none, InPart0), { 0.5 * t, 0.25 * t, 1 * t }, "part 0");
  ExpectRgb(At(none, InPart1), { 0.75, 0.125, 0.0625 }, "part 1");
  for (const char* rule : { "flat", "gouraud", "phong" })
  {
    std::vector<std::string> args{ "probe", files.Obj, "--json", "--shading", rule, "--light",
      "point:0.3,0.2,2", "--pixel", std::to_string(InPart0[0]) + "," + std::to_string(InPart0[1]),
      "--pixel", std::to_string(InPart1[0]) + "," + std::to_string(InPart1[1]) };
    args.insert(args.end(), View.begin(), View.end());
    const RunResult r = RunShadelab(args);
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    std::istringstream lines(r.Stdout);
    int part = 0;
    for (std::string line; std::getline(lines, line); ++part)
    {
      const json p = json::parse(line);
      EXPECT_EQ(p.at("part"), part) << rule;
      EXPECT_EQ(p.at("kd_from"), part == 0 ? "texture" : "material") << rule;
      ExpectRenderedIsOracle(p, std::string(rule) + ", part " + std::to_string(part));
    }
    EXPECT_EQ(part, 2) << r.Stdout;
  }
}

// The metadata lists each part's texture: its image, which of kd and ka it
// multiplies, its wrap (s, t) and filter; a part without one has none.
TEST(FileTextures, MetadataListsEachPartsTexture)
{
  const TwoParts files;
  const Image image = files.Render({});
  const json parts = PartsOf(image);
  const json& texture = parts.at(0).at("texture");
  EXPECT_EQ(texture.at("image"), (files.Dir / "tex.png").string());
  EXPECT_EQ(texture.at("maps"), json({ "kd", "ka" }));
  EXPECT_EQ(texture.at("wrap"), json({ "repeat", "repeat" }));
  EXPECT_EQ(texture.at("filter"), "bilinear");
  EXPECT_FALSE(parts.at(1).contains("texture"));
  EXPECT_EQ(json::parse(image.Description).at("kd_from"), "texture");
}

// --material and --kd drop the file's kd texture, --ka its ka texture
// (they say "this coefficient, everywhere"); --ks keeps both; --texture
// replaces every part's, over --kd's too.
TEST(FileTextures, OverridesDropOrReplaceTheFilesTextures)
{
  const TwoParts files;
  const double t = TexValue();

  const Image kd = files.Render({ "--kd", "0.25,0.5,0.75" });
  EXPECT_EQ(PartsOf(kd).at(0).at("texture").at("maps"), json({ "ka" }));
  ExpectRgb(At(kd, InPart0), { 0.25, 0.5, 0.75 }, "--kd: part 0");

  const Image ka = files.Render({ "--ka", "0.25,0.25,0.25" });
  EXPECT_EQ(PartsOf(ka).at(0).at("texture").at("maps"), json({ "kd" }));
  ExpectRgb(At(ka, InPart0), { 0.5 * t, 0.25 * t, 1 * t }, "--ka: part 0");

  const Image material = files.Render({ "--material", "gold" });
  for (const json& part : PartsOf(material))
  {
    EXPECT_FALSE(part.contains("texture")) << part;
  }

  const Image ks = files.Render({ "--ks", "0,0,0" });
  EXPECT_EQ(PartsOf(ks).at(0).at("texture").at("maps"), json({ "kd", "ka" }));
  ExpectRgb(At(ks, InPart0), { 0.5 * t, 0.25 * t, 1 * t }, "--ks: part 0");

  WriteImage8(files.Dir / "other.png", 1, 1, { 255, 255, 255 });
  const Image other =
    files.Render({ "--texture", (files.Dir / "other.png").string(), "--kd", "0.5,0.5,0.5" });
  for (const json& part : PartsOf(other))
  {
    EXPECT_EQ(part.at("texture").at("image"), (files.Dir / "other.png").string()) << part;
  }
  ExpectRgb(At(other, InPart0), { 0.5, 0.5, 0.5 }, "--texture: part 0");
  ExpectRgb(At(other, InPart1), { 0.5, 0.5, 0.5 }, "--texture: part 1");
}

// A metal's ks texture (BoxTextured) follows the overrides as kd's and ka's
// do: --ks drops it, --kd keeps it (and ka's), --material drops all, and
// --texture is kd's and ka's only.
TEST(FileTextures, OverridesOfAMetalsKsTexture)
{
  const TempDir dir;
  const auto metal = MetalBoxTextured(dir.path(), true);
  const auto maps = [&](const std::vector<std::string>& options)
  {
    const auto out = dir / "box.exr";
    std::vector<std::string> args{ "render", metal.string(), "-o", out.string(), "--size", "32x32",
      "--pixel-type", "float" };
    args.insert(args.end(), options.begin(), options.end());
    const RunResult r = RunShadelab(args);
    EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
    const json part = PartsOf(ReadImage(out)).at(0);
    return part.contains("texture") ? part.at("texture").at("maps") : json::array();
  };
  EXPECT_EQ(maps({}), json({ "kd", "ka", "ks" }));
  EXPECT_EQ(maps({ "--ks", "0.5,0.5,0.5" }), json({ "kd", "ka" }));
  EXPECT_EQ(maps({ "--kd", "0.5,0.5,0.5" }), json({ "ka", "ks" }));
  EXPECT_EQ(maps({ "--material", "gold" }), json::array());
  EXPECT_EQ(maps({ "--texture", TestMesh("teapot-texture.png").string() }), json({ "kd", "ka" }));
}
