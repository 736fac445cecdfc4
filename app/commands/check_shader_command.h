// `shadelab check-shader MESH --fragment-shader FILE [--vertex-shader FILE]
// [options] [-o OUT] [--json]`, or `--scene FILE.json` for every shot of a
// scene file: stages of one's own checked against the
// lecture's equation. The scene is rendered with them and with the
// generated stages, both are compared with the double-precision oracle
// pixel by pixel, and the exit status says whether one's own agree with it
// within the oracle tests' bound: a course's grading script is the user.
#ifndef shadelab_check_shader_command_h
#define shadelab_check_shader_command_h

#include "core/options.h"

#include <string>

namespace CLI
{
class App;
}

namespace shadelab
{
struct CheckShaderOptions
{
  SceneOptions Scene;
  std::string SceneFile; // check its shots instead (--scene)
  std::string Output;    // the heat map of the difference (with SceneFile a template), or ""
  bool Json = false;     // one JSON object instead of the text
  bool Quiet = false;    // no warnings
};

/** Declares the check-shader command and its options on the program. */
CLI::App* AddCheckShaderCommand(CLI::App& program, CheckShaderOptions& options);

/** Runs it; returns the exit code: 0 when the stages agree with the oracle, else 1. */
int RunCheckShader(const CheckShaderOptions& options, const std::string& commandLine);
}

#endif
