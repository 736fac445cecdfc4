#include "image/image_pixels.h"

#include "core/output_path.h"

namespace shadelab
{
PixelType ResolvePixelType(const std::string& path, PixelType requested)
{
  if (requested != PixelType::Auto)
  {
    return requested;
  }
  const std::string ext = LowerExtension(path);
  return ext == ".exr" || ext == ".hdr" || ext == ".pfm" ? PixelType::Float : PixelType::UInt8;
}
}
