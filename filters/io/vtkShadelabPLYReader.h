/**
 * @class   vtkShadelabPLYReader
 * @brief   reads PLY meshes: ASCII and binary of either byte order
 *
 * Reads the vertex element's x, y, z (any scalar type) and, when all three
 * are present, nx, ny, nz as point normals; the list property vertex_indices
 * (or vertex_index) of `face` elements as polygons; and the vertex_indices
 * list of `tristrips` elements as triangle strips separated by -1 (which
 * VTK 9.1's vtkPLYReader silently drops). Other properties and elements are
 * skipped by their declared sizes.
 *
 * Every count in the header is checked against the file's size before
 * anything is allocated. A file shorter than its header says fails with
 * "truncated: header declares N faces but the file ends after M"; vertex and
 * face numbers in messages count from 0, as PLY's indices do. Data after the
 * last declared element is ignored.
 */
#ifndef vtkShadelabPLYReader_h
#define vtkShadelabPLYReader_h

#include "shadelab_filtersModule.h" // the export macro

#include "vtkShadelabFileReader.h"

class SHADELAB_FILTERS_EXPORT vtkShadelabPLYReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabPLYReader* New();
  vtkTypeMacro(vtkShadelabPLYReader, vtkShadelabFileReader);

protected:
  vtkShadelabPLYReader() = default;
  ~vtkShadelabPLYReader() override = default;

  void ReadMesh(const char* fileName, vtkPolyData* triangles) override;

private:
  vtkShadelabPLYReader(const vtkShadelabPLYReader&) = delete;
  void operator=(const vtkShadelabPLYReader&) = delete;
};

#endif
