// The lecture's translucency a: a surface's colour I goes over what lies
// behind it as a*I + (1-a)*behind, every surface under a pixel in depth
// order (doc/design.md, "Translucency"). The double-precision composite
// that vtkShadelabPeelingPass's peels make on the GPU.
#ifndef shadelabTranslucency_h
#define shadelabTranslucency_h

#include "shadelabIllumination.h"

#include <vector>

namespace shadelab
{
/** One surface's fragment under a pixel: its shaded colour I and its opacity a. */
struct Layer
{
  Rgb Color{};
  double Opacity = 1;
};

/** A colour with its coverage: the opaque surface or the background behind, or the result. */
struct Covered
{
  Rgb Color{};
  double Alpha = 1;
};

/**
 * The layers (nearest first) over `behind`, from the farthest to the
 * nearest: C = a*I + (1-a)*C and A = a + (1-a)*A. With peels > 0 only the
 * nearest `peels` layers (--peels), the farther ones left out; 0: all.
 * With a transparent background (colour 0, alpha 0) C is the colour
 * over black and A the coverage, 1 - the product of (1 - a).
 */
Covered Composite(const std::vector<Layer>& nearestFirst, const Covered& behind, int peels = 0);
}

#endif
