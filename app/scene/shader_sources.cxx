#include "scene/shader_sources.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkMapper.h>
#include <vtkShader.h>
#include <vtkShaderProgram.h>

#include <utility>

namespace shadelab
{
ShaderSourceWatch::ShaderSourceWatch(std::function<void(const ShaderSources&)> seen)
  : Seen(std::move(seen))
  , Observer(vtkSmartPointer<vtkCallbackCommand>::New())
{
  this->Observer->SetClientData(this);
  // VTK's OpenGL mappers tell UpdateShaderEvent with the program they are
  // about to draw with, after it was built: the final source.
  this->Observer->SetCallback(
    [](vtkObject*, unsigned long, void* self, void* data)
    {
      auto* program = static_cast<vtkShaderProgram*>(data);
      static_cast<ShaderSourceWatch*>(self)->Seen(
        { program->GetVertexShader()->GetSource(), program->GetFragmentShader()->GetSource() });
    });
}

ShaderSourceWatch::~ShaderSourceWatch()
{
  this->Watch(nullptr);
}

void ShaderSourceWatch::Watch(vtkMapper* mapper)
{
  if (mapper == this->Mapper)
  {
    return;
  }
  if (this->Mapper)
  {
    this->Mapper->RemoveObserver(this->Observer);
  }
  this->Mapper = mapper;
  if (mapper)
  {
    mapper->AddObserver(vtkCommand::UpdateShaderEvent, this->Observer);
  }
}
}
