#include "commands/probe_command.h"

#include "core/errors.h"
#include "headless/headless_renderer.h"
#include "headless/scene_picture.h"
#include "image/image_writer_process.h"
#include "probe/pixel_probe.h"
#include "probe/probe_json.h"
#include "probe/probe_text.h"
#include "scene/camera.h"
#include "scene/mesh_cache.h"
#include "scene/scene_cache.h"
#include "settings/command_line.h"
#include "shadelabJsonProblem.h"

#include <vtkRenderer.h>

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

namespace shadelab
{
CLI::App* AddProbeCommand(CLI::App& program, ProbeOptions& o)
{
  CLI::App* probe = program.add_subcommand("probe",
    "Explain pixel X,Y of the picture render makes with the same options: the triangle under "
    "it, the lecture's equation term by term there, the oracle's value, the rendered and the "
    "stored value");
  probe->add_option("MESH", o.Scene.Mesh, MeshFileHelp())->required();
  AddSettings(*probe, o.Scene, Command::Probe);
  probe->get_option("--ssaa")->description(
    "Not for probe: it explains the one sample a pixel has without anti-aliasing");
  probe
    ->add_option_function<std::vector<std::string>>(
      "--pixel",
      [&o](const std::vector<std::string>& texts)
      {
        o.Pixels.clear();
        for (const std::string& text : texts)
        {
          try
          {
            o.Pixels.push_back(ParsePixel(text));
          }
          catch (const std::invalid_argument& e)
          {
            throw CLI::ValidationError("--pixel", e.what());
          }
        }
      },
      "The pixel, X from the left and Y from the top, from 0 (required); repeatable, each "
      "explained in turn from one render")
    ->option_text("X,Y")
    ->required()
    ->allow_extra_args(false) // one pixel an occurrence: MESH may follow it
    ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  probe->add_flag("--json", o.Json,
    "One JSON object per pixel, one a line, instead of the text (doc/user/probe.md lists the "
    "keys)");
  probe->add_flag("-q,--quiet", o.Quiet, "No warnings");
  probe->footer(CameraHelp);
  return probe;
}

int RunProbe(const ProbeOptions& o)
{
  const SceneOptions& s = o.Scene;
  if (s.Supersampling != 1)
  {
    ReportError("--ssaa",
      "probe explains a pixel's one sample: leave --ssaa out (a pixel of "
      "--ssaa N is the average of N x N samples)");
    return ExitUsage;
  }
  for (const Pixel& p : o.Pixels)
  {
    if (p.X >= s.Size.Width || p.Y >= s.Size.Height)
    {
      ReportError("--pixel",
        std::to_string(p.X) + "," + std::to_string(p.Y) + " is outside the " +
          std::to_string(s.Size.Width) + "x" + std::to_string(s.Size.Height) +
          " picture (X from 0 to " + std::to_string(s.Size.Width - 1) + ", Y from 0 to " +
          std::to_string(s.Size.Height - 1) + ")");
      return ExitUsage;
    }
  }
  std::unique_ptr<ImageWriterProcess> decoder; // started for a texture's image only
  MeshCache meshes(DecodingThrough(decoder));
  HeadlessRenderer renderer;
  if (const std::string error = renderer.Start(s.Size.Width, s.Size.Height); !error.empty())
  {
    return ReportError("render", error);
  }
  SceneCache scenes(meshes);
  const ScenePicture picture = RenderScenePicture(s, scenes, meshes, renderer);
  if (!picture.Errors.empty())
  {
    return ReportErrors(picture.Errors);
  }
  // The render's context is current: the prober reads its shadow maps.
  const PixelProber prober(s, picture.Scene->Mesh, renderer.GetRenderer()->GetActiveCamera(),
    s.Size, picture.Scene->Images, picture.Scene->Casters.get());
  for (std::size_t i = 0; i < o.Pixels.size(); ++i)
  {
    PixelProbe probe = prober.Probe(o.Pixels[i]);
    probe.Rendered = PixelRgb(picture.Picture, probe.At.X, probe.At.Y);
    if (o.Json)
    {
      std::cout << JsonText(ProbeJson(probe)) << "\n";
    }
    else
    {
      std::cout << (i > 0 ? "\n" : "") << ProbeText(probe);
    }
  }
  std::cout << std::flush;
  return 0;
}
}
