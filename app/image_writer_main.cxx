// shadelab-image-writer: writes the one picture that shadelab sends on
// standard input (image_writer_protocol.h) and answers on standard output
// with an error line, or nothing on success. See image_writer_process.h.
#include "image_output.h"
#include "image_writer_protocol.h"

#include <unistd.h>

int main()
{
  shadelab::ImageRequest request;
  if (!shadelab::ReceiveImageRequest(STDIN_FILENO, request))
  {
    return 0; // shadelab stopped before it had a picture: nothing to write
  }
  const std::string error =
    shadelab::WriteImage(request.Path, request.Image, request.Type, request.Metadata);
  if (!error.empty())
  {
    (void)!write(STDOUT_FILENO, error.data(), error.size());
    return 1;
  }
  return 0;
}
