// A mesh's parts drawn with their own materials: which material each part
// gets under the overrides (--material, --ka/--kd/--ks/--ns), as rendered,
// as the picture's metadata lists it and as `probe` explains it; on files
// written here (an OBJ with its MTL, a glTF with two materials) and on
// Khronos' BoxTextured (from Debian's assimp-testmodels).
#include "cli_test_support.h"
#include "probe_oracle_check.h"
#include "shadelabIllumination.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace shadelab_test;
using nlohmann::json;

namespace
{
using Rgb = std::array<double, 3>;

// Two triangles filling the square [-1, 1]^2 at z = 0: part 0 below the
// diagonal from (-1, 1) to (1, -1), part 1 above it. Part 0 is "red", from
// the MTL; part 1 names "nosuch", which the MTL does not define, so it has
// no material of its own. The numbers are exact in float (the reader's type).
constexpr const char* Obj = "mtllib parts.mtl\n"
                            "v -1 -1 0\nv 1 -1 0\nv -1 1 0\nv 1 1 0\n"
                            "usemtl red\nf 1 2 3\n"
                            "usemtl nosuch\nf 2 4 3\n";
constexpr const char* Mtl = "newmtl red\nKa 0.25 0 0\nKd 0.75 0.125 0.0625\nKs 0.5 0.5 0.5\n"
                            "Ns 16\n";
const Rgb RedKa{ 0.25, 0, 0 }, RedKd{ 0.75, 0.125, 0.0625 }, RedKs{ 0.5, 0.5, 0.5 };

// The same square as glTF, one primitive per triangle, with the materials
// "left" (part 0) and "right" (part 1): base colours B, metallic 0 and
// roughness 1, which the reader maps to kd = ka = B, ks = 0.04, ns = 0
// (doc/user/formats-and-materials.md, "Materials from glTF"). The buffer holds the six corners as
// float x y z, then a colour for each; with `vertexColors` they are COLOR_0.
std::string GltfText(bool vertexColors)
{
  const std::string colors0 = vertexColors ? R"(, "COLOR_0": 2)" : "";
  const std::string colors1 = vertexColors ? R"(, "COLOR_0": 3)" : "";
  return R"({
  "asset": { "version": "2.0" },
  "scene": 0, "scenes": [ { "nodes": [ 0 ] } ], "nodes": [ { "mesh": 0 } ],
  "meshes": [ { "primitives": [
    { "attributes": { "POSITION": 0)" +
    colors0 + R"( }, "material": 0 },
    { "attributes": { "POSITION": 1)" +
    colors1 + R"( }, "material": 1 } ] } ],
  "materials": [
    { "name": "left", "pbrMetallicRoughness": { "baseColorFactor": [0.5, 0.25, 0.125, 1],
      "metallicFactor": 0, "roughnessFactor": 1 } },
    { "name": "right", "pbrMetallicRoughness": { "baseColorFactor": [0.125, 0.5, 0.75, 1],
      "metallicFactor": 0, "roughnessFactor": 1 } } ],
  "buffers": [ { "byteLength": 144, "uri": "data:application/octet-stream;base64,AACAvwAAgL8AAAAAAACAPwAAgL8AAAAAAACAvwAAgD8AAAAAAACAPwAAgL8AAAAAAACAPwAAgD8AAAAAAACAvwAAgD8AAAAAAACAPwAAgD4AAAAAAAAAAAAAgD8AAAA/AACAPgAAAAAAAIA/AACAPwAAgD8AAAAAAAAAAAAAAD8AAIA/AACAPwAAAAAAAAA/" } ],
  "bufferViews": [ { "buffer": 0, "byteLength": 144 } ],
  "accessors": [
    { "bufferView": 0, "byteOffset": 0, "componentType": 5126, "count": 3, "type": "VEC3",
      "min": [-1, -1, 0], "max": [1, 1, 0] },
    { "bufferView": 0, "byteOffset": 36, "componentType": 5126, "count": 3, "type": "VEC3",
      "min": [-1, -1, 0], "max": [1, 1, 0] },
    { "bufferView": 0, "byteOffset": 72, "componentType": 5126, "count": 3, "type": "VEC3" },
    { "bufferView": 0, "byteOffset": 108, "componentType": 5126, "count": 3, "type": "VEC3" } ]
})";
}
const Rgb LeftKd{ 0.5, 0.25, 0.125 }, RightKd{ 0.125, 0.5, 0.75 };

// An orthographic view of the square: 100x100 pixels, 1.1 units either side
// of the centre, so (x, y) is at pixel (50 + 50x/1.1, 50 - 50y/1.1).
const std::vector<std::string> View{ "--size", "100x100", "--orthographic", "--camera-position",
  "0,0,5", "--camera-focal-point", "0,0,0", "--camera-view-up", "0,1,0", "--parallel-scale",
  "1.1" };
// Pixels well inside each part: (-0.5, -0.5) and (0.5, 0.5).
constexpr std::array<int, 2> InPart0{ 27, 72 }, InPart1{ 72, 27 };

Rgb Lecture(const char* name, Rgb shadelab::Material::*k)
{
  return shadelab::FindLectureMaterial(name)->*k;
}

// Files written for a test: the OBJ with its MTL and the glTF.
struct Files
{
  TempDir Dir;
  std::string ObjPath = (Dir / "parts.obj").string();
  std::string GltfPath = (Dir / "parts.gltf").string();
  std::string ColoredGltfPath = (Dir / "colored.gltf").string();
  Files()
  {
    WriteText(Dir / "parts.obj", Obj);
    WriteText(Dir / "parts.mtl", Mtl);
    WriteText(GltfPath, GltfText(false));
    WriteText(ColoredGltfPath, GltfText(true));
  }
};

// `shadelab render MESH` under `none` (the colour is kd, exactly, in a float
// EXR) with the options; the picture.
Image RenderNone(const Files& files, const std::string& mesh, std::vector<std::string> options)
{
  const auto out = files.Dir / "out.exr";
  std::vector<std::string> args{ "render", mesh, "-o", out.string(), "--shading", "none",
    "--pixel-type", "float" };
  args.insert(args.end(), View.begin(), View.end());
  args.insert(args.end(), options.begin(), options.end());
  const RunResult r = RunShadelab(args);
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  return ReadImage(out);
}

Rgb At(const Image& image, const std::array<int, 2>& xy)
{
  const size_t i = (static_cast<size_t>(xy[1]) * image.Width + xy[0]) * image.Channels;
  return { image.Pixels[i], image.Pixels[i + 1], image.Pixels[i + 2] };
}

// got is want as float keeps it (the picture's and the reader's type):
// equal within GoogleTest's 4 float ulps, channel by channel.
void ExpectFloats(const Rgb& got, const Rgb& want)
{
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_FLOAT_EQ(got[c], want[c]) << "channel " << c;
  }
}

json PartsOf(const Image& image)
{
  return json::parse(image.Description).at("parts");
}

Rgb Triple(const json& j)
{
  return { j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>() };
}
}

// Without overrides the file's material wins where the part has one, and
// the default (--material's, chrome) where it has none.
TEST(Parts, EachPartIsDrawnWithItsOwnMaterialOrTheDefault)
{
  const Files files;
  const Image image = RenderNone(files, files.ObjPath, {});
  ExpectFloats(At(image, InPart0), RedKd);
  ExpectFloats(At(image, InPart1), Lecture("chrome", &shadelab::Material::Kd));

  const json parts = PartsOf(image);
  ASSERT_EQ(parts.size(), 2u) << parts;
  EXPECT_EQ(parts[0].at("index"), 0);
  EXPECT_EQ(parts[0].at("name"), "red");
  EXPECT_EQ(parts[0].at("triangles"), 1);
  EXPECT_EQ(parts[0].at("source"), "file");
  EXPECT_EQ(parts[0].at("overridden"), json::array());
  ExpectFloats(Triple(parts[0].at("material").at("ka")), RedKa);
  ExpectFloats(Triple(parts[0].at("material").at("ks")), RedKs);
  EXPECT_EQ(parts[0].at("material").at("ns"), 16);
  EXPECT_EQ(parts[1].at("name"), "nosuch");
  EXPECT_EQ(parts[1].at("source"), "default");
  EXPECT_EQ(parts[1].at("material").at("name"), "chrome");
}

TEST(Parts, MaterialOptionReplacesEveryPartsWholeMaterial)
{
  const Files files;
  const Image image = RenderNone(files, files.ObjPath, { "--material", "gold" });
  const Rgb gold = Lecture("gold", &shadelab::Material::Kd);
  ExpectFloats(At(image, InPart0), gold);
  ExpectFloats(At(image, InPart1), gold);
  for (const json& part : PartsOf(image))
  {
    EXPECT_EQ(part.at("source"), "option") << part;
    EXPECT_EQ(part.at("material").at("name"), "gold") << part;
    EXPECT_EQ(Triple(part.at("material").at("ks")), Lecture("gold", &shadelab::Material::Ks));
  }
}

// --kd replaces kd of every part and keeps the rest of each: the file's ka,
// ks, ns for the part that has a material, the default's for the other.
TEST(Parts, CoefficientOptionReplacesThatCoefficientOfEveryPart)
{
  const Files files;
  const Image image = RenderNone(files, files.ObjPath, { "--kd", "0,1,0.5" });
  EXPECT_EQ(At(image, InPart0), (Rgb{ 0, 1, 0.5 }));
  EXPECT_EQ(At(image, InPart1), (Rgb{ 0, 1, 0.5 }));
  const json parts = PartsOf(image);
  ASSERT_EQ(parts.size(), 2u) << parts;
  EXPECT_EQ(parts[0].at("source"), "file");
  EXPECT_EQ(parts[0].at("overridden"), json::array({ "kd" }));
  ExpectFloats(Triple(parts[0].at("material").at("ka")), RedKa);
  ExpectFloats(Triple(parts[0].at("material").at("ks")), RedKs);
  EXPECT_EQ(parts[1].at("source"), "default");
  EXPECT_EQ(Triple(parts[1].at("material").at("ks")), Lecture("chrome", &shadelab::Material::Ks));

  // All four given: nothing of the file's is left.
  const Image all = RenderNone(
    files, files.ObjPath, { "--ka", "0,0,0", "--kd", "0,1,0.5", "--ks", "0,0,0", "--ns", "1" });
  for (const json& part : PartsOf(all))
  {
    EXPECT_EQ(part.at("source"), "option") << part;
  }
}

// glTF: a part per primitive, each with its material mapped from
// metallic-roughness (kd = base colour for a dielectric).
TEST(Parts, GltfPrimitivesAreDrawnWithTheirMaterials)
{
  const Files files;
  const Image image = RenderNone(files, files.GltfPath, {});
  EXPECT_EQ(At(image, InPart0), LeftKd);
  EXPECT_EQ(At(image, InPart1), RightKd);
  const json parts = PartsOf(image);
  ASSERT_EQ(parts.size(), 2u) << parts;
  EXPECT_EQ(parts[0].at("name"), "left");
  EXPECT_EQ(parts[1].at("name"), "right");
  EXPECT_EQ(parts[1].at("source"), "file");
}

// A scene file's shots of one mesh share its actors where they can: one
// that draws every part with one material, then one that draws them with
// their own again; neither leaves the other's actors in the picture.
TEST(Parts, ShotsOfOneMeshSwitchBetweenTheFilesMaterialsAndAnOverride)
{
  const Files files;
  const std::string scene = R"({ "mesh": "parts.obj", "shading": "none", "size": [100, 100],
    "pixel_type": "float", "camera": { "position": [0, 0, 5], "focal_point": [0, 0, 0],
    "view_up": [0, 1, 0], "orthographic": true, "parallel_scale": 1.1 },
    "shots": [ { "output": ")" +
    (files.Dir / "a.exr").string() + R"(" }, { "output": ")" + (files.Dir / "b.exr").string() +
    R"(", "material": "gold" }, { "output": ")" + (files.Dir / "c.exr").string() + R"(" } ] })";
  WriteText(files.Dir / "scene.json", scene);
  const RunResult r = RunShadelab({ "render", "--scene", (files.Dir / "scene.json").string() });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const Rgb chrome = Lecture("chrome", &shadelab::Material::Kd);
  const Rgb gold = Lecture("gold", &shadelab::Material::Kd);
  for (const char* own : { "a.exr", "c.exr" })
  {
    const Image image = ReadImage(files.Dir / own);
    ExpectFloats(At(image, InPart0), RedKd);
    ExpectFloats(At(image, InPart1), chrome);
  }
  const Image overridden = ReadImage(files.Dir / "b.exr");
  ExpectFloats(At(overridden, InPart0), gold);
  ExpectFloats(At(overridden, InPart1), gold);
}

// probe names the part under each pixel and where its material came from,
// and lights the pixel with that material.
TEST(Parts, ProbeReportsThePartUnderThePixel)
{
  const Files files;
  std::vector<std::string> args{ "probe", files.ObjPath, "--json", "--shading", "none", "--pixel",
    std::to_string(InPart0[0]) + "," + std::to_string(InPart0[1]), "--pixel",
    std::to_string(InPart1[0]) + "," + std::to_string(InPart1[1]) };
  args.insert(args.end(), View.begin(), View.end());
  const RunResult r = RunShadelab(args);
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  std::vector<json> pixels;
  std::istringstream lines(r.Stdout);
  for (std::string line; std::getline(lines, line);)
  {
    pixels.push_back(json::parse(line));
  }
  ASSERT_EQ(pixels.size(), 2u) << r.Stdout;
  EXPECT_EQ(pixels[0].at("part"), 0);
  EXPECT_EQ(pixels[0].at("part_name"), "red");
  EXPECT_EQ(pixels[0].at("material_from"), "file");
  ExpectFloats(Triple(pixels[0].at("material").at("kd")), RedKd);
  ExpectFloats(Triple(pixels[0].at("oracle")), RedKd);
  EXPECT_EQ(pixels[1].at("part"), 1);
  EXPECT_EQ(pixels[1].at("part_name"), "nosuch");
  EXPECT_EQ(pixels[1].at("material_from"), "default");
  EXPECT_EQ(Triple(pixels[1].at("oracle")), Lecture("chrome", &shadelab::Material::Kd));

  args.insert(args.end(), { "--material", "gold" });
  const RunResult gold = RunShadelab(args);
  ASSERT_EQ(gold.ExitCode, 0) << gold.Stderr;
  EXPECT_NE(gold.Stdout.find("\"material_from\":\"option\""), std::string::npos) << gold.Stdout;
  EXPECT_EQ(gold.Stdout.find("\"material_from\":\"file\""), std::string::npos) << gold.Stdout;
}

// Vertex colours stay each part's kd under every rule, the rest of each
// part's material its own (flat: each part's provoking points its own): the
// rendered pixel in each part against the oracle's value that probe gives,
// within the oracle tests' standard bound (1e-4 relative, floor 0.01;
// test_shading_oracle's Tolerance Standard says why).
TEST(Parts, VertexColorsAreEveryPartsKdUnderEveryRule)
{
  const Files files;
  for (const char* rule : { "flat", "gouraud", "phong" })
  {
    std::vector<std::string> args{ "probe", files.ColoredGltfPath, "--json", "--shading", rule,
      "--light", "point:0.3,0.2,2", "--pixel",
      std::to_string(InPart0[0]) + "," + std::to_string(InPart0[1]), "--pixel",
      std::to_string(InPart1[0]) + "," + std::to_string(InPart1[1]) };
    args.insert(args.end(), View.begin(), View.end());
    const RunResult r = RunShadelab(args);
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    std::istringstream lines(r.Stdout);
    int part = 0;
    for (std::string line; std::getline(lines, line); ++part)
    {
      const json p = json::parse(line);
      EXPECT_EQ(p.at("part"), part) << rule;
      EXPECT_EQ(p.at("kd_from"), "vertex colors") << rule;
      EXPECT_EQ(p.at("material").at("name"), part == 0 ? "left" : "right") << rule;
      ExpectRenderedIsOracle(p, std::string(rule) + ", part " + std::to_string(part));
    }
    EXPECT_EQ(part, 2) << r.Stdout;
  }
}

// Khronos' BoxTextured: one part, its named material as the glTF mapping
// gives it (base colour factor 1 under its texture, metallic 0: kd the base
// colour, ks a dielectric's 0.04).
TEST(Parts, BoxTexturedHasItsNamedMaterial)
{
  TempDir dir;
  const auto out = dir / "box.png";
  const RunResult r =
    RunShadelab({ "render", DebianModel("glTF2/BoxTextured-glTF/BoxTextured.gltf").string(), "-o",
      out.string(), "--size", "64x64" });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  const json parts = PartsOf(ReadImage(out));
  ASSERT_EQ(parts.size(), 1u) << parts;
  EXPECT_EQ(parts[0].at("name"), "Texture");
  EXPECT_EQ(parts[0].at("triangles"), 12);
  EXPECT_EQ(parts[0].at("source"), "file");
  EXPECT_EQ(Triple(parts[0].at("material").at("kd")), (Rgb{ 1, 1, 1 }));
  ExpectFloats(Triple(parts[0].at("material").at("ks")), Rgb{ 0.04, 0.04, 0.04 });
}
