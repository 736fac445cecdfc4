// The environment behind the scene (--background environment): each pixel
// that the mesh leaves uncovered shows the environment map along the ray
// through its centre, as a reflection shows it along R (shadelabEnvironment.h),
// looked up in double here for the picture, the oracle and probe alike.
#ifndef shadelabEnvironmentBackground_h
#define shadelabEnvironmentBackground_h

#include "shadelabEnvironment.h"
#include "shadelabPixelRays.h"

#include <vector>

namespace shadelab
{
/**
 * What picture point (x, y) (pixels from the top left, as PictureRay) of a
 * width x height picture shows of the environment: E along its ray's
 * direction (R and Direction that direction, Term zero).
 */
EnvironmentTerm EnvironmentBehind(
  const EnvironmentMap& e, const PinholeCamera& camera, int width, int height, double x, double y);

/**
 * rgba (4 floats a pixel, bottom row first, its colours associated with
 * its alpha: over black) laid over the environment behind each pixel's
 * centre: rgb + (1 - a) E, in double, and a = 1.
 */
void OverEnvironment(std::vector<float>& rgba, int width, int height, const PinholeCamera& camera,
  const EnvironmentMap& e);
}

#endif
