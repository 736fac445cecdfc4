// shadelab-view: `shadelab view` in a process without the OSMesa linkage,
// so that the window uses the system's OpenGL (view_command.h).
#include "commands/view_command.h"
#include "core/errors.h"
#include "image/metadata.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkLogger.h>

#include <CLI/CLI.hpp>

#include <csignal>
#include <iostream>

int main(int argc, char** argv)
{
  vtkShadelabOutputWindow::Install()->SetEcho(true);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  std::signal(SIGPIPE, SIG_IGN); // a dead image writer is reported, not fatal
  std::signal(SIGXFSZ, SIG_IGN); // a file-size limit is a write error (EFBIG)

  CLI::App program("shadelab view", "shadelab");
  program.require_subcommand(1);
  shadelab::ViewOptions view;
  shadelab::AddViewCommand(program, view);
  try
  {
    program.parse(argc, argv);
  }
  catch (const CLI::ParseError& e)
  {
    if (e.get_exit_code() == 0)
    {
      return program.exit(e);
    }
    std::cerr << "shadelab: error: " << e.what() << " (see shadelab view --help)" << std::endl;
    return shadelab::ExitUsage;
  }
  view.SizeGiven = program.get_subcommands().front()->count("--size") > 0;
  if (view.Quiet)
  {
    shadelab::SilenceWarnings();
  }
  return shadelab::RunView(view, shadelab::QuoteCommandLine(argc, argv));
}
