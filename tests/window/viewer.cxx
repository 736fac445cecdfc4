#include "viewer.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>

using namespace std::chrono_literals;

namespace shadelab_test
{
namespace
{
// An X server for this test program: Xvfb on the first free display,
// which it names through -displayfd once it accepts connections; -noreset,
// or a client connecting just as the last one left (xdotool, then the
// window) would be dropped by the server's reset. Its screen is
// $SHADELAB_TEST_SCREEN (default 1280x1024), and $SHADELAB_TEST_WINDOW_MANAGER
// names a window manager to run on it (default none).
class XServer : public ::testing::Environment
{
public:
  void SetUp() override
  {
    const char* size = std::getenv("SHADELAB_TEST_SCREEN");
    const std::string screen = std::string(size && *size ? size : "1280x1024") + "x24";
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    this->Pid = fork();
    if (this->Pid == 0)
    {
      close(fds[0]);
      const std::string fd = std::to_string(fds[1]);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", screen.c_str(), "-nolisten",
        "tcp", "-noreset", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    std::string number;
    char c;
    while (read(fds[0], &c, 1) == 1 && c != '\n')
    {
      number += c;
    }
    close(fds[0]);
    ASSERT_FALSE(number.empty()) << "Xvfb did not start (is the xvfb package installed?)";
    setenv("DISPLAY", (":" + number).c_str(), 1);
    const char* manager = std::getenv("SHADELAB_TEST_WINDOW_MANAGER");
    if (manager && *manager && std::string(manager) != "none")
    {
      this->Manager = fork();
      if (this->Manager == 0)
      {
        execlp(manager, manager, static_cast<char*>(nullptr));
        _exit(127);
      }
      // Managing once it has set the root window's _NET_SUPPORTING_WM_CHECK.
      for (int i = 0; i < 100 &&
           Run("xprop -root _NET_SUPPORTING_WM_CHECK 2>/dev/null | "
               "grep -q 'window id'") != 0;
           ++i)
      {
        std::this_thread::sleep_for(100ms);
      }
      ASSERT_EQ(waitpid(this->Manager, nullptr, WNOHANG), 0)
        << manager << " did not start (is its package installed?)";
    }
  }
  void TearDown() override
  {
    for (const pid_t pid : { this->Manager, this->Pid })
    {
      if (pid > 0)
      {
        kill(pid, SIGTERM);
        waitpid(pid, nullptr, 0);
      }
    }
  }

private:
  pid_t Pid = -1;
  pid_t Manager = -1;
};

const auto* const Server = ::testing::AddGlobalTestEnvironment(new XServer);
}

int Run(const std::string& command)
{
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

Viewer::Viewer(const std::vector<std::string>& args, const std::string& size, rlim_t fileSizeLimit,
  const std::filesystem::path& mesh)
  : Title("shadelab - " + mesh.filename().string())
{
  std::vector<std::string> words{ SHADELAB_BINARY, "view", mesh.string(), "--size", size,
    "--camera-position", "5,5,9" };
  words.insert(words.end(), args.begin(), args.end());
  this->Pid = fork();
  if (this->Pid == 0)
  {
    const rlimit limit{ fileSizeLimit, fileSizeLimit };
    if ((fileSizeLimit != RLIM_INFINITY && setrlimit(RLIMIT_FSIZE, &limit) != 0) ||
      chdir(this->Dir.path().c_str()) != 0 ||
      !freopen((this->Dir / "stdout").c_str(), "w", stdout) ||
      !freopen((this->Dir / "stderr").c_str(), "w", stderr))
    {
      _exit(127);
    }
    std::vector<char*> argv;
    for (std::string& w : words)
    {
      argv.push_back(w.data());
    }
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
  // The window exists once xdotool finds it by its title. xdotool gives up
  // at once when a window goes while it walks the tree (BadWindow: the last
  // test's viewer closing), so it searches again until the program exits
  // or a minute has passed.
  const std::string search =
    "timeout 60 xdotool search --sync --name '^" + this->Title + "$' 2>/dev/null | head -1";
  const auto deadline = std::chrono::steady_clock::now() + 60s;
  const auto running = [this]
  {
    siginfo_t info{}; // WNOWAIT: Wait() still collects its status
    return waitid(P_PID, static_cast<id_t>(this->Pid), &info, WEXITED | WNOHANG | WNOWAIT) == 0 &&
      info.si_pid == 0;
  };
  while (this->Window.empty() && std::chrono::steady_clock::now() < deadline && running())
  {
    FILE* found = popen(search.c_str(), "r");
    char line[64] = {};
    if (found && fgets(line, sizeof line, found))
    {
      this->Window = std::string(line, std::strcspn(line, "\n"));
    }
    if (found)
    {
      pclose(found);
    }
    if (this->Window.empty())
    {
      std::this_thread::sleep_for(100ms);
    }
  }
}

Viewer::~Viewer()
{
  if (this->Pid > 0 && !this->Exited)
  {
    kill(this->Pid, SIGKILL);
    waitpid(this->Pid, nullptr, 0);
  }
}

void Viewer::Keys(const std::vector<std::string>& keys)
{
  for (const std::string& key : keys)
  {
    Run("xdotool key --window " + this->Window + " " + key + " 2>/dev/null");
  }
}

void Viewer::Drag(int x, int y, int dx, bool hold)
{
  const std::string w = " --window " + this->Window;
  Run("xdotool mousemove" + w + " " + std::to_string(x) + " " + std::to_string(y) +
    " mousedown 1 mousemove_relative -- " + std::to_string(dx) + " 0 2>/dev/null");
  if (!hold)
  {
    Run("xdotool mouseup 1 2>/dev/null");
  }
}

void Viewer::Release()
{
  Run("xdotool mouseup 1 2>/dev/null");
}

Image Viewer::Screenshot()
{
  this->Keys({ "p" });
  const std::string path = this->Await("shadelab: screenshot ");
  return path.empty() ? Image{} : ReadImage(path);
}

std::string Viewer::Await(const std::string& tag)
{
  const auto deadline = std::chrono::steady_clock::now() + 30s;
  while (std::chrono::steady_clock::now() < deadline)
  {
    std::istringstream out(Slurp(this->Dir / "stdout"));
    std::vector<std::string> found;
    for (std::string line; std::getline(out, line);)
    {
      if (line.rfind(tag, 0) == 0)
      {
        found.push_back(line.substr(tag.size()));
      }
    }
    if (found.size() > this->Seen[tag])
    {
      this->Seen[tag] = found.size();
      return found.back();
    }
    std::this_thread::sleep_for(50ms);
  }
  return "";
}

int Viewer::Wait()
{
  const auto deadline = std::chrono::steady_clock::now() + 20s;
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline)
  {
    if (waitpid(this->Pid, &status, WNOHANG) == this->Pid)
    {
      this->Exited = true;
      const int code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      // In the sanitizer build, LeakSanitizer's check at exit sometimes
      // crashes in its own thread-stopping tracer ("Tracer caught signal
      // 11", then this fatal error and status 1) while the window's
      // threads wind down: the sanitizer runtime failed, not the viewer.
      // A leak found is another message and still fails.
      const bool leakCheckCrashed = code == 1 &&
        this->Stderr().find("LeakSanitizer has encountered a fatal error") != std::string::npos;
      return leakCheckCrashed ? 0 : code;
    }
    std::this_thread::sleep_for(50ms);
  }
  return -1;
}

std::string Viewer::Stderr() const
{
  return Slurp(this->Dir / "stderr");
}

Change Compare(const Image& a, const Image& b, float by, int top, int bottom, int left, int right)
{
  Change change;
  // A screenshot that never came (a viewer that hung) is empty: fail the
  // test instead of reading past it.
  const auto covers = [&](const Image& image)
  { return image.Width >= right && image.Height >= bottom && image.Channels >= 3; };
  if (!covers(a) || !covers(b))
  {
    ADD_FAILURE() << "a screenshot is missing or smaller than the compared region";
    return change;
  }
  for (int y = top; y < bottom; ++y)
  {
    for (int x = left; x < right; ++x)
    {
      float d = 0;
      for (int c = 0; c < 3; ++c)
      {
        const size_t i = (static_cast<size_t>(y) * a.Width + x) * a.Channels + c;
        d = std::max(d, std::fabs(a.Pixels[i] - b.Pixels[i]));
      }
      change.Largest = std::max(change.Largest, d);
      change.Pixels += d > by;
    }
  }
  return change;
}
}
