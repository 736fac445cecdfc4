/**
 * @class   vtkShadelabFileReader
 * @brief   abstract base of shadelab's mesh readers: one file in, triangles out
 *
 * A source (no input ports) that reads FileName. Every subclass outputs the
 * same thing: double points (float where a binary file stores 32-bit floats,
 * exactly its values), triangles only, and the file's point normals,
 * if it has any, as the float array "Normals" set as the active normals.
 *
 * On bad input a reader reports exactly one error through vtkErrorMacro, as
 * one line without the file name (the program adds it), sets ErrorCode (a
 * vtkErrorCode value), leaves the output empty and fails the request, so
 * GetExecutive()->Update() returns 0. Subclasses implement ReadMesh() and
 * throw shadelab::MeshReadError; this class turns that into the error.
 */
#ifndef vtkShadelabFileReader_h
#define vtkShadelabFileReader_h

#include "shadelab_filtersModule.h" // the export macro

#include <vtkPolyDataAlgorithm.h>

#include <cstdint>
#include <string>

class SHADELAB_FILTERS_EXPORT vtkShadelabFileReader : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkShadelabFileReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The file to read. */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);

  /**
   * Whether the file's normals are read (default on). Off, the output has no
   * point normals, and an OBJ's vertices are not split by their vn (so
   * normals computed afterwards are smooth across the file's normal seams).
   */
  vtkSetMacro(ReadNormals, bool);
  vtkGetMacro(ReadNormals, bool);
  vtkBooleanMacro(ReadNormals, bool);

  /**
   * Whether the files that the mesh file names (an MTL library, its maps, a
   * glTF buffer or image) may lie outside the mesh file's folder (default
   * off: one that resolves elsewhere, through "../", an absolute path or a
   * symbolic link, is refused unread). On for files you trust.
   */
  vtkSetMacro(AllowOutsideReferences, bool);
  vtkGetMacro(AllowOutsideReferences, bool);
  vtkBooleanMacro(AllowOutsideReferences, bool);

  /**
   * The whole file in memory, once shadelab::OpenChecked found it a regular
   * file that the memory can take; throws MeshReadError "cannot open:
   * <strerror>", "is not a regular file but a FIFO" and the like. Also for
   * the files that a mesh file refers to (glTF's buffers).
   */
  static std::string ReadFileBytes(const char* fileName);

  /** Throws like ReadFileBytes() when the file cannot be opened for reading. */
  static void CheckReadable(const char* fileName);

  /**
   * The memory this process can still get: the system's MemAvailable, or
   * less where a resource limit says so; 0 when nothing can be learnt.
   */
  static std::uint64_t AvailableMemory();

protected:
  vtkShadelabFileReader();
  ~vtkShadelabFileReader() override;

  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

  /** Reads `fileName` into `triangles`, or throws shadelab::MeshReadError. */
  virtual void ReadMesh(const char* fileName, vtkPolyData* triangles) = 0;

  char* FileName = nullptr;
  bool ReadNormals = true;
  bool AllowOutsideReferences = false;

private:
  vtkShadelabFileReader(const vtkShadelabFileReader&) = delete;
  void operator=(const vtkShadelabFileReader&) = delete;
};

#endif
