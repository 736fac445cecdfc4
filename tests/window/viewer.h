// The window tests' harness: an X server of the test program's own (Xvfb),
// `shadelab view` running in it, keys and the mouse sent as X events
// (xdotool), and what the window shows read back through the inspector's
// own screenshot key `p`.
#ifndef shadelab_window_viewer_h
#define shadelab_window_viewer_h

#include "cli_test_support.h"

#include <sys/resource.h>
#include <sys/types.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace shadelab_test
{
inline constexpr int W = 480;
inline constexpr int H = 360;
// The HUD's three lines at the bottom left; its ms/frame changes frame to
// frame, so pictures are compared above it.
inline constexpr int HudHeight = 70;

/** Runs command through the shell; its exit code, or -1 if it did not exit. */
int Run(const std::string& command);

// A running `shadelab view MESH ARGS...` in a temporary folder (where its
// screenshots go), under a file-size limit if one is given; MESH spot.obj
// unless given.
class Viewer
{
public:
  explicit Viewer(const std::vector<std::string>& args,
    const std::string& size = std::to_string(W) + "x" + std::to_string(H),
    rlim_t fileSizeLimit = RLIM_INFINITY,
    const std::filesystem::path& mesh = TestMesh("teapot.obj"));
  ~Viewer();

  bool HasWindow() const { return !this->Window.empty(); }

  /** Sends keys (xdotool names) to the window, one X event each. */
  void Keys(const std::vector<std::string>& keys);

  /** The mouse: press at (x, y) in the window, move by dx, and release unless `hold`. */
  void Drag(int x, int y, int dx, bool hold);

  void Release();

  /** Presses p and reads the screenshot the viewer names on its stdout. */
  Image Screenshot();

  /** Waits up to 30 s for a new stdout line starting with `tag`; its rest, or "". */
  std::string Await(const std::string& tag);

  /** Waits up to 20 s for the viewer to end; its exit code, or -1 if it did not. */
  int Wait();

  std::string Stderr() const;

  /** The files in the viewer's folder (stdout and stderr among them). */
  std::vector<std::string> Files() const { return this->Dir.Files(); }

  const std::string Title;

private:
  TempDir Dir;
  pid_t Pid = -1;
  bool Exited = false;
  std::string Window;
  std::map<std::string, std::size_t> Seen; // stdout lines read, by tag
};

// The largest difference of two screenshots above the HUD, and how many
// pixels differ there by more than `by`.
struct Change
{
  float Largest = 0;
  long long Pixels = 0;
};

Change Compare(const Image& a, const Image& b, float by = 2, int top = 0,
  int bottom = H - HudHeight, int left = 0, int right = W);
}

#endif
