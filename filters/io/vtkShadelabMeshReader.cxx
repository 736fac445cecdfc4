#include "vtkShadelabMeshReader.h"

#include "shadelabMeshReadError.h"
#include "shadelabTextScanner.h"
#include "shadelabTriangleMesh.h"
#include "shadelabXMLArraySizes.h"
#include "vtkShadelabAssimpReader.h"
#include "vtkShadelabGLTFReader.h"
#include "vtkShadelabLegacyVTKReader.h"
#include "vtkShadelabOBJReader.h"
#include "vtkShadelabOFFReader.h"
#include "vtkShadelabOutputWindow.h"
#include "vtkShadelabPLYReader.h"
#include "vtkShadelabSTLReader.h"

#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <sstream>
#include <string>
#include <string_view>

vtkStandardNewMacro(vtkShadelabMeshReader);

namespace
{
using shadelab::MeshReadError;

// ".PLY" of "dir.v2/Bunny.PLY" as ".ply"; empty without an extension.
std::string LowerExtension(const std::string& fileName)
{
  const auto slash = fileName.find_last_of('/');
  const auto dot = fileName.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return {};
  }
  return shadelab::ToLower(std::string_view(fileName).substr(dot));
}

// Keeps the errors of a reader that this one runs away from the output
// window, so that its first one becomes this reader's single error; observing
// the executive too silences its "returned failure" follow-up.
class NestedReader
{
public:
  explicit NestedReader(vtkAlgorithm* reader)
    : Reader(reader)
    , Executive(reader->GetExecutive())
    , ReaderTag(reader->AddObserver(vtkCommand::ErrorEvent, this, &NestedReader::Catch))
    , ExecutiveTag(this->Executive->AddObserver(vtkCommand::ErrorEvent, this, &NestedReader::Catch))
  {
  }

  ~NestedReader()
  {
    this->Reader->RemoveObserver(this->ReaderTag);
    this->Executive->RemoveObserver(this->ExecutiveTag);
  }

  /** Runs the reader; throws its first error if it failed or reported one. */
  void Update()
  {
    const int ok = this->Executive->Update();
    if (!ok || !this->First.empty())
    {
      const unsigned long code = this->Reader->GetErrorCode();
      throw MeshReadError(this->First.empty() ? "cannot be read" : this->First,
        code != vtkErrorCode::NoError ? code
                                      : static_cast<unsigned long>(vtkErrorCode::FileFormatError));
    }
  }

private:
  void Catch(vtkObject*, unsigned long, void* text)
  {
    if (this->First.empty())
    {
      this->First = vtkShadelabOutputWindow::OneLine(static_cast<const char*>(text));
    }
  }

  vtkAlgorithm* Reader;
  vtkExecutive* Executive;
  unsigned long ReaderTag;
  unsigned long ExecutiveTag;
  std::string First;
};

// One of vtkShadelabAssimpReader's extensions.
bool IsAssimpExtension(const std::string& extension)
{
  std::istringstream extensions(vtkShadelabAssimpReader::GetExtensions());
  for (std::string known; extensions >> known;)
  {
    if (extension == known)
    {
      return true;
    }
  }
  return false;
}

template <class Reader>
void ReadWith(const char* fileName, vtkShadelabFileReader* settings, vtkPolyData* triangles)
{
  vtkNew<Reader> reader;
  reader->SetFileName(fileName);
  reader->SetReadNormals(settings->GetReadNormals());
  reader->SetAllowOutsideReferences(settings->GetAllowOutsideReferences());
  NestedReader(reader).Update();
  triangles->ShallowCopy(reader->GetOutput());
}
}

const char* vtkShadelabMeshReader::GetKnownExtensions()
{
  return ".obj .ply .stl .off .gltf .glb .vtp .vtk";
}

void vtkShadelabMeshReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  const std::string extension = LowerExtension(fileName);
  if (extension == ".obj")
  {
    ReadWith<vtkShadelabOBJReader>(fileName, this, triangles);
  }
  else if (extension == ".ply")
  {
    ReadWith<vtkShadelabPLYReader>(fileName, this, triangles);
  }
  else if (extension == ".stl")
  {
    ReadWith<vtkShadelabSTLReader>(fileName, this, triangles);
  }
  else if (extension == ".vtp")
  {
    // VTK reads the bytes checked here, from memory: its own reading of the
    // file could meet another file by then.
    std::string bytes = ReadFileBytes(fileName);
    shadelab::CheckXMLPolyDataArrays(bytes);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->ReadFromInputStringOn();
    reader->SetInputString(bytes);
    std::string().swap(bytes);
    NestedReader(reader).Update();
    shadelab::MakeTriangleMesh(reader->GetOutput(), triangles);
  }
  else if (extension == ".gltf" || extension == ".glb")
  {
    ReadWith<vtkShadelabGLTFReader>(fileName, this, triangles);
  }
  else if (extension == ".off")
  {
    ReadWith<vtkShadelabOFFReader>(fileName, this, triangles);
  }
  else if (extension == ".vtk")
  {
    ReadWith<vtkShadelabLegacyVTKReader>(fileName, this, triangles);
  }
  else if (IsAssimpExtension(extension))
  {
    ReadWith<vtkShadelabAssimpReader>(fileName, this, triangles);
  }
  else
  {
    throw MeshReadError("unknown mesh format \"" + extension +
        "\" (known: " + GetKnownExtensions() + "), nor one that assimp reads (" +
        vtkShadelabAssimpReader::GetExtensions() + ")",
      vtkErrorCode::UnrecognizedFileTypeError);
  }
}
