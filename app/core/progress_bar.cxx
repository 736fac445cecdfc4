#include "core/progress_bar.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace shadelab
{
ProgressBar::ProgressBar(long long total, bool quiet)
  : Total(std::max(total, 1LL))
  , Enabled(!quiet && isatty(STDERR_FILENO) && isatty(STDOUT_FILENO))
{
}

ProgressBar::~ProgressBar()
{
  this->Finish();
}

std::string ProgressBar::Line(
  long long done, long long total, const std::string& label, double elapsed, int width)
{
  const int barWidth = 24;
  const int filled = static_cast<int>(barWidth * done / std::max(total, 1LL));
  std::string line = "[" + std::string(filled, '#') + std::string(barWidth - filled, '.') + "] " +
    std::to_string(done) + "/" + std::to_string(total);
  if (done > 0 && done < total)
  {
    // The mean pace so far: steps of one run differ, so no finer model holds.
    const long long eta = static_cast<long long>(elapsed / done * (total - done) + 0.5);
    char text[32];
    std::snprintf(text, sizeof text, " ETA %lld:%02lld", eta / 60, eta % 60);
    line += text;
  }
  line += "  " + label;
  if (static_cast<int>(line.size()) > width)
  {
    line.resize(std::max(width, 0));
  }
  return line;
}

void ProgressBar::Show(long long done, const std::string& label)
{
  if (!this->Enabled)
  {
    return;
  }
  winsize size{};
  const int columns =
    ioctl(STDERR_FILENO, TIOCGWINSZ, &size) == 0 && size.ws_col > 0 ? size.ws_col : 80;
  const double elapsed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - this->Start).count();
  // \r and erase-to-end-of-line: one line, redrawn in place.
  std::fprintf(stderr, "\r%s\033[K", Line(done, this->Total, label, elapsed, columns - 1).c_str());
  std::fflush(stderr);
  this->Drawn = true;
}

void ProgressBar::Finish()
{
  if (this->Drawn)
  {
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
    this->Drawn = false;
  }
}
}
