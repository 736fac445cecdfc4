// The comparison layout's raytrace panels: phong draws one while the camera
// moves (a ray-traced picture takes seconds, not a frame); once the camera
// rests, the panel is ray traced on every core a band of rows per timer
// tick, so that the window keeps answering, its label showing how far, and
// the picture is shown over the panel when it is whole. Anything that moves
// the camera, resizes the panel or changes the scene starts it again.
#include "desktop/inspector.h"

#include "core/milliseconds.h"
#include "scene/scene.h"

#include <vtkCommand.h>
#include <vtkImageMapper3D.h>

#include <algorithm>
#include <iostream>

namespace shadelab
{
namespace
{
// A tick traces rows for about this long: the window answers between ticks.
constexpr double TickMs = 60;
}

SceneOptions TracingPreview(const SceneOptions& scene)
{
  SceneOptions preview = scene;
  if (preview.ShadingRule == Shading::Raytrace)
  {
    // The phong panel's own scene: raytrace's shadows (every light's) are
    // the ray tracer's, not the preview's.
    preview.ShadingRule = Shading::Phong;
  }
  return preview;
}

// Shows the panel `panel` in slot as a raytrace panel, or none.
void Inspector::ShowTracing(Slot& slot, const Panel& panel)
{
  if (panel.Scene.ShadingRule != Shading::Raytrace)
  {
    if (slot.Traced)
    {
      this->Window->RemoveRenderer(slot.Traced->Renderer);
      slot.Traced.reset();
    }
    return;
  }
  if (!slot.Traced)
  {
    slot.Traced = std::make_unique<Tracing>();
    Tracing& t = *slot.Traced;
    t.Renderer = vtkSmartPointer<vtkRenderer>::New();
    t.Picture = vtkSmartPointer<vtkImageActor>::New();
    t.Picture->InterpolateOff(); // its pixels as traced
    // Out to the pixels' edges, not their centres: the panel's first and
    // last columns and rows are the picture's too.
    t.Picture->GetMapper()->BorderOn();
    t.Renderer->AddActor(t.Picture);
    t.Renderer->AddActor2D(slot.Label);
    t.Renderer->GetActiveCamera()->ParallelProjectionOn();
    t.Renderer->InteractiveOff(); // the panel's own renderer takes the mouse
    t.Renderer->SetViewport(slot.Renderer->GetViewport());
    t.Renderer->DrawOff(); // until a picture is whole
    // After the panel's renderer in the same layer: drawn over it.
    this->Window->AddRenderer(t.Renderer);
  }
  slot.Traced->Scene = panel.Scene;
  slot.Traced->Label = panel.Label;
  slot.Traced->Traced.clear(); // the scene may have changed
}

// What a raytrace panel's picture depends on beyond its scene (a change of
// which ShowTracing marks): the camera and the panel's size in pixels.
std::vector<double> Inspector::TracedView(const Slot& slot) const
{
  std::vector<double> view(9);
  this->Camera->GetPosition(view.data());
  this->Camera->GetFocalPoint(view.data() + 3);
  this->Camera->GetViewUp(view.data() + 6);
  const int* size = slot.Renderer->GetSize();
  view.insert(view.end(),
    { this->Camera->GetViewAngle(), this->Camera->GetParallelScale(),
      static_cast<double>(this->Camera->GetParallelProjection()), static_cast<double>(size[0]),
      static_cast<double>(size[1]) });
  return view;
}

// After each frame: a raytrace panel whose camera, size or scene changed
// (or that is being dragged) shows phong again and, once the camera rests,
// is traced anew.
void Inspector::FollowTracing()
{
  bool pending = false;
  for (Slot& slot : this->Slots)
  {
    if (!slot.Traced)
    {
      continue;
    }
    Tracing& t = *slot.Traced;
    const std::vector<double> view = this->TracedView(slot);
    if (!this->Dragging && view == t.Traced)
    {
      pending = pending || !t.Renderer->GetDraw(); // not whole yet
      continue;
    }
    t.Tracer.reset();
    t.Traced.clear();
    t.Renderer->DrawOff();
    if (!this->Dragging)
    {
      t.Traced = view;
      t.Row = 0;
      pending = true;
    }
  }
  if (pending && this->TraceTimer < 0)
  {
    this->TraceTimer = this->Interactor->CreateOneShotTimer(1);
  }
}

// A timer tick: the first raytrace panel that is not whole traces rows for
// about TickMs; a whole picture is shown over its panel.
void Inspector::TraceStep()
{
  this->TraceTimer = -1;
  const auto waiting = std::find_if(this->Slots.begin(), this->Slots.end(),
    [](const Slot& s)
    { return s.Traced && !s.Traced->Traced.empty() && !s.Traced->Renderer->GetDraw(); });
  if (waiting == this->Slots.end() || this->Dragging)
  {
    return;
  }
  Slot& slot = *waiting;
  Tracing& t = *slot.Traced;
  if (!t.Tracer)
  {
    t.Started = Clock::now();
    // The scene as the panel draws it now: its size, the lights as they
    // follow the camera.
    SceneOptions scene = t.Scene;
    const int* size = slot.Renderer->GetSize();
    scene.Size = { std::max(size[0], 1), std::max(size[1], 1) };
    scene.Lights = this->CameraLights(t.Scene);
    // The mesh and textures of the preview that Apply showed.
    const BuiltScene* shown = slot.Scenes.GetShown();
    if (!shown)
    {
      return; // the HUD shows the problem (Apply)
    }
    t.Tracer = std::make_unique<RayTracer>(scene, shown->Mesh, this->Camera, shown->Images);
    t.Image = t.Tracer->Blank(1);
    t.Row = 0;
  }
  const auto start = Clock::now();
  const int band = std::max(1, t.Image.Height / 64);
  while (t.Row < t.Image.Height && Milliseconds(start) < TickMs)
  {
    const int last = std::min(t.Row + band, t.Image.Height);
    t.Tracer->TraceRows(t.Image, t.Row, last);
    t.Row = last;
  }
  if (t.Row < t.Image.Height)
  {
    slot.Label->SetInput(
      (t.Label + ": tracing " + std::to_string(100 * t.Row / t.Image.Height) + "%").c_str());
  }
  else
  {
    t.Tracer.reset();
    t.Picture->SetInputData(ToVtkImage(t.Image));
    // Pixel for pixel: the picture's height fills the panel's.
    t.Renderer->ResetCamera();
    t.Renderer->GetActiveCamera()->SetParallelScale(0.5 * t.Image.Height);
    t.Renderer->DrawOn();
    slot.Label->SetInput(t.Label.c_str());
    std::cout << "shadelab: traced the " << t.Label << " panel (" << t.Image.Width << "x"
              << t.Image.Height << ") in " << Fixed(Milliseconds(t.Started) / 1000, 2) << " s"
              << std::endl;
  }
  this->Window->Render();
  if (t.Renderer->GetDraw())
  {
    this->RefreshDifference(); // of the traced picture
  }
}
}
