#include "shadelabCheckedFile.h"

#include "shadelabMeshReadError.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace shadelab
{
namespace
{
[[noreturn]] void FailErrno(const char* what, int error)
{
  throw MeshReadError(std::string(what) + ": " + std::strerror(error),
    error == ENOENT ? vtkErrorCode::FileNotFoundError : vtkErrorCode::CannotOpenFileError);
}

// Inside the folder or below it: no step of the relative path climbs out.
bool Inside(const std::filesystem::path& path, const std::filesystem::path& folder)
{
  const std::filesystem::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

// What a file that is neither regular nor a folder is, from its st_mode.
const char* FileKind(mode_t mode)
{
  switch (mode & S_IFMT)
  {
    case S_IFIFO:
      return "a FIFO";
    case S_IFSOCK:
      return "a socket";
    case S_IFCHR:
      return "a character device";
    case S_IFBLK:
      return "a block device";
    default:
      return "of another kind";
  }
}
}

CheckedFile::CheckedFile(CheckedFile&& other) noexcept
  : Descriptor(other.Descriptor)
  , Size(other.Size)
{
  other.Descriptor = -1;
}

CheckedFile::~CheckedFile()
{
  if (this->Descriptor >= 0)
  {
    close(this->Descriptor);
  }
}

std::string CheckedFile::ReadAll()
{
  std::string bytes(this->Size, '\0');
  std::size_t used = 0;
  const auto next = [this](char* to, std::size_t count)
  {
    ssize_t n;
    while ((n = read(this->Descriptor, to, count)) < 0 && errno == EINTR)
    {
    }
    if (n < 0)
    {
      FailErrno("cannot read", errno);
    }
    return static_cast<std::size_t>(n);
  };
  for (std::size_t n = 1; used < bytes.size() && n > 0; used += n)
  {
    n = next(bytes.data() + used, bytes.size() - used);
  }
  bytes.resize(used); // it shrank since it was opened: what is there
  // Its end, past the size it said: /proc's files say 0 and hold a few KiB.
  // One that goes on past the slack (appended to while read) is refused.
  constexpr std::size_t Slack = 1 << 20;
  char more[1 << 12];
  for (std::size_t n; used == this->Size && (n = next(more, sizeof more)) > 0;)
  {
    bytes.append(more, n);
    if (bytes.size() > this->Size + Slack)
    {
      throw MeshReadError("grew past its size while it was read", vtkErrorCode::UnknownError);
    }
  }
  return bytes;
}

CheckedFile OpenChecked(const std::string& path, std::uint64_t maxBytes)
{
  // O_NONBLOCK: opening a FIFO for reading returns at once instead of
  // waiting for a writer; it changes nothing for a regular file's reads.
  const int fd = open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
  if (fd < 0)
  {
    FailErrno("cannot open", errno);
  }
  CheckedFile file(fd, 0);
  struct stat info;
  if (fstat(fd, &info) != 0)
  {
    FailErrno("cannot open", errno);
  }
  if (S_ISDIR(info.st_mode))
  {
    FailErrno("cannot open", EISDIR); // as open() for writing would say
  }
  if (!S_ISREG(info.st_mode))
  {
    throw MeshReadError(std::string("is not a regular file but ") + FileKind(info.st_mode),
      vtkErrorCode::CannotOpenFileError);
  }
  const auto size = static_cast<std::uint64_t>(info.st_size);
  if (maxBytes > 0 && size > maxBytes)
  {
    throw MeshReadError("is " + std::to_string(size >> 20) + " MiB, more than the " +
        std::to_string(maxBytes >> 20) + " MiB allowed",
      vtkErrorCode::UnknownError);
  }
  file.Size = size;
  return file;
}

std::string ResolveReference(const std::string& meshFile, const std::string& base,
  const std::string& reference, bool allowOutside)
{
  const std::filesystem::path path = (std::filesystem::path(base) / reference).lexically_normal();
  if (allowOutside)
  {
    return path.string();
  }
  // Both with every symbolic link followed (as far as the path exists), so
  // that a link inside the folder to elsewhere is outside too.
  std::error_code error;
  std::filesystem::path folder = std::filesystem::path(meshFile).parent_path();
  folder = std::filesystem::weakly_canonical(folder.empty() ? "." : folder, error);
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(path, error);
  if (error || folder.empty() || !Inside(resolved, folder))
  {
    throw MeshReadError("lies outside the mesh's folder, so it is not read "
                        "(--allow-outside-references reads it)",
      vtkErrorCode::CannotOpenFileError);
  }
  return path.string();
}
}
