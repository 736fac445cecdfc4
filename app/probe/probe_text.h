// A pixel explained for people: one line per quantity of the lecture's
// equation, in its notation (I = ka*Ia + sum Il*[kd*(N.L) + ks*(N.H)^ns]),
// each with what it is. What `shadelab probe` prints without --json.
#ifndef shadelab_probe_text_h
#define shadelab_probe_text_h

#include "probe/pixel_probe.h"

#include <string>

namespace shadelab
{
std::string ProbeText(const PixelProbe& probe);

/** A number as the text writes it: six significant digits. */
std::string ProbeNumber(double value);

/** A vector or colour as the text writes it: "(x, y, z)". */
std::string ProbeTriple(const std::array<double, 3>& value);
}

#endif
