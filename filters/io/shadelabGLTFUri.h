/**
 * @brief   a glTF document's URIs: data URIs decoded, relative ones as files
 *
 * What shadelabGLTFDocument.cxx makes of a buffer's or an image's "uri": a
 * base64 data URI's bytes, or a relative file name (percent-escapes
 * decoded) resolved against the document's folder, as the other readers
 * resolve the files a mesh file names (shadelabCheckedFile.h).
 */
#ifndef shadelabGLTFUri_h
#define shadelabGLTFUri_h

#include "shadelabMeshReadError.h"
#include "shadelabTextScanner.h"

#include <string>
#include <string_view>

namespace shadelab::gltf
{
/** A data URI's bytes; `where` names its owner. Throws unless base64 and valid. */
std::string DecodeDataUri(std::string_view uri, const std::string& where);

/**
 * A relative URI as the path of a file in the document's folder or below
 * (anywhere when allowOutside); throws for an absolute one, a scheme, a
 * malformed percent-escape, or a path outside.
 */
std::string FilePath(const std::string& documentName, bool allowOutside, std::string_view uri,
  const std::string& where);

// What a file that the document refers to says when it cannot be read:
// "buffer 0: 'mesh.bin': cannot open: No such file or directory".
template <typename Action>
auto Referred(const std::string& where, std::string_view uri, Action action)
{
  try
  {
    return action();
  }
  catch (const MeshReadError& error)
  {
    throw MeshReadError(where + ": " + Quote(uri) + ": " + error.what(), error.GetCode());
  }
}
}

#endif
