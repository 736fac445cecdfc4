#include "render_command.h"

#include "camera.h"
#include "errors.h"
#include "headless_renderer.h"
#include "image_writer_process.h"
#include "mesh_input.h"
#include "metadata.h"
#include "scene.h"
#include "shader_dump.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <CLI/CLI.hpp>

#include <chrono>
#include <iostream>
#include <memory>

namespace shadelab
{
CLI::App* AddRenderCommand(CLI::App& program, RenderOptions& o)
{
  CLI::App* render = program.add_subcommand("render", "Render MESH headless into the image OUT");
  AddSceneOptions(*render, o.Scene);
  render->add_option("-o,--output", o.Output, "Image file; its extension picks the format")
    ->required()
    ->option_text("OUT");
  const std::map<std::string, PixelType> types{ { "auto", PixelType::Auto },
    { "uint8", PixelType::UInt8 }, { "uint16", PixelType::UInt16 }, { "half", PixelType::Half },
    { "float", PixelType::Float } };
  render
    ->add_option("--pixel-type", o.Pixels,
      "auto: float for .exr .hdr .pfm (unclamped), 8-bit otherwise (default)")
    ->transform(CLI::CheckedTransformer(types))
    ->option_text("auto|uint8|uint16|half|float");
  render
    ->add_option("--dump-shaders", o.DumpShaders,
      "Write the final GLSL of each shader program into DIR (RULE-REFLECTION.vert/.frag)")
    ->option_text("DIR");
  render->add_flag("-v,--verbose", o.Verbose, "Print each phase's time and VTK's messages");
  render->footer(CameraHelp);
  return render;
}

namespace
{
class PhaseTimer
{
public:
  explicit PhaseTimer(bool enabled)
    : Enabled(enabled)
  {
  }
  void Lap(const char* phase)
  {
    const auto now = std::chrono::steady_clock::now();
    if (this->Enabled)
    {
      std::cerr << "shadelab: " << phase << " "
                << std::chrono::duration<double, std::milli>(now - this->Last).count() << " ms\n";
    }
    this->Last = now;
  }

private:
  bool Enabled;
  std::chrono::steady_clock::time_point Last = std::chrono::steady_clock::now();
};
}

int RunRender(const RenderOptions& o, const std::string& commandLine)
{
  PhaseTimer timer(o.Verbose);
  if (const std::string error = ImageWriterProcess::CheckFolder(o.Output); !error.empty())
  {
    return ReportError(o.Output, error);
  }
  if (!o.DumpShaders.empty())
  {
    if (const std::string error = ShaderDump::PrepareFolder(o.DumpShaders); !error.empty())
    {
      return ReportError(o.DumpShaders, error);
    }
  }
  ImageWriterProcess writer;
  const LoadedMesh loaded = LoadMesh(o.Scene);
  if (!loaded.Mesh)
  {
    return ReportError(o.Scene.Mesh, loaded.Error);
  }
  timer.Lap("mesh");

  HeadlessRenderer renderer;
  if (const std::string error = renderer.Start(o.Scene.Size.Width, o.Scene.Size.Height);
      !error.empty())
  {
    return ReportError("render", error);
  }
  timer.Lap("context");
  const BuiltScene scene = BuildScene(o.Scene, loaded.Mesh, renderer.GetRenderer());
  if (!scene.Error.empty())
  {
    return ReportError("camera", scene.Error);
  }
  std::unique_ptr<ShaderDump> dump;
  if (!o.DumpShaders.empty())
  {
    dump = std::make_unique<ShaderDump>(scene.Actor->GetMapper(), o.DumpShaders,
      std::string(ToString(o.Scene.ShadingRule)) + "-" + ToString(o.Scene.ReflectionModel));
  }
  const FloatImage image = renderer.Render();
  timer.Lap("frame");
  if (dump && !dump->GetError().empty())
  {
    return ReportError(o.DumpShaders, dump->GetError());
  }

  const auto metadata =
    DescribePicture(commandLine, o.Scene, renderer.GetRenderer()->GetActiveCamera());
  if (const std::string error = writer.Write(o.Output, image, o.Pixels, metadata); !error.empty())
  {
    return ReportError(o.Output, error);
  }
  timer.Lap("write");
  return 0;
}
}
