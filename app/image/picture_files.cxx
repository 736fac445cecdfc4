#include "image/picture_files.h"

#include "core/output_path.h"
#include "image/image_output.h"
#include "image/video_output.h"

namespace shadelab
{
namespace
{
// The encoder of first's file, by its extension: .mp4 through ffmpeg,
// every other format through OpenImageIO.
template <typename Kind>
std::unique_ptr<Encoder> Start(const ImageRequest& first, std::string& error)
{
  auto encoder = std::make_unique<Kind>();
  error = encoder->Open(first);
  return error.empty() ? std::move(encoder) : nullptr;
}
}

std::string PictureFiles::Write(const ImageRequest& request)
{
  const FramePlace& frame = request.Frame;
  if (frame.Index == 0)
  {
    // An animation whose frames stopped coming is dropped unwritten.
    std::string error;
    this->Open = LowerExtension(request.Path) == ".mp4" ? Start<VideoEncoder>(request, error)
                                                        : Start<ImageEncoder>(request, error);
    this->Path = request.Path;
    if (!this->Open)
    {
      return error;
    }
  }
  else if (!this->Open || request.Path != this->Path || frame.Index != this->Next)
  {
    this->Open.reset();
    return "frame " + std::to_string(frame.Index) + " of " + std::to_string(frame.Count) +
      " came out of order";
  }
  this->Next = frame.Index + 1;
  std::string error = this->Open->Add(request);
  if (error.empty() && this->Next == frame.Count)
  {
    error = this->Open->Finish();
  }
  if (!error.empty() || this->Next == frame.Count)
  {
    this->Open.reset();
  }
  return error;
}
}
