// shadelab: the lecture's illumination model and shading rules on triangle
// meshes, through VTK. Each command lives in its own file.
#include "commands/advise_command.h"
#include "commands/bench_command.h"
#include "commands/check_shader_command.h"
#include "commands/compare_command.h"
#include "commands/normals_command.h"
#include "commands/probe_command.h"
#include "commands/profile_command.h"
#include "commands/render_command.h"
#include "commands/view_command.h"
#include "core/errors.h"
#include "core/interruption.h"
#include "image/metadata.h"
#include "settings/option_reference.h"
#include "shadelabVersion.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkLogger.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <csignal>
#include <functional>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace
{
// An entry of main's table of commands.
struct Command
{
  std::function<CLI::App*(CLI::App&)> Add; // declares the command and its options
  const bool* Quiet;        // its --quiet, which silences warnings; null if it has none
  std::function<int()> Run; // runs it; returns the exit code
};

// Parses the command line; the exit code when that is all there is to do
// (help, version, or a bad command line, reported as one line).
std::optional<int> Parse(CLI::App& program, int argc, char** argv)
{
  try
  {
    program.parse(argc, argv);
  }
  catch (const CLI::CallForHelp& e)
  {
    return program.exit(e);
  }
  catch (const CLI::CallForVersion& e)
  {
    return program.exit(e);
  }
  catch (const CLI::ParseError& e)
  {
    std::string what = e.what();
    for (char& c : what)
    {
      c = c == '\n' ? ' ' : c;
    }
    std::cerr << "shadelab: error: " << what << " (see shadelab --help)" << std::endl;
    return shadelab::ExitUsage;
  }
  return std::nullopt;
}

// The command's first positional argument (its mesh), or the command's name.
std::string FirstInput(const CLI::App& command)
{
  for (const CLI::Option* option : command.get_options())
  {
    if (option->get_positional() && !option->results().empty())
    {
      return option->results().front();
    }
  }
  return command.get_name();
}
}

int main(int argc, char** argv)
{
  // VTK's messages are collected and reported as one line by the commands;
  // VTK 9.1 also copies every error to its logger on stderr.
  vtkShadelabOutputWindow* vtkMessages = vtkShadelabOutputWindow::Install();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  // A writer process that died must not take shadelab with it through
  // SIGPIPE, nor a file-size limit (ulimit -f) through SIGXFSZ: the write
  // fails (EPIPE, EFBIG) and the error is reported instead.
  std::signal(SIGPIPE, SIG_IGN);
  std::signal(SIGXFSZ, SIG_IGN);
  shadelab::CatchInterruptions();

  CLI::App program("shadelab: triangle meshes under the classic illumination model "
                   "(ambient + diffuse + specular) with flat, Gouraud and Phong shading.",
    "shadelab");
  program.set_version_flag("--version", std::string("shadelab ") + shadelab::ShadelabVersion);
  program.require_subcommand(1);
  program.footer("Exit status: 0 on success, 1 for unreadable input or a failed render, "
                 "2 for a bad command line. Errors are one line on stderr.");

  // The commands: each entry adds one to the program and runs it when it
  // was the one parsed. Their options live here, as long as the program.
  shadelab::RenderOptions render;
  shadelab::CompareOptions compare;
  shadelab::ViewOptions view;
  shadelab::NormalsOptions normals;
  shadelab::BenchOptions bench;
  shadelab::AdviseOptions advise;
  shadelab::ProbeOptions probe;
  shadelab::CheckShaderOptions checkShader;
  shadelab::ProfileOptions profile;
  std::string commandLine; // set once parsed
  const Command commands[] = {
    { [&](CLI::App& p) { return shadelab::AddRenderCommand(p, render); }, &render.Quiet,
      [&]
      {
        vtkMessages->SetEcho(render.Verbose);
        if (render.Verbose)
        {
          vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_WARNING);
        }
        return shadelab::RunRender(render, commandLine);
      } },
    { [&](CLI::App& p) { return shadelab::AddCompareCommand(p, compare); }, &compare.Quiet,
      [&] { return shadelab::RunCompare(compare, commandLine); } },
    { [&](CLI::App& p) { return shadelab::AddViewCommand(p, view); }, nullptr,
      [&] { return shadelab::ExecViewer(argc, argv); } },
    { [&](CLI::App& p) { return shadelab::AddNormalsCommand(p, normals); }, &normals.Quiet,
      [&] { return shadelab::RunNormals(normals); } },
    { [&](CLI::App& p) { return shadelab::AddBenchCommand(p, bench); }, &bench.Quiet,
      [&] { return shadelab::RunBench(bench, commandLine); } },
    { [&](CLI::App& p) { return shadelab::AddAdviseCommand(p, advise); }, nullptr,
      [&] { return shadelab::RunAdvise(advise); } },
    { [&](CLI::App& p) { return shadelab::AddProbeCommand(p, probe); }, &probe.Quiet,
      [&] { return shadelab::RunProbe(probe); } },
    { [&](CLI::App& p) { return shadelab::AddCheckShaderCommand(p, checkShader); },
      &checkShader.Quiet, [&] { return shadelab::RunCheckShader(checkShader, commandLine); } },
    { [&](CLI::App& p) { return shadelab::AddProfileCommand(p, profile); }, &profile.Quiet,
      [&] { return shadelab::RunProfile(profile, commandLine); } },
  };
  std::vector<CLI::App*> added;
  for (const Command& command : commands)
  {
    added.push_back(command.Add(program));
  }
  // Hidden: the build makes doc/user/options.md with it.
  CLI::App* reference =
    program.add_subcommand("print-reference", "Print the option reference (markdown)")->group("");

  if (const std::optional<int> exit = Parse(program, argc, argv))
  {
    return *exit;
  }
  if (reference->parsed())
  {
    std::cout << shadelab::OptionReference(program);
    return 0;
  }
  commandLine = shadelab::QuoteCommandLine(argc, argv);
  for (std::size_t i = 0; i < added.size(); ++i)
  {
    if (added[i]->parsed())
    {
      if (commands[i].Quiet && *commands[i].Quiet)
      {
        shadelab::SilenceWarnings();
      }
      try
      {
        return commands[i].Run();
      }
      catch (const std::exception& e)
      {
        // Whatever a library throws that no command caught is still one
        // line, naming the input as far as the command line tells it.
        std::string what = e.what();
        std::replace(what.begin(), what.end(), '\n', ' ');
        return shadelab::ReportError(FirstInput(*added[i]), what);
      }
    }
  }
  return shadelab::ExitUsage;
}
