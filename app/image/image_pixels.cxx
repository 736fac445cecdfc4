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

FloatImage BoxAverage(const FloatImage& image, int n)
{
  FloatImage average{ image.Width / n, image.Height / n, {}, image.Alpha };
  average.Rgba.resize(static_cast<std::size_t>(average.Width) * average.Height * 4);
  const double samples = static_cast<double>(n) * n;
  for (int y = 0; y < average.Height; ++y)
  {
    for (int x = 0; x < average.Width; ++x)
    {
      for (int c = 0; c < 4; ++c)
      {
        double sum = 0;
        for (int sy = 0; sy < n; ++sy)
        {
          const float* row = image.Rgba.data() +
            (static_cast<std::size_t>(y * n + sy) * image.Width + static_cast<std::size_t>(x) * n) *
              4;
          for (int sx = 0; sx < n; ++sx)
          {
            sum += row[4 * sx + c];
          }
        }
        average.Rgba[(static_cast<std::size_t>(y) * average.Width + x) * 4 + c] =
          static_cast<float>(sum / samples);
      }
    }
  }
  return average;
}
}
