// The exact picture of an analytic surface: per pixel, the ray through the
// pixel's centre meets the surface in double precision, and the lecture's
// equation (the oracle's Illuminate) lights the hit with the exact normal.
// No tessellation, no interpolation: the ground truth of the
// speed-accuracy measurements.
#ifndef shadelabExactImage_h
#define shadelabExactImage_h

#include "shadelabAnalyticSurface.h"
#include "shadelabPixelRays.h"
#include "shadelabShadingOracle.h"

#include <vector>

namespace shadelab
{
/** Intensities per pixel, bottom row first as OpenGL reads them. */
struct ExactImage
{
  int Width = 0;
  int Height = 0;
  std::vector<double> Rgb;            // 3 per pixel; the background is 0
  std::vector<unsigned char> Covered; // 1 where the ray meets the surface
};

/**
 * Renders surface through camera at width x height. `in` is in world
 * coordinates; its view (Eye, or the direction of an orthographic camera)
 * is set to the camera's. The surface is closed, so every hit faces the
 * camera.
 */
ExactImage RenderExactImage(const AnalyticSurface& surface, const PinholeCamera& camera, int width,
  int height, IlluminationInputs in);
}

#endif
