#include "shadelabIsolatedRead.h"

#include "shadelabMeshReadError.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace shadelab
{
namespace
{
// The answer: a header (what follows, and its length), then that many bytes.
constexpr std::uint64_t Bytes = 'B'; // the bytes `read` returned
constexpr std::uint64_t Error = 'E'; // an error's code (8 bytes) and message
struct Header                        // two words: no padding
{
  std::uint64_t Kind = 0;
  std::uint64_t Length = 0;
};

MeshReadError SystemError(const char* call)
{
  return MeshReadError(
    std::string("cannot start a process to read it: ") + call + ": " + std::strerror(errno),
    vtkErrorCode::UnknownError);
}

// A closing descriptor, whatever leaves the scope.
class Descriptor
{
public:
  explicit Descriptor(int fd)
    : Fd(fd)
  {
  }
  ~Descriptor() { this->Close(); }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int Get() const { return this->Fd; }
  void Close()
  {
    if (this->Fd >= 0)
    {
      close(this->Fd);
      this->Fd = -1;
    }
  }

private:
  int Fd;
};

bool WriteAll(int fd, const char* bytes, size_t size)
{
  for (size_t done = 0; done < size;)
  {
    const ssize_t n = write(fd, bytes + done, size - done);
    if (n < 0 && errno != EINTR)
    {
      return false;
    }
    done += n > 0 ? static_cast<size_t>(n) : 0;
  }
  return true;
}

// Reads `size` bytes unless the pipe ends first; whether it read them all.
bool ReadAll(int fd, char* bytes, size_t size)
{
  for (size_t done = 0; done < size;)
  {
    const ssize_t n = ::read(fd, bytes + done, size - done);
    if (n == 0 || (n < 0 && errno != EINTR))
    {
      return false;
    }
    done += n > 0 ? static_cast<size_t>(n) : 0;
  }
  return true;
}

bool WriteAnswer(int fd, std::uint64_t kind, const std::string& bytes)
{
  const Header header{ kind, bytes.size() };
  return WriteAll(fd, reinterpret_cast<const char*>(&header), sizeof header) &&
    WriteAll(fd, bytes.data(), bytes.size());
}

// The child's part: never returns.
[[noreturn]] void Child(pid_t parent, int answer, const std::function<std::string()>& read)
{
  prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (getppid() != parent) // the parent ended before prctl took effect
  {
    _exit(1);
  }
  signal(SIGINT, SIG_IGN);
  signal(SIGTERM, SIG_IGN);
  const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
  if (null < 0 || dup2(null, STDOUT_FILENO) < 0 || dup2(null, STDERR_FILENO) < 0)
  {
    _exit(1);
  }
  bool written = false;
  try
  {
    written = WriteAnswer(answer, Bytes, read());
  }
  catch (const std::exception&)
  {
    const MeshReadError error = CurrentReadError();
    const std::uint64_t code = error.GetCode();
    written = WriteAnswer(
      answer, Error, std::string(reinterpret_cast<const char*>(&code), sizeof code) + error.what());
  }
  _exit(written ? 0 : 1);
}
}

std::string ReadIsolated(const char* who, const std::function<std::string()>& read)
{
  int ends[2];
  if (pipe2(ends, O_CLOEXEC) != 0)
  {
    throw SystemError("pipe");
  }
  Descriptor from(ends[0]), to(ends[1]);
  const pid_t parent = getpid();
  const pid_t child = fork();
  if (child < 0)
  {
    throw SystemError("fork");
  }
  if (child == 0)
  {
    from.Close();
    Child(parent, to.Get(), read);
  }
  to.Close(); // so that the child's end is the last, and its exit the answer's end
  // The answer read straight into the string it is returned in. A child
  // that ends early leaves it short: then its status tells what happened.
  Header header;
  std::string answer;
  bool whole = false;
  try
  {
    whole = ReadAll(from.Get(), reinterpret_cast<char*>(&header), sizeof header);
    if (whole)
    {
      answer.resize(header.Length);
      whole = ReadAll(from.Get(), answer.data(), answer.size());
    }
  }
  catch (...) // out of memory for the answer: the child is not left behind
  {
    kill(child, SIGKILL);
    waitpid(child, nullptr, 0);
    throw;
  }
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (whole && WIFEXITED(status) && WEXITSTATUS(status) == 0)
  {
    if (header.Kind == Bytes)
    {
      return answer;
    }
    std::uint64_t code = 0;
    if (header.Kind == Error && answer.size() >= sizeof code)
    {
      std::memcpy(&code, answer.data(), sizeof code);
      throw MeshReadError(answer.substr(sizeof code), static_cast<unsigned long>(code));
    }
  }
  const char* signal = WIFSIGNALED(status) ? sigabbrev_np(WTERMSIG(status)) : nullptr;
  throw MeshReadError(std::string(who) + " crashed reading it (" +
    (signal ? std::string("SIG") + signal
            : "exit status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1)) +
    ")");
}
}
