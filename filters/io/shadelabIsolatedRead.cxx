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
// The answer's first byte: what follows.
constexpr char Bytes = 'B'; // the bytes `read` returned
constexpr char Error = 'E'; // an error's code (8 bytes) and message

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

bool WriteAll(int fd, const std::string& bytes)
{
  for (size_t done = 0; done < bytes.size();)
  {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno != EINTR)
    {
      return false;
    }
    done += n > 0 ? static_cast<size_t>(n) : 0;
  }
  return true;
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
  std::string message;
  try
  {
    message = Bytes + read();
  }
  catch (const std::exception&)
  {
    const MeshReadError error = CurrentReadError();
    const std::uint64_t code = error.GetCode();
    message = Error + std::string(reinterpret_cast<const char*>(&code), sizeof code) + error.what();
  }
  _exit(WriteAll(answer, message) ? 0 : 1);
}

std::string ReadAll(int fd)
{
  std::string bytes;
  char buffer[65536];
  for (;;)
  {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0)
    {
      bytes.append(buffer, static_cast<size_t>(n));
    }
    else if (n == 0 || errno != EINTR)
    {
      return bytes;
    }
  }
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
  std::string answer;
  try
  {
    answer = ReadAll(from.Get());
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
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && !answer.empty())
  {
    if (answer[0] == Bytes)
    {
      answer.erase(0, 1);
      return answer;
    }
    std::uint64_t code = 0;
    if (answer[0] == Error && answer.size() >= 1 + sizeof code)
    {
      std::memcpy(&code, answer.data() + 1, sizeof code);
      throw MeshReadError(answer.substr(1 + sizeof code), static_cast<unsigned long>(code));
    }
  }
  const char* signal = WIFSIGNALED(status) ? sigabbrev_np(WTERMSIG(status)) : nullptr;
  throw MeshReadError(std::string(who) + " crashed reading it (" +
    (signal ? std::string("SIG") + signal
            : "exit status " + std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1)) +
    ")");
}
}
