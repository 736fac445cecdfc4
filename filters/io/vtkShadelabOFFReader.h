/**
 * @class   vtkShadelabOFFReader
 * @brief   reads Object File Format meshes (Geomview's OFF), strictly
 *
 * The text form of OFF as ModelNet, the Princeton Shape Benchmark and CGAL
 * write it: the keyword [ST][C][N]OFF (its prefixes in any order, each at
 * most once), then the counts "nV nF [nE]" on the same line or the next (nE
 * is not checked, as Geomview says; ModelNet's "OFF1234 5678 0", the keyword
 * run into the first count, is read too), then one vertex per line and one
 * face per line. '#' starts a comment up to the line's end anywhere.
 *
 * A vertex is x y z, then nx ny nz with N (the output's "Normals"), r g b or
 * r g b a with C (the "Colors" array: integers in 0..255, or numbers in 0..1
 * when any colour in the file is written with a point or an exponent, as
 * Geomview's format tells the two apart), then s t with ST (the
 * "TextureCoordinates"). A face is its vertex count k >= 3 and k indices
 * counted from 0, optionally followed by a colour (1, 3 or 4 numbers),
 * which is ignored: shadelab colours by vertex, and a face colour would
 * need the face's vertices split. Faces of more than 3 vertices are
 * triangulated by ear cutting (concave ones too; see MakeTriangleMesh).
 *
 * Strict where OpenMesh's reader is lenient: counts that the file could not
 * hold are refused before anything is allocated; a file with fewer vertices
 * or faces than its header says is "truncated", one with more is an error;
 * so are an index out of range, a face of fewer than 3 vertices, a vertex
 * line with the wrong number of values, non-finite numbers and colours out
 * of range, each with the line number. 4OFF, nOFF and binary OFF are
 * refused as not supported.
 */
#ifndef vtkShadelabOFFReader_h
#define vtkShadelabOFFReader_h

#include "shadelab_filtersModule.h" // the export macro

#include "vtkShadelabFileReader.h"

class SHADELAB_FILTERS_EXPORT vtkShadelabOFFReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabOFFReader* New();
  vtkTypeMacro(vtkShadelabOFFReader, vtkShadelabFileReader);

protected:
  vtkShadelabOFFReader() = default;
  ~vtkShadelabOFFReader() override = default;

  void ReadMesh(const char* fileName, vtkPolyData* triangles) override;

private:
  vtkShadelabOFFReader(const vtkShadelabOFFReader&) = delete;
  void operator=(const vtkShadelabOFFReader&) = delete;
};

#endif
