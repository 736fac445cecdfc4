// shadelab: the lecture's illumination model and shading rules on triangle
// meshes, through VTK. Each command lives in its own file.
#include "commands/advise_command.h"
#include "commands/bench_command.h"
#include "commands/compare_command.h"
#include "commands/normals_command.h"
#include "commands/render_command.h"
#include "commands/view_command.h"
#include "core/errors.h"
#include "image/metadata.h"
#include "shadelabVersion.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkLogger.h>

#include <CLI/CLI.hpp>

#include <csignal>
#include <iostream>

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

  CLI::App program("shadelab: triangle meshes under the classic illumination model "
                   "(ambient + diffuse + specular) with flat, Gouraud and Phong shading.",
    "shadelab");
  program.set_version_flag("--version", std::string("shadelab ") + shadelab::ShadelabVersion);
  program.require_subcommand(1);
  program.footer("Exit status: 0 on success, 1 for unreadable input or a failed render, "
                 "2 for a bad command line. Errors are one line on stderr.");

  shadelab::RenderOptions render;
  CLI::App* renderCommand = shadelab::AddRenderCommand(program, render);
  shadelab::CompareOptions compare;
  CLI::App* compareCommand = shadelab::AddCompareCommand(program, compare);
  shadelab::ViewOptions view;
  CLI::App* viewCommand = shadelab::AddViewCommand(program, view);
  shadelab::NormalsOptions normals;
  CLI::App* normalsCommand = shadelab::AddNormalsCommand(program, normals);
  shadelab::BenchOptions bench;
  CLI::App* benchCommand = shadelab::AddBenchCommand(program, bench);
  shadelab::AdviseOptions advise;
  CLI::App* adviseCommand = shadelab::AddAdviseCommand(program, advise);

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

  if (render.Quiet || compare.Quiet || normals.Quiet || bench.Quiet)
  {
    shadelab::SilenceWarnings();
  }
  const std::string commandLine = shadelab::QuoteCommandLine(argc, argv);
  if (renderCommand->parsed())
  {
    vtkMessages->SetEcho(render.Verbose);
    if (render.Verbose)
    {
      vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_WARNING);
    }
    return shadelab::RunRender(render, commandLine);
  }
  if (compareCommand->parsed())
  {
    return shadelab::RunCompare(compare, commandLine);
  }
  if (viewCommand->parsed())
  {
    return shadelab::ExecViewer(argc, argv);
  }
  if (normalsCommand->parsed())
  {
    return shadelab::RunNormals(normals);
  }
  if (benchCommand->parsed())
  {
    return shadelab::RunBench(bench, commandLine);
  }
  if (adviseCommand->parsed())
  {
    return shadelab::RunAdvise(advise);
  }
  return shadelab::ExitUsage;
}
