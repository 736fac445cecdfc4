/**
 * @class   vtkShadelabMeshReader
 * @brief   reads a mesh file of any format shadelab knows, by its extension
 *
 * The extension (case-insensitive) picks the reader: .obj
 * (vtkShadelabOBJReader), .ply (vtkShadelabPLYReader), .stl
 * (vtkShadelabSTLReader), .off (vtkShadelabOFFReader), .gltf and .glb
 * (vtkShadelabGLTFReader), .vtk (vtkShadelabLegacyVTKReader: legacy files of
 * polydata only) and .vtp (VTK's vtkXMLPolyDataReader). The output is what
 * every vtkShadelabFileReader gives: double points (or the file's floats),
 * triangles only, the
 * file's point normals as the float array "Normals", and where the format
 * has them, vertex colours, texture coordinates and parts
 * (shadelabTriangleMesh.h).
 *
 * The error of the reader it runs becomes this reader's one error, so that
 * the program prints a single line. vtkXMLPolyDataReader is given the
 * file's checked bytes (it says little about why it fails), parses their XML,
 * and decodes the arrays only once their sizes are checked against the bytes
 * (shadelabXMLArraySizes.h); its output is checked and triangulated as the
 * other formats are. Its XML parser reports malformed XML itself, so that
 * message comes first.
 */
#ifndef vtkShadelabMeshReader_h
#define vtkShadelabMeshReader_h

#include "shadelab_filtersModule.h" // the export macro

#include "vtkShadelabFileReader.h"

class SHADELAB_FILTERS_EXPORT vtkShadelabMeshReader : public vtkShadelabFileReader
{
public:
  static vtkShadelabMeshReader* New();
  vtkTypeMacro(vtkShadelabMeshReader, vtkShadelabFileReader);

  /** The extensions it reads, for messages and help: ".obj .ply .stl .off .gltf .glb .vtp .vtk". */
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
