#include "core/process_memory.h"

#include <cstring>
#include <fstream>
#include <limits>
#include <string>

namespace shadelab
{
double StatusMiB(const char* field)
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.rfind(field, 0) == 0)
    {
      return std::stod(line.substr(std::strlen(field))) / 1024;
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}
}
