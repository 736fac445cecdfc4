// The lecture's equation as GLSL: shadelabIlluminate(P, N) with the
// uniforms, constants and functions it reads, for the stage that lights.
// Per scene, the lights are unrolled with only their kinds' code; the
// all-features baseline chooses everything by uniforms at run time.
#ifndef shadelabIlluminateSource_h
#define shadelabIlluminateSource_h

#include "shadelabShaderSource.h"

#include <string>

namespace shadelab
{
/** The declarations and shadelabIlluminate that `features` need. */
std::string IlluminateSource(const ShaderFeatures& features);

/**
 * `text` with each `$` replaced by `value`: GLSL is written as it is
 * compiled, and `$` marks what differs per light or per normal.
 */
std::string FillGlsl(const char* text, const std::string& value);
}

#endif
