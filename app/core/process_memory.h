// The process's resident memory as the kernel counts it (/proc/self/status):
// what `-v`'s phase times and the benchmarks report.
#ifndef shadelab_process_memory_h
#define shadelab_process_memory_h

namespace shadelab
{
/** A field of /proc/self/status ("VmRSS:", "VmHWM:") in MiB; NaN if absent. */
double StatusMiB(const char* field);
}

#endif
