// `-v`'s phase times: each phase's wall-clock time since the one before and
// the process's peak resident memory so far, one line a phase on stderr,
// exactly `shadelab: PHASE MS ms, peak MIB MiB` (benchmark scripts parse it).
#ifndef shadelab_phase_timer_h
#define shadelab_phase_timer_h

#include "core/milliseconds.h"

namespace shadelab
{
class PhaseTimer
{
public:
  /** Times phases from now; prints them only if `enabled`. */
  explicit PhaseTimer(bool enabled)
    : Enabled(enabled)
  {
  }

  /** Ends `phase` (and starts the next). */
  void Lap(const char* phase);

private:
  bool Enabled;
  Clock::time_point Last = Clock::now();
};
}

#endif
