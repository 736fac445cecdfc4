// Images are written by a process of their own, started first thing.
//
// Debian's OpenImageIO links some 260 shared libraries (OpenCV, FFmpeg,
// GDCM, ...), and binding them takes the dynamic loader about 0.25 s: a third
// of a whole 1080p screenshot. Loading them on a thread does not help, since
// glibc's loader lock, held throughout a dlopen, stalls Mesa's context and
// shader compiler. So shadelab starts shadelab-image-writer (image_writer_main.cxx)
// before it reads the mesh, the writer binds OpenImageIO in its own process
// while shadelab renders, and then receives the picture through a pipe.
#ifndef shadelab_image_writer_process_h
#define shadelab_image_writer_process_h

#include "image/image_pixels.h"
#include "image/image_writer_protocol.h"
#include "scene/mesh_cache.h"

#include <sys/types.h>

#include <deque>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
class ImageWriterProcess
{
public:
  /** Starts the writer process. */
  ImageWriterProcess();
  /** Stops the writer if no picture was handed over; it has written nothing. */
  ~ImageWriterProcess();

  /**
   * What can be checked before any work, without OpenImageIO: the file has
   * an extension and its folder exists and is writable. An error text or "".
   */
  static std::string CheckFolder(const std::string& path);

  /**
   * What needs no picture either, for a file of `frames`' count: a format
   * written by another program (.mp4, through ffmpeg) has it on PATH; a
   * GIF's frames last the whole hundredths of a second that browsers keep
   * (at least 2). An error text or "".
   */
  static std::string CheckEncoder(const std::string& path, const FramePlace& frames);

  /** Hands the picture over and waits until it is written; an error text or "". */
  std::string Write(const std::string& path, const FloatImage& image, PixelType type,
    const std::vector<std::pair<std::string, std::string>>& metadata);

  /**
   * Hands the picture over and returns once the writer has it, so that the
   * caller renders the next while this one is encoded: "" or an error text.
   * Pictures may be submitted before earlier ones are collected (the writer
   * encodes them in parallel); each is collected once, in the order
   * submitted, and InFlight() says how many wait, for the caller to bound.
   * An animation's frames are submitted in order, each with its place; its
   * file is written when the last is in (its Collect says so).
   */
  std::string Submit(const std::string& path, const FloatImage& image, PixelType type,
    const std::vector<std::pair<std::string, std::string>>& metadata, const FramePlace& frame = {});
  /** The same of a picture already quantised, for an 8-bit file (its type resolves to UInt8). */
  std::string Submit(const std::string& path, Image8&& image,
    const std::vector<std::pair<std::string, std::string>>& metadata, const FramePlace& frame = {});

  /** Waits until the oldest picture submitted and not collected is written: "" or an error text. */
  std::string Collect();

  /** Pictures submitted and not yet collected. */
  std::size_t InFlight() const { return this->Early.size() + this->Unanswered; }

  /**
   * Has the writer decode an image for a texture (texture_decoding.h) and
   * waits for it: "" or the problem. May come between a Submit and its
   * Collect: the pictures' answers, which come first, are kept for their
   * Collects.
   */
  std::string Decode(const DecodeRequest& request, TextureImage& image);

private:
  ImageWriterProcess(const ImageWriterProcess&) = delete;
  void operator=(const ImageWriterProcess&) = delete;

  int Wait();
  // Sends a Submit's request: "" or an error text.
  std::string Send(const ImageRequest& request);
  // One answer line, or the writer's end as an error: "" when written.
  std::string ReadReply(bool& broke);

  pid_t Child = -1;
  int ToChild = -1;
  int FromChild = -1;
  std::string StartError;
  bool Written = false;          // a picture was handed over: let the writer finish
  std::size_t Unanswered = 0;    // submitted, their answers not yet read
  std::deque<std::string> Early; // answers read before a decode's, not yet collected
};

/** A MeshCache's decoder through writer. */
ImageDecoder DecodingThrough(ImageWriterProcess& writer);

/** The same through a writer that is started at the first image when there is none yet. */
ImageDecoder DecodingThrough(std::unique_ptr<ImageWriterProcess>& writer);
}

#endif
