// `shadelab check-shader`: the generated stages given back agree with the
// oracle; each of five mistakes a student makes in the fragment stage does
// not, and the pixel it names is one where that mistake matters, as the
// generated program's probe there shows.
#include "cli_test_support.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>

using namespace shadelab_test;
using nlohmann::json;

namespace
{
// Two lights, one behind the torus's far side from the camera's view, so
// that N.L is negative on a visible part of the surface.
const std::vector<std::string> Scene = { "--size", "160x120", "--light", "point:3,2,5", "--light",
  "directional:1,1,-1" };

std::vector<std::string> With(std::vector<std::string> args, const std::vector<std::string>& more)
{
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

// The phong-blinn fragment stage of Scene plus `extra`, dumped.
std::string Dumped(const TempDir& dir, const std::vector<std::string>& extra)
{
  const RunResult r = RunShadelab(
    With(With({ "render", TestMesh("torus.obj").string(), "-o", (dir / "dumped.png").string(),
                "--dump-shaders", (dir / "glsl").string() },
           Scene),
      extra));
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  return Slurp(dir / "glsl" / "phong-blinn.frag");
}

std::string Edited(std::string text, const std::string& from, const std::string& to)
{
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "the generated stage has no '" << from << "'";
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

struct Checked
{
  int ExitCode = -1;
  json Result;
};

Checked Check(const TempDir& dir, const std::string& fragment,
  const std::vector<std::string>& extra, const std::vector<std::string>& more = {})
{
  WriteText(dir / "mine.frag", fragment);
  const RunResult r =
    RunShadelab(With(With(With({ "check-shader", TestMesh("torus.obj").string(), "--json",
                                 "--fragment-shader", (dir / "mine.frag").string() },
                            Scene),
                       extra),
      more));
  Checked c;
  c.ExitCode = r.ExitCode;
  EXPECT_TRUE(r.Stderr.empty()) << r.Stderr;
  c.Result = json::parse(r.Stdout, nullptr, false);
  EXPECT_FALSE(c.Result.is_discarded()) << r.Stdout;
  return c;
}

bool AnyLight(const json& probe, const std::function<bool(const json&)>& holds)
{
  for (const json& light : probe.at("lights"))
  {
    if (holds(light))
    {
      return true;
    }
  }
  return false;
}

double LargestSpecular(const json& probe)
{
  double most = 0;
  for (const json& light : probe.at("lights"))
  {
    if (light.contains("specular"))
    {
      most = std::max(most, light.at("specular").at(0).get<double>());
    }
  }
  return most;
}

// The length of the normal interpolated from the triangle's vertex normals
// at the pixel, before it is renormalised.
double InterpolatedLength(const json& probe)
{
  double n[3] = { 0, 0, 0 };
  for (const json& vertex : probe.at("vertices"))
  {
    for (int c = 0; c < 3; ++c)
    {
      n[c] += vertex.at("weight").get<double>() * vertex.at("mesh_normal").at(c).get<double>();
    }
  }
  return std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

struct Mistake
{
  const char* Name;
  std::vector<std::pair<std::string, std::string>> Edits;
  std::vector<std::string> Scene;                  // what makes it show
  std::function<bool(const json&)> MattersAtWorst; // of the generated program's probe there
};

std::vector<Mistake> Mistakes()
{
  const auto backLit = [](const json& probe)
  {
    return AnyLight(
      probe, [](const json& light) { return light.at("n_dot_l").get<double>() <= 0; });
  };
  const auto specular = [](const json& probe) { return LargestSpecular(probe) > 0.01; };
  return {
    { "N.L not clamped", { { "NdotL > shadelabGrazingLimit", "NdotL > -2.0" } }, {}, backLit },
    { "the normal not renormalised",
      { { "shadelabN = normalVCVSOutput / shadelabLength;", "shadelabN = normalVCVSOutput;" } }, {},
      [](const json& probe) { return InterpolatedLength(probe) < 0.999; } },
    { "H not normalised", { { "vec3 H = sum / len;", "vec3 H = sum;" } }, {}, specular },
    // A low shininess, so that where N.L < 0 the half vector can still face N enough to show.
    { "the specular term without the N.L > 0 case",
      { { "distance > shadelabTinyLength && NdotL > shadelabGrazingLimit",
          "distance > shadelabTinyLength" },
        { "vec3 term = NdotL * shadelabKd;", "vec3 term = max(NdotL, 0.0) * shadelabKd;" } },
      { "--ns", "2" }, backLit },
    { "V constant under a perspective camera",
      { { "if (shadelabOrthographic == 0)", "if (shadelabOrthographic == 2)" } }, {}, specular },
  };
}
}

TEST(CheckShader, TheGeneratedStagesAgreeWithTheOracle)
{
  TempDir dir;
  const Checked c = Check(dir, Dumped(dir, {}), {}, { "-o", (dir / "heat.png").string() });
  EXPECT_EQ(c.ExitCode, 0);
  EXPECT_TRUE(c.Result.at("agrees").get<bool>());
  EXPECT_GT(c.Result.at("compared").get<long long>(), 1000);
  EXPECT_EQ(c.Result.at("own").at("beyond_bound").get<long long>(), 0);
  EXPECT_EQ(c.Result.at("own"), c.Result.at("generated")) << "the same program, the same errors";
  const Image heat = ReadImage(dir / "heat.png");
  EXPECT_GT(heat.Width, 3 * 160) << "yours, generated and the heat map side by side";
}

TEST(CheckShader, EachTypicalMistakeFailsWhereItMatters)
{
  TempDir dir;
  for (const Mistake& m : Mistakes())
  {
    SCOPED_TRACE(m.Name);
    std::string fragment = Dumped(dir, m.Scene);
    for (const auto& [from, to] : m.Edits)
    {
      fragment = Edited(fragment, from, to);
    }
    const Checked c = Check(dir, fragment, m.Scene);
    EXPECT_EQ(c.ExitCode, 1);
    EXPECT_FALSE(c.Result.at("agrees").get<bool>());
    EXPECT_GT(c.Result.at("own").at("beyond_bound").get<long long>(), 0);
    EXPECT_EQ(c.Result.at("generated").at("beyond_bound").get<long long>(), 0);
    const json& worst = c.Result.at("worst_probe");
    EXPECT_EQ(worst.at("pixel"), c.Result.at("own").at("worst_pixel"));
    EXPECT_TRUE(m.MattersAtWorst(worst)) << worst.dump();
  }
}

TEST(CheckShader, WithoutStagesIsAUsageError)
{
  const RunResult r = RunShadelab({ "check-shader", TestMesh("torus.obj").string() });
  EXPECT_EQ(r.ExitCode, 2);
  EXPECT_NE(r.Stderr.find("--fragment-shader FILE"), std::string::npos) << r.Stderr;
}

// --specular-form literal writes the lecture's pow(max(N.H, 0), ns): float
// holds it to the oracle at a low shininess, and at ns = 1e4 its rounding
// of N.H near 1 (the largest float below 1 is 1 - 2^-24) bands the
// highlight beyond the bound, where the stable form stays within it.
TEST(CheckShader, TheLiteralSpecularFormPartsFromTheOracleAtHighShininess)
{
  TempDir dir;
  const std::string literal = Dumped(dir, { "--specular-form", "literal" });
  EXPECT_NE(literal.find("pow(max(dot(N, H), 0.0), shadelabNs)"), std::string::npos);
  EXPECT_EQ(literal.find("shadelabSpecularFalloff"), std::string::npos);
  const Checked low = Check(dir, literal, { "--ns", "10" });
  EXPECT_EQ(low.ExitCode, 0);
  const Checked high = Check(dir, literal, { "--ns", "10000" });
  EXPECT_EQ(high.ExitCode, 1);
  EXPECT_GT(high.Result.at("own").at("beyond_bound").get<long long>(), 0);
  EXPECT_EQ(high.Result.at("generated").at("beyond_bound").get<long long>(), 0);
  EXPECT_GT(LargestSpecular(high.Result.at("worst_probe")), 0.01);
}

// probe renders with the form it is given and says so: at the literal
// form's worst pixel its rendered value parts from the oracle, where the
// stable form's agrees.
TEST(CheckShader, ProbeExplainsTheLiteralFormsPixel)
{
  TempDir dir;
  const Checked high =
    Check(dir, Dumped(dir, { "--specular-form", "literal" }), { "--ns", "10000" });
  const json& at = high.Result.at("own").at("worst_pixel");
  const std::string pixel =
    std::to_string(at.at(0).get<int>()) + "," + std::to_string(at.at(1).get<int>());
  const auto probe = [&](const std::string& form)
  {
    const RunResult r = RunShadelab(With(
      With({ "probe", TestMesh("torus.obj").string(), "--json", "--pixel", pixel, "--ns", "10000" },
        Scene),
      { "--specular-form", form }));
    EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
    return json::parse(r.Stdout);
  };
  const auto largestError = [](const json& p)
  {
    double most = 0;
    for (int c = 0; c < 3; ++c)
    {
      most = std::max(
        most, std::abs(p.at("rendered").at(c).get<double>() - p.at("oracle").at(c).get<double>()));
    }
    return most;
  };
  const json literal = probe("literal");
  const json stable = probe("stable");
  EXPECT_EQ(literal.at("specular_form"), "literal");
  EXPECT_FALSE(stable.contains("specular_form"));
  EXPECT_EQ(literal.at("oracle"), stable.at("oracle"));
  EXPECT_GT(largestError(literal), 1e-4 * std::abs(literal.at("oracle").at(0).get<double>()));
  EXPECT_LT(
    largestError(stable), 1e-4 * std::max(std::abs(stable.at("oracle").at(0).get<double>()), 0.01));
}

// A scene file checks several scenes in one call, each shot with its own
// stages: two lighting setups and two materials whose dumped stages agree,
// and one whose N.L is unclamped, which fails alone and fails the file.
TEST(CheckShader, AScenesShotsAreCheckedInOneCall)
{
  const TempDir dir;
  const std::string two = Dumped(dir, {}); // Scene's two lights
  WriteText(dir / "two.frag", two);
  WriteText(dir / "unclamped.frag", Edited(two, "NdotL > shadelabGrazingLimit", "NdotL > -2.0"));
  const RunResult one =
    RunShadelab({ "render", TestMesh("torus.obj").string(), "-o", (dir / "one.png").string(),
      "--size", "160x120", "--light", "point:3,0,1", "--dump-shaders", (dir / "one").string() });
  ASSERT_EQ(one.ExitCode, 0) << one.Stderr;
  const std::string lights =
    R"("lights": [{"kind": "point", "position": [3, 2, 5]}, {"kind": "directional", "direction": [1, 1, -1]}])";
  const auto shot = [&](const std::string& stage, const std::string& more)
  { return R"({"fragment_shader": ")" + (dir / stage).string() + "\", " + more + "}"; };
  const auto write = [&](bool withMistake)
  {
    WriteText(dir / "scene.json",
      R"({"mesh": ")" + TestMesh("torus.obj").string() + R"(", "size": [160, 120], "shots": [)" +
        shot("one/phong-blinn.frag", R"("lights": [{"kind": "point", "position": [3, 0, 1]}])") +
        ", " + shot("two.frag", lights) + ", " +
        shot("two.frag", lights + R"(, "material": "gold")") +
        (withMistake ? ", " + shot("unclamped.frag", lights) : "") + "]}");
  };
  write(false);
  RunResult r = RunShadelab({ "check-shader", "--scene", (dir / "scene.json").string(), "--json" });
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  json result = json::parse(r.Stdout, nullptr, false);
  ASSERT_FALSE(result.is_discarded()) << r.Stdout;
  ASSERT_EQ(result.at("shots").size(), 3u);
  EXPECT_TRUE(result.at("agrees").get<bool>());
  for (const json& s : result.at("shots"))
  {
    EXPECT_TRUE(s.at("agrees").get<bool>()) << s.at("shot");
    EXPECT_GT(s.at("compared").get<long long>(), 1000);
  }

  write(true);
  r = RunShadelab({ "check-shader", "--scene", (dir / "scene.json").string(), "--json" });
  EXPECT_EQ(r.ExitCode, 1) << r.Stderr;
  result = json::parse(r.Stdout, nullptr, false);
  ASSERT_FALSE(result.is_discarded()) << r.Stdout;
  ASSERT_EQ(result.at("shots").size(), 4u);
  EXPECT_FALSE(result.at("agrees").get<bool>());
  EXPECT_TRUE(result.at("shots")[2].at("agrees").get<bool>());
  EXPECT_FALSE(result.at("shots")[3].at("agrees").get<bool>());
  EXPECT_NE(
    result.at("shots")[3].at("shot").get<std::string>().find("shots[3]"), std::string::npos);

  // A shot that names no stage is refused before anything is checked.
  WriteText(
    dir / "scene.json", R"({"mesh": ")" + TestMesh("torus.obj").string() + R"(", "shots": [{}]})");
  r = RunShadelab({ "check-shader", "--scene", (dir / "scene.json").string() });
  EXPECT_EQ(r.ExitCode, 1);
  EXPECT_NE(r.Stderr.find("shots[0]: names no stage to check"), std::string::npos) << r.Stderr;
  EXPECT_TRUE(r.Stdout.empty()) << r.Stdout;
}
