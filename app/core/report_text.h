// Text for the measurements' reports (`shadelab bench`'s summary,
// shadelab-bench-normals): numbers through printf formats, and the machine
// they were taken on.
#ifndef shadelab_report_text_h
#define shadelab_report_text_h

#include <string>

namespace shadelab
{
/** value through a printf format for one double, such as "%.2e". */
std::string FormatNumber(const char* format, double value);

/** The processor's model name from /proc/cpuinfo, or "unknown CPU". */
std::string CpuModel();
}

#endif
