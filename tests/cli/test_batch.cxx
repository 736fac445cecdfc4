// `shadelab render --scene` end to end: a batch equals its shots
// rendered one by one, shards cover every shot once, a failing shot does
// not stop the rest, the same scene gives the same bytes, and the pictures
// say which scene and shot they come from.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <fstream>
#include <iterator>
#include <set>
#include <sstream>

using namespace shadelab_test;

namespace
{
const std::vector<std::string> Rules{ "flat", "gouraud", "phong" };
const std::vector<std::string> Materials{ "brass", "bronze", "polished-bronze", "chrome", "copper",
  "polished-copper", "gold", "polished-gold" };

// 3 rules x 8 materials of the teapot at 160x120, written as out/{shading}-{material}.png.
std::string TwentyFourShots(const std::string& mesh)
{
  std::ostringstream scene;
  scene << R"({ "mesh": ")" << mesh << R"(", "output": "{shading}-{material}.png",)"
        << R"( "size": [160, 120], "camera": { "position": [5, 5, 9] }, "shots": [)";
  for (std::size_t i = 0; i < Rules.size() * Materials.size(); ++i)
  {
    scene << (i ? "," : "") << R"({ "shading": ")" << Rules[i / Materials.size()]
          << R"(", "material": ")" << Materials[i % Materials.size()] << R"(" })";
  }
  scene << "] }";
  return scene.str();
}

std::set<std::string> Names(const std::vector<std::string>& files)
{
  return { files.begin(), files.end() };
}
}

TEST(Batch, TwentyFourShotsEqualTheSameShotsRenderedOneByOne)
{
  TempDir dir;
  const std::string mesh = TestMesh("teapot.obj").string();
  WriteText(dir / "scene.json", TwentyFourShots(mesh));
  const RunResult batch = RunShadelab({ "render", "--scene", (dir / "scene.json").string(), "-o",
    (dir / "batch/{shading}-{material}.png").string() });
  ASSERT_EQ(batch.ExitCode, 0) << batch.Stderr;
  EXPECT_EQ(batch.Stderr, "") << "no progress bar when not on a terminal";
  for (const std::string& rule : Rules)
  {
    for (const std::string& material : Materials)
    {
      const auto single = dir / ("single-" + rule + "-" + material + ".png");
      const RunResult r = RunShadelab({ "render", mesh, "-o", single.string(), "--size", "160x120",
        "--camera-position", "5,5,9", "--shading", rule, "--material", material });
      ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
      const Image a = ReadImage(dir / "batch" / (rule + "-" + material + ".png"));
      const Image b = ReadImage(single);
      ASSERT_EQ(a.Width, 160) << rule << " " << material;
      EXPECT_EQ(a.Pixels, b.Pixels) << rule << " " << material << ": the batch's picture differs";
      EXPECT_GT(CountCovered(a), 1000u);
    }
  }
}

TEST(Batch, TheSameSceneGivesTheSameBytesAndSaysWhereItCameFrom)
{
  TempDir dir;
  WriteText(dir / "scene.json", TwentyFourShots(TestMesh("teapot.obj").string()));
  // The same command twice (the command line is in the metadata too).
  const std::vector<std::string> args{ "render", "--scene", (dir / "scene.json").string(), "-o",
    (dir / "a" / "{index}.png").string() };
  ASSERT_EQ(RunShadelab(args).ExitCode, 0);
  std::vector<std::string> first;
  for (int i = 0; i < 24; ++i)
  {
    first.push_back(Slurp(dir / "a" / ((i < 10 ? "0" : "") + std::to_string(i) + ".png")));
    ASSERT_GT(first.back().size(), 100u) << i;
  }
  ASSERT_EQ(RunShadelab(args).ExitCode, 0);
  for (int i = 0; i < 24; ++i)
  {
    EXPECT_EQ(Slurp(dir / "a" / ((i < 10 ? "0" : "") + std::to_string(i) + ".png")), first[i])
      << "shot " << i << " is not bit-identical";
  }
  const Image shot5 = ReadImage(dir / "a" / "05.png");
  EXPECT_NE(shot5.Description.find("\"shot\":\"" + (dir / "scene.json").string() + " shots[5]\""),
    std::string::npos)
    << shot5.Description;
  EXPECT_NE(shot5.Description.find("\"shading\":\"flat\""), std::string::npos);
  EXPECT_NE(shot5.Description.find("\"name\":\"polished-copper\""), std::string::npos);
}

TEST(Batch, ShardsCoverEveryShotExactlyOnce)
{
  TempDir dir;
  WriteText(dir / "scene.json", TwentyFourShots(TestMesh("teapot.obj").string()));
  std::multiset<std::string> all;
  for (int shard = 0; shard < 5; ++shard)
  {
    const auto folder = dir / ("shard" + std::to_string(shard));
    const RunResult r = RunShadelab({ "render", "--scene", (dir / "scene.json").string(), "-o",
      (folder / "{shading}-{material}.png").string(), "--shard", std::to_string(shard) + "/5" });
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    std::vector<std::string> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
    {
      files.push_back(entry.path().filename().string());
    }
    // Shot k goes to shard k mod 5.
    EXPECT_EQ(files.size(), shard < 4 ? 5u : 4u) << "shard " << shard;
    all.insert(files.begin(), files.end());
  }
  EXPECT_EQ(all.size(), 24u);
  EXPECT_EQ(std::set<std::string>(all.begin(), all.end()).size(), 24u) << "a shot in two shards";
}

TEST(Batch, ShardsAndRerunsWriteTheBytesOfOneWholeRun)
{
  TempDir dir;
  WriteText(dir / "scene.json", TwentyFourShots(TestMesh("teapot.obj").string()));
  const std::vector<std::string> whole{ "render", "--scene", (dir / "scene.json").string(), "-o",
    (dir / "out" / "{index}.png").string() };
  ASSERT_EQ(RunShadelab(whole).ExitCode, 0);
  std::vector<std::string> first;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out"))
  {
    first.push_back(entry.path().filename().string() + Slurp(entry.path()));
  }
  ASSERT_EQ(first.size(), 24u);
  std::filesystem::remove_all(dir / "out");
  // The options that pick the shots and silence the run are not in the
  // pictures' command line, so each shard writes what the whole run wrote.
  for (const char* shard : { "0/2", "1/2" })
  {
    std::vector<std::string> args = whole;
    args.insert(args.end(), { "--shard", shard, "--skip-existing", "-q", "--verbose" });
    ASSERT_EQ(RunShadelab(args).ExitCode, 0);
  }
  std::vector<std::string> sharded;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out"))
  {
    sharded.push_back(entry.path().filename().string() + Slurp(entry.path()));
  }
  EXPECT_EQ(std::set<std::string>(sharded.begin(), sharded.end()),
    std::set<std::string>(first.begin(), first.end()));
}

TEST(Batch, AFailingShotIsReportedAndTheOthersStillRun)
{
  TempDir dir;
  const std::string mesh = TestMesh("teapot.obj").string();
  WriteText(dir / "scene.json",
    R"({ "output": ")" + (dir / "{name}.png").string() + R"(", "size": [64, 48], "mesh": ")" +
      mesh +
      R"(", "shots": [ { "name": "a" }, { "name": "b", "mesh": "missing.obj" }, { "name": "c" }, )" +
      R"({ "name": "d", "output": "/proc/no/such/d.png" }, { "name": "e" }, )"
      R"({ "name": "f", "output": "/sys/shadelab/f.png" } ] })");
  const RunResult r = RunShadelab({ "render", "--scene", (dir / "scene.json").string() });
  EXPECT_EQ(r.ExitCode, 1);
  const std::string scene = (dir / "scene.json").string();
  EXPECT_NE(r.Stderr.find("shadelab: error: " + scene +
              " shots[1]: " + (dir / "missing.obj").string() + ": cannot open"),
    std::string::npos)
    << r.Stderr;
  EXPECT_NE(r.Stderr.find("shadelab: error: " + scene + " shots[3]: /proc/no/such/d.png: "),
    std::string::npos)
    << r.Stderr;
  // A folder that cannot be made says why (sysfs refuses it: "Operation not
  // permitted", or "Read-only file system"), not what that left: no folder.
  const std::string folder =
    "shots[5]: /sys/shadelab/f.png: cannot make the folder /sys/shadelab: ";
  EXPECT_NE(r.Stderr.find(folder), std::string::npos) << r.Stderr;
  EXPECT_EQ(r.Stderr.find(folder + "No such file"), std::string::npos) << r.Stderr;
  EXPECT_NE(r.Stderr.find("shadelab: 3 of 6 shots failed"), std::string::npos) << r.Stderr;
  EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 4) << r.Stderr;
  EXPECT_EQ(Names(dir.Files()), (std::set<std::string>{ "scene.json", "a.png", "c.png", "e.png" }));
}

// Pictures are encoded in parallel, several in flight: an error that only
// the writer finds (a JPEG cannot hold the transparent background) comes
// back for its own shot, in the shots' order, while the pictures around it
// are written.
TEST(Batch, WriterErrorsOfPicturesInFlightGoToTheirOwnShots)
{
  TempDir dir;
  const std::string scene = (dir / "scene.json").string();
  WriteText(scene,
    R"({ "mesh": ")" + TestMesh("teapot.obj").string() + R"(", "output": ")" +
      (dir / "{name}.png").string() +
      R"(", "size": [96, 64], "background": "transparent", "shots": [ { "name": "a" },)"
      R"( { "name": "b", "output": ")" +
      (dir / "b.jpg").string() + R"(" }, { "name": "c" }, { "name": "d", "output": ")" +
      (dir / "d.jpg").string() + R"(" }, { "name": "e" }, { "name": "f" } ] })");
  const RunResult r = RunShadelab({ "render", "--scene", scene });
  EXPECT_EQ(r.ExitCode, 1);
  const std::string problem =
    ": the jpeg format cannot store transparency (--background transparent: .png, .tif or .exr)\n";
  EXPECT_EQ(r.Stderr,
    "shadelab: error: " + scene + " shots[1]: " + (dir / "b.jpg").string() + problem +
      "shadelab: error: " + scene + " shots[3]: " + (dir / "d.jpg").string() + problem +
      "shadelab: 2 of 6 shots failed\n");
  EXPECT_EQ(Names(dir.Files()),
    (std::set<std::string>{ "scene.json", "a.png", "c.png", "e.png", "f.png" }));
}

TEST(Batch, EachShotReportsItsOwnErrorAndAWarningOnce)
{
  // Two differently broken meshes: each shot's error is its own, not the
  // one before it. An OBJ whose vn cover only some faces warns once, though
  // two shots (two normals settings) read it.
  TempDir dir;
  WriteText(dir / "lies.ply", "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n0 0 0\n");
  WriteText(dir / "index.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\n");
  WriteText(dir / "partial-vn.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nf 2 4 3\n");
  const std::string scene = (dir / "scene.json").string();
  WriteText(scene,
    R"({ "output": ")" + (dir / "{index}.png").string() +
      R"(", "size": [32, 32], "shots": [ { "mesh": "lies.ply" }, { "mesh": "index.obj" },)"
      R"( { "mesh": "partial-vn.obj" }, { "mesh": "partial-vn.obj", "weighting": "area" } ] })");
  const RunResult r = RunShadelab({ "render", "--scene", scene });
  EXPECT_EQ(r.ExitCode, 1);
  const std::string lies = (dir / "lies.ply").string();
  const std::string index = (dir / "index.obj").string();
  const std::string partial = (dir / "partial-vn.obj").string();
  EXPECT_EQ(r.Stderr,
    "shadelab: error: " + scene + " shots[0]: " + lies +
      ": element 'vertex' has no properties\n"
      "shadelab: error: " +
      scene + " shots[1]: " + index +
      ": line 3: face refers to vertex 7, but only 2 vertices are defined\n"
      "shadelab: warning: " +
      partial +
      ": some faces have no vn normals, so the file's normals are ignored\n"
      "shadelab: 2 of 4 shots failed\n");

  const RunResult quiet = RunShadelab({ "render", "--scene", scene, "--quiet" });
  EXPECT_EQ(quiet.Stderr.find("warning"), std::string::npos) << quiet.Stderr;
}

TEST(Batch, CommandLineMistakes)
{
  TempDir dir;
  WriteText(dir / "scene.json", TwentyFourShots(TestMesh("teapot.obj").string()));
  const std::string scene = (dir / "scene.json").string();
  struct Case
  {
    std::vector<std::string> Args;
    int Code;
    std::string Text;
  };
  const std::vector<Case> cases{
    { { "render", "--scene", scene, "--shading", "flat" }, 2, "--shading excludes --scene" },
    { { "render", "--scene", scene, "--shard", "5/5" }, 2,
      "'5/5' is not a shard I/N with 0 <= I < N" },
    { { "render", TestMesh("teapot.obj").string(), "-o", (dir / "x.png").string(), "--shard",
        "0/2" },
      2, "--shard requires --scene" },
    { { "render", TestMesh("teapot.obj").string() }, 2, "--output is required unless --scene" },
    { { "render", "-o", (dir / "x.png").string() }, 2, "MESH is required unless --scene" },
    { { "render", "--scene", (dir / "none.json").string() }, 1,
      "shadelab: error: " + (dir / "none.json").string() +
        ": cannot open: No such file or directory" },
  };
  for (const Case& c : cases)
  {
    const RunResult r = RunShadelab(c.Args);
    EXPECT_EQ(r.ExitCode, c.Code) << c.Text << ": " << r.Stderr;
    EXPECT_NE(r.Stderr.find(c.Text), std::string::npos) << r.Stderr;
    EXPECT_EQ(std::count(r.Stderr.begin(), r.Stderr.end(), '\n'), 1) << r.Stderr;
  }
  EXPECT_EQ(Names(dir.Files()), (std::set<std::string>{ "scene.json" }));
  const RunResult schema = RunShadelab({ "render", "--print-schema" });
  EXPECT_EQ(schema.ExitCode, 0);
  EXPECT_NE(schema.Stdout.find("\"title\": \"shadelab scene file\""), std::string::npos);
}
