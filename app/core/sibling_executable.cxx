#include "core/sibling_executable.h"

#include <filesystem>

namespace shadelab
{
std::string SiblingExecutable(const std::string& name)
{
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return (exe.parent_path() / name).string();
}
}
