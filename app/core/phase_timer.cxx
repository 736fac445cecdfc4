#include "core/phase_timer.h"

#include "core/process_memory.h"

#include <cmath>
#include <iostream>

namespace shadelab
{
void PhaseTimer::Lap(const char* phase)
{
  const auto now = Clock::now();
  if (this->Enabled)
  {
    // VmHWM: the peak resident size, in whole MiB as the kernel has it in kB.
    std::cerr << this->Program << ": " << phase << " " << Milliseconds(this->Last, now)
              << " ms, peak " << std::lround(StatusMiB("VmHWM:")) << " MiB\n";
  }
  this->Last = now;
}
}
