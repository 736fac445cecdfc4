#include "vtkShadelabFileReader.h"

#include "shadelabCheckedFile.h"
#include "shadelabMeshReadError.h"

#include <vtkErrorCode.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <sys/resource.h>

#include <cstdint>
#include <fstream>
#include <new>

namespace
{
// Reading needs the file's bytes and, for the mesh made from them, about as
// many again (points and faces in double and 64-bit ids). A file bigger than
// half of what the process can get fails here with a message, rather than
// overcommitted memory meeting the kernel's OOM killer halfway through.
void CheckMemoryFor(std::uint64_t fileBytes)
{
  const std::uint64_t available = vtkShadelabFileReader::AvailableMemory();
  if (available > 0 && fileBytes > available / 2)
  {
    throw shadelab::MeshReadError("is " + std::to_string(fileBytes >> 20) +
        " MiB; reading it needs more than the " + std::to_string(available >> 20) +
        " MiB of memory available",
      vtkErrorCode::UnknownError);
  }
}
}

vtkShadelabFileReader::vtkShadelabFileReader()
{
  this->SetNumberOfInputPorts(0);
}

vtkShadelabFileReader::~vtkShadelabFileReader()
{
  this->SetFileName(nullptr);
}

std::uint64_t vtkShadelabFileReader::AvailableMemory()
{
  std::uint64_t available = 0;
  std::ifstream meminfo("/proc/meminfo");
  for (std::string key; meminfo >> key;)
  {
    std::uint64_t kib = 0;
    meminfo >> kib;
    if (key == "MemAvailable:")
    {
      available = kib * 1024;
      break;
    }
    meminfo.ignore(1 << 10, '\n');
  }
  for (int resource : { RLIMIT_AS, RLIMIT_DATA })
  {
    rlimit limit{};
    if (getrlimit(resource, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      (available == 0 || limit.rlim_cur < available))
    {
      available = limit.rlim_cur;
    }
  }
  return available;
}

std::string vtkShadelabFileReader::ReadFileBytes(const char* fileName)
{
  shadelab::CheckedFile file = shadelab::OpenChecked(fileName);
  CheckMemoryFor(file.GetSize());
  return file.ReadAll();
}

void vtkShadelabFileReader::CheckReadable(const char* fileName)
{
  shadelab::OpenChecked(fileName);
}

int vtkShadelabFileReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->SetErrorCode(vtkErrorCode::NoError);
  try
  {
    if (!this->FileName || !*this->FileName)
    {
      throw shadelab::MeshReadError("no file name given", vtkErrorCode::NoFileNameError);
    }
    // Into a mesh of its own: the output (emptied by the executive) stays
    // empty unless the whole file was read.
    vtkNew<vtkPolyData> triangles;
    this->ReadMesh(this->FileName, triangles);
    if (!this->ReadNormals)
    {
      triangles->GetPointData()->SetNormals(nullptr);
    }
    vtkPolyData::GetData(outputVector)->ShallowCopy(triangles);
    return 1;
  }
  catch (const std::exception&)
  {
    const shadelab::MeshReadError error = shadelab::CurrentReadError();
    this->SetErrorCode(error.GetCode());
    vtkErrorMacro(<< error.what());
  }
  return 0;
}

void vtkShadelabFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReadNormals: " << (this->ReadNormals ? "On" : "Off") << "\n";
  os << indent << "AllowOutsideReferences: " << (this->AllowOutsideReferences ? "On" : "Off")
     << "\n";
}
