// shadelab's helper executables sit beside the one running.
#ifndef shadelab_sibling_executable_h
#define shadelab_sibling_executable_h

#include <string>

namespace shadelab
{
/** The path of the executable `name` in the running executable's folder. */
std::string SiblingExecutable(const std::string& name);
}

#endif
