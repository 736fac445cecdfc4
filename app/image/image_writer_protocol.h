// What shadelab sends its image-writer process through a pipe: one picture
// and where and how to write it. Both ends are the same build on the same
// machine, so numbers travel in native byte order.
#ifndef shadelab_image_writer_protocol_h
#define shadelab_image_writer_protocol_h

#include "image/image_pixels.h"

#include <cstdint>

#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
/**
 * Where a picture goes in its file: frame Index of Count, the frames of an
 * --orbit animation shown FramesPerSecond (a picture: 0 of 1).
 */
struct FramePlace
{
  std::uint32_t Index = 0;
  std::uint32_t Count = 1;
  double FramesPerSecond = 25;
};

struct ImageRequest
{
  std::string Path;
  PixelType Type = PixelType::Auto;
  std::vector<std::pair<std::string, std::string>> Metadata;
  FramePlace Frame;
  FloatImage Image; // its Width and Height always; its pixels unless Pixels8 has them
  std::vector<std::uint8_t> Pixels8; // 8-bit pictures: top-down RGB(A), quantised by the sender
};

/** Writes request to fd; false if the pipe broke. */
bool SendImageRequest(int fd, const ImageRequest& request);

/** Reads one request from fd; false at end of input or on a malformed request. */
bool ReceiveImageRequest(int fd, ImageRequest& request);
}

#endif
