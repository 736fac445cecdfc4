// The inspector's panels: one, or compare's grid with linked cameras and the
// difference cell; the glyphs and edges drawn over a panel's mesh.
#include "desktop/inspector.h"

#include "scene/comparison_panels.h"
#include "scene/overlays.h"
#include "scene/own_stage_files.h"
#include "scene/scene.h"
#include "shadelabEnvironmentBackground.h"

#include "vtkShadelabPeelingPass.h"

#include <vtkRenderStepsPass.h>
#include <vtkTextProperty.h>

#include <algorithm>

namespace shadelab
{
// Shows the settings as they are now: the panels' scenes, their extras and
// labels, the help and the HUD.
void Inspector::Apply()
{
  SceneOptions base = this->State.Scene;
  base.Edges = this->State.Edges; // the surface's code makes room for lines over it
  base.NormalGlyphs = this->State.Glyphs;
  ShowTerms(base, this->State.Ambient, this->State.Diffuse, this->State.Specular,
    this->State.Reflected, this->State.Relief);
  std::vector<Panel> panels;
  if (this->State.Compare)
  {
    this->Plan = PlanComparison(this->Options.Panels, base); // checked at start
    panels = this->Plan.Panels;
  }
  else
  {
    // The drag-time rule only outside the comparison, where the rules are the point.
    if (this->Dragging && this->Options.InteractiveShading)
    {
      base.ShadingRule = *this->Options.InteractiveShading;
    }
    panels.push_back({ base, "", "", Terms::All });
  }
  this->MakeSlots(panels.size(), this->State.Compare ? this->Plan.Columns : 0,
    this->State.Compare && this->Plan.DifferenceA >= 0);
  this->Problem.clear();
  for (std::size_t i = 0; i < panels.size(); ++i)
  {
    Slot& slot = this->Slots[i];
    this->ShowTracing(slot, panels[i]);
    const SceneOptions scene = TracingPreview(panels[i].Scene);
    const std::vector<Light> lights = CameraLights(scene);
    // The state's stages draw its rule's panels that take the view's
    // stages (a comparison mode may name files of its own); others, none.
    const OwnStages none;
    const bool viewStages =
      scene.VertexShader == base.VertexShader && scene.FragmentShader == base.FragmentShader;
    const OwnStages* stages = !viewStages           ? nullptr
      : scene.ShadingRule == this->State.StagesRule ? &this->State.Stages
                                                    : &none;
    const SceneCache::Shown shown = slot.Scenes.Show(scene, slot.Renderer, &lights, stages);
    slot.Peeling->SetMaximumNumberOfPeels(scene.Peels);
    if (!shown.Scene)
    {
      this->Problem = shown.Error;
      continue;
    }
    this->ShowExtras(slot, scene, shown.Mesh->Mesh);
    slot.Behind =
      scene.EnvironmentBackground ? SceneEnvironment(scene, shown.Scene->Images) : std::nullopt;
    slot.BehindCamera.reset(); // painted again at the next draw
    slot.Renderer->SetTexturedBackground(slot.Behind.has_value());
    if (i == 0)
    {
      // The first material's program: the others differ at most in their specular code.
      this->ShaderWatch.Watch(shown.Scene->Drawn.front().Actor->GetMapper());
    }
    slot.Label->SetInput(panels[i].Label.c_str());
    slot.Label->SetVisibility(this->State.Compare);
  }
  this->Help->SetVisibility(this->State.Help);
  this->Line->VisibilityOff(); // the profile's line is of the picture before
  this->UpdateHud();
}

const BuiltScene* Inspector::RefusingScene() const
{
  for (const Slot& slot : this->Slots)
  {
    if (const BuiltScene* shown = slot.Scenes.GetShown();
        shown && !LocateStageErrors(*shown).empty())
    {
      return shown;
    }
  }
  return nullptr;
}

void Inspector::ReportStageErrors()
{
  const BuiltScene* refusing = this->RefusingScene();
  const std::vector<InputProblem> problems =
    refusing ? StageErrorLines(this->StageNames(), *refusing) : std::vector<InputProblem>{};
  if (problems != this->StageProblems && !problems.empty())
  {
    ReportErrors(problems);
  }
  this->StageProblems = problems;
  if (!problems.empty())
  {
    this->Problem =
      problems.front().first + ": " + problems.front().second + " (the generated stages draw)";
    this->UpdateHud();
  }
}

void Inspector::PaintBehind(vtkObject* renderer, unsigned long, void*)
{
  const auto slot = std::find_if(this->Slots.begin(), this->Slots.end(),
    [renderer](const Slot& s) { return s.Renderer.GetPointer() == renderer; });
  if (slot == this->Slots.end() || !slot->Behind)
  {
    return;
  }
  const int* size = slot->Renderer->GetSize();
  const std::array<int, 2> now{ std::max(size[0], 1), std::max(size[1], 1) };
  const PinholeCamera camera = PinholeCameraOf(slot->Renderer->GetActiveCamera());
  if (camera == slot->BehindCamera && now == slot->BehindSize)
  {
    return;
  }
  // Pixel for pixel, as headless lays a picture over it (nearest texels).
  FloatImage behind{ now[0], now[1],
    std::vector<float>(static_cast<std::size_t>(now[0]) * now[1] * 4, 0.0f) };
  OverEnvironment(behind.Rgba, now[0], now[1], camera, *slot->Behind);
  if (!slot->BehindPicture)
  {
    slot->BehindPicture = vtkSmartPointer<vtkTexture>::New();
    slot->BehindPicture->InterpolateOff();
  }
  slot->BehindPicture->SetInputData(ToVtkImage(behind));
  slot->Renderer->SetBackgroundTexture(slot->BehindPicture);
  slot->BehindCamera = camera;
  slot->BehindSize = now;
}

// The glyphs and edges that are on, over the panel's mesh `shown`.
void Inspector::ShowExtras(Slot& slot, const SceneOptions& scene, vtkPolyData* shown)
{
  for (auto* extras : { &slot.Glyphs, &slot.Edges })
  {
    for (auto& [mesh, actor] : *extras)
    {
      actor->VisibilityOff();
    }
  }
  if (this->State.Glyphs)
  {
    if (vtkPolyData* normals = LitMesh(scene, this->Meshes))
    {
      this->GlyphsOf(slot, normals)->VisibilityOn();
    }
  }
  if (this->State.Edges)
  {
    this->EdgesOf(slot, shown)->VisibilityOn();
  }
}

void Inspector::MakeSlots(std::size_t count, int columns, bool difference)
{
  const int cells = static_cast<int>(count) + (difference ? 1 : 0);
  const ComparisonLayout grid = LayOut(cells, 1, 1, columns, false);
  if (this->Slots.size() == count && this->Columns == grid.Columns && this->Rows == grid.Rows &&
    this->DifferenceCell == difference)
  {
    return;
  }
  for (Slot& slot : this->Slots)
  {
    this->Window->RemoveRenderer(slot.Renderer);
    if (slot.Traced)
    {
      this->Window->RemoveRenderer(slot.Traced->Renderer);
    }
  }
  this->Window->RemoveRenderer(this->DifferenceRenderer);
  this->Slots.clear();
  while (this->Slots.size() < count)
  {
    this->Slots.emplace_back(this->Meshes);
  }
  this->Columns = grid.Columns;
  this->Rows = grid.Rows;
  this->DifferenceCell = difference;
  const auto place = [&grid](vtkRenderer* renderer, int cell)
  {
    const int column = cell % grid.Columns, row = cell / grid.Columns;
    renderer->SetViewport(static_cast<double>(column) / grid.Columns,
      1 - static_cast<double>(row + 1) / grid.Rows, static_cast<double>(column + 1) / grid.Columns,
      1 - static_cast<double>(row) / grid.Rows);
  };
  for (std::size_t i = 0; i < count; ++i)
  {
    Slot& slot = this->Slots[i];
    slot.Renderer = vtkSmartPointer<vtkRenderer>::New();
    // Translucency composited in exact depth order, as headless.
    slot.Peeling = vtkSmartPointer<vtkShadelabPeelingPass>::New();
    auto steps = vtkSmartPointer<vtkRenderStepsPass>::New();
    steps->SetTranslucentPass(slot.Peeling);
    slot.Renderer->SetPass(steps);
    place(slot.Renderer, static_cast<int>(i));
    slot.Renderer->SetActiveCamera(this->Camera);
    slot.Renderer->SetBackground(this->Options.Scene.Background.data());
    slot.Renderer->AddObserver(vtkCommand::StartEvent, this, &Inspector::PaintBehind);
    slot.Label = vtkSmartPointer<vtkTextActor>::New();
    slot.Label->GetTextProperty()->SetFontSize(16);
    slot.Label->GetTextProperty()->SetVerticalJustificationToTop();
    slot.Label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
    slot.Label->SetPosition(0.02, 0.98);
    slot.Renderer->AddActor2D(slot.Label);
    this->Window->AddRenderer(slot.Renderer);
  }
  if (difference)
  {
    // The grid's last cell, bottom right: away from the HUD at the bottom left.
    place(this->DifferenceRenderer, grid.Columns * grid.Rows - 1);
    this->DifferenceImage->VisibilityOff(); // until RefreshDifference
    this->Window->AddRenderer(this->DifferenceRenderer);
  }
  // The panels' aspect changes with their number.
  this->Slots.front().Renderer->ResetCameraClippingRange(this->Bounds);
}

vtkActor* Inspector::GlyphsOf(Slot& slot, vtkPolyData* mesh)
{
  auto& actor = slot.Glyphs[mesh];
  if (!actor)
  {
    actor = MakeNormalGlyphs(mesh, this->Bounds);
    slot.Renderer->AddActor(actor);
  }
  return actor;
}

vtkActor* Inspector::EdgesOf(Slot& slot, vtkPolyData* mesh)
{
  auto& actor = slot.Edges[mesh];
  if (!actor)
  {
    const SceneOptions& s = this->Options.Scene;
    actor = MakeEdges(mesh, s.EdgeColor, s.EdgeWidth);
    slot.Renderer->AddActor(actor);
  }
  return actor;
}
}
