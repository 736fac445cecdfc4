// Wall-clock intervals in milliseconds, as the benchmarks, the batch's
// phase times and the viewer's frame times report them.
#ifndef shadelab_milliseconds_h
#define shadelab_milliseconds_h

#include <chrono>

namespace shadelab
{
using Clock = std::chrono::steady_clock;

/** Milliseconds from `from` to `to` (now, by default). */
inline double Milliseconds(Clock::time_point from, Clock::time_point to = Clock::now())
{
  return std::chrono::duration<double, std::milli>(to - from).count();
}
}

#endif
