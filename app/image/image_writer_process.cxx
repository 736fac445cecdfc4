#include "image/image_writer_process.h"

#include "core/find_program.h"
#include "core/output_path.h"
#include "core/sibling_executable.h"
#include "image/image_writer_protocol.h"

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
  const std::string path = SiblingExecutable("shadelab-image-writer");
  // Our process id: the writer dies with us (PR_SET_PDEATHSIG), and so
  // checks that we are still its parent once it has asked for that.
  std::string parent = std::to_string(getpid());
  char* const argv[] = { const_cast<char*>(path.c_str()), parent.data(), nullptr };
  const int spawned = posix_spawn(&this->Child, path.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  close(toChild[0]);
  close(fromChild[1]);
  this->ToChild = toChild[1];
  this->FromChild = fromChild[0];
  // A 1080p float picture is 33 MB: through the default 64 KiB pipe that is
  // 500 round trips between the processes; 1 MiB (Linux's unprivileged
  // maximum) cuts them to 32. Only a speed-up: failure changes nothing.
  (void)fcntl(this->ToChild, F_SETPIPE_SZ, 1 << 20);
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
  // Otherwise the closed pipe ends it.
  if (this->Child > 0 && !this->Written)
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
  const std::string error = this->Submit(path, image, type, metadata);
  return error.empty() ? this->Collect() : error;
}

std::string ImageWriterProcess::CheckEncoder(const std::string& path, const FramePlace& frames)
{
  const std::string extension = LowerExtension(path);
  if (extension == ".mp4" && FindProgram("ffmpeg").empty())
  {
    return "writing .mp4 needs the ffmpeg program, which is not on PATH (Debian: apt-get "
           "install ffmpeg)";
  }
  if (extension == ".gif" && frames.Count > 1 && frames.FramesPerSecond > 50)
  {
    return "a GIF's frames last at least 2/100 s (browsers slow shorter ones to 1/10 s): "
           "--fps at most 50, or .mp4";
  }
  return {};
}

std::string ImageWriterProcess::Submit(const std::string& path, const FloatImage& image,
  PixelType type, const std::vector<std::pair<std::string, std::string>>& metadata,
  const FramePlace& frame)
{
  if (ResolvePixelType(path, type) == PixelType::UInt8)
  {
    return this->Submit(path, QuantiseToImage8(image), metadata, frame); // a quarter of the bytes
  }
  ImageRequest request{ path, type, metadata, frame, image, {} };
  return this->Send(request);
}

std::string ImageWriterProcess::Submit(const std::string& path, Image8&& image,
  const std::vector<std::pair<std::string, std::string>>& metadata, const FramePlace& frame)
{
  ImageRequest request{ path, PixelType::UInt8, metadata, frame, {}, std::move(image.Pixels) };
  request.Image.Width = image.Width;
  request.Image.Height = image.Height;
  request.Image.Alpha = image.Alpha;
  return this->Send(request);
}

std::string ImageWriterProcess::Send(const ImageRequest& request)
{
  if (!this->StartError.empty())
  {
    return this->StartError;
  }
  if (this->ToChild < 0)
  {
    return "the image writer has stopped";
  }
  this->Written = true;
  if (SendImageRequest(this->ToChild, request))
  {
    ++this->Unanswered;
    return {};
  }
  // The writer ended: its last words, unless they are an earlier picture's answer.
  if (this->InFlight() > 0)
  {
    return "the image writer has stopped";
  }
  bool broke = false;
  return this->ReadReply(broke);
}

std::string ImageWriterProcess::ReadReply(bool& broke)
{
  // One line answers each request: empty when it is done.
  std::string reply;
  char c = 0;
  ssize_t n = 0;
  broke = false;
  while ((n = read(this->FromChild, &c, 1)) > 0 || (n < 0 && errno == EINTR))
  {
    if (n == 1 && c == '\n')
    {
      return reply;
    }
    reply.append(n == 1 ? 1 : 0, c);
  }
  // The pipe broke: the writer died; its status says how.
  broke = true;
  Close(this->ToChild);
  const int status = this->Wait();
  if (!reply.empty())
  {
    return reply;
  }
  return WIFSIGNALED(status)
    ? "the image writer died (signal " + std::to_string(WTERMSIG(status)) + ")"
    : std::string("the image writer failed");
}

std::string ImageWriterProcess::Collect()
{
  if (!this->Early.empty())
  {
    std::string answer = std::move(this->Early.front());
    this->Early.pop_front();
    return answer;
  }
  if (this->Unanswered == 0)
  {
    return "the image writer has stopped";
  }
  --this->Unanswered;
  bool broke = false;
  return this->ReadReply(broke);
}

std::string ImageWriterProcess::Decode(const DecodeRequest& request, TextureImage& image)
{
  if (!this->StartError.empty())
  {
    return this->StartError;
  }
  for (; this->Unanswered > 0; --this->Unanswered)
  {
    bool broke = false;
    this->Early.push_back(this->ReadReply(broke));
  }
  if (this->ToChild < 0 || !SendDecodeRequest(this->ToChild, request))
  {
    return "the image writer has stopped";
  }
  bool broke = false;
  const std::string reply = this->ReadReply(broke);
  if (broke || !reply.empty())
  {
    return reply;
  }
  return ReceiveTextureImage(this->FromChild, image) ? std::string()
                                                     : std::string("the image writer failed");
}

ImageDecoder DecodingThrough(ImageWriterProcess& writer)
{
  return [&writer](
           const std::string& path, const std::vector<std::uint8_t>& bytes, TextureImage& image) {
    return writer.Decode({ path, bytes }, image);
  };
}

ImageDecoder DecodingThrough(std::unique_ptr<ImageWriterProcess>& writer)
{
  return
    [&writer](const std::string& path, const std::vector<std::uint8_t>& bytes, TextureImage& image)
  {
    if (!writer)
    {
      writer = std::make_unique<ImageWriterProcess>();
    }
    return writer->Decode({ path, bytes }, image);
  };
}
}
