/**
 * @brief   an AssimpMesh as bytes, for the answer of the process that read it
 *
 * vtkShadelabAssimpReader runs assimp in a child process
 * (shadelabIsolatedRead.h); what the child made of the file
 * (shadelabAssimpScene.h) comes back through a pipe as these bytes: each
 * number in the machine's own layout (both ends are the same program), each
 * array and string its length first. Decoding checks every length against
 * the bytes there are.
 */
#ifndef shadelabAssimpMeshBytes_h
#define shadelabAssimpMeshBytes_h

#include "shadelabAssimpScene.h"

#include <string>

namespace shadelab
{
std::string EncodeAssimpMesh(const AssimpMesh& mesh);

/** The mesh that EncodeAssimpMesh encoded; MeshReadError where the bytes are short or too many. */
AssimpMesh DecodeAssimpMesh(const std::string& bytes);
}

#endif
