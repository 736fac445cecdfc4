/**
 * @class   vtkShadelabLegacyVTKReader
 * @brief   reads legacy .vtk files of polydata, strictly
 *
 * VTK 9.1's vtkPolyDataReader crashes on a truncated cell section, reads
 * past its buffer on a cell that claims more vertices than the section
 * holds, allocates whatever a header declares, and returns partly read
 * attributes with only a warning. This reader takes the same files (ASCII
 * or big-endian BINARY, the cell layout before and since file version 5.0)
 * and stops at the first inconsistency instead.
 *
 * It reads POINTS, POLYGONS, TRIANGLE_STRIPS and the NORMALS of POINT_DATA;
 * VERTICES, LINES, the other attributes, CELL_DATA, FIELD data and METADATA
 * are checked and skipped. A dataset other than POLYDATA is an error, as are
 * bit and string arrays, which meshes do not use. Vertex and cell numbers in
 * messages count from 0.
 */
#ifndef vtkShadelabLegacyVTKReader_h
#define vtkShadelabLegacyVTKReader_h

#include "shadelab_filtersModule.h" // the export macro

#include "vtkShadelabFileReader.h"

class SHADELAB_FILTERS_EXPORT vtkShadelabLegacyVTKReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabLegacyVTKReader* New();
  vtkTypeMacro(vtkShadelabLegacyVTKReader, vtkShadelabFileReader);

protected:
  vtkShadelabLegacyVTKReader() = default;
  ~vtkShadelabLegacyVTKReader() override = default;

  void ReadMesh(const char* fileName, vtkPolyData* triangles) override;

private:
  vtkShadelabLegacyVTKReader(const vtkShadelabLegacyVTKReader&) = delete;
  void operator=(const vtkShadelabLegacyVTKReader&) = delete;
};

#endif
