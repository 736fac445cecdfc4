#include "shadelabExactImage.h"

#include "shadelabVec3.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace shadelab
{
ExactImage RenderExactImage(const AnalyticSurface& surface, const PinholeCamera& camera, int width,
  int height, IlluminationInputs in)
{
  in.Orthographic = false;
  in.Eye = camera.Position;
  // vtkCamera's frame: the view-up made orthogonal to the direction of view.
  const Vec3 forward = normalize(camera.FocalPoint - camera.Position);
  const Vec3 right = normalize(cross(forward, camera.ViewUp));
  const Vec3 up = cross(right, forward);
  const double tanHalf = std::tan(camera.ViewAngle * 3.14159265358979323846 / 360);
  const double aspect = static_cast<double>(width) / height;

  ExactImage image;
  image.Width = width;
  image.Height = height;
  image.Rgb.assign(3 * static_cast<std::size_t>(width) * height, 0.0);
  image.Covered.assign(static_cast<std::size_t>(width) * height, 0);
  auto renderRows = [&](int first, int step)
  {
    for (int j = first; j < height; j += step)
    {
      // The pixel centre in normalised device coordinates, as glViewport maps it.
      const double y = (2 * (j + 0.5) / height - 1) * tanHalf;
      for (int i = 0; i < width; ++i)
      {
        const double x = (2 * (i + 0.5) / width - 1) * tanHalf * aspect;
        const Vec3 direction = normalize(forward + x * right + y * up);
        const RayHit hit = surface.Intersect(camera.Position, direction);
        if (!hit.Hit)
        {
          continue;
        }
        const std::size_t p = static_cast<std::size_t>(j) * width + i;
        image.Covered[p] = 1;
        const Rgb color = Illuminate(in, hit.Point, hit.Normal);
        std::copy(color.begin(), color.end(), image.Rgb.begin() + 3 * p);
      }
    }
  };
  // Rows interleaved over the cores: the torus's rays cost unevenly.
  const int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t)
  {
    workers.emplace_back(renderRows, t, threads);
  }
  renderRows(0, threads);
  for (std::thread& worker : workers)
  {
    worker.join();
  }
  return image;
}
}
