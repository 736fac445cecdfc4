// shadelab-image-writer: writes the pictures that shadelab sends on
// standard input (image_writer_protocol.h) and answers each on standard
// output with one line: empty when it was written (or, for an animation's
// frame, taken), else the error. Images to decode for textures are answered
// the same way, an empty line followed by the image. Pictures are encoded in
// parallel and answered in order (writer_replies.h). See
// image_writer_process.h.
#include "core/output_file.h"
#include "image/image_writer_protocol.h"
#include "image/picture_files.h"
#include "image/texture_decoding.h"
#include "image/video_output.h"
#include "image/writer_replies.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <memory>
#include <string>

namespace
{
// shadelab ended without closing the pipe (SIGKILL, or its grace after
// SIGTERM ran out): nothing it asked for is wanted any more. What is being
// written is removed, not left partial, and ffmpeg goes too.
void ParentGone(int)
{
  shadelab::RemoveTemporariesNow();
  shadelab::StopVideoEncodersNow();
  _exit(1);
}

// libpng prints "libpng error: ..." on stderr before OpenImageIO returns the
// same problem, which shadelab's one error line quotes: stderr goes to
// /dev/null while an image decodes (the writer itself never prints there).
class QuietStderr
{
public:
  QuietStderr()
    : Saved(dup(STDERR_FILENO))
  {
    const int null = open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (null >= 0)
    {
      dup2(null, STDERR_FILENO);
      close(null);
    }
  }
  ~QuietStderr()
  {
    if (this->Saved >= 0)
    {
      dup2(this->Saved, STDERR_FILENO);
      close(this->Saved);
    }
  }
  QuietStderr(const QuietStderr&) = delete;
  QuietStderr& operator=(const QuietStderr&) = delete;

private:
  int Saved;
};
}

// argv[1], where given: the process id of the shadelab that started it.
int main(int argc, char** argv)
{
  std::signal(SIGUSR1, ParentGone);
  prctl(PR_SET_PDEATHSIG, SIGUSR1);
  if (argc > 1 && getppid() != std::atoi(argv[1]))
  {
    ParentGone(SIGUSR1); // it died before the line above
  }
  // Ctrl-C reaches the whole process group: the writer finishes the picture
  // it has (whole, renamed into place) and ends when shadelab closes the pipe.
  std::signal(SIGINT, SIG_IGN);
  std::signal(SIGTERM, SIG_IGN);
  // A file-size limit (ulimit -f) makes the write fail with EFBIG, and an
  // ffmpeg that died makes the next frame's fail with EPIPE: reported.
  std::signal(SIGXFSZ, SIG_IGN);
  std::signal(SIGPIPE, SIG_IGN);
  // Until shadelab closes the pipe (or sends something malformed); then
  // every picture in flight is finished and answered.
  shadelab::WriterReplies replies(STDOUT_FILENO);
  shadelab::PictureFiles animations; // an --orbit's frames, into one file in order
  shadelab::RequestKind kind;
  while (shadelab::ReceiveRequestKind(STDIN_FILENO, kind))
  {
    if (kind == shadelab::RequestKind::Picture)
    {
      auto request = std::make_shared<shadelab::ImageRequest>();
      if (!shadelab::ReceiveImageRequest(STDIN_FILENO, *request))
      {
        break;
      }
      if (request->Frame.Count > 1)
      {
        replies.Answer(request->Path,
          [&] {
            return shadelab::WriterReply{ animations.Write(*request), {} };
          });
      }
      else
      {
        replies.Encode(
          request->Path, [request] { return shadelab::PictureFiles().Write(*request); });
      }
    }
    else
    {
      shadelab::DecodeRequest decode;
      if (!shadelab::ReceiveDecodeRequest(STDIN_FILENO, decode))
      {
        break;
      }
      replies.Answer(decode.Path,
        [&]
        {
          auto image = std::make_unique<shadelab::TextureImage>();
          const QuietStderr quiet;
          std::string problem = shadelab::DecodeTexture(decode, *image);
          if (!problem.empty())
          {
            image.reset();
          }
          return shadelab::WriterReply{ std::move(problem), std::move(image) };
        });
    }
  }
  return replies.Finish() ? 0 : 1;
}
