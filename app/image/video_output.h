// An --orbit animation out as .mp4 through the ffmpeg program (Debian's
// ffmpeg package): the frames piped to it as raw RGB, encoded as H.264 in
// yuv420p (what browsers and players take) with the index at the front
// (faststart). ffmpeg writes into a MemoryFile, which OutputFile writes once
// ffmpeg has finished: a failure, or frames that stop coming, leave nothing.
#ifndef shadelab_video_output_h
#define shadelab_video_output_h

#include "core/output_file.h"
#include "image/picture_files.h"

#include <sys/types.h>

#include <string>

namespace shadelab
{
/**
 * Kills the ffmpeg that an encoder runs, if one does: for a writer about to
 * end at once. Async-signal-safe.
 */
void StopVideoEncodersNow();

class VideoEncoder : public Encoder
{
public:
  VideoEncoder() = default;
  /** An unfinished video: ffmpeg is stopped, nothing is written. */
  ~VideoEncoder() override;

  /** Starts ffmpeg for first's frames: "" or the problem. */
  std::string Open(const ImageRequest& first);
  std::string Add(const ImageRequest& frame) override;
  std::string Finish() override;

private:
  VideoEncoder(const VideoEncoder&) = delete;
  void operator=(const VideoEncoder&) = delete;

  // ffmpeg's end: "" when it exited 0, else what it said.
  std::string Wait();

  std::string Path;
  MemoryFile Video;
  MemoryFile Log; // ffmpeg's messages
  pid_t Child = -1;
  int ToChild = -1;
};
}

#endif
