#include "image_writer_process.h"

#include "image_writer_protocol.h"
#include "output_path.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

extern char** environ;

namespace shadelab
{
namespace
{
// The writer sits beside the shadelab executable.
std::string WriterPath()
{
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return (exe.parent_path() / "shadelab-image-writer").string();
}

void Close(int& fd)
{
  if (fd >= 0)
  {
    close(fd);
    fd = -1;
  }
}
}

ImageWriterProcess::ImageWriterProcess()
{
  int toChild[2], fromChild[2];
  if (pipe2(toChild, O_CLOEXEC) != 0)
  {
    this->StartError = std::string("cannot start the image writer: ") + std::strerror(errno);
    return;
  }
  if (pipe2(fromChild, O_CLOEXEC) != 0)
  {
    this->StartError = std::string("cannot start the image writer: ") + std::strerror(errno);
    close(toChild[0]);
    close(toChild[1]);
    return;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, toChild[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, fromChild[1], STDOUT_FILENO);
  const std::string path = WriterPath();
  char* const argv[] = { const_cast<char*>(path.c_str()), nullptr };
  const int spawned = posix_spawn(&this->Child, path.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(toChild[0]);
  close(fromChild[1]);
  this->ToChild = toChild[1];
  this->FromChild = fromChild[0];
  if (spawned != 0)
  {
    this->Child = -1;
    this->StartError = "cannot start the image writer " + path + ": " + std::strerror(spawned);
    Close(this->ToChild);
    Close(this->FromChild);
  }
}

ImageWriterProcess::~ImageWriterProcess()
{
  // No picture came (an error came first): the writer, still binding
  // OpenImageIO, has nothing to do and is stopped rather than waited for.
  if (this->Child > 0)
  {
    kill(this->Child, SIGKILL);
  }
  Close(this->ToChild);
  this->Wait();
  Close(this->FromChild);
}

int ImageWriterProcess::Wait()
{
  int status = 0;
  if (this->Child > 0)
  {
    while (waitpid(this->Child, &status, 0) < 0 && errno == EINTR)
    {
    }
    this->Child = -1;
  }
  return status;
}

std::string ImageWriterProcess::CheckFolder(const std::string& path)
{
  const std::filesystem::path p(path);
  if (p.extension().empty())
  {
    return "no file extension to choose an image format by";
  }
  if (std::string error = CheckWritableFolder(path); !error.empty())
  {
    return error;
  }
  std::error_code error;
  if (std::filesystem::is_directory(p, error))
  {
    return "cannot write: is a folder";
  }
  return {};
}

std::string ImageWriterProcess::Write(const std::string& path, const FloatImage& image,
  PixelType type, const std::vector<std::pair<std::string, std::string>>& metadata)
{
  if (!this->StartError.empty())
  {
    return this->StartError;
  }
  const bool sent = SendImageRequest(this->ToChild, { path, type, metadata, image });
  Close(this->ToChild);
  std::string reply;
  char buffer[512];
  ssize_t n = 0;
  while ((n = read(this->FromChild, buffer, sizeof buffer)) > 0 || (n < 0 && errno == EINTR))
  {
    reply.append(buffer, n > 0 ? static_cast<size_t>(n) : 0);
  }
  const int status = this->Wait();
  if (!reply.empty())
  {
    return reply;
  }
  if (!sent || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
  {
    return WIFSIGNALED(status)
      ? "the image writer died (signal " + std::to_string(WTERMSIG(status)) + ")"
      : std::string("the image writer failed");
  }
  return {};
}
}
