// Normal maps through the lecture's equation, pixel by pixel: orthographic
// renders by `shadelab render --normal-map` of the test grid against the
// double-precision oracle, which perturbs the normal as shadelabNormalMap.h
// defines it, where each rule takes the normal (phong per fragment,
// gouraud per vertex, flat at the provoking vertex), in the frame of the
// grid's tangent (GridTangent, stated on its own). Every rule that lights,
// a constant and a patterned map, both filters, scales, back faces, with a
// texture and with an environment (reflected about the perturbed normal),
// and the 8-bit picture; the scenes and the comparison are oracle_scene.h's.
//
// The tolerance is the standard one (1e-4 relative): the map is uploaded
// as float texels and filtered in float as the textures are
// (test_texture_oracle.cxx says how that was measured), and the tangent is
// stored as float (1e-7). With the nearest texel, phong's pixels within
// the oracle's edge margin of a switch to another texel are left out
// (Oracle::Switches).
#include "probe_support.h"

#include <gtest/gtest.h>

using namespace shadelab_test;
using shadelab::TextureFilter;

namespace
{
std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);
  for (Shading r : LitRules)
  {
    const std::string rule = ToString(r);
    for (NormalMapKind kind : { NormalMapKind::Constant, NormalMapKind::Pattern })
    {
      for (TextureFilter filter : { TextureFilter::Nearest, TextureFilter::Bilinear })
      {
        Scene s;
        s.Rule = r;
        s.NormalMap = kind;
        s.Filter = filter;
        add(
          rule + (kind == NormalMapKind::Constant ? "_constant_" : "_pattern_") + ToString(filter),
          s);
      }
    }
    Scene s;
    s.Rule = r;
    s.NormalMap = NormalMapKind::Pattern;
    s.NormalScale = 0.5;
    add(rule + "_scale_half", s);
    s.NormalScale = -1.5;
    s.Wrap = shadelab::TextureWrap::Clamp;
    add(rule + "_scale_negative_clamped", s);
    s.NormalScale = 1;
    s.Wrap = shadelab::TextureWrap::Repeat;
    s.Geometry.BackFaces = true;
    add(rule + "_back_faces", s);
    s.Geometry.BackFaces = false;
    s.Geometry.Bump = 0;
    add(rule + "_plane", s);
    s.Geometry.Bump = -0.25;
    s.Textured = true;
    s.Model = Reflection::Phong;
    add(rule + "_textured_phong_model", s);
    s.Textured = false;
    s.Model = Reflection::BlinnPhong;
    s.Environment = EnvironmentKind::Pattern;
    add(rule + "_environment", s);
    s = ColouredLights();
    s.Rule = r;
    s.NormalMap = NormalMapKind::Pattern;
    s.EightBit = true;
    add(rule + "_coloured_lights_png", s);
  }
  return cases;
}

class NormalMapOracle : public testing::TestWithParam<Case>
{
};
}

TEST_P(NormalMapOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, NormalMapOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });

// A constant normal map on a plane tilts every normal alike: the picture
// equals the plane drawn with its file's normals tilted so, glTF's
// definition written out here on its own (x along dP/ds, y along dP/dt, z
// along the normal). Gouraud and phong take the normals; within float's
// rounding of the two ways to the same normal (1e-5).
TEST(NormalMap, AConstantMapTiltsTheNormalsAsTheGeometryWould)
{
  GridSpec plane;
  plane.Bump = 0;
  const Vec3 n = normalize(Vec3{ -plane.SlopeX, -plane.SlopeY, 1 });
  const Vec3 dPds = Vec3{ 1, 0, plane.SlopeX };
  const Vec3 dPdt = Vec3{ 0, 1, plane.SlopeY };
  const Vec3 t = normalize(dPds - dot(n, dPds) * n);
  const Vec3 b = normalize(dPdt - dot(n, dPdt) * n - dot(t, dPdt) * t);
  Vec3 m;
  for (int c = 0; c < 3; ++c)
  {
    m[c] = 2 * ConstantNormal[c] / 255.0 - 1;
  }
  const Vec3 tilted = normalize(m[0] * t + m[1] * b + m[2] * n);
  for (Shading r : { Shading::Gouraud, Shading::Phong })
  {
    SCOPED_TRACE(ToString(r));
    Scene mapped;
    mapped.Rule = r;
    mapped.Geometry = plane;
    mapped.NormalMap = NormalMapKind::Constant;
    Scene geometry = mapped;
    geometry.NormalMap = NormalMapKind::None;
    geometry.Geometry.EveryNormal = tilted;
    TempDir dir;
    std::string error;
    const Image a = Render(mapped, dir, error);
    ASSERT_EQ(error, "");
    const Image g = Render(geometry, dir, error);
    ASSERT_EQ(error, "");
    ASSERT_EQ(a.Pixels.size(), g.Pixels.size());
    double largest = 0;
    int lit = 0;
    for (std::size_t i = 0; i < a.Pixels.size(); ++i)
    {
      largest = std::max(largest, static_cast<double>(std::abs(a.Pixels[i] - g.Pixels[i])));
      lit += g.Pixels[i] > 0.3;
    }
    EXPECT_LT(largest, 1e-5);
    EXPECT_GT(lit, 1000); // the tilt lights the plane, not only its ambient term
  }
}

// probe explains the map where the rule took the normal: the tangent frame
// (the grid's dP/ds made orthogonal to N, B = N x T), the texel (a bump
// map's heights there and one texel along s and t, and the vector they
// make), and the perturbed normal, which is the normal its terms are lit
// with; they add up to the oracle, and the oracle's normal is the
// harness's (phong's and flat's at the pixel, gouraud's at each vertex
// through the weights).
TEST(NormalMapProbe, ExplainsThePerturbedNormalThatLights)
{
  for (const auto& [r, kind] : { std::pair{ Shading::Flat, NormalMapKind::Pattern },
         std::pair{ Shading::Gouraud, NormalMapKind::Pattern },
         std::pair{ Shading::Phong, NormalMapKind::Pattern },
         std::pair{ Shading::Flat, NormalMapKind::Heights },
         std::pair{ Shading::Gouraud, NormalMapKind::Heights },
         std::pair{ Shading::Phong, NormalMapKind::Heights } })
  {
    SCOPED_TRACE(std::string(ToString(r)) + (IsHeightMap(kind) ? " bump map" : " normal map"));
    Scene s;
    s.Rule = r;
    s.NormalMap = kind;
    s.NormalScale = IsHeightMap(kind) ? 2 : 1;
    shadelab::TextureMap heights;
    heights.Image = std::make_shared<shadelab::TextureImage>(NormalMapOf(kind).Decoded());
    TempDir dir;
    const Oracle oracle(s);
    const std::vector<std::array<int, 2>> pixels = ComparedPixels(s, oracle);
    std::string error;
    const std::vector<json> probes = Probe(SceneArguments(s, dir), pixels, error);
    ASSERT_EQ(error, "");
    ASSERT_EQ(probes.size(), pixels.size());
    ASSERT_GT(probes.size(), 100u);
    const shadelab::Tangent grid = GridTangent(s.Geometry);
    const Vec3 dPds{ grid[0], grid[1], grid[2] };
    for (std::size_t i = 0; i < probes.size(); ++i)
    {
      const json& p = probes[i];
      std::vector<const json*> lit{ &p };
      if (r == Shading::Gouraud)
      {
        lit.clear();
        for (const json& v : p.at("vertices"))
        {
          lit.push_back(&v);
        }
      }
      for (const json* at : lit)
      {
        const char* key = IsHeightMap(kind) ? "bump_map" : "normal_map";
        ASSERT_TRUE(at->contains(key));
        const json& m = at->at(key);
        const Vec3 n = Vec(m.at("normal"));
        if (IsHeightMap(kind))
        {
          // The heights at (s, t) and one texel (of TextureSide) along s and t.
          const auto st = m.at("texcoord").get<std::array<double, 2>>();
          const Vec3 h = Vec(m.at("heights"));
          ExpectNear(h,
            { shadelab::SampleTexture(heights, st[0], st[1])[0],
              shadelab::SampleTexture(heights, st[0] + 1.0 / TextureSide, st[1])[0],
              shadelab::SampleTexture(heights, st[0], st[1] + 1.0 / TextureSide)[0] },
            1e-7, "heights"); // the texels as float
          ExpectNear(Vec(m.at("tangent_space")), { -2 * (h[1] - h[0]), -2 * (h[2] - h[0]), 1 },
            1e-12, "the heights' vector");
        }
        ExpectNear(Vec(m.at("tangent")), normalize(dPds - dot(n, dPds) * n), 1e-6, "T");
        ExpectNear(Vec(m.at("bitangent")), cross(n, Vec(m.at("tangent"))), 1e-12, "B");
        const Vec3 t = Vec(m.at("tangent_space"));
        ExpectNear(Vec(m.at("perturbed")),
          normalize(t[0] * Vec(m.at("tangent")) + t[1] * Vec(m.at("bitangent")) + t[2] * n), 1e-12,
          "N'");
        ExpectNear(Vec(at->at("normal")), Vec(m.at("perturbed")), 1e-12, "the normal that lit");
      }
      if (r != Shading::Gouraud)
      {
        ExpectNear(Vec(p.at("normal")), oracle.At(pixels[i][0], pixels[i][1]).Terms.N, 1e-6,
          "the harness's N'");
        ExpectNear(TermsSum(p), Vec(p.at("oracle")), 1e-12, "the terms' sum");
      }
      ExpectWithinTheBound(Vec(p.at("rendered")), Vec(p.at("oracle")));
    }
  }
}

namespace
{
// `args` without the options named in `drop`, each with its value.
std::vector<std::string> Without(
  const std::vector<std::string>& args, const std::vector<std::string>& drop)
{
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    if (std::find(drop.begin(), drop.end(), args[i]) != drop.end())
    {
      ++i;
      continue;
    }
    kept.push_back(args[i]);
  }
  return kept;
}

// The grid as an OBJ (v, vt, vn) whose one material, the scene's, has the
// MTL statement `map` (naming normals.png in dir).
std::filesystem::path GridObj(const Scene& s, const TempDir& dir, const std::string& map)
{
  const Mesh m = Grid(s.Geometry);
  std::ostringstream obj;
  obj << "mtllib grid.mtl\nusemtl grid\n";
  for (std::size_t v = 0; v < m.Positions.size(); ++v)
  {
    const Vec3 w = s.World(m.Positions[v]);
    obj << "v " << Num(w[0]) << " " << Num(w[1]) << " " << Num(w[2]) << "\nvt "
        << Num(m.TexCoords[v][0]) << " " << Num(m.TexCoords[v][1]) << "\nvn "
        << Num(m.Normals[v][0]) << " " << Num(m.Normals[v][1]) << " " << Num(m.Normals[v][2])
        << "\n";
  }
  for (const auto& t : m.Triangles)
  {
    obj << "f";
    for (const auto v : t)
    {
      obj << " " << v + 1 << "/" << v + 1 << "/" << v + 1;
    }
    obj << "\n";
  }
  WriteText(dir / "grid.obj", obj.str());
  const Material& k = s.Surface;
  const auto spaced = [](const Rgb& c) { return Num(c[0]) + " " + Num(c[1]) + " " + Num(c[2]); };
  WriteText(dir / "grid.mtl",
    "newmtl grid\nKa " + spaced(k.Ka) + "\nKd " + spaced(k.Kd) + "\nKs " + spaced(k.Ks) + "\nNs " +
      Num(k.Ns) + "\n" + map + "\n");
  return dir / "grid.obj";
}

Image RenderArgs(std::vector<std::string> args, const TempDir& dir, std::string& error)
{
  const auto out = dir / "file.exr";
  args.insert(args.begin(), { "render", "-o", out.string() });
  const RunResult r = RunShadelab(args);
  if (r.ExitCode != 0)
  {
    error = r.Stderr;
    return {};
  }
  return ReadImage(out);
}

double Largest(const Image& a, const Image& b)
{
  double largest = a.Pixels.size() == b.Pixels.size() ? 0 : 1;
  for (std::size_t i = 0; i < a.Pixels.size() && i < b.Pixels.size(); ++i)
  {
    largest = std::max(largest, static_cast<double>(std::abs(a.Pixels[i] - b.Pixels[i])));
  }
  return largest;
}
}

// An OBJ's normal map, norm or bump / map_Bump with -bm as its scale, is
// drawn as --normal-map IMAGE:SCALE is, and a bump statement naming a grey
// image (a height map) as --bump-map IMAGE:SCALE is (which the oracle cases
// hold to the oracle): the same picture, under every rule.
TEST(NormalMapFiles, AnObjsNormAndBumpAreTheOptionsMaps)
{
  for (Shading r : LitRules)
  {
    for (NormalMapKind kind : { NormalMapKind::Pattern, NormalMapKind::Heights })
    {
      SCOPED_TRACE(std::string(ToString(r)) + (IsHeightMap(kind) ? " bump map" : " normal map"));
      Scene s;
      s.Rule = r;
      s.NormalMap = kind;
      s.NormalScale = 0.5;
      TempDir dir;
      std::string error;
      const Image option = Render(s, dir, error);
      ASSERT_EQ(error, "");
      std::vector<std::string> args = Without(
        SceneArguments(s, dir), { "--normal-map", "--bump-map", "--ka", "--kd", "--ks", "--ns" });
      std::vector<std::string> statements{ "map_Bump -bm 0.5 normals.png",
        "bump -bm 0.5 normals.png" };
      if (!IsHeightMap(kind))
      {
        statements.push_back("norm -bm 0.5 normals.png");
      }
      for (const std::string& map : statements)
      {
        SCOPED_TRACE(map);
        args[0] = GridObj(s, dir, map).string();
        EXPECT_EQ(Largest(RenderArgs(args, dir, error), option), 0);
        EXPECT_EQ(error, "");
      }
    }
  }
}

// --normal-map none draws no normal map, not even the file's own: the
// picture of the mesh without its norm statement.
TEST(NormalMapFiles, NoneDrawsNotEvenTheFilesOwn)
{
  Scene s;
  s.NormalMap = NormalMapKind::Pattern;
  TempDir dir;
  std::string error;
  Render(s, dir, error); // writes normals.png
  ASSERT_EQ(error, "");
  std::vector<std::string> args =
    Without(SceneArguments(s, dir), { "--normal-map", "--ka", "--kd", "--ks", "--ns" });
  args[0] = GridObj(s, dir, "").string();
  const Image plain = RenderArgs(args, dir, error);
  args[0] = GridObj(s, dir, "norm normals.png").string();
  const Image mapped = RenderArgs(args, dir, error);
  args.insert(args.end(), { "--normal-map", "none" });
  const Image none = RenderArgs(args, dir, error);
  ASSERT_EQ(error, "");
  EXPECT_GT(Largest(mapped, plain), 0.01);
  EXPECT_EQ(Largest(none, plain), 0);
  EXPECT_EQ(json::parse(none.Description).at("normal_map"), "none");
}

// A real file with normal maps (assimp-testmodels' glTF clear-coat test:
// ribbed and wrinkled normalTextures on some of its parts): at every
// third pixel, probe finds the map where a part has one, and the render
// is within 1e-4 of the oracle there. Not the oracle cases' relative bound:
// these maps' normals turn by up to a radian from one texel of a 1024-texel
// image to the next, so that the float texture coordinates' rounding (some
// 6e-8, 6e-5 of a texel) moves phong's filtered normal, and its dark
// pixels' light, by a few 1e-6, above 1e-4 of their values (measured:
// 2.6e-6 at most).
TEST(NormalMapFiles, ARealGltfsNormalTexturesMatchTheOracle)
{
  const std::filesystem::path file =
    std::filesystem::path(SHADELAB_DEBIAN_MODELS) / "glTF2/ClearCoat-glTF/ClearCoatTest.gltf";
  if (!std::filesystem::exists(file))
  {
    GTEST_SKIP() << file << " is missing (Debian's assimp-testmodels)";
  }
  for (Shading r : LitRules)
  {
    SCOPED_TRACE(ToString(r));
    std::vector<std::array<int, 2>> pixels;
    for (int y = 2; y < 200; y += 3)
    {
      for (int x = 2; x < 200; x += 3)
      {
        pixels.push_back({ x, y });
      }
    }
    std::string error;
    const std::vector<json> probes = Probe({ file.string(), "--size", "200x200", "--shading",
                                             ToString(r), "--light", "directional:-0.3,-0.5,-1" },
      pixels, error);
    ASSERT_EQ(error, "");
    int mapped = 0;
    double largest = 0;
    for (const json& p : probes)
    {
      if (!p.at("hit").get<bool>() || p.at("edge_distance").get<double>() < 1.5)
      {
        continue;
      }
      mapped += p.contains("normal_map") ||
        (p.contains("vertices") && p.at("vertices")[0].contains("normal_map"));
      const Rgb difference = Vec(p.at("rendered")) - Vec(p.at("oracle"));
      for (double d : difference)
      {
        largest = std::max(largest, std::abs(d));
      }
    }
    EXPECT_LT(largest, 1e-4);
    EXPECT_GT(mapped, 40);
  }
}

// A scene file's shots, its normal map relative to the file with a scale,
// then without one, then another filter: each shot is its own render,
// and the picture names the map with its scale (the metadata).
TEST(NormalMapBatch, EachShotMapsAsItsOwnRender)
{
  TempDir dir;
  Scene s;
  s.NormalMap = NormalMapKind::Pattern; // an OFF, with texture coordinates
  const std::string mesh = SceneArguments(s, dir).front();
  const std::string normals = (dir / "normals.png").string();
  ExpectEachShotIsItsOwnRender(dir,
    R"({ "mesh": ")" + mesh + R"(", "normal_map": "normals.png:0.5", "size": [64, 64],
         "material": "chrome",
         "shots": [ {}, { "normal_map": "normals.png" }, { "texture_filter": "nearest" },
                    { "normal_map": "none" } ] })",
    mesh,
    { { "--normal-map", normals + ":0.5" }, { "--normal-map", normals },
      { "--normal-map", normals + ":0.5", "--texture-filter", "nearest" },
      { "--normal-map", "none" } });
  const json described = json::parse(ReadImage(dir / "shot0.exr").Description);
  EXPECT_EQ(described.at("normal_map").at("image"), (dir / "normals.png").string());
  EXPECT_EQ(described.at("normal_map").at("scale"), 0.5);
  EXPECT_NE(ReadImage(dir / "shot0.exr").Pixels, ReadImage(dir / "shot1.exr").Pixels);
  EXPECT_NE(ReadImage(dir / "shot0.exr").Pixels, ReadImage(dir / "shot2.exr").Pixels);
}
