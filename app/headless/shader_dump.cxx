#include "headless/shader_dump.h"

#include "core/output_file.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace shadelab
{
ShaderDump::ShaderDump(vtkMapper* mapper, const std::string& folder, const std::string& name)
  : Base((std::filesystem::path(folder) / name).string())
  , Watch(
      [this](const ShaderSources& sources)
      {
        if (!this->Written)
        {
          this->Written = true;
          this->Write(".vert", sources.Vertex);
          this->Write(".frag", sources.Fragment);
        }
      })
{
  this->Watch.Watch(mapper);
}

std::string ShaderDump::PrepareFolder(const std::string& folder)
{
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error)
  {
    return "cannot create the folder: " + error.message();
  }
  if (access(folder.c_str(), W_OK) != 0)
  {
    return std::string("cannot write: ") + std::strerror(errno);
  }
  return {};
}

void ShaderDump::Write(const std::string& extension, const std::string& source)
{
  const std::string path = this->Base + extension;
  const std::string error = WriteFile(path, source);
  if (this->Error.empty() && !error.empty())
  {
    this->ErrorFile = path;
    this->Error = error;
  }
}
}
