// "Compiled in only when a scene uses it": the GLSL of scenes that use none
// of the effects added after the lecture's core (attenuation, and those to
// come), byte for byte as it was before them. The reviewed dumps are in
// tests/cli/glsl_baseline/, one .vert and .frag per scene; a change to them
// is a change to every such scene's program, to be reviewed as one. With
// SHADELAB_WRITE_GLSL_BASELINE=1 the test writes them instead of comparing.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

using namespace shadelab_test;

namespace
{
struct BaselineScene
{
  std::string Name;    // its files' names in the baseline folder
  std::string Mesh;    // a test mesh (TestMesh)
  std::string Output;  // the picture's extension: .png ends with the 8-bit capture's step
  std::string Program; // the dumped program's name (RULE-MODEL)
  std::vector<std::string> Arguments;
};

// Every light kind, every rule and both reflection models, a texture, lines
// over the surface, and a float picture.
std::vector<BaselineScene> Scenes()
{
  const std::vector<std::string> lights{ "--light", "point:1,2,9", "--light",
    "directional:-1,-1,-2:0.5,0.5,0.5", "--light", "spot:0,4,8:0,-0.4,-1:25:2:0.8,0.7,0.6" };
  std::vector<BaselineScene> scenes;
  for (const char* rule : { "none", "flat", "gouraud", "phong" })
  {
    for (const char* model : { "blinn", "phong" })
    {
      if (std::string(rule) == "none" && std::string(model) == "phong")
      {
        continue; // none has no specular term
      }
      BaselineScene s{ std::string("lights_") + rule + "_" + model, "teapot.obj", ".png",
        std::string(rule) + "-" + model, { "--shading", rule, "--reflection", model } };
      s.Arguments.insert(s.Arguments.end(), lights.begin(), lights.end());
      scenes.push_back(s);
    }
  }
  for (const char* rule : { "flat", "gouraud", "phong" })
  {
    scenes.push_back({ std::string("textured_") + rule, "teapot-textured.obj", ".png",
      std::string(rule) + "-blinn", { "--shading", rule } });
  }
  scenes.push_back({ "edges_phong", "teapot.obj", ".png", "phong-blinn", { "--edges" } });
  scenes.push_back({ "float_phong", "teapot.obj", ".exr", "phong-blinn", {} });
  return scenes;
}

std::filesystem::path Baseline()
{
  return std::filesystem::path(SHADELAB_SOURCE_DIR) / "tests" / "cli" / "glsl_baseline";
}
}

TEST(UnchangedGlsl, ScenesWithoutTheLaterEffectsKeepTheirProgramByteForByte)
{
  const char* write = std::getenv("SHADELAB_WRITE_GLSL_BASELINE");
  const bool writing = write && std::string(write) == "1";
  for (const BaselineScene& s : Scenes())
  {
    SCOPED_TRACE(s.Name);
    TempDir dir;
    std::vector<std::string> args{ "render", TestMesh(s.Mesh).string(), "-o",
      (dir / ("picture" + s.Output)).string(), "--size", "64x48", "--dump-shaders",
      (dir / "glsl").string() };
    args.insert(args.end(), s.Arguments.begin(), s.Arguments.end());
    const RunResult r = RunShadelab(args);
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    for (const char* stage : { ".vert", ".frag" })
    {
      const std::string dumped = Slurp(dir / "glsl" / (s.Program + stage));
      ASSERT_FALSE(dumped.empty()) << s.Program << stage;
      const std::filesystem::path reviewed = Baseline() / (s.Name + stage);
      if (writing)
      {
        std::filesystem::create_directories(Baseline());
        WriteText(reviewed, dumped);
        continue;
      }
      // EXPECT_TRUE, not EXPECT_EQ: a dump is some 300 lines; say where they part.
      const std::string expected = Slurp(reviewed);
      const auto first =
        std::mismatch(dumped.begin(), dumped.end(), expected.begin(), expected.end());
      const auto line = 1 + std::count(dumped.begin(), first.first, '\n');
      EXPECT_TRUE(dumped == expected)
        << reviewed.string() << " and the dump part at line " << line << ": the dump has\n"
        << std::string(first.first, std::find(first.first, dumped.end(), '\n'));
    }
  }
}
