// Where outputs go. Every command writes a file to a temporary name beside
// its target and renames it, so that a reader never sees a partial file.
#ifndef shadelab_output_path_h
#define shadelab_output_path_h

#include <string>

namespace shadelab
{
/** The extension of path in lower case, with its dot (".png"), or "". */
std::string LowerExtension(const std::string& path);

/** A temporary name beside path: in its folder, so the rename stays on one file system. */
std::string TemporaryName(const std::string& path);

/** Writes text to path through a temporary name; "" or "cannot write PATH: REASON". */
std::string WriteTextFile(const std::string& path, const std::string& text);

/** "" when path's folder can be written to, else "cannot write: REASON". */
std::string CheckWritableFolder(const std::string& path);
}

#endif
