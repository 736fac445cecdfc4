// A pixel explained for people: one line per quantity of the lecture's
// equation, in its notation (I = ka*Ia + sum Il*[kd*(N.L) + ks*(N.H)^ns]),
// each with what it is. What `shadelab probe` prints without --json.
#ifndef shadelab_probe_text_h
#define shadelab_probe_text_h

#include "probe/pixel_probe.h"
#include "scene/comparison_panels.h"

#include <optional>

#include <string>

namespace shadelab
{
std::string ProbeText(const PixelProbe& probe);

/**
 * The term of the equation that a line of ProbeText computes (the lines of
 * ka*Ia, kd*Il*(N.L) and ks*Il*(base)^ns), or none: what the window's probe
 * readout highlights in the shader panel when the line is picked.
 */
std::optional<Terms> ProbeTextTerm(const std::string& line);

/** A number as the text writes it: six significant digits. */
std::string ProbeNumber(double value);

/** A vector or colour as the text writes it: "(x, y, z)". */
std::string ProbeTriple(const std::array<double, 3>& value);
}

#endif
