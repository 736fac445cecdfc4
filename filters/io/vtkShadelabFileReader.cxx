#include "vtkShadelabFileReader.h"

#include "shadelabMeshReadError.h"

#include <vtkErrorCode.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <sys/resource.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <new>

namespace
{
struct FileCloser
{
  void operator()(std::FILE* file) const { std::fclose(file); }
};
using FilePointer = std::unique_ptr<std::FILE, FileCloser>;

[[noreturn]] void FailErrno(const char* what, int error)
{
  throw shadelab::MeshReadError(std::string(what) + ": " + std::strerror(error),
    error == ENOENT ? vtkErrorCode::FileNotFoundError : vtkErrorCode::CannotOpenFileError);
}

// Opens for reading and returns the size, or 0 where the file (a pipe)
// does not know it. fopen() succeeds on a directory; fstat() catches that.
FilePointer Open(const char* fileName, std::size_t& size)
{
  FilePointer file(std::fopen(fileName, "rb"));
  if (!file)
  {
    FailErrno("cannot open", errno);
  }
  struct stat info;
  if (fstat(fileno(file.get()), &info) != 0)
  {
    FailErrno("cannot open", errno);
  }
  if (S_ISDIR(info.st_mode))
  {
    FailErrno("cannot open", EISDIR);
  }
  size = S_ISREG(info.st_mode) ? static_cast<std::size_t>(info.st_size) : 0;
  return file;
}

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
  std::size_t size = 0;
  FilePointer file = Open(fileName, size);
  CheckMemoryFor(size);
  std::string bytes(size, '\0');
  std::size_t used = std::fread(bytes.data(), 1, bytes.size(), file.get());
  // A file without a size (or one that grew) is read on to its end. A read
  // that fills the buffer exactly has not met the end yet, so one byte tells
  // whether more come: growing the buffer on spec would leave a file of the
  // size it said in twice its memory (the zeroed tail stays resident).
  int next = EOF;
  while (used == bytes.size() && (next = std::fgetc(file.get())) != EOF)
  {
    bytes.resize(std::max<std::size_t>(2 * bytes.size(), 1 << 16));
    bytes[used++] = static_cast<char>(next);
    used += std::fread(bytes.data() + used, 1, bytes.size() - used, file.get());
  }
  if (std::ferror(file.get()))
  {
    FailErrno("cannot read", errno);
  }
  bytes.resize(used);
  return bytes;
}

void vtkShadelabFileReader::CheckReadable(const char* fileName)
{
  std::size_t size;
  Open(fileName, size);
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
  catch (const shadelab::MeshReadError& error)
  {
    this->SetErrorCode(error.GetCode());
    vtkErrorMacro(<< error.what());
  }
  catch (const std::bad_alloc&)
  {
    this->SetErrorCode(vtkErrorCode::UnknownError);
    vtkErrorMacro(<< "out of memory");
  }
  return 0;
}

void vtkShadelabFileReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReadNormals: " << (this->ReadNormals ? "On" : "Off") << "\n";
}
