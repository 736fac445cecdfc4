#include "settings/command_line.h"

#include <CLI/CLI.hpp>

#include <stdexcept>

namespace shadelab
{
void AddSettings(CLI::App& command, SceneOptions& o, Command which)
{
  for (const Setting& s : Settings())
  {
    if (s.Declare && (s.Commands & Of(which)))
    {
      s.Declare(command, o);
    }
  }
}

void ApplySceneArguments(SceneOptions& o, const std::vector<std::string>& args)
{
  CLI::App app;
  for (const Setting& s : Settings())
  {
    if (s.Declare)
    {
      s.Declare(app, o);
    }
  }
  std::vector<std::string> reversed(args.rbegin(), args.rend()); // CLI11 takes them backwards
  try
  {
    app.parse(reversed);
  }
  catch (const CLI::ParseError& e)
  {
    std::string message = e.what();
    // "--view-angle: '200' is outside ...": the caller names the setting.
    const auto colon = message.find(": ");
    if (message.rfind("--", 0) == 0 && colon != std::string::npos)
    {
      message = message.substr(colon + 2);
    }
    throw std::invalid_argument(message);
  }
}

std::vector<std::string> SceneArguments(const SceneOptions& o)
{
  std::vector<std::string> words;
  for (const Setting& s : Settings())
  {
    if (s.Arguments)
    {
      s.Arguments(o, words);
    }
  }
  return words;
}
}
