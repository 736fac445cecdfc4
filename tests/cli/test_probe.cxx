// `shadelab probe` (doc/design.md, "Explaining a pixel"), pixel by pixel over
// the fine teapot (perspective) and the teapot (orthographic), for each rule and
// both reflection models, under point, directional and spot lights: the
// oracle is the sum of its terms, `rendered` is render's float picture at
// the pixel bit for bit, and away from edges the oracle is within the
// oracle tests' tolerance of it; off the mesh, the background. Gouraud's
// weights and vertex colours make the oracle; flat's face normal and
// provoking vertex are the mesh's. The text shows the numbers of the JSON.
// Bad input is one line.
#include "probe_support.h"

#include <vtkCellArray.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>

using namespace shadelab_test;
using nlohmann::json;

namespace
{
struct ProbeCase
{
  std::string Name;
  std::string Mesh;
  Shading Rule;
  std::vector<std::string> Options; // for render and probe alike, the rule's among them
  int Width, Height;
};

void PrintTo(const ProbeCase& c, std::ostream* os)
{
  *os << c.Name;
}

std::vector<ProbeCase> Cases()
{
  std::vector<ProbeCase> cases;
  for (Shading rule : LitRules)
  {
    for (Reflection model : { Reflection::BlinnPhong, Reflection::Phong })
    {
      // The fine teapot's 65,280 triangles, a few pixels each.
      ProbeCase c{ std::string("fine_") + ToString(rule) + "_" + ToString(model), Fine, rule,
        { "--shading", ToString(rule), "--reflection", ToString(model), "--material", "gold",
          "--zoom", "3" },
        640, 480 };
      c.Options.insert(c.Options.end(), TeapotLights.begin(), TeapotLights.end());
      cases.push_back(c);
    }
    ProbeCase c{ std::string("teapot_orthographic_") + ToString(rule), Teapot, rule,
      { "--shading", ToString(rule), "--material", "polished-copper", "--orthographic", "--view",
        "iso", "--zoom", "1.6" },
      480, 400 };
    c.Options.insert(c.Options.end(), TeapotLights.begin(), TeapotLights.end());
    cases.push_back(c);
    // Distance attenuation: the scene's on every point and spot light but
    // the first, which has its own.
    c.Name = std::string("teapot_attenuated_") + ToString(rule);
    c.Options.insert(c.Options.end(), { "--attenuation", "0.5,0.05,0.01" });
    *std::find(c.Options.begin(), c.Options.end(), TeapotLights[1]) += "@0.25,0,0.02";
    cases.push_back(c);
    // Fog, in perspective: the depth along the view direction, per fragment.
    ProbeCase fogged{ std::string("teapot_fog_perspective_") + ToString(rule), Teapot, rule,
      { "--shading", ToString(rule), "--material", "polished-copper", "--view", "iso", "--zoom",
        "1.6", "--fog", "exp2:0.07:0.3,0.35,0.4" },
      480, 400 };
    fogged.Options.insert(fogged.Options.end(), TeapotLights.begin(), TeapotLights.end());
    cases.push_back(fogged);
  }
  return cases;
}

std::vector<std::string> Common(const ProbeCase& c)
{
  std::vector<std::string> args{ c.Mesh, "--size",
    std::to_string(c.Width) + "x" + std::to_string(c.Height), "--background", Triple(Background) };
  args.insert(args.end(), c.Options.begin(), c.Options.end());
  return args;
}

// An attenuated light's distance and factor at the probed point, and its
// Il: the colour times the factor (and a spot's factor).
void ExpectAttenuation(const json& at)
{
  for (const json& l : at.at("lights"))
  {
    if (!l.contains("attenuation"))
    {
      continue;
    }
    const Vec3 c = Vec(l.at("attenuation_coefficients"));
    const double d = length(Vec(l.at("position")) - Vec(at.at("position")));
    EXPECT_NEAR(l.at("distance").get<double>(), d, 1e-12 * d);
    const double factor = 1 / (c[0] + c[1] * d + c[2] * d * d);
    EXPECT_NEAR(l.at("attenuation").get<double>(), factor, 1e-12 * factor);
    const double spot = l.value("spot_factor", 1.0);
    ExpectNear(Vec(l.at("Il")), factor * spot * Vec(l.at("color")), 1e-12, "Il attenuated");
  }
}

class ProbePixels : public testing::TestWithParam<ProbeCase>
{
};
}

// Every 7th pixel of each row and column.
TEST_P(ProbePixels, AgreeWithRenderAndTheOracle)
{
  const ProbeCase& c = GetParam();
  TempDir dir;
  std::vector<std::string> render{ "render", "-o", (dir / "out.exr").string() };
  const std::vector<std::string> common = Common(c);
  render.insert(render.end(), common.begin(), common.end());
  const RunResult rendered = RunShadelab(render);
  ASSERT_EQ(rendered.ExitCode, 0) << rendered.Stderr;
  const Image picture = ReadImage(dir / "out.exr");
  ASSERT_EQ(picture.Width, c.Width);

  std::vector<std::array<int, 2>> pixels;
  for (int y = 1; y < c.Height; y += 7)
  {
    for (int x = 2; x < c.Width; x += 7)
    {
      pixels.push_back({ x, y });
    }
  }
  std::string error;
  const std::vector<json> probes = Probe(common, pixels, error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(probes.size(), pixels.size());

  const auto mesh = ReadMesh(c.Mesh);
  const bool flat = c.Rule == Shading::Flat, gouraud = c.Rule == Shading::Gouraud;
  std::size_t compared = 0, background = 0;
  double worst = 0; // the largest |rendered - oracle| in units of the bound
  for (std::size_t i = 0; i < probes.size(); ++i)
  {
    const json& p = probes[i];
    const auto [x, y] = pixels[i];
    SCOPED_TRACE(PixelName(x, y));
    ASSERT_EQ(p.at("pixel"), json({ x, y }));
    // rendered: render's float output, bit for bit; stored: its 8-bit value.
    const Rgb got = Vec(p.at("rendered"));
    const Rgb want = Got(picture, x, y);
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_EQ(static_cast<float>(got[k]), static_cast<float>(want[k]));
      EXPECT_EQ(p.at("stored").at(k).get<int>(), std::lround(255 * std::clamp(got[k], 0.0, 1.0)));
    }
    const double edge = p.at("edge_distance").get<double>();
    if (!p.at("hit").get<bool>())
    {
      EXPECT_EQ(Vec(p.at("background")), Background);
      EXPECT_FALSE(p.contains("oracle") || p.contains("position") || p.contains("lights"));
      if (edge > EdgeMargin)
      {
        ++background;
        for (int k = 0; k < 3; ++k)
        {
          EXPECT_EQ(static_cast<float>(got[k]), static_cast<float>(Background[k]))
            << "off the mesh";
        }
      }
      continue;
    }
    for (const char* key : { "oracle", "position", "normal", "view", "ambient", "lights",
           "triangle", "material", "vertices" })
    {
      ASSERT_TRUE(p.contains(key)) << key;
    }
    const Rgb oracle = Vec(p.at("oracle"));
    // The rule's colour: the oracle, or with fog what the fog took.
    Rgb unfogged = oracle;
    if (p.contains("fog"))
    {
      const json& fog = p.at("fog");
      unfogged = Vec(fog.at("before"));
      const double f = fog.at("factor").get<double>();
      ExpectNear(f * unfogged + (1 - f) * Vec(fog.at("color")), oracle, 1e-12, "fogged");
      // The depth is the GPU's own (-z in view coordinates) where the
      // rendered value is held to the oracle below.
      const double x = 0.07 * fog.at("depth").get<double>();
      EXPECT_NEAR(f, std::exp(-x * x), 1e-12);
    }
    ExpectNear(TermsSum(p), unfogged, 1e-12, "ambient + terms against the oracle");
    if (!gouraud)
    {
      ExpectAttenuation(p); // gouraud's lights are the vertices', below
    }

    const auto corners = Corners(mesh, p.at("triangle").get<vtkIdType>());
    bool near = NearACase(p.at("lights"));
    Vec3 point{ 0, 0, 0 };
    double weights = 0;
    Rgb mixed{ 0, 0, 0 };
    for (int k = 0; k < 3; ++k)
    {
      const json& v = p.at("vertices").at(k);
      ASSERT_EQ(v.at("index").get<vtkIdType>(), corners[k]);
      const double w = v.at("weight").get<double>();
      weights += w;
      point = point + w * PointOf(mesh, corners[k]);
      if (gouraud)
      {
        const Rgb color = Vec(v.at("color"));
        ExpectNear(TermsSum(v), color, 1e-12, "a vertex's terms against its colour");
        ExpectAttenuation(v);
        mixed = mixed + w * color;
        near = near || NearACase(v.at("lights"));
      }
    }
    EXPECT_NEAR(weights, 1, 1e-12);
    if (gouraud)
    {
      ExpectNear(mixed, unfogged, 1e-12, "the vertex colours mixed by the weights");
    }
    if (flat)
    {
      // The provoking vertex is the triangle's last, lit with the face normal.
      EXPECT_EQ(p.at("provoking_vertex").get<vtkIdType>(), corners[2]);
      const Vec3 p0 = PointOf(mesh, corners[0]);
      EXPECT_EQ(Vec(p.at("position")), PointOf(mesh, corners[2]));
      const Vec3 face =
        normalize(cross(PointOf(mesh, corners[1]) - p0, PointOf(mesh, corners[2]) - p0));
      ExpectNear(Vec(p.at("face_normal")), face, 1e-12, "face normal");
      ExpectNear(Vec(p.at("normal")), p.at("front_facing").get<bool>() ? face : -face, 1e-12,
        "flat's normal");
    }
    else
    {
      // The point under the pixel centre, which gouraud and phong interpolate to.
      ExpectNear(Vec(p.at("position")), point, 1e-12 * (1 + length(point)), "position");
    }
    if (edge <= EdgeMargin || near)
    {
      continue;
    }
    ++compared;
    worst = std::max(worst, ExpectWithinTheBound(got, oracle));
  }
  std::cout << "[probe] " << c.Name << ": " << probes.size() << " pixels, " << compared
            << " compared with the oracle (worst " << worst << " of the bound), " << background
            << " background" << std::endl;
  EXPECT_GE(compared, 300u) << "too few pixels away from edges to say anything";
  EXPECT_GE(background, 300u);
}

INSTANTIATE_TEST_SUITE_P(Probe, ProbePixels, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<ProbeCase>& info) { return info.param.Name; });

// none: kd as it is, nothing lit.
TEST(Probe, NoneIsKdUnlit)
{
  std::string error;
  const std::vector<json> p =
    Probe({ Teapot, "--size", "64x48", "--shading", "none", "--kd", "0.3,0.5,0.7" }, { { 32, 24 } },
      error);
  ASSERT_EQ(error, "");
  ASSERT_EQ(p.size(), 1u);
  ASSERT_TRUE(p[0].at("hit").get<bool>());
  EXPECT_EQ(Vec(p[0].at("oracle")), (Rgb{ 0.3, 0.5, 0.7 }));
  EXPECT_EQ(Vec(p[0].at("unlit")), (Rgb{ 0.3, 0.5, 0.7 }));
  ExpectNear(Vec(p[0].at("rendered")), { 0.3, 0.5, 0.7 }, 1e-7, "rendered"); // float(kd)
  EXPECT_FALSE(p[0].contains("lights") || p[0].contains("ambient"));
}

// A texture: the probe gives where it was looked up and the texel, the kd
// that lit is the texel (--texture alone: factor 1), and the render agrees.
TEST(Probe, TexelIsTheKdThatLit)
{
  TempDir dir;
  // A unit square with (s, t) = (x, y); the 2 x 2 image's bottom left texel
  // is 8-bit (255, 128, 0): (1, 128/255, 0), as stored.
  WriteText(dir / "square.off",
    "STNOFF\n4 2 0\n0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n"
    "0 1 0 0 0 1 0 1\n3 0 1 2\n3 0 2 3\n");
  WriteImage8(dir / "four.png", 2, 2, { 0, 0, 255, 255, 255, 255, 255, 128, 0, 0, 255, 0 });
  for (Shading rule : { Shading::None, Shading::Phong })
  {
    SCOPED_TRACE(ToString(rule));
    std::string error;
    // Pixel (26, 30) of the 64x48 picture lies in the square's bottom left quarter.
    const std::vector<json> p =
      Probe({ (dir / "square.off").string(), "--size", "64x48", "--shading", ToString(rule),
              "--texture", (dir / "four.png").string(), "--texture-filter", "nearest" },
        { { 26, 30 } }, error);
    ASSERT_EQ(error, "");
    ASSERT_TRUE(p.at(0).at("hit").get<bool>());
    const auto st = p[0].at("texture_coordinates");
    EXPECT_LT(st.at(0).get<double>(), 0.5);
    EXPECT_LT(st.at(1).get<double>(), 0.5);
    EXPECT_EQ(p[0].at("kd_from"), "texture");
    ExpectNear(Vec(p[0].at("texel")), { 1, 128 / 255.0, 0 }, 1e-6, "texel");
    ExpectNear(Vec(p[0].at("kd")), Vec(p[0].at("texel")), 0, "kd");
    ExpectNear(Vec(p[0].at("rendered")), Vec(p[0].at("oracle")), 1e-5, "rendered");
  }
}

// The colour rule of the texture decoding: the stored values, whatever the
// file's colour space (OpenImageIO says sRGB of every PNG without a gAMA
// chunk, 16-bit ones too; linear of 16-bit TIFFs and of EXRs).
TEST(Probe, TexelsAreTheStoredValuesWhateverTheFilesColourSpace)
{
  TempDir dir;
  WriteText(dir / "square.off",
    "STNOFF\n4 2 0\n0 0 0 0 0 1 0 0\n1 0 0 0 0 1 1 0\n1 1 0 0 0 1 1 1\n"
    "0 1 0 0 0 1 0 1\n3 0 1 2\n3 0 2 3\n");
  const double v8 = 128 / 255.0, v16 = 32768 / 65535.0;
  const struct
  {
    const char* File;
    const char* Type;
    double Stored;
  } cases[] = { { "t8.png", "uint8", v8 }, { "t16.tif", "uint16", v16 },
    { "t16.png", "uint16", v16 }, { "t.exr", "float", 0.5 } };
  for (const auto& c : cases)
  {
    SCOPED_TRACE(c.File);
    const float stored = static_cast<float>(c.Stored);
    WriteImage(dir / c.File, 1, 1, { stored, stored, stored }, c.Type);
    std::string error;
    const std::vector<json> p = Probe({ (dir / "square.off").string(), "--size", "64x48",
                                        "--shading", "none", "--texture", (dir / c.File).string() },
      { { 32, 24 } }, error);
    ASSERT_EQ(error, "");
    ExpectNear(Vec(p.at(0).at("texel")), { c.Stored, c.Stored, c.Stored }, 1e-6, "texel");
  }
}

// Vertex colours are kd: the probe says so and which kd lit (flat the
// provoking vertex's, the others the weights' mix), each light's diffuse
// term is that kd's; --kd puts the material's back.
TEST(Probe, VertexColorsAreTheKdThatLit)
{
  TempDir dir;
  const auto mesh = dir / "rgb.ply";
  WriteRgbTriangle(mesh);
  const std::array<Rgb, 3> colors{ { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } } };
  for (Shading rule : { Shading::None, Shading::Flat, Shading::Gouraud, Shading::Phong })
  {
    SCOPED_TRACE(ToString(rule));
    std::string error;
    const std::vector<std::string> common{ mesh.string(), "--size", "64x48", "--shading",
      ToString(rule) };
    const std::vector<json> p = Probe(common, { { 32, 24 } }, error);
    ASSERT_EQ(error, "");
    ASSERT_TRUE(p.at(0).at("hit").get<bool>());
    EXPECT_EQ(p[0].at("kd_from"), "vertex colors");
    Rgb mixed{};
    for (int k = 0; k < 3; ++k)
    {
      const json& v = p[0].at("vertices").at(k);
      EXPECT_EQ(Vec(v.at("kd")), colors[v.at("index").get<int>()]);
      mixed = mixed + v.at("weight").get<double>() * colors[v.at("index").get<int>()];
    }
    const Rgb kd = rule == Shading::Flat ? colors[p[0].at("provoking_vertex").get<int>()] : mixed;
    ExpectNear(Vec(p[0].at("kd")), kd, 1e-12, "kd");
    if (rule == Shading::Flat || rule == Shading::Phong)
    {
      const json& light = p[0].at("lights").at(0);
      ExpectNear(Vec(light.at("diffuse")), light.at("n_dot_l").get<double>() * kd, 1e-12,
        "diffuse = kd*Il*(N.L), white light");
    }
    // The render agrees with the oracle (its float error, as the oracle tests bound it).
    ExpectNear(Vec(p[0].at("rendered")), Vec(p[0].at("oracle")), 1e-4, "rendered");

    std::vector<std::string> overridden = common;
    overridden.insert(overridden.end(), { "--kd", "0.3,0.5,0.7" });
    const std::vector<json> q = Probe(overridden, { { 32, 24 } }, error);
    ASSERT_EQ(error, "");
    EXPECT_EQ(q.at(0).at("kd_from"), "material");
    EXPECT_EQ(Vec(q[0].at("kd")), (Rgb{ 0.3, 0.5, 0.7 }));
  }
}

namespace
{
std::string Number(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", v); // the text's six significant digits
  return text;
}

std::string Numbers(const json& v)
{
  return "(" + Number(v.at(0).get<double>()) + ", " + Number(v.at(1).get<double>()) + ", " +
    Number(v.at(2).get<double>()) + ")";
}

// The text holds every number of one point's equation that the JSON holds.
void ExpectTermsShown(const std::string& text, const json& at, bool blinn)
{
  for (const char* key : { "normal", "view", "ambient" })
  {
    EXPECT_NE(text.find(Numbers(at.at(key))), std::string::npos) << key;
  }
  for (const json& l : at.at("lights"))
  {
    for (const char* key : { "L", "Il", "diffuse", "specular", blinn ? "H" : "R" })
    {
      EXPECT_NE(text.find(Numbers(l.at(key))), std::string::npos) << key;
    }
    for (const char* key : { "n_dot_l", "base", "power" })
    {
      EXPECT_NE(text.find(" = " + Number(l.at(key).get<double>())), std::string::npos) << key;
    }
  }
}
}

// The text, in the lecture's notation, shows the JSON's numbers: per rule
// and reflection model, a pixel on the mesh and one off it.
TEST(Probe, TextShowsTheNumbers)
{
  for (Shading rule : LitRules)
  {
    for (Reflection model : { Reflection::BlinnPhong, Reflection::Phong })
    {
      const bool blinn = model == Reflection::BlinnPhong;
      std::vector<std::string> args{ Fine, "--size", "160x120", "--shading", ToString(rule),
        "--reflection", ToString(model), "--background", Triple(Background) };
      args.insert(args.end(), TeapotLights.begin(), TeapotLights.end());
      std::string error;
      const std::vector<json> p = Probe(args, { { 80, 60 }, { 2, 2 } }, error);
      ASSERT_EQ(error, "");
      ASSERT_EQ(p.size(), 2u);
      ASSERT_TRUE(p[0].at("hit").get<bool>());
      ASSERT_FALSE(p[1].at("hit").get<bool>());
      args.insert(args.begin(), "probe");
      args.insert(args.end(), { "--pixel", "80,60", "--pixel", "2,2" });
      const RunResult r = RunShadelab(args);
      ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
      const std::string& text = r.Stdout;
      SCOPED_TRACE(text);
      const std::string base = blinn ? "(N.H)^ns" : "(V.R)^ns";
      for (const std::string& notation : { std::string("ka*Ia = "), std::string("N.L = "),
             std::string("kd*Il*(N.L) = "), base + " = ", "ks*Il*" + base + " = " })
      {
        EXPECT_NE(text.find(notation), std::string::npos) << notation;
      }
      for (const json& q : p)
      {
        EXPECT_NE(text.find("rendered = " + Numbers(q.at("rendered"))), std::string::npos);
        EXPECT_NE(text.find("stored = " + Numbers(q.at("stored"))), std::string::npos);
      }
      EXPECT_NE(text.find(" = " + Numbers(p[0].at("oracle"))), std::string::npos);
      EXPECT_NE(text.find("= " + Numbers(p[0].at("position"))), std::string::npos);
      EXPECT_NE(text.find("background = " + Numbers(p[1].at("background"))), std::string::npos);
      if (rule == Shading::Gouraud)
      {
        for (int k = 0; k < 3; ++k)
        {
          const json& v = p[0].at("vertices").at(k);
          EXPECT_NE(
            text.find("C" + std::to_string(k) + " = " + Numbers(v.at("color"))), std::string::npos);
          ExpectTermsShown(text, v, blinn);
        }
      }
      else
      {
        ExpectTermsShown(text, p[0], blinn);
      }
    }
  }
}

// Each bad command line: its exit status and what its one line must name.
TEST(Probe, BadInputIsOneLine)
{
  const std::string mesh = Teapot;
  struct Bad
  {
    std::vector<std::string> Args;
    int ExitCode;
    std::vector<std::string> Words;
  };
  const std::vector<Bad> cases{
    { { mesh, "--size", "64x48", "--pixel", "64,0" }, 2, { "--pixel", "64,0", "outside" } },
    { { mesh, "--size", "64x48", "--pixel", "0,48" }, 2, { "--pixel", "0,48", "outside" } },
    { { mesh, "--pixel", "1" }, 2, { "--pixel", "'1'" } },
    { { mesh, "--pixel", "a,b" }, 2, { "--pixel", "a,b" } },
    { { mesh, "--pixel", "-1,3" }, 2, { "--pixel", "-1,3" } },
    { { mesh, "--pixel", "1,2,3" }, 2, { "--pixel", "1,2,3" } },
    { { mesh, "--pixel", "1.5,2" }, 2, { "--pixel", "1.5,2" } },
    { { mesh, "--pixel", "" }, 2, { "--pixel" } },
    { { mesh }, 2, { "--pixel" } },
    { { "--pixel", "1,1" }, 2, { "MESH" } },
    { { mesh, "--pixel", "1,1", "--ssaa", "2" }, 2, { "--ssaa" } },
    { { "/nonexistent/nope.obj", "--pixel", "1,1" }, 1, { "nope.obj", "No such file" } },
  };
  for (const Bad& bad : cases)
  {
    std::vector<std::string> args{ "probe" };
    args.insert(args.end(), bad.Args.begin(), bad.Args.end());
    const RunResult r = RunShadelab(args);
    SCOPED_TRACE(r.Stderr);
    EXPECT_EQ(r.ExitCode, bad.ExitCode);
    EXPECT_EQ(r.Stdout, "");
    ASSERT_FALSE(r.Stderr.empty());
    EXPECT_EQ(r.Stderr.find('\n'), r.Stderr.size() - 1) << "one line";
    EXPECT_EQ(r.Stderr.rfind("shadelab: error: ", 0), 0u);
    for (const std::string& word : bad.Words)
    {
      EXPECT_NE(r.Stderr.find(word), std::string::npos) << word;
    }
  }
}
