/**
 * @class   vtkShadelabPLYWriter
 * @brief   writes triangles with point and cell normals as binary PLY
 *
 * VTK 9.1's vtkPLYWriter cannot write normals. This writer stores a
 * triangle mesh as binary little-endian PLY: vertex x, y, z as double and,
 * when the point data has normals, nx, ny, nz as float; faces as a uchar
 * count and int indices and, when the cell data has normals, nx, ny, nz.
 * Errors through vtkErrorMacro (one line); the file is written completely
 * or reported.
 */
#ifndef vtkShadelabPLYWriter_h
#define vtkShadelabPLYWriter_h

#include "shadelab_filtersModule.h" // the export macro

#include <vtkWriter.h>

class vtkPolyData;

class SHADELAB_FILTERS_EXPORT vtkShadelabPLYWriter : public vtkWriter
{
public:
  static vtkShadelabPLYWriter* New();
  vtkTypeMacro(vtkShadelabPLYWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);

protected:
  vtkShadelabPLYWriter() = default;
  ~vtkShadelabPLYWriter() override;

  void WriteData() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;

private:
  vtkShadelabPLYWriter(const vtkShadelabPLYWriter&) = delete;
  void operator=(const vtkShadelabPLYWriter&) = delete;

  char* FileName = nullptr;
};

#endif
