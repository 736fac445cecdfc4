/**
 * @class   vtkShadelabMeshReader
 * @brief   reads a mesh file of any format shadelab knows, by its extension
 *
 * The extension (case-insensitive) picks the reader: .obj
 * (vtkShadelabOBJReader), .ply (vtkShadelabPLYReader), .stl
 * (vtkShadelabSTLReader), .vtp (vtkXMLPolyDataReader) and .vtk (legacy
 * vtkPolyDataReader; a legacy file of any other dataset type is an error).
 * The output is what every vtkShadelabFileReader gives: double points,
 * triangles only, and the file's point normals as the float array "Normals".
 *
 * Errors of the reader it runs become this reader's one error, so that the
 * program prints a single line. For .vtp and .vtk, VTK's readers are given
 * only readable files (they say little about why they fail), and their
 * output is checked and triangulated as the other formats are.
 */
#ifndef vtkShadelabMeshReader_h
#define vtkShadelabMeshReader_h

#include "vtkShadelabFileReader.h"

class vtkShadelabMeshReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabMeshReader* New();
  vtkTypeMacro(vtkShadelabMeshReader, vtkShadelabFileReader);

  /** The extensions it reads, for messages and help: ".obj .ply .stl .vtp .vtk". */
  static const char* GetKnownExtensions();

protected:
  vtkShadelabMeshReader() = default;
  ~vtkShadelabMeshReader() override = default;

  void ReadMesh(const char* fileName, vtkPolyData* triangles) override;

private:
  vtkShadelabMeshReader(const vtkShadelabMeshReader&) = delete;
  void operator=(const vtkShadelabMeshReader&) = delete;
};

#endif
