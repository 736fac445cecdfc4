// The inverse of the scene options' parsing: the command-line words that
// make SceneOptions again, for a command to be given back (the inspector's
// Copy command). Only what differs from the defaults is written; numbers
// with 17 significant digits, so that they parse back to the same doubles.
#ifndef shadelab_scene_arguments_h
#define shadelab_scene_arguments_h

#include "core/options.h"

#include <string>
#include <vector>

namespace shadelab
{
/** Words such as {"--shading", "flat", "--ka", "0.1,0.2,0.3"}; not the mesh. */
std::vector<std::string> SceneArguments(const SceneOptions& scene);

/** A light as --light writes it: point:X,Y,Z:R,G,B, ... */
std::string LightArgument(const Light& light);
}

#endif
