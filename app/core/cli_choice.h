// A command-line option whose value is one of an enum's names (its
// NameTable): the choices, the help text's list and the parsing from one table.
#ifndef shadelab_cli_choice_h
#define shadelab_cli_choice_h

#include "shadelabNames.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace shadelab
{
template <typename Enum>
CLI::Option* AddChoice(
  CLI::App& command, const std::string& name, Enum& value, const std::string& help)
{
  return command.add_option(name, value, help)
    ->transform(CLI::CheckedTransformer(NamedValues<Enum>()))
    ->option_text(JoinedNames<Enum>("|"));
}

/** The same for a choice that is absent until given. */
template <typename Enum>
CLI::Option* AddChoice(
  CLI::App& command, const std::string& name, std::optional<Enum>& value, const std::string& help)
{
  return command
    .add_option_function<Enum>(
      name, [&value](const Enum& given) { value = given; }, help)
    ->transform(CLI::CheckedTransformer(NamedValues<Enum>()))
    ->option_text(JoinedNames<Enum>("|"));
}
}

#endif
