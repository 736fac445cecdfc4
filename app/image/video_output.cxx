#include "image/video_output.h"

#include "core/find_program.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

extern char** environ;

namespace shadelab
{
namespace
{
std::string Number(double value)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// The last line of a program's messages.
std::string LastLine(std::string text)
{
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' '))
  {
    text.pop_back();
  }
  const auto newline = text.find_last_of('\n');
  return newline == std::string::npos ? text : text.substr(newline + 1);
}

std::atomic<pid_t> RunningEncoder{ -1 }; // for StopVideoEncodersNow

// The unsigned big-endian number in bytes[0, count).
std::uint64_t BigEndian(const unsigned char* bytes, int count)
{
  std::uint64_t value = 0;
  for (int i = 0; i < count; ++i)
  {
    value = value << 8 | bytes[i];
  }
  return value;
}

// Whether the MP4 in fd is whole: its top-level boxes, one after another,
// end exactly at the file's end, and the index (moov) and the frames (mdat)
// are among them. ffmpeg that met a full disk or a file-size limit can end
// with status 0 and a file cut short ("moov atom not found" to players).
bool WholeMp4(int fd)
{
  struct stat info;
  if (fstat(fd, &info) != 0)
  {
    return false;
  }
  const auto end = static_cast<std::uint64_t>(info.st_size);
  bool moov = false, mdat = false;
  std::uint64_t at = 0;
  while (at < end)
  {
    unsigned char header[16];
    if (end - at < 8 || pread(fd, header, 8, static_cast<off_t>(at)) != 8)
    {
      return false;
    }
    std::uint64_t size = BigEndian(header, 4);
    if (size == 1) // a 64-bit size follows the type
    {
      if (end - at < 16 || pread(fd, header + 8, 8, static_cast<off_t>(at + 8)) != 8)
      {
        return false;
      }
      size = BigEndian(header + 8, 8);
    }
    else if (size == 0) // the last box, to the file's end
    {
      size = end - at;
    }
    if (size < 8 || size > end - at)
    {
      return false;
    }
    const std::string type(reinterpret_cast<const char*>(header) + 4, 4);
    moov = moov || type == "moov";
    mdat = mdat || type == "mdat";
    at += size;
  }
  return moov && mdat;
}
}

void StopVideoEncodersNow()
{
  const pid_t child = RunningEncoder.load();
  if (child > 0)
  {
    kill(child, SIGKILL);
  }
}

VideoEncoder::~VideoEncoder()
{
  if (this->Child > 0)
  {
    kill(this->Child, SIGKILL);
    this->Wait();
  }
}

std::string VideoEncoder::Open(const ImageRequest& first)
{
  const FloatImage& image = first.Image;
  this->Path = first.Path;
  if (image.Alpha)
  {
    return "the mp4 format cannot store transparency (--background transparent: .png, .tif, "
           ".exr or .gif)";
  }
  if (ResolvePixelType(first.Path, first.Type) != PixelType::UInt8)
  {
    return "the mp4 format stores 8-bit pixels only (--pixel-type auto or uint8)";
  }
  if (image.Width % 2 != 0 || image.Height % 2 != 0)
  {
    return "H.264 in .mp4 needs an even width and height, not " + std::to_string(image.Width) +
      "x" + std::to_string(image.Height);
  }
  for (const MemoryFile* file : { &this->Video, &this->Log })
  {
    if (!file->Error().empty())
    {
      return file->Error();
    }
  }
  const std::string ffmpeg = FindProgram("ffmpeg");
  if (ffmpeg.empty())
  {
    return "writing .mp4 needs the ffmpeg program, which is not on PATH";
  }
  std::vector<std::string> args{ ffmpeg, "-nostdin", "-v", "error", "-f", "rawvideo", "-pix_fmt",
    "rgb24", "-video_size", std::to_string(image.Width) + "x" + std::to_string(image.Height),
    "-framerate", Number(first.Frame.FramesPerSecond), "-i", "pipe:0", "-c:v", "libx264",
    "-pix_fmt", "yuv420p", "-movflags", "+faststart" };
  for (const auto& [key, value] : first.Metadata)
  {
    if (key == "ImageDescription")
    {
      args.insert(args.end(), { "-metadata", "comment=" + value });
    }
  }
  args.insert(args.end(), { "-f", "mp4", "-y", this->Video.Name() });

  int pipe[2];
  if (pipe2(pipe, O_CLOEXEC) != 0)
  {
    return std::string("cannot start ffmpeg: ") + std::strerror(errno);
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, this->Log.Descriptor(), STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, this->Log.Descriptor(), STDERR_FILENO);
  // A group of its own: Ctrl-C stops shadelab between pictures, and a
  // video is finished or dropped by us, not cut short by the signal.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  std::vector<char*> argv;
  for (std::string& a : args)
  {
    argv.push_back(a.data());
  }
  argv.push_back(nullptr);
  const int spawned =
    posix_spawn(&this->Child, ffmpeg.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  posix_spawn_file_actions_destroy(&actions);
  close(pipe[0]);
  this->ToChild = pipe[1];
  if (spawned != 0)
  {
    this->Child = -1;
    close(this->ToChild);
    this->ToChild = -1;
    return "cannot start " + ffmpeg + ": " + std::strerror(spawned);
  }
  RunningEncoder = this->Child;
  return {};
}

std::string VideoEncoder::Add(const ImageRequest& frame)
{
  const std::uint8_t* p = frame.Pixels8.data();
  std::size_t left = frame.Pixels8.size();
  while (left > 0)
  {
    const ssize_t n = write(this->ToChild, p, left);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      // ffmpeg stopped reading: it has ended, and says why.
      const std::string ended = this->Wait();
      return ended.empty() ? "ffmpeg ended before the last frame" : ended;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return {};
}

std::string VideoEncoder::Finish()
{
  std::string ended = this->Wait();
  if (ended.empty() && !WholeMp4(this->Video.Descriptor()))
  {
    // It said why at -v error, if it said anything.
    const std::string said = LastLine(this->Log.Read());
    ended = "ffmpeg left the video unfinished" + (said.empty() ? "" : ": " + said);
  }
  return ended.empty() ? this->Video.WriteTo(this->Path) : ended;
}

std::string VideoEncoder::Wait()
{
  if (this->Child <= 0)
  {
    return "ffmpeg is not running";
  }
  if (this->ToChild >= 0)
  {
    close(this->ToChild);
    this->ToChild = -1;
  }
  int status = 0;
  while (waitpid(this->Child, &status, 0) < 0 && errno == EINTR)
  {
  }
  RunningEncoder = -1;
  this->Child = -1;
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0)
  {
    return {};
  }
  const std::string said = LastLine(this->Log.Read());
  return (WIFSIGNALED(status)
             ? "ffmpeg died (signal " + std::to_string(WTERMSIG(status)) + ")"
             : "ffmpeg failed (exit status " + std::to_string(WEXITSTATUS(status)) + ")") +
    (said.empty() ? "" : ": " + said);
}
}
