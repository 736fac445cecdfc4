#include "image_output.h"

#include "output_path.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
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

// Creates the writer for path's format and opens it on the temporary name.
std::unique_ptr<OIIO::ImageOutput> Open(
  const std::string& path, const OIIO::ImageSpec& spec, std::string& error)
{
  auto out = OIIO::ImageOutput::create(path);
  if (!out)
  {
    const std::string ext = std::filesystem::path(path).extension().string();
    error = ext.empty()
      ? "no file extension to choose an image format by"
      : "no image format for \"" + ext + "\" (OpenImageIO: " + OneLine(OIIO::geterror()) + ")";
    return nullptr;
  }
  const std::string temporary = TemporaryName(path);
  if (!out->open(temporary, spec))
  {
    const int saved = errno;
    std::remove(temporary.c_str());
    error = CheckWritableFolder(path);
    if (error.empty())
    {
      const std::string why = OneLine(out->geterror());
      error = "cannot write: " + (why.empty() ? std::string(std::strerror(saved)) : why);
    }
    return nullptr;
  }
  if (out->spec().format != spec.format)
  {
    out->close();
    std::remove(temporary.c_str());
    error = std::string("the ") + out->format_name() + " format cannot store " +
      spec.format.c_str() + " pixels (float output: .exr, or .tif with --pixel-type float)";
    return nullptr;
  }
  return out;
}
}

std::string WriteImage(const std::string& path, const FloatImage& image, PixelType type,
  const std::vector<std::pair<std::string, std::string>>& metadata,
  const std::vector<std::uint8_t>* rgb8)
{
  const PixelType resolved = ResolvePixelType(path, type);
  OIIO::ImageSpec spec(image.Width, image.Height, 3, ToTypeDesc(resolved));
  for (const auto& [key, value] : metadata)
  {
    spec.attribute(key, value);
  }
  std::string error;
  auto out = Open(path, spec, error);
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
        OIIO::TypeDesc::FLOAT, ToTopDownRgb<float>(image, [](float v) { return v; }).data());
      break;
    default:
      written = out->write_image(
        OIIO::TypeDesc::UINT8, rgb8 ? rgb8->data() : Quantise<uint8_t>(image, 255).data());
      break;
  }
  const std::string temporary = TemporaryName(path);
  if (!written || !out->close())
  {
    error = "cannot write: " + OneLine(out->geterror());
    std::remove(temporary.c_str());
    return error;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
  {
    error = std::string("cannot rename the finished image into place: ") + std::strerror(errno);
    std::remove(temporary.c_str());
    return error;
  }
  return {};
}
}
