#include "headless/shader_dump.h"

#include "core/output_file.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkMapper.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace shadelab
{
ShaderDump::ShaderDump(vtkMapper* mapper, const std::string& folder, const std::string& name)
  : Mapper(mapper)
  , Base((std::filesystem::path(folder) / name).string())
  , Observer(vtkSmartPointer<vtkCallbackCommand>::New())
{
  this->Observer->SetClientData(this);
  this->Observer->SetCallback(
    [](vtkObject*, unsigned long, void* self, void* data)
    {
      auto* dump = static_cast<ShaderDump*>(self);
      auto* program = static_cast<vtkShaderProgram*>(data);
      if (!dump->Written)
      {
        dump->Written = true;
        dump->Write(".vert", program->GetVertexShader()->GetSource());
        dump->Write(".frag", program->GetFragmentShader()->GetSource());
      }
    });
  mapper->AddObserver(vtkCommand::UpdateShaderEvent, this->Observer);
}

ShaderDump::~ShaderDump()
{
  this->Mapper->RemoveObserver(this->Observer);
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
