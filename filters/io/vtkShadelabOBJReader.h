/**
 * @class   vtkShadelabOBJReader
 * @brief   reads Wavefront OBJ meshes, fast and strictly
 *
 * Reads `v`, `vt`, `vn`, `f` (corners as v, v/vt, v//vn or v/vt/vn,
 * negative indices relative to the last definition, polygons of any size)
 * and `usemtl` and `mtllib`, and ignores every other statement (o, g, s, l,
 * p, ...) and comments.
 * Three numbers after a vertex's x y z are its colour, r g b in 0..1 (the
 * "Colors" point data, opaque), when every vertex has one (when only some
 * do, they are ignored with a warning); other extra numbers (w) are read
 * and ignored, as is a texture coordinate's third (w); `vt u` alone is u 0.
 * Unlike vtkOBJReader it stops at the first malformed number, at an index of
 * 0 or out of range, or at a face with fewer than 3 vertices, with
 * "line N: ..." in the message; non-finite coordinates are reported by vertex
 * number, counted from 1 as in the file.
 *
 * Texture coordinates ("TextureCoordinates") are output when some corner
 * carries a vt (corners without one get 0 0, with a warning); normals only
 * when every corner carries a vn (when only some do, they are ignored with
 * a warning). A vertex used with different vt or vn becomes one point per
 * (v, vt, vn): point i stays vertex i + 1 of the file with the vt and vn of
 * its first use, further combinations are appended after the file's
 * vertices, and vertices that no face uses get a zero normal and 0 0. Where
 * there are such copies, the point data "FileVertex" gives each point's
 * vertex (0-based: point i < the vertex count is i itself), so that normals
 * computed later (vtkShadelabMeshNormals) are the file vertices' and do not
 * crease at a texture's seams (shadelabObjVertices.h).
 *
 * With `usemtl`, each triangle's part (cell data "Part") is its material
 * name's, parts numbered in the order of the names' first use, with part 0
 * named "" for faces before the first usemtl; field data "PartMaterials"
 * holds the names. `mtllib`'s files (MTL, beside the OBJ) give the parts'
 * materials: "PartMaterialIndices" is each part's material's index among
 * the libraries' materials in their order (-1 for "" and for a name they do
 * not define) and "PartKa", "PartKd", "PartKs", "PartNs" its coefficients.
 * The materials' map_Kd and map_Ka are the parts' textures
 * ("PartKdTexture", "PartKaTexture", "TextureSources"... of
 * shadelabPartMaterials.h): their files resolved against the MTL's folder
 * (not opened here: a missing image is the renderer's to report), repeated
 * unless `-clamp on`, bilinear; the options shadelabMtlParser.h skips are
 * warnings. A library that cannot be read is a warning (OBJ files from the
 * web often come without theirs) and its materials are undefined; a
 * malformed one is an error naming it and its line.
 */
#ifndef vtkShadelabOBJReader_h
#define vtkShadelabOBJReader_h

#include "shadelab_filtersModule.h" // the export macro

#include "shadelabMtlParser.h"
#include "vtkShadelabFileReader.h"

#include <string>
#include <vector>

class SHADELAB_FILTERS_EXPORT vtkShadelabOBJReader : public vtkShadelabFileReader
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
   * The materials of mtllib's files (beside fileName), in order, their maps'
   * files resolved; a library that cannot be read is a warning, a malformed
   * one an error.
   */
  std::vector<shadelab::MtlMaterial> ReadLibraries(
    const char* fileName, const std::vector<std::string>& libraries);

  vtkShadelabOBJReader(const vtkShadelabOBJReader&) = delete;
  void operator=(const vtkShadelabOBJReader&) = delete;
};

#endif
