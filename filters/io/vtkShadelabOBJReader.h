/**
 * @class   vtkShadelabOBJReader
 * @brief   reads Wavefront OBJ meshes, fast and strictly
 *
 * Reads `v`, `vn` and `f` (corners as v, v/vt, v//vn or v/vt/vn, negative
 * indices relative to the last definition, polygons of any size) and ignores
 * every other statement (vt, o, g, s, usemtl, mtllib, l, p, ...) and comments.
 * Extra numbers after a vertex's x y z (w, or r g b colours) are ignored.
 * Unlike vtkOBJReader it stops at the first malformed number, at an index of
 * 0 or out of range, or at a face with fewer than 3 vertices, with
 * "line N: ..." in the message; non-finite coordinates are reported by vertex
 * number, counted from 1 as in the file.
 *
 * Normals are output only when every face corner carries a vn; then a vertex
 * used with different normals becomes one point per (v, vn) pair: point i
 * stays vertex i + 1 of the file with the normal of its first use, further
 * pairs are appended after the file's vertices, and vertices that no face
 * uses get a zero normal. When only some corners carry a vn, the normals are
 * ignored with a warning.
 */
#ifndef vtkShadelabOBJReader_h
#define vtkShadelabOBJReader_h

#include "vtkShadelabFileReader.h"

class vtkShadelabOBJReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabOBJReader* New();
  vtkTypeMacro(vtkShadelabOBJReader, vtkShadelabFileReader);

protected:
  vtkShadelabOBJReader() = default;
  ~vtkShadelabOBJReader() override = default;

  void ReadMesh(const char* fileName, vtkPolyData* triangles) override;

private:
  vtkShadelabOBJReader(const vtkShadelabOBJReader&) = delete;
  void operator=(const vtkShadelabOBJReader&) = delete;
};

#endif
