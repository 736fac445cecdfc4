// Nothing lost: on a file system that fills up (a small tmpfs, mounted by
// the test when it runs as root, as CI does) and under a file-size limit
// (RLIMIT_FSIZE, no privileges needed), every kind of output shadelab writes
// either appears whole or not at all, no temporary is left behind, each
// failure is reported once with its own cause, and the exit status says so.
// Also: temporaries left by a killed run are never taken for outputs and are
// removed by the next run that writes the same output.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/mount.h>
#include <sys/resource.h>
#include <unistd.h>

#include <fstream>
#include <iterator>
#include <set>

using namespace shadelab_test;
namespace fs = std::filesystem;

namespace
{
// A tmpfs of `bytes` on a fresh folder, unmounted by the destructor. Mounting
// needs root: Mounted() says whether it worked.
class SmallDisk
{
public:
  explicit SmallDisk(int kibibytes)
  {
    this->IsMounted = mount("shadelab-test", this->Dir.path().c_str(), "tmpfs", 0,
                        ("size=" + std::to_string(kibibytes) + "k").c_str()) == 0;
  }
  ~SmallDisk()
  {
    if (this->IsMounted)
    {
      umount2(this->Dir.path().c_str(), MNT_DETACH);
    }
  }
  bool Mounted() const { return this->IsMounted; }
  fs::path operator/(const std::string& name) const { return this->Dir / name; }
  std::vector<std::string> Files() const { return this->Dir.Files(); }

private:
  TempDir Dir;
  bool IsMounted = false;
};

#define NEEDS_ROOT_FOR(disk)                                                                       \
  if (!(disk).Mounted())                                                                           \
  {                                                                                                \
    GTEST_SKIP() << "mounting a small tmpfs needs root (CI runs as root); the file-size limit "    \
                    "tests cover the same paths without it";                                       \
  }

// Lowers this process's file-size limit while it lives; the shadelab
// processes started meanwhile inherit it (the test itself writes nothing then).
class FileSizeLimit
{
public:
  explicit FileSizeLimit(rlim_t bytes)
  {
    getrlimit(RLIMIT_FSIZE, &this->Old);
    const rlimit lower{ bytes, this->Old.rlim_max };
    setrlimit(RLIMIT_FSIZE, &lower);
  }
  ~FileSizeLimit() { setrlimit(RLIMIT_FSIZE, &this->Old); }

private:
  rlimit Old{};
};

const std::string Mesh = TestMesh("teapot.obj").string();
const std::string NoSpace = "cannot write: No space left on device";
const std::string TooLarge = "cannot write: File too large";

std::size_t Count(const std::string& text, const std::string& part)
{
  std::size_t n = 0;
  for (auto at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
  {
    ++n;
  }
  return n;
}

// No temporary of OutputFile's ("NAME.tmp-...") among files.
void ExpectNoTemporaries(const std::vector<std::string>& files)
{
  for (const std::string& name : files)
  {
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << "left behind: " << name;
  }
}

RunResult Render(const fs::path& out, const std::string& size)
{
  return RunShadelab({ "render", Mesh, "-o", out.string(), "--size", size });
}
}

TEST(NothingLost, AFullDiskKeepsTheWholePictureThatWasThereForEveryFormat)
{
  SmallDisk disk(16); // a 24x24 picture fits, an 800x800 one (34 kB and more) does not
  NEEDS_ROOT_FOR(disk);
  for (const std::string ext : { ".png", ".jpg", ".tif", ".exr" })
  {
    SCOPED_TRACE(ext);
    const fs::path out = disk / ("teapot" + ext);
    ASSERT_EQ(Render(out, "24x24").ExitCode, 0);
    const RunResult r = Render(out, "800x800");
    EXPECT_EQ(r.ExitCode, 1);
    EXPECT_EQ(r.Stderr, "shadelab: error: " + out.string() + ": " + NoSpace + "\n");
    const Image kept = ReadImage(out);
    EXPECT_EQ(kept.Width, 24) << "the picture from before is gone or broken";
    EXPECT_EQ(kept.Height, 24);
    ExpectNoTemporaries(disk.Files());
    fs::remove(out);
  }
}

TEST(NothingLost, AFileSizeLimitIsAnErrorLikeTheOthers)
{
  TempDir dir;
  for (const std::string ext : { ".png", ".jpg", ".tif", ".exr" })
  {
    SCOPED_TRACE(ext);
    const fs::path out = dir / ("teapot" + ext);
    RunResult r;
    {
      const FileSizeLimit limit(8192);
      r = Render(out, "800x800");
    }
    EXPECT_EQ(r.ExitCode, 1);
    EXPECT_EQ(r.Stderr, "shadelab: error: " + out.string() + ": " + TooLarge + "\n");
    EXPECT_FALSE(fs::exists(out));
  }
  ExpectNoTemporaries(dir.Files());
  EXPECT_TRUE(dir.Files().empty());
}

// normals writes through a memory file (VTK's writers open their own):
// VTK's message named that, /proc/PID/fd/N, instead of the output, or (VTP)
// was its executive's; an OBJ came out cut, with exit 0.
TEST(NothingLost, NormalsUnderAFileSizeLimitNameTheirOutput)
{
  TempDir dir;
  for (const std::string ext : { ".ply", ".vtp", ".obj" })
  {
    SCOPED_TRACE(ext);
    const fs::path out = dir / ("teapot" + ext);
    RunResult r;
    {
      const FileSizeLimit limit(8192);
      r = RunShadelab({ "normals", Mesh, "-o", out.string() });
    }
    EXPECT_EQ(r.ExitCode, 1);
    EXPECT_EQ(r.Stderr, "shadelab: error: " + out.string() + ": " + TooLarge + "\n");
    EXPECT_FALSE(fs::exists(out));
  }
  EXPECT_TRUE(dir.Files().empty());
}

// ffmpeg meeting the limit can end with status 0 and an MP4 cut short
// ("moov atom not found"): an error, and no file, like any other write.
TEST(NothingLost, AnMp4CutShortByAFileSizeLimitIsNoOutput)
{
  TempDir dir;
  const fs::path out = dir / "teapot.mp4";
  RunResult r;
  {
    const FileSizeLimit limit(8 << 10); // 30 frames of the teapot at 640x480 take about 19 KB
    r = RunShadelab(
      { "render", Mesh, "-o", out.string(), "--size", "640x480", "--orbit", "30", "--quiet" });
  }
  EXPECT_EQ(r.ExitCode, 1);
  EXPECT_EQ(r.Stderr.rfind("shadelab: error: " + out.string() + ": ", 0), 0u) << r.Stderr;
  EXPECT_EQ(Count(r.Stderr, "\n"), 1u) << r.Stderr;
  EXPECT_FALSE(fs::exists(out));
  ExpectNoTemporaries(dir.Files());
}

TEST(NothingLost, ABatchOnAFullDiskReportsEachShotAndWritesThoseThatFit)
{
  SmallDisk disk(16);
  NEEDS_ROOT_FOR(disk);
  TempDir dir;
  const std::string scene = (dir / "scene.json").string();
  WriteText(scene,
    R"({ "mesh": ")" + Mesh + R"(", "output": ")" + (disk / "{name}.png").string() +
      R"(", "shots": [ { "name": "big1", "size": [800, 800] }, { "name": "small1", "size": [24, 24] },)"
      R"( { "name": "big2", "size": [800, 800] }, { "name": "small2", "size": [24, 24] } ] })");
  const RunResult r = RunShadelab({ "render", "--scene", scene });
  EXPECT_EQ(r.ExitCode, 1);
  EXPECT_EQ(r.Stderr,
    "shadelab: error: " + scene + " shots[0]: " + (disk / "big1.png").string() + ": " + NoSpace +
      "\nshadelab: error: " + scene + " shots[2]: " + (disk / "big2.png").string() + ": " +
      NoSpace + "\nshadelab: 2 of 4 shots failed\n");
  const std::vector<std::string> written = disk.Files();
  EXPECT_EQ(std::set<std::string>(written.begin(), written.end()),
    (std::set<std::string>{ "small1.png", "small2.png" }));
  for (const char* name : { "small1.png", "small2.png" })
  {
    EXPECT_EQ(ReadImage(disk / name).Width, 24) << name;
  }
}

TEST(NothingLost, MeshesComparisonsShadersAndBenchResultsOnAFullDisk)
{
  SmallDisk disk(8);
  NEEDS_ROOT_FOR(disk);
  // normals: each mesh format (250 kB and more) fails whole.
  for (const std::string ext : { ".ply", ".vtp", ".obj" })
  {
    const fs::path out = disk / ("teapot" + ext);
    const RunResult r = RunShadelab({ "normals", Mesh, "-o", out.string() });
    EXPECT_EQ(r.ExitCode, 1) << ext;
    EXPECT_EQ(r.Stderr, "shadelab: error: " + out.string() + ": " + NoSpace + "\n");
  }
  // compare: one picture.
  const fs::path comparison = disk / "compare.png";
  const RunResult c =
    RunShadelab({ "compare", Mesh, "-o", comparison.string(), "--size", "300x300" });
  EXPECT_EQ(c.ExitCode, 1);
  EXPECT_EQ(c.Stderr, "shadelab: error: " + comparison.string() + ": " + NoSpace + "\n");
  EXPECT_TRUE(disk.Files().empty());

  // bench: each of its four outputs is tried and each failure reported; those
  // that fit are whole (the CSV reads back).
  const fs::path bench = disk / "bench";
  const RunResult b = RunShadelab({ "bench", "--quick", "--quiet", "--out", bench.string() });
  EXPECT_EQ(b.ExitCode, 1);
  std::size_t failures = 0;
  for (const char* name :
    { "speed_accuracy.csv", "speed_accuracy.json", "speed_accuracy.md", "speed_accuracy.png" })
  {
    const std::string line = "shadelab: error: " + (bench / name).string() + ": " + NoSpace + "\n";
    EXPECT_LE(Count(b.Stderr, line), 1u) << name;
    failures += Count(b.Stderr, line);
    if (fs::exists(bench / name) && std::string(name).find(".png") != std::string::npos)
    {
      EXPECT_GT(ReadImage(bench / name).Width, 0);
    }
  }
  EXPECT_GE(failures, 1u) << b.Stderr;
  EXPECT_EQ(Count(b.Stderr, "\n"), failures) << b.Stderr;
  ExpectNoTemporaries(FilesIn(bench));
}

TEST(NothingLost, DumpedShadersAreWholeOrAbsent)
{
  TempDir full, limited;
  ASSERT_EQ(RunShadelab({ "render", Mesh, "-o", (full / "a.png").string(), "--size", "24x24",
                          "--dump-shaders", (full / "glsl").string() })
              .ExitCode,
    0);
  RunResult r;
  {
    // The vertex shader (about 1.7 kB) fits, the fragment shader (about 6 kB) does not.
    const FileSizeLimit limit(4096);
    r = RunShadelab({ "render", Mesh, "-o", (limited / "a.png").string(), "--size", "24x24",
      "--dump-shaders", (limited / "glsl").string() });
  }
  EXPECT_EQ(r.ExitCode, 1);
  EXPECT_EQ(r.Stderr,
    "shadelab: error: " + (limited / "glsl" / "phong-blinn.frag").string() + ": " + TooLarge +
      "\n");
  for (const fs::path& file : fs::directory_iterator(limited / "glsl"))
  {
    EXPECT_EQ(Slurp(file), Slurp(full / "glsl" / file.filename())) << file;
  }
  ExpectNoTemporaries(FilesIn(limited / "glsl"));
  EXPECT_FALSE(fs::exists(limited / "a.png")) << "a shot whose shaders failed wrote a picture";
}

TEST(NothingLost, StaleTemporariesAreNeverOutputsAndTheNextRunRemovesThem)
{
  TempDir dir;
  // What a killed run leaves: a temporary nobody writes any more; and one
  // that a live writer (this test) holds locked; and one of another output.
  WriteText(dir / "a.png.tmp-99999-0", "half a picture");
  WriteText(dir / "a.png.tmp-99999-1", "being written");
  WriteText(dir / "b.png.tmp-99999-0", "another output's");
  const int held = open((dir / "a.png.tmp-99999-1").c_str(), O_RDONLY | O_CLOEXEC);
  ASSERT_GE(held, 0);
  ASSERT_EQ(flock(held, LOCK_EX), 0);

  // --skip-existing takes no temporary for the picture it would be.
  WriteText(dir / "scene.json",
    R"({ "mesh": ")" + Mesh + R"(", "size": [24, 24], "shots": [ { "output": "a.png" } ] })");
  const fs::path cwd = fs::current_path();
  fs::current_path(dir.path());
  const RunResult r =
    RunShadelab({ "render", "--scene", (dir / "scene.json").string(), "--skip-existing" });
  fs::current_path(cwd);
  close(held);
  EXPECT_EQ(r.ExitCode, 0) << r.Stderr;
  EXPECT_EQ(ReadImage(dir / "a.png").Width, 24);
  const std::vector<std::string> files = dir.Files();
  EXPECT_EQ(std::set<std::string>(files.begin(), files.end()),
    (std::set<std::string>{ "scene.json", "a.png", "a.png.tmp-99999-1", "b.png.tmp-99999-0" }));
}
