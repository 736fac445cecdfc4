// What shadelab's charts share (the bench's speed against accuracy, the
// profile's intensity along a line): drawn with VTK's charts through the
// headless backend, one colour per rule.
#ifndef shadelab_chart_style_h
#define shadelab_chart_style_h

#include "image/image_pixels.h"

#include <array>
#include <string>

namespace shadelab
{
struct ChartImage
{
  FloatImage Image;
  std::string Error; // no OpenGL context, else empty
};

/** A rule's colour (flat red, gouraud green, phong blue; others grey), 8-bit RGB. */
inline std::array<unsigned char, 3> RuleColour(const std::string& rule)
{
  if (rule == "flat")
  {
    return { 214, 39, 40 };
  }
  if (rule == "gouraud")
  {
    return { 44, 160, 44 };
  }
  if (rule == "phong")
  {
    return { 31, 119, 180 };
  }
  return { 127, 127, 127 };
}
}

#endif
