// A light as the command line writes it and as JSON writes it: the forms
// that Copy command, Save scene and a picture's description give back.
#ifndef shadelab_light_setting_h
#define shadelab_light_setting_h

#include "shadelabIllumination.h"

#include <nlohmann/json.hpp>

#include <string>

namespace shadelab
{
/** A light as --light takes it: point:X,Y,Z:R,G,B, ... */
std::string LightArgument(const Light& light);

/**
 * A light as JSON: kind, position (not a directional light's), direction
 * (not a point light's), color, a spot's half angle under halfAngleKey
 * ("half_angle" in scene files, "half_angle_deg" in a picture's
 * description) and exponent.
 */
nlohmann::ordered_json LightJson(const Light& light, const char* halfAngleKey);
}

#endif
