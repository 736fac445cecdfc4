// shadelab's helper executables (shadelab-image-writer, shadelab-view): in
// the build tree beside the one running; installed, in the helper folder
// (libexec/shadelab, GNU's place for programs that only programs run).
#ifndef shadelab_sibling_executable_h
#define shadelab_sibling_executable_h

#include <string>

namespace shadelab
{
/**
 * The path of the helper executable `name`: in the installed helper folder
 * relative to the running executable's folder if it is there, else in that
 * folder itself.
 */
std::string SiblingExecutable(const std::string& name);
}

#endif
