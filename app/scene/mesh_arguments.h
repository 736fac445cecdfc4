// The meshes of `shadelab render A.obj B.ply things/ 'scans/*.ply'`: files
// as given, folders as the mesh files in them, globs (quoted, so that the
// shell leaves them) as the files they match.
#ifndef shadelab_mesh_arguments_h
#define shadelab_mesh_arguments_h

#include <string>
#include <vector>

namespace shadelab
{
/**
 * The mesh files that arguments name, in their order (a folder's and a
 * glob's sorted by name). "" or the problem, which names the argument: a
 * folder without mesh files, a glob that matches none.
 */
std::string ExpandMeshArguments(
  const std::vector<std::string>& arguments, std::vector<std::string>& meshes);

/** Whether arguments name one mesh file as it is (no folder, no glob). */
bool IsOneMeshFile(const std::vector<std::string>& arguments);
}

#endif
