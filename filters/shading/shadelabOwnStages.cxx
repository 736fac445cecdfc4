#include "shadelabOwnStages.h"

#include <vtkObjectFactory.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkShader.h>
#include <vtkSmartPointer.h>
#include <vtk_glew.h>

#include <string>

namespace
{
// VTK's own substitutions (the version line, the fragment outputs), which
// the cache keeps protected: the check compiles what the cache would.
class SubstitutingCache : public vtkOpenGLShaderCache
{
public:
  static SubstitutingCache* New();
  using vtkOpenGLShaderCache::ReplaceShaderValues;
};
vtkStandardNewMacro(SubstitutingCache);

std::string ProgramLog(GLuint program)
{
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(length > 1 ? static_cast<std::size_t>(length) : 0, '\0');
  if (length > 1)
  {
    glGetProgramInfoLog(program, length, nullptr, log.data());
    log.resize(log.size() - 1); // the terminating null
  }
  return log.empty() ? std::string("the program did not link") : log;
}
}

namespace shadelab
{
std::vector<StageError> CheckStages(
  const std::string& vertex, const std::string& fragment, const std::string& geometry)
{
  std::string sources[3] = { vertex, fragment, geometry };
  const unsigned int outputs = vtkSmartPointer<SubstitutingCache>::New()->ReplaceShaderValues(
    sources[0], sources[1], sources[2]);
  const vtkShader::Type types[3] = { vtkShader::Vertex, vtkShader::Fragment, vtkShader::Geometry };
  const StageError::Stage stages[2] = { StageError::Stage::Vertex, StageError::Stage::Fragment };
  std::vector<StageError> errors;
  vtkSmartPointer<vtkShader> shaders[3];
  for (int i = 0; i < 3; ++i)
  {
    if (sources[i].empty())
    {
      continue;
    }
    shaders[i] = vtkSmartPointer<vtkShader>::New();
    shaders[i]->SetType(types[i]);
    shaders[i]->SetSource(sources[i]);
    if (!shaders[i]->Compile())
    {
      // A geometry stage is VTK's (wide lines), never one's own.
      errors.push_back({ i < 2 ? stages[i] : StageError::Stage::Link, shaders[i]->GetError() });
    }
  }
  if (errors.empty())
  {
    const GLuint program = glCreateProgram();
    for (const auto& shader : shaders)
    {
      if (shader)
      {
        glAttachShader(program, static_cast<GLuint>(shader->GetHandle()));
      }
    }
    for (unsigned int i = 0; i < outputs; ++i)
    {
      glBindFragDataLocation(program, i, ("fragOutput" + std::to_string(i)).c_str());
    }
    glLinkProgram(program);
    GLint linked = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked)
    {
      errors.push_back({ StageError::Stage::Link, ProgramLog(program) });
    }
    glDeleteProgram(program);
  }
  for (const auto& shader : shaders)
  {
    if (shader)
    {
      shader->Cleanup();
    }
  }
  return errors;
}
}
