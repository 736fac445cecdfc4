/**
 * The made meshes written in the formats shadelab reads, each as a modeller
 * would write it, so that the tests read them through the real readers.
 */
#ifndef shadelab_meshes_mesh_file_writers_h
#define shadelab_meshes_mesh_file_writers_h

#include "surface_grid.h"

#include <string>

namespace shadelab::meshes
{
/** What an OBJ file carries besides its points and faces. */
struct ObjContents
{
  bool Uv = true;
  bool Normals = false;
  /** A material library and the one material every face uses; "" for none. */
  std::string MaterialLibrary;
  std::string Material;
};

/** Each writer throws std::runtime_error naming the file it cannot write. */
void WriteObj(const std::string& path, const SurfaceMesh& mesh, const ObjContents& contents);
/** Binary STL; faces of more than three corners as fans. */
void WriteStl(const std::string& path, const SurfaceMesh& mesh);
void WriteOff(const std::string& path, const SurfaceMesh& mesh);
/** Binary little-endian PLY: float x y z, uchar-counted int vertex_indices. */
void WritePly(const std::string& path, const SurfaceMesh& mesh);
}

#endif
