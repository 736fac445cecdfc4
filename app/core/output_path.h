// Where outputs go: what can be checked of an output's name before any work
// (output_file.h writes it).
#ifndef shadelab_output_path_h
#define shadelab_output_path_h

#include <string>

namespace shadelab
{
/** The extension of path in lower case, with its dot (".png"), or "". */
std::string LowerExtension(const std::string& path);

/**
 * The file that path names, as a key to tell two outputs apart: absolute,
 * without "." and "..", its existing symbolic links followed. So "out/x.png",
 * "./out/x.png" and "out/../out/x.png" are one file.
 */
std::string OutputIdentity(const std::string& path);

/** "" when path's folder can be written to, else "cannot write: REASON". */
std::string CheckWritableFolder(const std::string& path);
}

#endif
