#include "vtkShadelabMeshReader.h"

#include "shadelabMeshReadError.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabOBJReader.h"
#include "vtkShadelabOutputWindow.h"
#include "vtkShadelabPLYReader.h"
#include "vtkShadelabSTLReader.h"

#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkXMLPolyDataReader.h>

#include <cctype>
#include <string>

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
  std::string extension = fileName.substr(dot);
  for (char& c : extension)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return extension;
}

// Keeps the first error of a reader that this one runs, instead of letting
// it reach the output window; the executive's "returned failure" follows it.
struct FirstError
{
  std::string Message;
  void Catch(vtkObject*, unsigned long, void* text)
  {
    if (this->Message.empty())
    {
      this->Message = vtkShadelabOutputWindow::OneLine(static_cast<const char*>(text));
    }
  }
};

// Runs `reader` and throws its first error as this reader's.
void Run(vtkAlgorithm* reader)
{
  FirstError error;
  const unsigned long fromReader = reader->AddObserver(vtkCommand::ErrorEvent, &error, &FirstError::Catch);
  const unsigned long fromExecutive =
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, &error, &FirstError::Catch);
  const int ok = reader->GetExecutive()->Update();
  reader->RemoveObserver(fromReader);
  reader->GetExecutive()->RemoveObserver(fromExecutive);
  if (!ok || !error.Message.empty())
  {
    const unsigned long code = reader->GetErrorCode();
    throw MeshReadError(error.Message.empty() ? "cannot be read" : error.Message,
      code != vtkErrorCode::NoError ? code : static_cast<unsigned long>(vtkErrorCode::FileFormatError));
  }
}

template <class Reader>
void ReadWith(const char* fileName, vtkPolyData* triangles)
{
  vtkNew<Reader> reader;
  reader->SetFileName(fileName);
  Run(reader);
  triangles->ShallowCopy(reader->GetOutput());
}
}

const char* vtkShadelabMeshReader::GetKnownExtensions()
{
  return ".obj .ply .stl .vtp .vtk";
}

void vtkShadelabMeshReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  const std::string extension = LowerExtension(fileName);
  if (extension == ".obj")
  {
    ReadWith<vtkShadelabOBJReader>(fileName, triangles);
  }
  else if (extension == ".ply")
  {
    ReadWith<vtkShadelabPLYReader>(fileName, triangles);
  }
  else if (extension == ".stl")
  {
    ReadWith<vtkShadelabSTLReader>(fileName, triangles);
  }
  else if (extension == ".vtp")
  {
    CheckReadable(fileName);
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(fileName);
    Run(reader);
    shadelab::MakeTriangleMesh(reader->GetOutput(), triangles);
  }
  else if (extension == ".vtk")
  {
    CheckReadable(fileName);
    vtkNew<vtkPolyDataReader> reader;
    reader->SetFileName(fileName);
    if (!reader->IsFilePolyData())
    {
      throw MeshReadError("not a legacy VTK file of polydata (DATASET POLYDATA)");
    }
    Run(reader);
    shadelab::MakeTriangleMesh(reader->GetOutput(), triangles);
  }
  else
  {
    throw MeshReadError("unknown mesh format \"" + extension + "\" (known: " +
        GetKnownExtensions() + ")",
      vtkErrorCode::UnrecognizedFileTypeError);
  }
}
