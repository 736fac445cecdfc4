#include "commands/compare_command.h"

#include "core/errors.h"
#include "headless/headless_renderer.h"
#include "headless/scene_picture.h"
#include "image/comparison_picture.h"
#include "image/image_writer_process.h"
#include "image/metadata.h"
#include "scene/camera.h"
#include "scene/comparison_panels.h"
#include "scene/mesh_cache.h"
#include "scene/scene.h"
#include "scene/scene_cache.h"
#include "settings/command_line.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <CLI/CLI.hpp>

#include <iostream>
#include <map>
#include <memory>

namespace shadelab
{
CLI::App* AddCompareCommand(CLI::App& program, CompareOptions& o)
{
  CLI::App* compare = program.add_subcommand("compare",
    "Render MESH headless once per mode into one picture: panels side by side, one camera, a "
    "label each; --diff adds |A - B| as a heat map");
  // A panel of 1024x768 makes a three-panel picture 3 k wide: smaller by default.
  o.Scene.Size = { 512, 512 };
  compare->add_option("MESH", o.Scene.Mesh, MeshFileHelp())->required();
  AddSettings(*compare, o.Scene, Command::Compare);
  compare->get_option("--size")->description("Each panel's size in pixels (default 512x512)");
  compare->add_option("-o,--output", o.Output, "Image file; its extension picks the format")
    ->required()
    ->option_text("OUT");
  AddComparisonOptions(*compare, o.Panels);
  compare->add_flag("-q,--quiet", o.Quiet, "No warnings");
  compare->footer(CameraHelp);
  return compare;
}

namespace
{
// A comparison picture's largest area, a square of this side: its float
// pixels (256 MiB) and the panels' it is composed of, at most as many
// again, stay well within 2 GiB.
constexpr long long MaxComparisonSide = 4096;
}

int RunCompare(const CompareOptions& o, const std::string& commandLine)
{
  Comparison plan;
  try
  {
    plan = PlanComparison(o.Panels, o.Scene);
  }
  catch (const std::invalid_argument& e)
  {
    std::cerr << "shadelab: error: compare: " << e.what() << " (see shadelab compare --help)"
              << std::endl;
    return ExitUsage;
  }
  const std::vector<Panel>& panels = plan.Panels;
  // The panels are kept until the picture is composed: both within bounds,
  // said now rather than after rendering them (or the writer failing).
  const ComparisonLayout layout =
    LayOut(static_cast<int>(panels.size()) + (plan.DifferenceA >= 0 ? 1 : 0), o.Scene.Size.Width,
      o.Scene.Size.Height, plan.Columns, plan.DifferenceA >= 0);
  if (static_cast<long long>(layout.Width) * layout.Height > MaxComparisonSide * MaxComparisonSide)
  {
    const std::string side = std::to_string(MaxComparisonSide);
    return ReportError(o.Output,
      "the comparison of " + std::to_string(panels.size()) + " panels would be " +
        std::to_string(layout.Width) + "x" + std::to_string(layout.Height) + " pixels, more than " +
        side + "x" + side + ": fewer panels or a smaller --size");
  }
  if (const std::string error = ImageWriterProcess::CheckFolder(o.Output); !error.empty())
  {
    return ReportError(o.Output, error);
  }
  ImageWriterProcess writer; // started first: it binds OpenImageIO while we render

  MeshCache meshes(DecodingThrough(writer));
  HeadlessRenderer renderer;
  ImageSize rendered;
  if (const std::string error = RenderedSize(o.Scene, rendered); !error.empty())
  {
    return ReportError("render", error);
  }
  if (const std::string error =
        renderer.Start(o.Scene.Size.Width, o.Scene.Size.Height, o.Scene.Supersampling);
      !error.empty())
  {
    return ReportError("render", error);
  }
  // Panels that differ only in material or terms keep their rule's
  // compiled program and uploaded buffers.
  SceneCache scenes(meshes);
  std::vector<FloatImage> pictures;
  vtkPolyData* mesh = nullptr; // every panel's
  for (const Panel& panel : panels)
  {
    ScenePicture shot = RenderScenePicture(panel.Scene, scenes, meshes, renderer);
    if (!shot.Errors.empty())
    {
      return ReportErrors(shot.Errors);
    }
    pictures.push_back(std::move(shot.Picture));
    mesh = shot.Scene->Mesh;
  }

  std::vector<ComparisonCell> cells;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < panels.size(); ++i)
  {
    cells.push_back({ &pictures[i], panels[i].Label });
    labels.push_back(panels[i].Label);
  }
  std::unique_ptr<Difference> heat;
  if (plan.DifferenceA >= 0)
  {
    heat = std::make_unique<Difference>(
      CompareImages(pictures[plan.DifferenceA], pictures[plan.DifferenceB]));
    cells.push_back({ &heat->Heat, plan.DifferenceLabel });
    labels.push_back(plan.DifferenceLabel);
    std::cout << "difference " << plan.DifferenceLabel << ": largest " << heat->Largest << ", mean "
              << heat->Mean << ", " << heat->Differing << " of "
              << static_cast<long long>(heat->Heat.Width) * heat->Heat.Height << " pixels differ"
              << std::endl;
  }
  const FloatImage picture =
    ComposeComparison(cells, plan.Columns, heat.get(), static_cast<int>(cells.size()) - 1);
  const auto metadata = DescribePicture(
    commandLine, o.Scene, renderer.GetRenderer()->GetActiveCamera(), mesh, "", labels);
  if (const std::string error = writer.Write(o.Output, picture, PixelType::Auto, metadata);
      !error.empty())
  {
    return ReportError(o.Output, error);
  }
  return 0;
}
}
