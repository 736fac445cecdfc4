// --dump-shaders DIR: the final vertex and fragment GLSL of each shader
// program a render uses, written as DIR/NAME.vert and DIR/NAME.frag, so a
// learner can read exactly what runs (the lecture's hands-on asks for that).
#ifndef shadelab_shader_dump_h
#define shadelab_shader_dump_h

#include "scene/shader_sources.h"

#include <string>

class vtkMapper;

namespace shadelab
{
class ShaderDump
{
public:
  /** Writes the programs that mapper draws with into folder, named name. */
  ShaderDump(vtkMapper* mapper, const std::string& folder, const std::string& name);

  /** Creates folder if needed; an error text or "". */
  static std::string PrepareFolder(const std::string& folder);

  /** The file of the first write error, and the error; both "" when all went well. */
  const std::string& GetErrorFile() const { return this->ErrorFile; }
  const std::string& GetError() const { return this->Error; }

private:
  ShaderDump(const ShaderDump&) = delete;
  void operator=(const ShaderDump&) = delete;

  void Write(const std::string& extension, const std::string& source);

  std::string Base;
  std::string ErrorFile;
  std::string Error;
  bool Written = false;
  ShaderSourceWatch Watch; // last: it calls back into the members above
};
}

#endif
