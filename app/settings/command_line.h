// The settings on the command line: each command's options, declared from
// the table of settings, and their inverse, the words that give a
// SceneOptions again (the inspector's Copy command). Only what differs from
// the defaults is given back; numbers with 17 significant digits, so that
// they parse back to the same doubles.
#ifndef shadelab_command_line_h
#define shadelab_command_line_h

#include "settings/setting.h"

#include <string>
#include <vector>

namespace shadelab
{
/** Declares on command, into o, every setting that command takes, in the table's order. */
void AddSettings(CLI::App& command, SceneOptions& o, Command which);

/**
 * Sets on o what args (command-line words, such as {"--shading", "flat"})
 * say, through every setting's own option. Throws std::invalid_argument
 * with CLI11's message, less its leading "--option: ".
 */
void ApplySceneArguments(SceneOptions& o, const std::vector<std::string>& args);

/** Words such as {"--shading", "flat", "--ka", "0.1,0.2,0.3"}; not the mesh. */
std::vector<std::string> SceneArguments(const SceneOptions& scene);
}

#endif
