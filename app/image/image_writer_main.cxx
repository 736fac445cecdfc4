// shadelab-image-writer: writes the pictures that shadelab sends on
// standard input (image_writer_protocol.h), one after another, and answers
// each on standard output with one line: empty when it was written (or, for
// an animation's frame, taken), else the error. See image_writer_process.h.
#include "image/image_writer_protocol.h"
#include "image/picture_files.h"

#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <string>

int main()
{
  // Ctrl-C reaches the whole process group: the writer finishes the picture
  // it has (whole, renamed into place) and ends when shadelab closes the pipe.
  std::signal(SIGINT, SIG_IGN);
  std::signal(SIGTERM, SIG_IGN);
  // A file-size limit (ulimit -f) makes the write fail with EFBIG, and an
  // ffmpeg that died makes the next frame's fail with EPIPE: reported.
  std::signal(SIGXFSZ, SIG_IGN);
  std::signal(SIGPIPE, SIG_IGN);
  // Until shadelab closes the pipe (or sends something malformed).
  shadelab::PictureFiles files;
  shadelab::ImageRequest request;
  while (shadelab::ReceiveImageRequest(STDIN_FILENO, request))
  {
    std::string reply = files.Write(request);
    std::replace(reply.begin(), reply.end(), '\n', ' ');
    reply += '\n';
    if (write(STDOUT_FILENO, reply.data(), reply.size()) != static_cast<ssize_t>(reply.size()))
    {
      return 1;
    }
  }
  return 0;
}
