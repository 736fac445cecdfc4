// A progress bar on the terminal for long commands: counts, the current
// step and an ETA, redrawn in place on stderr. Silent unless both stdout and
// stderr are a terminal, so scripts and logs get no control characters.
#ifndef shadelab_progress_bar_h
#define shadelab_progress_bar_h

#include <chrono>
#include <string>

namespace shadelab
{
class ProgressBar
{
public:
  /** total steps; shown only on a terminal (stdout and stderr) and when not `quiet`. */
  ProgressBar(long long total, bool quiet);
  ~ProgressBar();

  /** Shows that `label` is now under way, after `done` steps. */
  void Show(long long done, const std::string& label);

  /** Clears the bar, so that what follows starts on a clean line. */
  void Finish();

  /** The line Show draws (exposed for tests): width characters at most. */
  static std::string Line(
    long long done, long long total, const std::string& label, double elapsedSeconds, int width);

private:
  long long Total;
  bool Enabled;
  bool Drawn = false;
  std::chrono::steady_clock::time_point Start = std::chrono::steady_clock::now();
};
}

#endif
