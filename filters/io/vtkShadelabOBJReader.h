/**
 * @class   vtkShadelabOBJReader
 * @brief   reads Wavefront OBJ meshes, fast and strictly
 *
 * Reads `v`, `vn`, `f` (corners as v, v/vt, v//vn or v/vt/vn, negative
 * indices relative to the last definition, polygons of any size) and
 * `usemtl` and `mtllib`, and ignores every other statement (vt, o, g, s, l,
 * p, ...) and comments.
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
 *
 * With `usemtl`, each triangle's part (cell data "Part") is its material
 * name's, parts numbered in the order of the names' first use, with part 0
 * named "" for faces before the first usemtl; field data "PartMaterials"
 * holds the names. `mtllib`'s files (MTL, beside the OBJ) give the parts'
 * materials: "PartMaterialIndices" is each part's material's index among
 * the libraries' materials in their order (-1 for "" and for a name they do
 * not define) and "PartKa", "PartKd", "PartKs", "PartNs" its coefficients.
 * A library that cannot be read is a warning (OBJ files from the web often
 * come without theirs) and its materials are undefined; a malformed one is
 * an error naming it and its line.
 *
 * `vt` stays ignored: texture coordinates split a vertex at every seam of
 * the texture, and normals computed for the split points would crease
 * there (spot.obj has vt without vn); they need the normals computed on the
 * file's vertices first.
 */
#ifndef vtkShadelabOBJReader_h
#define vtkShadelabOBJReader_h

#include "shadelabIllumination.h"
#include "vtkShadelabFileReader.h"

#include <string>
#include <vector>

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
  /**
   * The materials of mtllib's files (beside fileName), in order; a library
   * that cannot be read is a warning, a malformed one an error.
   */
  std::vector<shadelab::Material> ReadLibraries(
    const char* fileName, const std::vector<std::string>& libraries);

  vtkShadelabOBJReader(const vtkShadelabOBJReader&) = delete;
  void operator=(const vtkShadelabOBJReader&) = delete;
};

#endif
