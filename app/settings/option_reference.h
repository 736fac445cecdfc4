// The option reference (doc/user/options.md): every option of every command,
// a heading each so that each can be linked, made from the table of settings
// and the commands' own declarations (`shadelab print-reference`, a hidden command).
#ifndef shadelab_option_reference_h
#define shadelab_option_reference_h

#include <string>

namespace CLI
{
class App;
}

namespace shadelab
{
/** The reference of program's commands, in markdown. */
std::string OptionReference(CLI::App& program);
}

#endif
