// Shader stages of one's own (the lecture's hands-on): the complete GLSL of
// a vertex or fragment stage, as `--dump-shaders` writes it and a student
// edits it, checked by compiling and linking it with the stage it is paired
// with in the current OpenGL context, exactly as VTK's shader cache would,
// so that a stage that fails is reported with the driver's own messages
// and never drawn.
#ifndef shadelabOwnStages_h
#define shadelabOwnStages_h

#include <string>
#include <vector>

namespace shadelab
{
/** The stages of one's own; an empty one is the generated stage. */
struct OwnStages
{
  std::string Vertex;
  std::string Fragment;

  bool Empty() const { return this->Vertex.empty() && this->Fragment.empty(); }
  bool operator==(const OwnStages& other) const
  {
    return this->Vertex == other.Vertex && this->Fragment == other.Fragment;
  }
};

/** Where a program failed, and the driver's log of it. */
struct StageError
{
  enum class Stage
  {
    Vertex,
    Fragment,
    Link
  };
  Stage Where = Stage::Link;
  std::string Log;
};

/**
 * Compiles the vertex and fragment (and, when not empty, geometry) sources
 * as VTK 9.1's shader cache would (its substitutions first) and links them
 * in the current OpenGL context; the errors, none when they would draw.
 */
std::vector<StageError> CheckStages(
  const std::string& vertex, const std::string& fragment, const std::string& geometry);
}

#endif
