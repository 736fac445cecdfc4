// What shadelab sends its image-writer process through a pipe: one picture
// and where and how to write it, or an image to decode for a texture (the
// writer is the one process that links OpenImageIO). Both ends are the same
// build on the same machine, so numbers travel in native byte order.
#ifndef shadelab_image_writer_protocol_h
#define shadelab_image_writer_protocol_h

#include "image/image_pixels.h"
#include "shadelabTexture.h"

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

/**
 * An image file to decode into a texture: the file at Path, or, when Bytes
 * are given, those (an image embedded in a mesh file; Path then names it in
 * errors). Answered by one line, empty or the problem, and after an empty
 * one the image (SendTextureImage).
 */
struct DecodeRequest
{
  std::string Path;
  std::vector<std::uint8_t> Bytes;
};

enum class RequestKind
{
  Picture,
  Decode
};

/** Writes request to fd; false if the pipe broke. */
bool SendImageRequest(int fd, const ImageRequest& request);
bool SendDecodeRequest(int fd, const DecodeRequest& request);

/**
 * Reads which request comes next from fd, then the request itself with
 * its kind's Receive; false at end of input or on a malformed request.
 */
bool ReceiveRequestKind(int fd, RequestKind& kind);
bool ReceiveImageRequest(int fd, ImageRequest& request);
bool ReceiveDecodeRequest(int fd, DecodeRequest& request);

/** A decoded image: its size, then its linear RGB floats; false if the pipe broke or it is
 * malformed. */
bool SendTextureImage(int fd, const TextureImage& image);
bool ReceiveTextureImage(int fd, TextureImage& image);
}

#endif
