// The hands-on's stages of one's own (--vertex-shader, --fragment-shader):
// the stages --dump-shaders writes, given back, draw the same picture;
// an edited stage draws what its code says; a stage the driver refuses is
// reported at its lines, and nothing is written.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <sstream>

using namespace shadelab_test;

namespace
{
// "TEXT" replaced once in text; fails the test where it is not there.
std::string Edited(const std::string& text, const std::string& from, const std::string& to)
{
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "the generated stage has no '" << from << "'";
  return at == std::string::npos ? text : text.substr(0, at) + to + text.substr(at + from.size());
}

// The 1-based line of the first line of text that holds `part`.
int LineOf(const std::string& text, const std::string& part)
{
  std::istringstream lines(text);
  std::string line;
  for (int n = 1; std::getline(lines, line); ++n)
  {
    if (line.find(part) != std::string::npos)
    {
      return n;
    }
  }
  ADD_FAILURE() << "no line holds '" << part << "'";
  return 0;
}

const std::vector<std::string> TorusArgs(const TempDir& dir, const std::string& output)
{
  return { "render", TestMesh("torus.obj").string(), "-o", (dir / output).string(), "--size",
    "64x48", "--light", "point:2,3,4", "--light", "directional:1,0,-1" };
}

RunResult Render(const TempDir& dir, const std::string& output, std::vector<std::string> extra)
{
  std::vector<std::string> args = TorusArgs(dir, output);
  args.insert(args.end(), extra.begin(), extra.end());
  return RunShadelab(args);
}

// The number of 8-bit values that differ between two pictures of one size.
std::size_t DifferingValues(const Image& a, const Image& b)
{
  EXPECT_EQ(a.Pixels.size(), b.Pixels.size());
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.Pixels.size() && i < b.Pixels.size(); ++i)
  {
    n += a.Pixels[i] != b.Pixels[i];
  }
  return n;
}
}

// The pixels, not the files: a picture's metadata holds its command line.
TEST(OwnStages, DumpedStagesGivenBackDrawTheSamePicture)
{
  TempDir dir;
  const std::string texture = (TestMesh("teapot-texture.png")).string();
  for (const std::string rule : { "none", "flat", "gouraud", "phong" })
  {
    for (const std::string model : { "blinn", "phong" })
    {
      for (const bool textured : { false, true })
      {
        SCOPED_TRACE(rule + " " + model + (textured ? " textured" : ""));
        std::vector<std::string> scene = { "--shading", rule, "--reflection", model };
        if (textured)
        {
          scene.insert(scene.end(), { "--texture", texture });
        }
        std::vector<std::string> dump = scene;
        dump.insert(dump.end(), { "--dump-shaders", (dir / "generated").string() });
        const RunResult generated = Render(dir, "generated.png", dump);
        ASSERT_EQ(generated.ExitCode, 0) << generated.Stderr;
        const std::string name = rule + "-" + model;
        const std::filesystem::path vert = dir / "generated" / (name + ".vert");
        const std::filesystem::path frag = dir / "generated" / (name + ".frag");
        std::vector<std::string> own = scene;
        own.insert(own.end(),
          { "--vertex-shader", vert.string(), "--fragment-shader", frag.string(), "--dump-shaders",
            (dir / "own").string() });
        const RunResult given = Render(dir, "own.png", own);
        ASSERT_EQ(given.ExitCode, 0) << given.Stderr;
        EXPECT_EQ(
          DifferingValues(ReadImage(dir / "generated.png"), ReadImage(dir / "own.png")), 0u);
        EXPECT_EQ(Slurp(dir / "own" / (name + ".frag")), Slurp(frag)) << "the program that ran";
        EXPECT_EQ(Slurp(dir / "own" / (name + ".vert")), Slurp(vert));
      }
    }
  }
}

// The lecture's max(N.L, 0) taken out: where a light is behind the surface
// its diffuse term goes negative, so those pixels darken and no pixel brightens.
TEST(OwnStages, AnEditedStageDrawsWhatItsCodeSays)
{
  TempDir dir;
  struct Case
  {
    std::string Rule, Stage;
  };
  for (const Case& c : { Case{ "phong", "frag" }, Case{ "gouraud", "vert" } })
  {
    SCOPED_TRACE(c.Rule);
    ASSERT_EQ(Render(dir, "generated.png",
                { "--shading", c.Rule, "--dump-shaders", (dir / "generated").string() })
                .ExitCode,
      0);
    const std::string stage = Slurp(dir / "generated" / (c.Rule + "-blinn." + c.Stage));
    WriteText(dir / ("unclamped." + c.Stage),
      Edited(stage, "NdotL > shadelabGrazingLimit", "NdotL > -2.0"));
    const RunResult edited = Render(dir, "edited.png",
      { "--shading", c.Rule, c.Stage == "frag" ? "--fragment-shader" : "--vertex-shader",
        (dir / ("unclamped." + c.Stage)).string() });
    ASSERT_EQ(edited.ExitCode, 0) << edited.Stderr;
    const Image before = ReadImage(dir / "generated.png");
    const Image after = ReadImage(dir / "edited.png");
    ASSERT_EQ(before.Pixels.size(), after.Pixels.size());
    std::size_t darker = 0, brighter = 0;
    for (std::size_t i = 0; i < before.Pixels.size(); ++i)
    {
      darker += after.Pixels[i] < before.Pixels[i];
      brighter += after.Pixels[i] > before.Pixels[i];
    }
    EXPECT_GT(darker, 100u);
    EXPECT_EQ(brighter, 0u);
  }
}

// Mesa says "0:LINE(COLUMN): error: ...": each error becomes one line
// "shadelab: error: FILE:LINE: ..." at the line of the file as given.
TEST(OwnStages, ARefusedStageIsReportedAtItsLinesAndNothingIsWritten)
{
  TempDir dir;
  ASSERT_EQ(
    Render(dir, "generated.png", { "--dump-shaders", (dir / "generated").string() }).ExitCode, 0);
  for (const std::string stage : { "vert", "frag" })
  {
    SCOPED_TRACE(stage);
    const std::string generated = Slurp(dir / "generated" / ("phong-blinn." + stage));
    const std::string broken = Edited(generated, "void main()", "void main(()");
    const std::filesystem::path file = dir / ("broken." + stage);
    WriteText(file, broken);
    const RunResult r = Render(dir, "broken.png",
      { stage == "frag" ? "--fragment-shader" : "--vertex-shader", file.string() });
    EXPECT_EQ(r.ExitCode, 1);
    EXPECT_FALSE(std::filesystem::exists(dir / "broken.png"));
    const std::string expected = "shadelab: error: " + file.string() + ":" +
      std::to_string(LineOf(broken, "void main(()")) + ": ";
    EXPECT_EQ(r.Stderr.rfind(expected, 0), 0u) << r.Stderr;
    std::istringstream lines(r.Stderr);
    for (std::string line; std::getline(lines, line);)
    {
      EXPECT_EQ(line.rfind("shadelab: error: " + file.string() + ":", 0), 0u) << line;
    }
  }
}

// compare: a mode names its own stages, so one's own phong sits beside the
// generated one with their difference; a stage given for the comparison
// is --shading's rule's, and the other rules' panels keep their own code.
TEST(OwnStages, CompareSetsOnesOwnBesideTheGenerated)
{
  TempDir dir;
  ASSERT_EQ(
    Render(dir, "generated.png", { "--dump-shaders", (dir / "generated").string() }).ExitCode, 0);
  const std::string frag = Slurp(dir / "generated" / "phong-blinn.frag");
  WriteText(dir / "unclamped.frag", Edited(frag, "NdotL > shadelabGrazingLimit", "NdotL > -2.0"));
  const RunResult mine = RunShadelab({ "compare", TestMesh("torus.obj").string(), "-o",
    (dir / "mine.png").string(), "--size", "64x48", "--modes",
    "phong,phong:fragment_shader=" + (dir / "unclamped.frag").string(), "--diff", "1,2" });
  ASSERT_EQ(mine.ExitCode, 0) << mine.Stderr;
  EXPECT_EQ(mine.Stdout.find(" 0 of "), std::string::npos) << mine.Stdout;
  EXPECT_NE(mine.Stdout.find("pixels differ"), std::string::npos) << mine.Stdout;

  const RunResult same = RunShadelab({ "compare", TestMesh("torus.obj").string(), "-o",
    (dir / "same.png").string(), "--size", "64x48", "--modes", "flat,gouraud,phong", "--diff",
    "phong,flat", "--fragment-shader", (dir / "generated" / "phong-blinn.frag").string() });
  ASSERT_EQ(same.ExitCode, 0) << same.Stderr;
}
