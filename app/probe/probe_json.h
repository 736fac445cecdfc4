// A pixel explained, as JSON: the contract of `shadelab probe --json`
// (doc/design.md, "Explaining a pixel"; doc/user/probe.md lists every key).
#ifndef shadelab_probe_json_h
#define shadelab_probe_json_h

#include "probe/pixel_probe.h"

#include <nlohmann/json.hpp>

namespace shadelab
{
nlohmann::ordered_json ProbeJson(const PixelProbe& probe);
}

#endif
