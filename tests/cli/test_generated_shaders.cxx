// "Model only what a scene requires": the GLSL that --dump-shaders writes is
// the code that ran, generated for the scene.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

using namespace shadelab_test;

namespace
{
bool Contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

struct Dumped
{
  std::string Vertex, Fragment;
};

Dumped Render(const TempDir& dir, const std::string& name, std::vector<std::string> extra,
  const std::filesystem::path& mesh = TestMesh("torus.obj"))
{
  std::vector<std::string> args = { "render", mesh.string(), "-o", (dir / "torus.png").string(),
    "--size", "48x48", "--dump-shaders", (dir / "glsl").string() };
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = RunShadelab(args);
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  return { Slurp(dir / "glsl" / (name + ".vert")), Slurp(dir / "glsl" / (name + ".frag")) };
}
}

TEST(GeneratedShaders, PhongLightsPerFragmentWithTheLightsOfTheScene)
{
  TempDir dir;
  const Dumped d = Render(dir, "phong-blinn",
    { "--shading", "phong", "--light", "point:1,1,1", "--light", "directional:0,-1,0" });
  EXPECT_TRUE(Contains(d.Fragment, "vec3 shadelabIlluminate(vec3 P, vec3 N)"));
  EXPECT_TRUE(Contains(d.Fragment, "uniform vec3 shadelabLightColor[2];"));
  EXPECT_TRUE(Contains(d.Fragment, "// light 0: point"));
  EXPECT_TRUE(Contains(d.Fragment, "// light 1: directional"));
  EXPECT_FALSE(Contains(d.Fragment, "// light 2"));
  EXPECT_FALSE(Contains(d.Fragment, "shadelabLightCosCutoff")) << "teapot code without a teapot";
  EXPECT_TRUE(Contains(d.Fragment, "vec3 H = sum / len;")) << "Blinn-Phong's halfway vector";
  EXPECT_FALSE(Contains(d.Vertex, "shadelabIlluminate")) << "phong lights per fragment only";
}

TEST(GeneratedShaders, PhongReflectionUsesTheReflectedVector)
{
  TempDir dir;
  const Dumped d = Render(dir, "phong-phong", { "--reflection", "phong" });
  EXPECT_TRUE(Contains(d.Fragment, "vec3 R = (2.0 * dot(N, L)) * N - L;"));
  EXPECT_FALSE(Contains(d.Fragment, "vec3 H ="));
}

TEST(GeneratedShaders, GouraudLightsInTheVertexStageOnly)
{
  TempDir dir;
  const Dumped d = Render(dir, "gouraud-blinn", { "--shading", "gouraud" });
  EXPECT_TRUE(Contains(d.Vertex, "shadelabFront = shadelabIlluminate("));
  EXPECT_TRUE(Contains(d.Vertex, "shadelabBack = shadelabIlluminate("));
  EXPECT_FALSE(Contains(d.Fragment, "shadelabIlluminate"));
  EXPECT_TRUE(Contains(d.Fragment, "gl_FrontFacing ? shadelabFront : shadelabBack"));
  EXPECT_TRUE(Contains(d.Vertex, "in vec3 normalMC;"));
}

// Flat: the provoking vertex's view position passed uninterpolated, the face
// normal read by the triangle's primitive id, the side it faces lit; VTK's
// point normals are not uploaded.
TEST(GeneratedShaders, FlatLightsAtTheProvokingVertexWithTheFaceNormal)
{
  TempDir dir;
  const Dumped d = Render(dir, "flat-blinn", { "--shading", "flat" });
  EXPECT_TRUE(Contains(d.Vertex, "flat out vec4 shadelabProvokingVC;"));
  EXPECT_TRUE(Contains(d.Vertex, "shadelabProvokingVC = vertexVCVSOutput;"));
  EXPECT_FALSE(Contains(d.Vertex, "shadelabIlluminate"));
  EXPECT_FALSE(Contains(d.Vertex, "normalMC"));
  EXPECT_TRUE(Contains(d.Fragment, "uniform samplerBuffer shadelabFaceNormals;"));
  EXPECT_TRUE(Contains(d.Fragment, "texelFetch(shadelabFaceNormals, gl_PrimitiveID).rgb"));
  EXPECT_TRUE(Contains(d.Fragment,
    "shadelabIlluminate(shadelabProvokingVC.xyz, gl_FrontFacing ? n / len : -n / len)"));
}

TEST(GeneratedShaders, NoSpecularCodeWhenKsIsZero)
{
  TempDir dir;
  const Dumped d = Render(dir, "phong-blinn", { "--ks", "0,0,0" });
  EXPECT_FALSE(Contains(d.Fragment, "shadelabKs"));
  EXPECT_FALSE(Contains(d.Fragment, "shadelabSpecularFalloff"));
}

TEST(GeneratedShaders, NoneDrawsOneColourWithoutNormals)
{
  TempDir dir;
  const Dumped d = Render(dir, "none-blinn", { "--shading", "none" });
  EXPECT_TRUE(Contains(d.Fragment, "fragOutput0 = vec4(shadelabKd, 1.0);"));
  EXPECT_FALSE(Contains(d.Fragment, "shadelabIlluminate"));
  EXPECT_FALSE(Contains(d.Vertex, "normalMC"));
}

TEST(GeneratedShaders, TextureCodeOnlyWithATexture)
{
  TempDir dir;
  const auto mesh = dir / "square.off";
  WriteText(mesh,
    "STNOFF\n4 2 0\n0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n"
    "0 1 0 0 0 1 0 1\n3 0 1 2\n3 0 2 3\n");
  WriteImage8(dir / "one.png", 1, 1, { 200, 100, 50 });
  for (const char* rule : { "none", "flat", "gouraud", "phong" })
  {
    SCOPED_TRACE(rule);
    const std::string name = std::string(rule) + "-blinn";
    const Dumped plain = Render(dir, name, { "--shading", rule }, mesh);
    EXPECT_FALSE(Contains(plain.Fragment + plain.Vertex, "shadelabTexture"));
    EXPECT_FALSE(Contains(plain.Fragment + plain.Vertex, "shadelabTCoord"));
    const Dumped textured =
      Render(dir, name, { "--shading", rule, "--texture", (dir / "one.png").string() }, mesh);
    EXPECT_TRUE(Contains(textured.Fragment, "uniform sampler2D shadelabTexture;"));
    EXPECT_TRUE(Contains(textured.Fragment,
      "vec3 shadelabTexel = texture(shadelabTexture, shadelabTCoordVSOutput).rgb;"));
    EXPECT_TRUE(Contains(textured.Vertex, "shadelabTCoordVSOutput = shadelabTCoord;"));
    // Flat and gouraud light with the sums apart (gouraud per vertex, flat
    // at the provoking vertex); the fragment multiplies by its texel.
    const std::string r = rule;
    EXPECT_EQ(Contains(textured.Vertex, "shadelabIlluminateApart("), r == "gouraud");
    EXPECT_EQ(
      Contains(textured.Fragment, "shadelabIlluminateApart(shadelabProvokingVC.xyz"), r == "flat");
    EXPECT_EQ(Contains(textured.Fragment, "shadelabTexel * shadelabDiffuse"),
      r == "flat" || r == "gouraud");
  }
}

// A glTF metal's base colour texture colours ks (BoxTextured made a metal):
// phong's ks per fragment, flat's and gouraud's vertices lit with ks = 1 for
// the fragment to multiply (flat's in the fragment stage); none has no specular. --ks drops the ks
// texture, and --texture is kd's and ka's only.
TEST(GeneratedShaders, KsTextureCodeOnlyForATexturedMetal)
{
  TempDir dir;
  const auto metal = MetalBoxTextured(dir.path(), true);
  WriteImage8(dir / "one.png", 1, 1, { 200, 100, 50 });
  for (const char* rule : { "none", "flat", "gouraud", "phong" })
  {
    SCOPED_TRACE(rule);
    const std::string name = std::string(rule) + "-blinn";
    const Dumped textured = Render(dir, name, { "--shading", rule }, metal);
    const std::string r = rule;
    EXPECT_EQ(Contains(textured.Fragment, "uniform vec3 shadelabKsScale;"), r != "none");
    EXPECT_EQ(Contains(textured.Fragment,
                "  shadelabKs = shadelabKsFactor + shadelabKsScale * (shadelabTexel - 1.0);"),
      r == "phong");
    EXPECT_EQ(Contains(textured.Vertex, "const vec3 shadelabKs = vec3(1.0);"), r == "gouraud");
    EXPECT_EQ(Contains(textured.Fragment, "const vec3 shadelabKs = vec3(1.0);"), r == "flat");
    EXPECT_EQ(Contains(textured.Fragment,
                "(shadelabKsFactor + shadelabKsScale * (shadelabTexel - 1.0)) * shadelabSpecular"),
      r == "flat" || r == "gouraud");
    for (const std::vector<std::string>& extra :
      { std::vector<std::string>{ "--ks", "0.5,0.5,0.5" },
        std::vector<std::string>{ "--texture", (dir / "one.png").string() } })
    {
      std::vector<std::string> args{ "--shading", rule };
      args.insert(args.end(), extra.begin(), extra.end());
      const Dumped other = Render(dir, name, args, metal);
      EXPECT_FALSE(Contains(other.Fragment + other.Vertex, "shadelabKsScale")) << extra[0];
      EXPECT_FALSE(Contains(other.Vertex + other.Fragment, "shadelabKs = vec3(1.0);")) << extra[0];
    }
  }
}

TEST(GeneratedShaders, AnEightBitFileEndsWithTheCapturesQuantisation)
{
  TempDir dir;
  const std::string step = "fragOutput0 = shadelabQuantised(fragOutput0);";
  EXPECT_TRUE(Contains(Render(dir, "phong-blinn", {}).Fragment, step));
  std::filesystem::remove_all(dir / "glsl");
  const RunResult r = RunShadelab({ "render", TestMesh("torus.obj").string(), "-o",
    (dir / "torus.exr").string(), "--size", "48x48", "--dump-shaders", (dir / "glsl").string() });
  ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_FALSE(Contains(Slurp(dir / "glsl" / "phong-blinn.frag"), step)) << "floats: no step";
}

// --specular-form literal: the lecture's expressions as written, under
// either model and in either stage, and no stable falloff compiled in.
TEST(GeneratedShaders, TheLiteralSpecularFormReadsAsTheLecture)
{
  TempDir dir;
  const Dumped phong =
    Render(dir, "phong-phong", { "--reflection", "phong", "--specular-form", "literal" });
  EXPECT_TRUE(Contains(phong.Fragment, "vec3 R = reflect(-L, N); // shadelab: specular"));
  EXPECT_TRUE(Contains(phong.Fragment,
    "term += pow(max(dot(V, R), 0.0), shadelabNs) * shadelabKs; // shadelab: specular"));
  EXPECT_FALSE(Contains(phong.Fragment, "shadelabSpecularFalloff"));
  const Dumped gouraud =
    Render(dir, "gouraud-blinn", { "--shading", "gouraud", "--specular-form", "literal" });
  EXPECT_TRUE(Contains(gouraud.Vertex, "vec3 H = normalize(L + V); // shadelab: specular"));
  EXPECT_TRUE(Contains(gouraud.Vertex, "if (dot(N, H) > 0.0)"));
  EXPECT_FALSE(Contains(gouraud.Vertex, "shadelabSpecularD("));
}

// An environment's code only where it reflects something: in the stage
// that lights (gouraud's vertex stage, flat's and phong's fragment stage),
// marked for the shader panel; none without one, with ks zero, or under
// none, which does not light.
TEST(GeneratedShaders, EnvironmentCodeOnlyWhereItReflects)
{
  TempDir dir;
  WriteImage8(dir / "sky.png", 2, 1, { 200, 180, 40, 20, 60, 220 });
  const std::vector<std::string> sky{ "--environment", (dir / "sky.png").string() };
  for (const char* rule : { "none", "flat", "gouraud", "phong" })
  {
    SCOPED_TRACE(rule);
    const std::string r = rule;
    const std::string name = r + "-blinn";
    const Dumped plain = Render(dir, name, { "--shading", rule });
    EXPECT_FALSE(Contains(plain.Vertex + plain.Fragment, "shadelabEnvironment"));
    std::vector<std::string> args{ "--shading", rule };
    args.insert(args.end(), sky.begin(), sky.end());
    const Dumped reflecting = Render(dir, name, args);
    const std::string lit = r == "gouraud" ? reflecting.Vertex : reflecting.Fragment;
    const std::string unlit = r == "gouraud" ? reflecting.Fragment : reflecting.Vertex;
    EXPECT_EQ(Contains(lit, "uniform sampler2D shadelabEnvironment;"), r != "none");
    EXPECT_EQ(Contains(lit,
                "I += shadelabKs * shadelabEnvironmentAt((2.0 * dot(N, V)) * N - V); // shadelab: "
                "environment"),
      r != "none");
    EXPECT_FALSE(Contains(unlit, "shadelabEnvironment"));
    args.insert(args.end(), { "--ks", "0,0,0" });
    const Dumped dull = Render(dir, name, args);
    EXPECT_FALSE(Contains(dull.Vertex + dull.Fragment, "shadelabEnvironment"));
  }
}

// A normal map's lookup, or a bump map's (its heights one texel apart),
// is in the stage that takes the normal (gouraud's vertex stage, flat's
// and phong's fragment stage) and nowhere without one, under none, or
// drawing edges (which have no tangent plane).
TEST(GeneratedShaders, NormalMapCodeOnlyWhereItMapsNormals)
{
  TempDir dir;
  const auto mesh = dir / "square.off";
  WriteText(mesh, "STOFF\n4 2 0\n0 0 0 0 0\n1 0 0 1 0\n1 1 0 1 1\n0 1 0 0 1\n3 0 1 2\n3 0 2 3\n");
  WriteImage8(dir / "n.png", 2, 1, { 200, 110, 220, 128, 128, 255 });
  const std::string map = (dir / "n.png").string() + ":0.5";
  WriteImage8(dir / "h.png", 2, 1, { 10, 10, 10, 200, 200, 200 });
  const std::string heights = (dir / "h.png").string() + ":2";
  for (const char* rule : { "none", "flat", "gouraud", "phong" })
  {
    SCOPED_TRACE(rule);
    const std::string r = rule;
    const std::string name = r + "-blinn";
    const Dumped plain = Render(dir, name, { "--shading", rule }, mesh);
    EXPECT_FALSE(Contains(plain.Vertex + plain.Fragment, "Tangent"));
    const Dumped mapped = Render(dir, name, { "--shading", rule, "--normal-map", map }, mesh);
    const std::string lit = r == "gouraud" ? mapped.Vertex : mapped.Fragment;
    const std::string unlit = r == "gouraud" ? mapped.Fragment : mapped.Vertex;
    EXPECT_EQ(Contains(lit, "uniform sampler2D shadelabNormalMap;"), r != "none");
    EXPECT_EQ(Contains(lit, "); // shadelab: normal map\n"), r != "none");
    EXPECT_FALSE(Contains(unlit, "shadelabNormalMap"));
    const Dumped edges = Render(
      dir, name, { "--shading", rule, "--normal-map", map, "--representation", "wireframe" }, mesh);
    EXPECT_FALSE(Contains(edges.Vertex + edges.Fragment, "shadelabNormalMap"));
    EXPECT_FALSE(Contains(mapped.Vertex + mapped.Fragment, "bump map"));
    const Dumped bumped = Render(dir, name, { "--shading", rule, "--bump-map", heights }, mesh);
    const std::string bumpedLit = r == "gouraud" ? bumped.Vertex : bumped.Fragment;
    EXPECT_EQ(Contains(bumpedLit, "st + vec2(texel.x, 0.0), 0.0).r - h; // shadelab: bump map"),
      r != "none");
    EXPECT_EQ(Contains(bumpedLit, "); // shadelab: bump map\n"), r != "none");
    EXPECT_FALSE(Contains(bumped.Vertex + bumped.Fragment, "normal map"));
  }
}
