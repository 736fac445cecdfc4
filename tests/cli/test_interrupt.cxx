// Nothing lost: a batch stopped by SIGINT or SIGTERM leaves only
// whole pictures and says how far it got; --skip-existing then renders the
// rest and leaves the others alone.
#include "cli_test_support.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <thread>
#include <utility>
#include <vector>

using namespace shadelab_test;

namespace
{
constexpr int Shots = 120;

std::size_t Pictures(const std::filesystem::path& folder)
{
  std::size_t n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
  {
    n += entry.path().extension() == ".png";
  }
  return n;
}

void InterruptAndFinish(int signal, const std::string& name)
{
  TempDir dir;
  std::ostringstream scene;
  scene << R"({ "mesh": ")" << TestMesh("teapot.obj").string() << R"(", "output": ")"
        << (dir / "out/{index}.png").string() << R"(", "size": [320, 240], "shots": [)";
  for (int i = 0; i < Shots; ++i)
  {
    scene << (i ? "," : "") << R"({ "shading": ")" << (i % 2 ? "flat" : "phong") << R"(" })";
  }
  scene << "] }";
  WriteText(dir / "scene.json", scene.str());
  const std::vector<std::string> args{ "render", "--scene", (dir / "scene.json").string() };

  const int pid = StartShadelab(args, dir / "stdout", dir / "stderr");
  ASSERT_GT(pid, 0);
  // Stop it once some pictures are out, well before the end.
  const auto start = std::chrono::steady_clock::now();
  while (!std::filesystem::exists(dir / "out") || Pictures(dir / "out") < 5)
  {
    ASSERT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(60));
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(pid, signal);
  EXPECT_EQ(WaitShadelab(pid), 128 + signal);
  std::ifstream err(dir / "stderr");
  const std::string message(
    (std::istreambuf_iterator<char>(err)), std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("shadelab: interrupted (" + name + ") after "), std::string::npos)
    << message;
  EXPECT_NE(message.find("--skip-existing renders the rest"), std::string::npos) << message;

  // Only whole pictures, and no temporary files: the writer finished the
  // one it had (it ignores the signals), shadelab stopped between shots.
  std::map<std::string, std::filesystem::file_time_type> first;
  for (const auto& entry : std::filesystem::directory_iterator(dir / "out"))
  {
    const std::string file = entry.path().filename().string();
    ASSERT_EQ(entry.path().extension(), ".png") << "left behind: " << file;
    const Image image = ReadImage(entry.path());
    EXPECT_EQ(image.Width, 320) << file << " is not a whole picture";
    EXPECT_GT(CountCovered(image), 1000u) << file;
    first[file] = entry.last_write_time();
  }
  ASSERT_GE(first.size(), 5u);
  ASSERT_LT(first.size(), static_cast<std::size_t>(Shots)) << "it ran to the end: nothing tested";

  std::vector<std::string> again = args;
  again.push_back("--skip-existing");
  const RunResult rest = RunShadelab(again);
  ASSERT_EQ(rest.ExitCode, 0) << rest.Stderr;
  EXPECT_EQ(Pictures(dir / "out"), static_cast<std::size_t>(Shots));
  for (const auto& [file, time] : first)
  {
    EXPECT_EQ(std::filesystem::last_write_time(dir / "out" / file), time)
      << file << " was rendered again";
  }
}
}

TEST(Interrupt, SigintLeavesWholePicturesAndSkipExistingFinishes)
{
  InterruptAndFinish(SIGINT, "SIGINT");
}

TEST(Interrupt, SigtermLeavesWholePicturesAndSkipExistingFinishes)
{
  InterruptAndFinish(SIGTERM, "SIGTERM");
}

namespace
{
// The processes that pid started (its image writer), from /proc.
std::vector<int> Children(int pid)
{
  std::vector<int> children;
  const std::filesystem::path tasks = "/proc/" + std::to_string(pid) + "/task";
  std::error_code error;
  for (const auto& task : std::filesystem::directory_iterator(tasks, error))
  {
    std::ifstream list(task.path() / "children");
    for (int child; list >> child;)
    {
      children.push_back(child);
    }
  }
  return children;
}

// Whether pid still runs (a zombie waiting for its reaper has ended).
bool Running(int pid)
{
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line))
  {
    return false;
  }
  const auto close = line.rfind(')');
  return close != std::string::npos && close + 2 < line.size() && line[close + 2] != 'Z';
}

int StartedWriter(int shadelab)
{
  const auto start = std::chrono::steady_clock::now();
  for (;;)
  {
    if (const std::vector<int> children = Children(shadelab); !children.empty())
    {
      return children.front();
    }
    if (std::chrono::steady_clock::now() - start > std::chrono::seconds(30))
    {
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// Whether pid has a handler of its own for signal (/proc's SigCgt mask): the
// writer has one for its parent's death once its main() runs.
bool Catches(int pid, int signal)
{
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
  {
    if (line.rfind("SigCgt:", 0) == 0)
    {
      return (std::stoull(line.substr(7), nullptr, 16) >> (signal - 1)) & 1;
    }
  }
  return false;
}

// A render of the teapot at size into dir/output started, with the options more,
// and its image writer found: {shadelab, writer}, -1 for one that did not start.
std::pair<int, int> StartRenderWithWriter(const TempDir& dir, const std::string& output,
  const std::string& size, const std::vector<std::string>& more = {})
{
  std::vector<std::string> args{ "render", TestMesh("teapot.obj").string(), "-o",
    (dir / output).string(), "--size", size };
  args.insert(args.end(), more.begin(), more.end());
  const int pid = StartShadelab(args, dir / "stdout", dir / "stderr");
  return { pid, pid > 0 ? StartedWriter(pid) : -1 };
}

// Waits (up to 30 s) until the writer's main() runs: it has its handler for
// its parent's death then. Until the writer execs, posix_spawn (a vfork)
// keeps shadelab suspended, and a stopped child would keep it so.
bool ReachedMain(int writer)
{
  const auto start = std::chrono::steady_clock::now();
  while (!Catches(writer, SIGUSR1) &&
    std::chrono::steady_clock::now() - start < std::chrono::seconds(30))
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return Catches(writer, SIGUSR1);
}

bool EndsWithin(int pid, std::chrono::milliseconds bound)
{
  const auto start = std::chrono::steady_clock::now();
  while (Running(pid))
  {
    if (std::chrono::steady_clock::now() - start > bound)
    {
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}
}

// Work that never reaches a point where the run can stop by itself (here:
// the writer is stopped, so its answer never comes) ends GraceSeconds after
// SIGTERM all the same: exit 143, nothing at the output's name, and the
// writer, once it runs again, follows its parent.
TEST(Interrupt, SigtermEndsARunThatCannotStopByItselfWithinTheGrace)
{
  TempDir dir;
  // A picture large enough that the writer cannot encode and commit it in
  // the moment between reaching its main() and being stopped: its image may
  // already wait in the pipe then, when the machine is busy.
  const auto [pid, writer] = StartRenderWithWriter(dir, "teapot.png", "2048x2048");
  ASSERT_GT(pid, 0);
  ASSERT_GT(writer, 0);
  ASSERT_TRUE(ReachedMain(writer)) << "the writer never reached its main()";
  kill(writer, SIGSTOP);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  kill(pid, SIGTERM);
  // The bound stated in interruption.h: the grace (2 s) and a fraction.
  const bool ended = EndsWithin(pid, std::chrono::milliseconds(3500));
  if (!ended)
  {
    kill(pid, SIGKILL); // so that the test ends too
  }
  EXPECT_TRUE(ended) << "still running 3.5 s after SIGTERM";
  EXPECT_EQ(WaitShadelab(pid), ended ? 128 + SIGTERM : 128 + SIGKILL);
  EXPECT_NE(Slurp(dir / "stderr").find("shadelab: interrupted (SIGTERM)"), std::string::npos)
    << Slurp(dir / "stderr");
  kill(writer, SIGCONT);
  EXPECT_TRUE(EndsWithin(writer, std::chrono::seconds(10))) << "the writer outlived shadelab";
  EXPECT_EQ(FilesIn(dir.path()), (std::vector<std::string>{ "stderr", "stdout" }));
}

// After a SIGKILL nothing of the run stays: the writer dies with its parent,
// even where its input does not end (here the test holds it open too, as a
// writer busy with a long picture would not read it). Killed before the
// writer's main() runs, the writer's own check of its parent ends it; here
// after, so that the parent-death signal does.
TEST(Interrupt, SigkillLeavesNoProcessBehind)
{
  TempDir dir;
  // An animation of many frames: shadelab still runs when it is killed.
  const auto [pid, writer] =
    StartRenderWithWriter(dir, "teapot.gif", "64x64", { "--orbit", "3600" });
  ASSERT_GT(pid, 0);
  ASSERT_GT(writer, 0);
  ASSERT_TRUE(ReachedMain(writer)) << "the writer never reached its main()";
  const int input =
    open(("/proc/" + std::to_string(writer) + "/fd/0").c_str(), O_WRONLY | O_CLOEXEC);
  ASSERT_GE(input, 0);
  kill(pid, SIGKILL);
  EXPECT_EQ(WaitShadelab(pid), 128 + SIGKILL);
  EXPECT_TRUE(EndsWithin(writer, std::chrono::seconds(10))) << "the writer outlived shadelab";
  close(input);
}
