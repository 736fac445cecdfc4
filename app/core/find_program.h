// Programs shadelab runs (ffmpeg for .mp4), looked up as the shell would.
#ifndef shadelab_find_program_h
#define shadelab_find_program_h

#include <string>

namespace shadelab
{
/** The path of the executable `name` in a folder of PATH, or "" when none has it. */
std::string FindProgram(const std::string& name);
}

#endif
