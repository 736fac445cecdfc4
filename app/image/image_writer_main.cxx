// shadelab-image-writer: writes the pictures that shadelab sends on
// standard input (image_writer_protocol.h), one after another, and answers
// each on standard output with one line: empty when it was written (or, for
// an animation's frame, taken), else the error. Images to decode for
// textures are answered the same way, an empty line followed by the image.
// See image_writer_process.h.
#include "image/image_writer_protocol.h"
#include "image/picture_files.h"
#include "image/texture_decoding.h"

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
  shadelab::DecodeRequest decode;
  shadelab::RequestKind kind;
  while (shadelab::ReceiveRequestKind(STDIN_FILENO, kind))
  {
    std::string reply;
    shadelab::TextureImage image;
    if (kind == shadelab::RequestKind::Picture)
    {
      if (!shadelab::ReceiveImageRequest(STDIN_FILENO, request))
      {
        return 0;
      }
      reply = files.Write(request);
    }
    else
    {
      if (!shadelab::ReceiveDecodeRequest(STDIN_FILENO, decode))
      {
        return 0;
      }
      reply = shadelab::DecodeTexture(decode, image);
    }
    std::replace(reply.begin(), reply.end(), '\n', ' ');
    const bool decoded = kind == shadelab::RequestKind::Decode && reply.empty();
    reply += '\n';
    if (write(STDOUT_FILENO, reply.data(), reply.size()) != static_cast<ssize_t>(reply.size()) ||
      (decoded && !shadelab::SendTextureImage(STDOUT_FILENO, image)))
    {
      return 1;
    }
  }
  return 0;
}
