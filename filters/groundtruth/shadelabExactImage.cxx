#include "shadelabExactImage.h"

#include "shadelabParallelRows.h"
#include "shadelabVec3.h"

#include <algorithm>
#include <cmath>

namespace shadelab
{
ExactImage RenderExactImage(const AnalyticSurface& surface, const PinholeCamera& camera, int width,
  int height, IlluminationInputs in)
{
  in.Orthographic = camera.Orthographic;
  in.Eye = camera.Position;
  in.ViewDirection = normalize(camera.FocalPoint - camera.Position);
  ExactImage image;
  image.Width = width;
  image.Height = height;
  image.Rgb.assign(3 * static_cast<std::size_t>(width) * height, 0.0);
  image.Covered.assign(static_cast<std::size_t>(width) * height, 0);
  ForEachRow(0, height,
    [&](int j)
    {
      for (int i = 0; i < width; ++i)
      {
        // Row j from the bottom: the pixel centre from the top is height - j - 0.5.
        const Ray ray = PictureRay(camera, width, height, i + 0.5, height - j - 0.5);
        const RayHit hit = surface.Intersect(ray.Origin, ray.Direction);
        if (!hit.Hit)
        {
          continue;
        }
        const std::size_t p = static_cast<std::size_t>(j) * width + i;
        image.Covered[p] = 1;
        const Rgb color = Illuminate(in, hit.Point, hit.Normal);
        std::copy(color.begin(), color.end(), image.Rgb.begin() + 3 * p);
      }
    });
  return image;
}
}
