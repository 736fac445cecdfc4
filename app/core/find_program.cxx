#include "core/find_program.h"

#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace shadelab
{
std::string FindProgram(const std::string& name)
{
  // Without PATH, the shell's default search (glibc's confstr(_CS_PATH)).
  const char* variable = std::getenv("PATH");
  const std::string path = variable ? variable : "/bin:/usr/bin";
  std::string::size_type start = 0;
  while (start <= path.size())
  {
    const auto end = std::min(path.find(':', start), path.size());
    const std::string folder = path.substr(start, end - start);
    const std::filesystem::path candidate =
      std::filesystem::path(folder.empty() ? "." : folder) / name;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) && access(candidate.c_str(), X_OK) == 0)
    {
      return candidate.string();
    }
    start = end + 1;
  }
  return {};
}
}
