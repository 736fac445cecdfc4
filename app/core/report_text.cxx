#include "core/report_text.h"

#include <cstdio>
#include <fstream>

namespace shadelab
{
std::string FormatNumber(const char* format, double value)
{
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string CpuModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);)
  {
    if (line.rfind("model name", 0) == 0)
    {
      const std::size_t start = line.find_first_not_of(" \t", line.find(':') + 1);
      return start == std::string::npos ? "" : line.substr(start);
    }
  }
  return "unknown CPU";
}
}
