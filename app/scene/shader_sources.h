// The complete GLSL that a mapper draws with: the vertex and fragment
// source of the shader program it binds, as VTK assembled it from its
// templates and the shading rule's replacements. What `render
// --dump-shaders` writes and the window's shader panel shows, taken from
// the same place so that both are exactly what runs.
#ifndef shadelab_shader_sources_h
#define shadelab_shader_sources_h

#include <vtkSmartPointer.h>

#include <functional>
#include <string>

class vtkCallbackCommand;
class vtkMapper;

namespace shadelab
{
struct ShaderSources
{
  std::string Vertex;
  std::string Fragment;
};

class ShaderSourceWatch
{
public:
  /** `seen` gets the sources each time the watched mapper binds its program to draw. */
  explicit ShaderSourceWatch(std::function<void(const ShaderSources&)> seen);
  ~ShaderSourceWatch();

  /** Watches mapper (nullptr: none) instead of the one watched before. */
  void Watch(vtkMapper* mapper);

private:
  ShaderSourceWatch(const ShaderSourceWatch&) = delete;
  void operator=(const ShaderSourceWatch&) = delete;

  std::function<void(const ShaderSources&)> Seen;
  vtkSmartPointer<vtkMapper> Mapper;
  vtkSmartPointer<vtkCallbackCommand> Observer;
};
}

#endif
