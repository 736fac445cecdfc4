// `-v`'s phase times: each phase's wall-clock time since the one before and
// the process's peak resident memory so far, one line a phase on stderr,
// exactly `PROGRAM: PHASE MS ms, peak MIB MiB` (benchmark scripts parse it;
// the benchmarks' own programs print their phases the same way).
#ifndef shadelab_phase_timer_h
#define shadelab_phase_timer_h

#include "core/milliseconds.h"

namespace shadelab
{
class PhaseTimer
{
public:
  /** Times phases from now; prints them, as `program`'s, only if `enabled`. */
  explicit PhaseTimer(bool enabled, const char* program = "shadelab")
    : Enabled(enabled)
    , Program(program)
  {
  }

  /** Ends `phase` (and starts the next). */
  void Lap(const char* phase);

private:
  bool Enabled;
  const char* Program;
  Clock::time_point Last = Clock::now();
};
}

#endif
