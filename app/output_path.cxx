#include "output_path.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace shadelab
{
std::string LowerExtension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

std::string TemporaryName(const std::string& path)
{
  return path + ".tmp-" + std::to_string(getpid());
}

std::string CheckWritableFolder(const std::string& path)
{
  const std::string folder = std::filesystem::path(path).parent_path().string();
  if (access(folder.empty() ? "." : folder.c_str(), W_OK) != 0)
  {
    return std::string("cannot write: ") + std::strerror(errno);
  }
  return {};
}

std::string WriteTextFile(const std::string& path, const std::string& text)
{
  const std::string temporary = TemporaryName(path);
  std::ofstream out(temporary, std::ios::binary);
  out << text;
  out.close();
  if (!out || std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    return "cannot write " + path + ": " + reason;
  }
  return {};
}
}
