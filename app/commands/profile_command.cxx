#include "commands/profile_command.h"

#include "core/errors.h"
#include "core/output_file.h"
#include "core/output_path.h"
#include "headless/headless_renderer.h"
#include "headless/scene_picture.h"
#include "image/image_writer_process.h"
#include "image/metadata.h"
#include "probe/pixel_probe.h"
#include "profile/line_profile.h"
#include "profile/profile_chart.h"
#include "scene/camera.h"
#include "scene/comparison_panels.h"
#include "scene/mesh_cache.h"
#include "scene/scene_cache.h"
#include "settings/command_line.h"

#include <vtkRenderer.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <regex>

namespace shadelab
{
namespace
{
bool IsCsv(const std::string& path)
{
  return LowerExtension(path) == ".csv";
}

// "X0,Y0,X1,Y1" inside a picture of size; on failure why.
std::string ParseLine(const std::string& text, const ImageSize& size, Pixel& from, Pixel& to)
{
  static const std::regex four(R"(\s*(-?\d+)\s*,\s*(-?\d+)\s*,\s*(-?\d+)\s*,\s*(-?\d+)\s*)");
  std::smatch m;
  if (!std::regex_match(text, m, four) ||
    std::any_of(m.begin() + 1, m.end(), [](const auto& n) { return n.length() > 6; }))
  {
    return "'" + text + "' is not X0,Y0,X1,Y1 (four whole pixel numbers)";
  }
  from = { std::stoi(m[1]), std::stoi(m[2]) };
  to = { std::stoi(m[3]), std::stoi(m[4]) };
  for (const Pixel& p : { from, to })
  {
    if (p.X < 0 || p.Y < 0 || p.X >= size.Width || p.Y >= size.Height)
    {
      return "the end " + std::to_string(p.X) + "," + std::to_string(p.Y) + " is outside the " +
        std::to_string(size.Width) + "x" + std::to_string(size.Height) +
        " picture (X from 0 at the left, Y from 0 at the top)";
    }
  }
  return "";
}

double LargestAbs(const std::vector<double>& values)
{
  double largest = 0;
  for (double v : values)
  {
    if (std::isfinite(v))
    {
      largest = std::max(largest, std::abs(v));
    }
  }
  return largest;
}

// Per curve: the largest differences, and how far it is from the oracle on
// the mesh: what the chart shows, as numbers.
void PrintSummary(const LineProfile& profile)
{
  std::cout << "profile: " << profile.Samples.size() << " samples, "
            << std::count_if(profile.Triangles.begin(), profile.Triangles.end(),
                 [](vtkIdType t) { return t >= 0; })
            << " on the mesh, " << EdgeCrossings(profile).size() << " triangle edges crossed\n"
            << std::setprecision(3);
  for (const ProfileCurve& c : profile.Curves)
  {
    double fromOracle = 0;
    for (std::size_t i = 0; i < profile.Samples.size(); ++i)
    {
      if (profile.Triangles[i] >= 0)
      {
        fromOracle = std::max(fromOracle, std::abs(c.Luminance[i] - profile.Oracle.Luminance[i]));
      }
    }
    std::cout << "  " << c.Label << ": largest |first difference| " << LargestAbs(c.First)
              << ", largest |second difference| " << LargestAbs(c.Second)
              << ", largest |luminance - the oracle's phong| " << fromOracle << "\n";
  }
  std::cout << "  oracle (phong): largest |first difference| " << LargestAbs(profile.Oracle.First)
            << ", largest |second difference| " << LargestAbs(profile.Oracle.Second) << std::endl;
}
}

CLI::App* AddProfileCommand(CLI::App& program, ProfileOptions& o)
{
  CLI::App* profile = program.add_subcommand("profile",
    "Mach bands as a measurement: the luminance (and R, G, B) of MESH's picture along a line, "
    "for each mode, with its first and second differences and the double-precision oracle's "
    "phong beside it, as a chart with the line drawn over the picture, or as CSV");
  profile->add_option("MESH", o.Scene.Mesh, MeshFileHelp())->required();
  profile
    ->add_option("--line", o.Line,
      "The line's ends in pixels, X from 0 at the left, Y from 0 at the top; a sample per pixel "
      "along its longer axis")
    ->option_text("X0,Y0,X1,Y1")
    ->required();
  profile->add_option("--modes", o.Modes, ModesHelp)->option_text("MODE,...");
  AddSettings(*profile, o.Scene, Command::Profile);
  profile
    ->add_option("-o,--output", o.Outputs,
      "The chart (an image: .png, .exr, ...) or the samples as CSV (.csv); give both with -o "
      "twice")
    ->required();
  profile->add_flag("-q,--quiet", o.Quiet, "No warnings");
  profile->footer(CameraHelp);
  return profile;
}

int RunProfile(const ProfileOptions& o, const std::string& commandLine)
{
  LineProfile profile;
  Pixel from, to;
  if (const std::string error = ParseLine(o.Line, o.Scene.Size, from, to); !error.empty())
  {
    std::cerr << "shadelab: error: --line: " << error << " (see shadelab profile --help)"
              << std::endl;
    return ExitUsage;
  }
  std::vector<Panel> modes;
  try
  {
    modes = ParseModes(o.Modes, o.Scene);
  }
  catch (const std::invalid_argument& e)
  {
    std::cerr << "shadelab: error: profile: " << e.what() << " (see shadelab profile --help)"
              << std::endl;
    return ExitUsage;
  }
  for (const std::string& output : o.Outputs)
  {
    const std::string error =
      IsCsv(output) ? CheckWritableFolder(output) : ImageWriterProcess::CheckFolder(output);
    if (!error.empty())
    {
      return ReportError(output, error);
    }
  }
  std::unique_ptr<ImageWriterProcess> writer; // started for a texture's image or the chart
  MeshCache meshes(DecodingThrough(writer));
  HeadlessRenderer renderer;
  if (const std::string error =
        renderer.Start(o.Scene.Size.Width, o.Scene.Size.Height, o.Scene.Supersampling);
      !error.empty())
  {
    return ReportError("render", error);
  }
  SceneCache scenes(meshes);
  std::vector<FloatImage> pictures;
  for (const Panel& mode : modes)
  {
    ScenePicture shot = RenderScenePicture(mode.Scene, scenes, meshes, renderer);
    if (!shot.Errors.empty())
    {
      return ReportErrors(shot.Errors);
    }
    pictures.push_back(std::move(shot.Picture));
  }
  // The oracle's smooth curve: the scene under phong, explained pixel by
  // pixel where the line passes (the render's context current: the prober
  // reads its shadow maps). Its picture is the inset's.
  SceneOptions smooth = o.Scene;
  smooth.ShadingRule = Shading::Phong;
  smooth.VertexShader.clear(); // the generated phong: the stages are the modes'
  smooth.FragmentShader.clear();
  const ScenePicture reference = RenderScenePicture(smooth, scenes, meshes, renderer);
  if (!reference.Errors.empty())
  {
    return ReportErrors(reference.Errors);
  }
  const PixelProber prober(smooth, reference.Scene->Mesh, renderer.GetRenderer()->GetActiveCamera(),
    o.Scene.Size, reference.Scene->Images, reference.Scene->Casters.get());
  profile.Samples = LinePixels(from, to);
  std::vector<Rgb> oracle;
  for (const Pixel& at : profile.Samples)
  {
    const PixelProbe p = prober.Probe(at);
    profile.Triangles.push_back(p.Hit ? p.Triangle : -1);
    profile.EdgeDistances.push_back(p.Hit ? p.EdgeDistance : 0);
    oracle.push_back(OracleOf(p));
  }
  profile.Oracle = MakeCurve("oracle", std::move(oracle), profile.Triangles);
  for (std::size_t i = 0; i < modes.size(); ++i)
  {
    profile.Curves.push_back(ReadCurve(modes[i].Label, pictures[i], profile));
  }
  PrintSummary(profile);

  int status = 0;
  std::optional<ChartImage> chart; // drawn once, for the first image asked for
  for (const std::string& output : o.Outputs)
  {
    std::string error;
    if (IsCsv(output))
    {
      error = WriteFile(output, ProfileCsv(profile));
    }
    else
    {
      if (!chart)
      {
        chart = DrawProfileChart(profile, reference.Picture,
          "shadelab profile: " + std::filesystem::path(o.Scene.Mesh).filename().string() + ", " +
            o.Modes + " along " + o.Line);
      }
      error = chart->Error;
      if (error.empty())
      {
        if (!writer)
        {
          writer = std::make_unique<ImageWriterProcess>();
        }
        error = writer->Write(output, chart->Image, PixelType::UInt8,
          { { "ImageDescription", "shadelab profile: " + commandLine } });
      }
    }
    if (!error.empty())
    {
      status = ReportError(output, error);
    }
  }
  return status;
}
}
