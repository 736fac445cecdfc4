#include "image/image_output.h"

#include "core/output_file.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

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
    default:
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

// The writer for path's format, encoding into memory: OpenImageIO's PNG and
// JPEG writers do not report a failed write to a file of their own, so the
// bytes are written by OutputFile, which checks every step.
std::unique_ptr<OIIO::ImageOutput> Open(const std::string& path, const OIIO::ImageSpec& spec,
  OIIO::Filesystem::IOProxy& memory, std::string& error)
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

std::string WriteImage(const std::string& path, const FloatImage& image, PixelType type,
  const std::vector<std::pair<std::string, std::string>>& metadata,
  const std::vector<std::uint8_t>* pixels8)
{
  const PixelType resolved = ResolvePixelType(path, type);
  OIIO::ImageSpec spec(image.Width, image.Height, Channels(image), ToTypeDesc(resolved));
  if (image.Alpha)
  {
    // Associated alpha (the colours are over black), as OpenImageIO takes
    // it; PNG's writer stores it unassociated.
    spec.alpha_channel = 3;
  }
  for (const auto& [key, value] : metadata)
  {
    spec.attribute(key, value);
  }
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  std::string error;
  auto out = Open(path, spec, memory, error);
  if (!out)
  {
    return error;
  }
  bool written = false;
  switch (resolved)
  {
    case PixelType::UInt16:
      written = out->write_image(OIIO::TypeDesc::UINT16, Quantise<uint16_t>(image, 65535).data());
      break;
    case PixelType::Half:
    case PixelType::Float:
      written = out->write_image(
        OIIO::TypeDesc::FLOAT, ToTopDown<float>(image, [](float v) { return v; }).data());
      break;
    default:
      written = out->write_image(
        OIIO::TypeDesc::UINT8, pixels8 ? pixels8->data() : Quantise<uint8_t>(image, 255).data());
      break;
  }
  if (!written || !out->close())
  {
    return "cannot encode: " + OneLine(out->geterror());
  }
  return WriteFile(
    path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}
}
