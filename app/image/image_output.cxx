#include "image/image_output.h"

#include "core/output_file.h"
#include "core/output_path.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

namespace shadelab
{
namespace
{
OIIO::TypeDesc ToTypeDesc(PixelType type)
{
  switch (type)
  {
    case PixelType::UInt16:
      return OIIO::TypeDesc::UINT16;
    case PixelType::Half:
      return OIIO::TypeDesc::HALF;
    case PixelType::Float:
      return OIIO::TypeDesc::FLOAT;
    case PixelType::Auto: // resolved before: the file's 8 bits
    case PixelType::UInt8:
      return OIIO::TypeDesc::UINT8;
  }
  return OIIO::TypeDesc::UINT8;
}

}

std::string OneLine(std::string s)
{
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && s.back() == ' ')
  {
    s.pop_back();
  }
  return s;
}

namespace
{
// The writer for path's format, encoding into memory: OpenImageIO's PNG and
// JPEG writers do not report a failed write to a file of their own, so the
// bytes are written by OutputFile, which checks every step.
std::unique_ptr<OIIO::ImageOutput> OpenInMemory(const std::string& path,
  const OIIO::ImageSpec& spec, OIIO::Filesystem::IOProxy& memory, std::string& error)
{
  auto out = OIIO::ImageOutput::create(path, &memory);
  if (!out)
  {
    const std::string ext = std::filesystem::path(path).extension().string();
    error = ext.empty()
      ? "no file extension to choose an image format by"
      : "no image format for \"" + ext + "\" (OpenImageIO: " + OneLine(OIIO::geterror()) + ")";
    return nullptr;
  }
  if (!out->supports("ioproxy"))
  {
    error = std::string("the ") + out->format_name() + " writer cannot encode into memory";
    return nullptr;
  }
  if (!out->open(path, spec))
  {
    error = "cannot encode: " + OneLine(out->geterror());
    return nullptr;
  }
  if (spec.alpha_channel >= 0 && !out->supports("alpha"))
  {
    error = std::string("the ") + out->format_name() +
      " format cannot store transparency (--background transparent: .png, .tif or .exr)";
    return nullptr;
  }
  if (out->spec().format != spec.format)
  {
    error = std::string("the ") + out->format_name() + " format cannot store " +
      spec.format.c_str() + " pixels (float output: .exr, or .tif with --pixel-type float)";
    return nullptr;
  }
  return out;
}
}

std::string ImageEncoder::Open(const ImageRequest& first)
{
  const FloatImage& image = first.Image;
  this->Path = first.Path;
  this->Type = ResolvePixelType(first.Path, first.Type);
  this->Spec = OIIO::ImageSpec(image.Width, image.Height, Channels(image), ToTypeDesc(this->Type));
  if (image.Alpha)
  {
    // Associated alpha (the colours are over black), as OpenImageIO takes
    // it; PNG's writer stores it unassociated.
    this->Spec.alpha_channel = 3;
  }
  for (const auto& [key, value] : first.Metadata)
  {
    this->Spec.attribute(key, value);
  }
  if (LowerExtension(first.Path) == ".png")
  {
    // zlib level 4 with every row's filter "up", chosen by measurement at
    // 1080p (doc/benchmarks-log.md, "PNG encoding"): 2.5-3x faster than
    // OpenImageIO's level 6 with libpng's adaptive filter, for files 6-8%
    // larger. Only the file's size changes: PNG is lossless.
    this->Spec.attribute("png:compressionLevel", 4);
    this->Spec.attribute("png:filter", PNG_FILTER_UP);
  }
  if (first.Frame.Count > 1)
  {
    // An animation's (GIF counts a frame's time in whole hundredths of a second).
    this->Spec.attribute("FramesPerSecond", static_cast<float>(first.Frame.FramesPerSecond));
  }
  this->Memory = std::make_unique<OIIO::Filesystem::IOVecOutput>(this->Encoded);
  std::string error;
  this->Output = OpenInMemory(first.Path, this->Spec, *this->Memory, error);
  return error;
}

std::string ImageEncoder::Add(const ImageRequest& frame)
{
  if (frame.Frame.Index > 0 &&
    !this->Output->open(this->Path, this->Spec, OIIO::ImageOutput::AppendSubimage))
  {
    return "cannot encode: " + OneLine(this->Output->geterror());
  }
  const FloatImage& image = frame.Image;
  bool written = false;
  switch (this->Type)
  {
    case PixelType::UInt16:
      written =
        this->Output->write_image(OIIO::TypeDesc::UINT16, Quantise<uint16_t>(image, 65535).data());
      break;
    case PixelType::Half:
    case PixelType::Float:
      written = this->Output->write_image(
        OIIO::TypeDesc::FLOAT, ToTopDown<float>(image, [](float v) { return v; }).data());
      break;
    case PixelType::Auto:
    case PixelType::UInt8:
      written = this->Output->write_image(OIIO::TypeDesc::UINT8,
        frame.Pixels8.empty() ? Quantise<uint8_t>(image, 255).data() : frame.Pixels8.data());
      break;
  }
  return written ? std::string() : "cannot encode: " + OneLine(this->Output->geterror());
}

std::string ImageEncoder::Finish()
{
  if (!this->Output->close())
  {
    return "cannot encode: " + OneLine(this->Output->geterror());
  }
  return WriteFile(this->Path,
    std::string_view(reinterpret_cast<const char*>(this->Encoded.data()), this->Encoded.size()));
}
}
