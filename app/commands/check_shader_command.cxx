#include "commands/check_shader_command.h"

#include "core/errors.h"
#include "headless/headless_renderer.h"
#include "headless/scene_picture.h"
#include "image/comparison_picture.h"
#include "image/image_writer_process.h"
#include "image/metadata.h"
#include "probe/pixel_probe.h"
#include "probe/probe_json.h"
#include "probe/probe_text.h"
#include "scene/camera.h"
#include "scene/mesh_cache.h"
#include "scene/own_stage_files.h"
#include "scene/scene_cache.h"
#include "scene/scene_file.h"
#include "settings/command_line.h"
#include "shadelabJsonProblem.h"

#include <vtkRenderer.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace shadelab
{
namespace
{
// A pixel is compared where the ray through its centre meets the mesh at
// least this many pixels from every edge of the triangle it meets. Both
// the rasteriser and the oracle then take that triangle (a float's
// rounding moves a pixel centre across an edge only within about 1e-4 of
// a pixel) and interpolate its corners with the same weights; at an edge
// flat's colour jumps and the two may take either side.
constexpr double CheckedEdgeMargin = 0.5;

// The oracle tests' bound on a channel (tests/cli/oracle_scene.h): float's
// arithmetic through the shader's steps, relative, with a floor for values
// near 0.
double Bound(double oracle)
{
  return 1e-4 * std::max(std::abs(oracle), 0.01);
}

// One picture's errors against the oracle over the compared pixels.
struct Errors
{
  std::array<double, 3> Largest{};
  std::array<double, 3> Sum{};
  long long Beyond = 0;  // pixels with a channel beyond its bound
  double Worst = -1;     // the largest error over the channels (-1: no pixel yet)
  Pixel WorstAt;         // where it is
  std::vector<float> At; // per pixel (top row first): the largest channel's error

  void Add(const Rgb& rendered, const Rgb& oracle, Pixel at, int width)
  {
    double pixel = 0;
    bool beyond = false;
    for (int c = 0; c < 3; ++c)
    {
      const double error = std::abs(rendered[c] - oracle[c]);
      this->Largest[c] = std::max(this->Largest[c], error);
      this->Sum[c] += error;
      pixel = std::max(pixel, error);
      beyond = beyond || error > Bound(oracle[c]);
    }
    this->Beyond += beyond;
    if (pixel > this->Worst)
    {
      this->Worst = pixel;
      this->WorstAt = at;
    }
    this->At[static_cast<std::size_t>(at.Y) * width + at.X] = static_cast<float>(pixel);
  }

  std::array<double, 3> Mean(long long compared) const
  {
    std::array<double, 3> mean{};
    for (int c = 0; c < 3; ++c)
    {
      mean[c] = compared ? this->Sum[c] / compared : 0;
    }
    return mean;
  }
};

std::string Triple(const std::array<double, 3>& v)
{
  std::ostringstream out;
  out << std::setprecision(3) << v[0] << ", " << v[1] << ", " << v[2];
  return out.str();
}

nlohmann::ordered_json ErrorsJson(const Errors& e, long long compared)
{
  nlohmann::ordered_json j;
  j["largest"] = e.Largest;
  j["mean"] = e.Mean(compared);
  j["beyond_bound"] = e.Beyond;
  j["worst_pixel"] = { e.WorstAt.X, e.WorstAt.Y };
  return j;
}

// The heat map of one's own errors: black where the picture agrees, through
// red and yellow to white at the largest error; uncompared pixels black.
// Its colour bar reads Largest alone.
Difference HeatOf(const Errors& e, int width, int height)
{
  Difference d;
  d.Largest = std::max(e.Worst, 0.0);
  d.Heat.Width = width;
  d.Heat.Height = height;
  d.Heat.Rgba.assign(static_cast<std::size_t>(width) * height * 4, 1.0f);
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const double error = e.At[static_cast<std::size_t>(y) * width + x];
      const Rgb colour = HeatColour(d.Largest > 0 ? error / d.Largest : 0);
      float* p = d.Heat.Rgba.data() + (static_cast<std::size_t>(height - 1 - y) * width + x) * 4;
      std::copy(colour.begin(), colour.end(), p);
    }
  }
  return d;
}

}

CLI::App* AddCheckShaderCommand(CLI::App& program, CheckShaderOptions& o)
{
  CLI::App* check = program.add_subcommand("check-shader",
    "Check stages of one's own (--vertex-shader, --fragment-shader) against the lecture's "
    "equation: render MESH with them and with the generated stages, compare both with the "
    "double-precision oracle pixel by pixel, and say where they part; exit 0 when the "
    "stages agree with the oracle within the oracle tests' bound, 1 when not");
  o.Scene.Size = { 320, 240 };
  check->add_option("MESH", o.Scene.Mesh, MeshFileHelp());
  AddSettings(*check, o.Scene, Command::CheckShader);
  check->get_option("--size")->description("Image size in pixels (default 320x240)");
  // With a scene file, its shots say all that these say.
  std::vector<CLI::Option*> sceneSettings =
    check->get_options([](const CLI::Option* option) { return option->get_name() != "--help"; });
  CLI::Option* scene = check
                         ->add_option("--scene", o.SceneFile,
                           "Check every shot of a scene file (several lights, rules and "
                           "materials, each shot naming its vertex_shader and fragment_shader); "
                           "exit 0 when every shot agrees")
                         ->option_text("FILE.json");
  for (CLI::Option* setting : sceneSettings)
  {
    setting->excludes(scene);
  }
  check->add_option("-o,--output", o.Output,
    "A picture of the stages' render, the generated one's, and the heat map of the stages' "
    "error against the oracle; with --scene, a name template for every shot's (as render's, "
    "{index} {name} ...), none without it");
  check->add_flag("--json", o.Json, "One JSON object instead of the text");
  check->add_flag("-q,--quiet", o.Quiet, "No warnings");
  check->footer(CameraHelp);
  return check;
}

namespace
{
// Checks one scene's stages: prints the text (or fills json), writes the
// picture to output where given, and says whether they agree; 0, or the
// exit code of an error (reported).
int CheckShot(const SceneOptions& own, const std::string& output, nlohmann::ordered_json* json,
  const std::string& commandLine, MeshCache& meshes, std::unique_ptr<ImageWriterProcess>& writer,
  bool& agrees)
{
  SceneOptions generated = own;
  generated.VertexShader.clear();
  generated.FragmentShader.clear();
  HeadlessRenderer renderer;
  const int width = own.Size.Width, height = own.Size.Height;
  if (const std::string error = renderer.Start(width, height); !error.empty())
  {
    return ReportError("render", error);
  }
  SceneCache scenes(meshes);
  // One's own first: a stage the driver refuses ends the check at once.
  ScenePicture mine = RenderScenePicture(own, scenes, meshes, renderer);
  if (!mine.Errors.empty())
  {
    return ReportErrors(mine.Errors);
  }
  const ScenePicture theirs = RenderScenePicture(generated, scenes, meshes, renderer);
  if (!theirs.Errors.empty())
  {
    return ReportErrors(theirs.Errors);
  }
  // The render's context is current: the prober reads its shadow maps.
  const PixelProber prober(generated, theirs.Scene->Mesh, renderer.GetRenderer()->GetActiveCamera(),
    own.Size, theirs.Scene->Images, theirs.Scene->Casters.get());
  Errors ownErrors, generatedErrors;
  ownErrors.At.assign(static_cast<std::size_t>(width) * height, 0.0f);
  generatedErrors.At = ownErrors.At;
  long long compared = 0;
  for (int y = 0; y < height; ++y)
  {
    for (int x = 0; x < width; ++x)
    {
      const PixelProbe p = prober.Probe({ x, y });
      if (!p.Hit || p.EdgeDistance < CheckedEdgeMargin)
      {
        continue;
      }
      ++compared;
      const Rgb oracle = OracleOf(p);
      ownErrors.Add(PixelRgb(mine.Picture, x, y), oracle, { x, y }, width);
      generatedErrors.Add(PixelRgb(theirs.Picture, x, y), oracle, { x, y }, width);
    }
  }
  agrees = ownErrors.Beyond == 0;
  PixelProbe worst;
  if (compared > 0)
  {
    worst = prober.Probe(ownErrors.WorstAt);
    worst.Rendered = PixelRgb(theirs.Picture, worst.At.X, worst.At.Y);
    worst.RenderedFrom = "the generated stages' float render at the pixel";
  }
  const std::string label = OwnStageFiles(own);
  if (json)
  {
    nlohmann::ordered_json& j = *json;
    j["mesh"] = own.Mesh;
    j["stages"] = label;
    j["size"] = { width, height };
    j["compared"] = compared;
    j["edge_margin"] = CheckedEdgeMargin;
    j["own"] = ErrorsJson(ownErrors, compared);
    j["generated"] = ErrorsJson(generatedErrors, compared);
    if (compared > 0)
    {
      j["own_at_worst"] = PixelRgb(mine.Picture, worst.At.X, worst.At.Y);
      j["worst_probe"] = ProbeJson(worst);
    }
    j["agrees"] = agrees;
  }
  else
  {
    std::cout << "check-shader: " << label << " against the oracle, " << own.Mesh << ", "
              << ToString(own.ShadingRule) << " " << ToString(own.ReflectionModel) << ", " << width
              << "x" << height << "\n"
              << "compared " << compared << " pixels (the mesh, " << CheckedEdgeMargin
              << " pixels or more from a triangle's edge); a channel's bound is 1e-4 * "
                 "max(|oracle|, 0.01)\n"
              << "  yours:     largest error (R, G, B) " << Triple(ownErrors.Largest) << ", mean "
              << Triple(ownErrors.Mean(compared)) << ", " << ownErrors.Beyond
              << " pixels beyond the bound\n"
              << "  generated: largest error (R, G, B) " << Triple(generatedErrors.Largest)
              << ", mean " << Triple(generatedErrors.Mean(compared)) << ", "
              << generatedErrors.Beyond << " pixels beyond the bound\n";
    if (compared > 0)
    {
      const Rgb at = PixelRgb(mine.Picture, worst.At.X, worst.At.Y);
      std::cout << "yours part most from the oracle at pixel " << worst.At.X << "," << worst.At.Y
                << ": yours " << Triple(at) << ", the oracle " << Triple(OracleOf(worst))
                << "; the generated stages there:\n"
                << ProbeText(worst);
    }
    std::cout << (agrees ? "agrees with the oracle" : "does not agree with the oracle")
              << std::endl;
  }
  if (!output.empty())
  {
    const Difference heat = HeatOf(ownErrors, width, height);
    const std::string heatLabel = "|yours - oracle|";
    const FloatImage picture = ComposeComparison(
      { { &mine.Picture, "yours" }, { &theirs.Picture, "generated" }, { &heat.Heat, heatLabel } },
      0, &heat, 2);
    const auto metadata =
      DescribePicture(commandLine, own, renderer.GetRenderer()->GetActiveCamera(), mine.Scene->Mesh,
        "", { "yours", "generated", heatLabel });
    if (!writer)
    {
      writer = std::make_unique<ImageWriterProcess>();
    }
    if (const std::string error = writer->Write(output, picture, PixelType::Auto, metadata);
        !error.empty())
    {
      return ReportError(output, error);
    }
  }
  return 0;
}

// The shots to check: the scene file's, or the command line's one; each
// names its stages and its output's folder is there. 0, or the exit code
// (reported).
int ShotsToCheck(const CheckShaderOptions& o, std::vector<Shot>& shots)
{
  if (o.SceneFile.empty())
  {
    if (o.Scene.Mesh.empty())
    {
      std::cerr << "shadelab: error: check-shader: MESH is required unless --scene gives the "
                   "shots (see shadelab check-shader --help)"
                << std::endl;
      return ExitUsage;
    }
    shots.push_back({ o.Scene, o.Output, "", false, false });
  }
  else
  {
    // Shots need no output here: a template stands in for the file's, and
    // the names it makes are dropped below when -o gives none.
    const std::string outputs = o.Output.empty() ? "{index}.png" : o.Output;
    if (const std::string error = ReadSceneFile(o.SceneFile, outputs, shots); !error.empty())
    {
      return ReportError(o.SceneFile, error);
    }
  }
  for (Shot& shot : shots)
  {
    if (o.Output.empty())
    {
      shot.Output.clear(); // a scene file's outputs are its renders', not these pictures'
    }
    const SceneOptions& s = shot.Scene;
    if (s.VertexShader.empty() && s.FragmentShader.empty())
    {
      if (shot.Label.empty())
      {
        ReportError("check-shader",
          "give the stages to check: --fragment-shader FILE and/or --vertex-shader FILE (as "
          "render --dump-shaders writes them)");
        return ExitUsage;
      }
      return ReportError(
        shot.Label, "names no stage to check: give it vertex_shader and/or fragment_shader");
    }
    OwnStages stages;
    if (auto [input, error] = ReadOwnStages(s, stages); !error.empty())
    {
      return ReportError(input, error);
    }
    if (!shot.Output.empty())
    {
      if (const std::string error = ImageWriterProcess::CheckFolder(shot.Output); !error.empty())
      {
        return ReportError(shot.Output, error);
      }
    }
  }
  return 0;
}
}

int RunCheckShader(const CheckShaderOptions& o, const std::string& commandLine)
{
  std::vector<Shot> shots;
  if (const int status = ShotsToCheck(o, shots); status != 0)
  {
    return status;
  }
  std::unique_ptr<ImageWriterProcess> writer; // started for a texture's image or a picture
  MeshCache meshes(DecodingThrough(writer));
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  bool agree = true;
  for (const Shot& shot : shots)
  {
    if (!shot.Label.empty() && !o.Json)
    {
      std::cout << shot.Label << ":\n";
    }
    nlohmann::ordered_json one;
    if (!shot.Label.empty())
    {
      one["shot"] = shot.Label;
    }
    bool agrees = false;
    if (const int status = CheckShot(
          shot.Scene, shot.Output, o.Json ? &one : nullptr, commandLine, meshes, writer, agrees);
        status != 0)
    {
      return status;
    }
    agree = agree && agrees;
    all.push_back(one);
  }
  if (o.Json)
  {
    // One object for one check, as before scene files; {"shots": [...], "agrees"} for a file's.
    nlohmann::ordered_json j;
    if (o.SceneFile.empty())
    {
      j = all.front();
    }
    else
    {
      j["scene"] = o.SceneFile;
      j["shots"] = all;
      j["agrees"] = agree;
    }
    std::cout << JsonText(j) << std::endl;
  }
  else if (shots.size() > 1)
  {
    std::cout << (agree ? "every shot agrees with the oracle" : "not every shot agrees")
              << std::endl;
  }
  return agree ? 0 : ExitFailure;
}
}
