#include "core/output_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <filesystem>
#include <iterator>
#include <vector>

namespace shadelab
{
namespace
{
std::string CannotWrite(int error)
{
  return std::string("cannot write: ") + std::strerror(error);
}

std::string FolderOf(const std::string& path)
{
  const std::string folder = std::filesystem::path(path).parent_path().string();
  return folder.empty() ? "." : folder;
}

// "out.png" -> "out.png.tmp-": every temporary of path starts so.
std::string TemporaryPrefix(const std::string& path)
{
  return std::filesystem::path(path).filename().string() + ".tmp-";
}

// A temporary that nobody holds locked was left by a run that died while
// writing it (killed, crashed, the machine lost power): remove it. One that
// is being written stays, whichever process writes it.
void RemoveStaleTemporaries(const std::string& path)
{
  DIR* folder = opendir(FolderOf(path).c_str());
  if (!folder)
  {
    return; // the open of the temporary reports what is wrong with the folder
  }
  const std::string prefix = TemporaryPrefix(path);
  while (const dirent* entry = readdir(folder))
  {
    if (std::strncmp(entry->d_name, prefix.c_str(), prefix.size()) != 0)
    {
      continue;
    }
    const int fd = openat(
      dirfd(folder), entry->d_name, O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK | O_NOCTTY);
    if (fd < 0)
    {
      continue;
    }
    if (flock(fd, LOCK_EX | LOCK_NB) == 0)
    {
      unlinkat(dirfd(folder), entry->d_name, 0);
    }
    close(fd);
  }
  closedir(folder);
}

// The temporaries this process is writing, for RemoveTemporariesNow: fixed
// slots of plain bytes, so that a signal handler can read them.
struct TemporarySlot
{
  std::atomic<bool> Used{ false };
  std::atomic<bool> Ready{ false };
  char Path[PATH_MAX] = {};
};
TemporarySlot Temporaries[64];

// The slot that now names temporary, or -1 when all are taken (it is then
// only left for the next run's stale-temporary removal).
int RegisterTemporary(const std::string& temporary)
{
  if (temporary.size() >= PATH_MAX)
  {
    return -1;
  }
  for (int i = 0; i < static_cast<int>(std::size(Temporaries)); ++i)
  {
    bool expected = false;
    if (Temporaries[i].Used.compare_exchange_strong(expected, true))
    {
      std::memcpy(Temporaries[i].Path, temporary.c_str(), temporary.size() + 1);
      Temporaries[i].Ready = true;
      return i;
    }
  }
  return -1;
}

void ReleaseTemporary(int& slot)
{
  if (slot >= 0)
  {
    Temporaries[slot].Ready = false;
    Temporaries[slot].Used = false;
    slot = -1;
  }
}
}

void RemoveTemporariesNow()
{
  for (TemporarySlot& slot : Temporaries)
  {
    if (slot.Ready)
    {
      unlink(slot.Path);
    }
  }
}

OutputFile::OutputFile(std::string path)
  : Path(std::move(path))
{
  RemoveStaleTemporaries(this->Path);
  static std::atomic<unsigned> counter{ 0 };
  for (int attempt = 0; attempt < 100; ++attempt)
  {
    this->Temporary =
      this->Path + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
    // 0666 less the umask: the permissions any new file of the user gets.
    this->Descriptor = open(this->Temporary.c_str(),
      O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOCTTY | O_NOFOLLOW, 0666);
    if (this->Descriptor < 0)
    {
      const int error = errno;
      this->Temporary.clear();
      if (error == EEXIST)
      {
        continue;
      }
      this->Fail(nullptr, error);
      return;
    }
    // Between the open and the lock, another run's RemoveStaleTemporaries
    // may have taken the file for stale and removed it: then start again.
    struct stat status = {};
    if (flock(this->Descriptor, LOCK_EX) != 0 ||
      (fstat(this->Descriptor, &status) == 0 && status.st_nlink > 0))
    {
      this->Slot = RegisterTemporary(this->Temporary);
      return; // locked and still there (or no locks here: written unlocked)
    }
    close(this->Descriptor);
    this->Descriptor = -1;
    this->Temporary.clear();
  }
  this->Fail(nullptr, EEXIST);
}

OutputFile::~OutputFile()
{
  if (this->Descriptor >= 0)
  {
    close(this->Descriptor);
  }
  if (!this->Temporary.empty())
  {
    unlink(this->Temporary.c_str());
  }
  ReleaseTemporary(this->Slot);
}

bool OutputFile::Fail(const char* what, int error)
{
  if (this->Failure.empty())
  {
    this->Failure = what ? std::string("cannot write: ") + what + ": " + std::strerror(error)
                         : CannotWrite(error);
  }
  return false;
}

bool OutputFile::Write(const void* data, std::size_t size)
{
  if (this->Descriptor < 0 || !this->Failure.empty())
  {
    return false;
  }
  const char* bytes = static_cast<const char*>(data);
  while (size > 0)
  {
    const ssize_t written = write(this->Descriptor, bytes, size);
    if (written < 0)
    {
      if (errno == EINTR)
      {
        continue;
      }
      return this->Fail(nullptr, errno);
    }
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

std::string OutputFile::Commit()
{
  if (this->Descriptor < 0 || !this->Failure.empty())
  {
    return this->Failure;
  }
  if (fsync(this->Descriptor) != 0)
  {
    this->Fail(nullptr, errno);
  }
  // Closing gives up the lock before the rename: another run that removes
  // stale temporaries of this very output in between makes the rename fail,
  // which is reported; nothing is lost.
  if (close(this->Descriptor) != 0)
  {
    this->Fail(nullptr, errno);
  }
  this->Descriptor = -1;
  if (!this->Failure.empty())
  {
    return this->Failure;
  }
  if (std::rename(this->Temporary.c_str(), this->Path.c_str()) != 0)
  {
    this->Fail(nullptr, errno);
    return this->Failure;
  }
  ReleaseTemporary(this->Slot);
  this->Temporary.clear();
  // The rename is an entry of the folder: synced, it survives a power loss.
  const int folder = open(FolderOf(this->Path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder < 0 || (fsync(folder) != 0 && errno != EINVAL))
  {
    this->Fail("the folder", errno);
  }
  if (folder >= 0)
  {
    close(folder);
  }
  return this->Failure;
}

std::string WriteFile(const std::string& path, std::string_view bytes)
{
  OutputFile file(path);
  file.Write(bytes);
  return file.Commit();
}

MemoryFile::MemoryFile()
  : Memory(memfd_create("shadelab-output", MFD_CLOEXEC))
{
  if (this->Memory < 0)
  {
    this->Failure = CannotWrite(errno);
  }
}

MemoryFile::~MemoryFile()
{
  if (this->Memory >= 0)
  {
    close(this->Memory);
  }
}

std::string MemoryFile::Name() const
{
  return "/proc/" + std::to_string(getpid()) + "/fd/" + std::to_string(this->Memory);
}

std::string MemoryFile::Read() const
{
  std::string text;
  std::vector<char> chunk(1 << 16);
  ssize_t n = 0;
  while ((n = pread(this->Memory, chunk.data(), chunk.size(), static_cast<off_t>(text.size()))) > 0)
  {
    text.append(chunk.data(), static_cast<std::size_t>(n));
  }
  return text;
}

bool MemoryFile::AtSizeLimit() const
{
  struct stat held = {};
  rlimit limit = {};
  return fstat(this->Memory, &held) == 0 && getrlimit(RLIMIT_FSIZE, &limit) == 0 &&
    limit.rlim_cur != RLIM_INFINITY && static_cast<rlim_t>(held.st_size) >= limit.rlim_cur;
}

std::string MemoryFile::WriteTo(const std::string& path) const
{
  if (this->AtSizeLimit())
  {
    return CannotWrite(EFBIG);
  }
  OutputFile file(path);
  std::vector<char> chunk(1 << 20);
  off_t offset = 0;
  ssize_t n = 0;
  while ((n = pread(this->Memory, chunk.data(), chunk.size(), offset)) > 0 &&
    file.Write(chunk.data(), static_cast<std::size_t>(n)))
  {
    offset += n;
  }
  return n < 0 ? CannotWrite(errno) : file.Commit();
}

std::string WriteFileThroughMemory(
  const std::string& path, const std::function<std::string(const std::string& name)>& write)
{
  const MemoryFile memory;
  if (!memory.Error().empty())
  {
    return memory.Error();
  }
  const std::string name = memory.Name();
  std::string error = write(name);
  if (!error.empty() && memory.AtSizeLimit())
  {
    return CannotWrite(EFBIG); // the cause, whatever the writer made of it
  }
  // A writer's message names the file it was given: the user's is the output.
  for (auto at = error.find(name); at != std::string::npos; at = error.find(name, at + path.size()))
  {
    error.replace(at, name.size(), path);
  }
  return error.empty() ? memory.WriteTo(path) : error;
}
}
