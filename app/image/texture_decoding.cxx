#include "image/texture_decoding.h"

#include "core/options.h"
#include "image/image_output.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

namespace shadelab
{
namespace
{
// What an embedded image is, from its first bytes: glTF allows PNG and
// JPEG. OpenImageIO picks a reader by the name's extension.
std::string EmbeddedName(const std::vector<std::uint8_t>& bytes)
{
  const auto starts = [&bytes](std::initializer_list<std::uint8_t> magic)
  { return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin()); };
  if (starts({ 0x89, 'P', 'N', 'G' }))
  {
    return "embedded.png";
  }
  if (starts({ 0xFF, 0xD8, 0xFF }))
  {
    return "embedded.jpg";
  }
  return "";
}
}

std::string DecodeTexture(const DecodeRequest& request, TextureImage& image)
{
  std::unique_ptr<OIIO::Filesystem::IOMemReader> memory;
  std::string name = request.Path;
  if (!request.Bytes.empty())
  {
    name = EmbeddedName(request.Bytes);
    if (name.empty())
    {
      return "embedded image: neither PNG nor JPEG";
    }
    memory = std::make_unique<OIIO::Filesystem::IOMemReader>(
      const_cast<std::uint8_t*>(request.Bytes.data()), request.Bytes.size());
  }
  else
  {
    std::error_code error;
    if (!std::filesystem::exists(name, error))
    {
      return "cannot read: " + std::string(std::strerror(ENOENT));
    }
    if (std::filesystem::is_directory(name, error))
    {
      return "cannot read: is a folder";
    }
  }
  auto in = OIIO::ImageInput::open(name, nullptr, memory.get());
  if (!in)
  {
    return "not an image OpenImageIO can read (" + OneLine(OIIO::geterror()) + ")";
  }
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 || spec.width > MaxImageSide ||
    spec.height > MaxImageSide || static_cast<long long>(spec.width) * spec.height > MaxImagePixels)
  {
    return "an image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
      " pixels is beyond " + std::to_string(MaxImageSide) + " a side";
  }
  const int channels = spec.nchannels;
  std::vector<float> pixels(static_cast<size_t>(spec.width) * spec.height * channels);
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, pixels.data()))
  {
    return "cannot decode: " + OneLine(in->geterror());
  }
  image.Width = spec.width;
  image.Height = spec.height;
  image.Pixels.resize(static_cast<size_t>(spec.width) * spec.height * 3);
  // Grey (one or two channels) fills R, G and B; the file's top row is
  // the texture's last (t = 1 at the top).
  const int colour = channels >= 3 ? 3 : 1;
  for (int y = 0; y < spec.height; ++y)
  {
    const float* src = pixels.data() + static_cast<size_t>(y) * spec.width * channels;
    float* dst = image.Pixels.data() + static_cast<size_t>(spec.height - 1 - y) * spec.width * 3;
    for (int x = 0; x < spec.width; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        dst[3 * x + c] = src[x * channels + (colour == 3 ? c : 0)];
      }
    }
  }
  return {};
}
}
