#include "core/sibling_executable.h"

#include <filesystem>

namespace shadelab
{
std::string SiblingExecutable(const std::string& name)
{
  std::error_code error;
  const auto folder = std::filesystem::read_symlink("/proc/self/exe", error).parent_path();
  // SHADELAB_HELPERS_FROM_BINDIR: the helper folder relative to the
  // installed bin folder (app/CMakeLists.txt).
  const auto installed = (folder / SHADELAB_HELPERS_FROM_BINDIR / name).lexically_normal();
  if (std::filesystem::exists(installed, error))
  {
    return installed.string();
  }
  return (folder / name).string();
}
}
