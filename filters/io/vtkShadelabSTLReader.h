/**
 * @class   vtkShadelabSTLReader
 * @brief   reads ASCII and binary STL, welding the corners of the triangles
 *
 * A binary STL is an 80-byte header, a little-endian uint32 triangle count
 * and 50 bytes per triangle. Its header may start with "solid" as ASCII
 * files do, so the size decides: a file of exactly 84 + 50 * count bytes is
 * binary; otherwise a file that starts with "solid" and holds no NUL byte is
 * read as ASCII, and anything else is a binary file whose count does not
 * match its size (an error, as is an ASCII file without its "endsolid").
 *
 * STL repeats every vertex in each triangle. Corners with exactly equal
 * coordinates (-0 and +0 alike) become one point, so that smooth normals can
 * be computed later; the facet normals are per face and are ignored.
 * Triangles are numbered from 0 in messages.
 */
#ifndef vtkShadelabSTLReader_h
#define vtkShadelabSTLReader_h

#include "shadelab_filtersModule.h" // the export macro

#include "vtkShadelabFileReader.h"

class SHADELAB_FILTERS_EXPORT vtkShadelabSTLReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabSTLReader* New();
  vtkTypeMacro(vtkShadelabSTLReader, vtkShadelabFileReader);

protected:
  vtkShadelabSTLReader() = default;
  ~vtkShadelabSTLReader() override = default;

  void ReadMesh(const char* fileName, vtkPolyData* triangles) override;

private:
  vtkShadelabSTLReader(const vtkShadelabSTLReader&) = delete;
  void operator=(const vtkShadelabSTLReader&) = delete;
};

#endif
