// The image writer's files (image_writer_main.cxx): pictures arrive one
// request each, an --orbit animation's frames in order, and each file is
// encoded in memory, then written whole by OutputFile once its last frame
// is in. A failure, or frames that stop coming (an interrupted batch, a
// frame that could not be rendered), leaves nothing.
#ifndef shadelab_picture_files_h
#define shadelab_picture_files_h

#include "image/image_writer_protocol.h"

#include <memory>
#include <string>

namespace shadelab
{
/** One file's encoding: its frames, then the file. */
class Encoder
{
public:
  virtual ~Encoder() = default;
  /** Encodes the next frame: "" or the problem. */
  virtual std::string Add(const ImageRequest& frame) = 0;
  /** After the last frame: the file written through OutputFile, "" or the problem. */
  virtual std::string Finish() = 0;
};

class PictureFiles
{
public:
  /** Takes one request: "" or the problem, the reply that shadelab waits for. */
  std::string Write(const ImageRequest& request);

private:
  std::unique_ptr<Encoder> Open; // the file whose frames are coming
  std::string Path;
  std::uint32_t Next = 0; // the frame it expects
};
}

#endif
