// The lecture's maps as GLSL (doc/design.md, "Maps"): the functions that
// look a map up where the rule lights, each mirroring its oracle.
#ifndef shadelabMapSource_h
#define shadelabMapSource_h

#include <string>

namespace shadelab
{
/**
 * shadelabEnvironmentAt(R): E(R) in view coordinates (the oracle's
 * EnvironmentAt, shadelabEnvironment.cxx), with its sampler and frame.
 */
extern const char* const EnvironmentSource;

/**
 * shadelabMapNormal(N, T, w, st): unit N perturbed by the normal map, or
 * the height (bump) map, at st in the frame of tangent T with handedness w
 * (the oracle's MapNormal, shadelabNormalMap.cxx), with its sampler and
 * scale. Reads shadelabTinyLength.
 */
std::string ReliefSource(bool height);

/** The shader panel's mark of a normal map's lines, or a height map's. */
const char* ReliefMark(bool height);
}

#endif
