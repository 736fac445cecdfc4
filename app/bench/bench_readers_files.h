// The files that shadelab-bench-readers times the readers on: one triangle
// mesh with vertex normals written as OFF (x y z and triangles, as ModelNet
// and CGAL write it), as glTF 2.0 with its buffer in a .bin beside it, and
// as GLB (POSITION and NORMAL as FLOAT, indices as UNSIGNED_INT, one node).
#ifndef shadelab_bench_readers_files_h
#define shadelab_bench_readers_files_h

#include <string>

class vtkPolyData;

namespace shadelab::bench_readers
{
/** Writes `mesh` (triangles, point normals) as PATH.off; "" or the error. */
std::string WriteOff(vtkPolyData* mesh, const std::string& path);

/** Writes PATH.gltf and PATH.bin, or PATH.glb when `binary`; "" or the error. */
std::string WriteGltf(vtkPolyData* mesh, const std::string& path, bool binary);
}

#endif
