// libFuzzer target: a texture's image decoded from bytes, as an image
// embedded in a mesh file is (image/texture_decoding, through OpenImageIO).
// It may only answer a problem or an image whose size fits its pixels and
// the limits, with finite values.
#include "image/texture_decoding.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  shadelab::DecodeRequest request{ "fuzz", std::vector<std::uint8_t>(data, data + size) };
  shadelab::TextureImage image;
  if (!shadelab::DecodeTexture(request, image).empty())
  {
    return 0;
  }
  if (image.Width < 1 || image.Height < 1 || image.Width > shadelab::MaxImageSide ||
    image.Height > shadelab::MaxImageSide ||
    image.Pixels.size() != static_cast<std::size_t>(image.Width) * image.Height * 3)
  {
    std::abort();
  }
  for (float v : image.Pixels)
  {
    if (!std::isfinite(v))
    {
      std::abort();
    }
  }
  return 0;
}
