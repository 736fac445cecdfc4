// `shadelab render MESH -o OUT [options]`: one headless picture; or
// `shadelab render --scene FILE.json [-o TEMPLATE] [--shard I/N]`: many.
#ifndef shadelab_render_command_h
#define shadelab_render_command_h

#include "core/options.h"

#include <string>

namespace CLI
{
class App;
}

namespace shadelab
{
/** Declares the render command and its options on the program. */
CLI::App* AddRenderCommand(CLI::App& program, RenderOptions& options);

/** Runs it; returns the exit code. */
int RunRender(const RenderOptions& options, const std::string& commandLine);
}

#endif
