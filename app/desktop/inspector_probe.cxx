// The probe in the window: a Ctrl+click (press and release in place, so
// that a Ctrl+drag still spins the camera) explains that pixel of the
// single view as `shadelab probe` does, from the scene that Copy command
// writes, prints it as JSON and draws N, L and H or R at the surface point.
#include "desktop/inspector.h"

#include "probe/probe_json.h"
#include "shadelabJsonProblem.h"

#include <vtkArrowSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>

#include <cmath>
#include <cstdlib>
#include <iostream>

namespace shadelab
{
Rgb ProbeArrowColor(char vector)
{
  switch (vector)
  {
    case 'N':
      return { 0.2, 1, 0.2 };
    case 'L':
      return { 0.1, 0.8, 1 };
    default:
      return { 1, 0.3, 0.9 };
  }
}

namespace
{
// The arrows' length: a fraction of the mesh's bounding box diagonal, so
// that they read the same on any mesh.
double ArrowLength(const double bounds[6])
{
  return 0.25 * std::hypot(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4]);
}

// An arrow from `from` along `direction`, `length` long (VTK's arrow runs
// along +X from 0 to 1), drawn unlit in its colour.
vtkSmartPointer<vtkActor> MakeArrow(vtkPolyDataMapper* shape, const Vec3& from,
  const Vec3& direction, double length, const Rgb& color)
{
  const double norm = std::hypot(direction[0], direction[1], direction[2]);
  Vec3 axis{ 0, -direction[2], direction[1] }; // +X x direction
  const double sine = std::hypot(axis[1], axis[2]);
  if (sine < 1e-12 * norm)
  {
    axis = { 0, 1, 0 }; // along +X or -X: any axis across it
  }
  vtkNew<vtkTransform> place;
  place->Translate(from.data());
  place->RotateWXYZ(std::atan2(sine, direction[0]) * 180 / M_PI, axis.data());
  place->Scale(length, length, length);
  auto arrow = vtkSmartPointer<vtkActor>::New();
  arrow->SetMapper(shape);
  arrow->SetUserTransform(place);
  arrow->GetProperty()->LightingOff(); // the scene's lights come in through our shaders
  arrow->GetProperty()->SetColor(color[0], color[1], color[2]);
  arrow->PickableOff();
  return arrow;
}
}

void Inspector::ObserveClicks()
{
  this->Interactor->AddObserver(vtkCommand::LeftButtonPressEvent, this, &Inspector::OnPress);
  // The style holds the mouse's focus from a press to its release: the
  // release comes as the end of its interaction.
  this->Style->AddObserver(vtkCommand::EndInteractionEvent, this, &Inspector::OnRelease);
}

void Inspector::OnPress()
{
  if (!this->Style->LineDrag)
  {
    this->Line->VisibilityOff(); // the profile's line is of the picture before the drag
  }
  const int* at = this->Interactor->GetEventPosition();
  this->PressAt[0] = at[0];
  this->PressAt[1] = at[1];
  // Ctrl+Shift is the trackball's dolly.
  this->PressControl = this->Interactor->GetControlKey() && !this->Interactor->GetShiftKey();
}

void Inspector::OnRelease()
{
  const int* at = this->Interactor->GetEventPosition();
  const bool control = this->PressControl;
  this->PressControl = false; // the wheel ends interactions too
  // A hand's click may slip a pixel; more is a spin.
  if (!control || std::abs(at[0] - this->PressAt[0]) > 2 || std::abs(at[1] - this->PressAt[1]) > 2)
  {
    return;
  }
  // VTK counts rows from the bottom, the probe from the top.
  this->Probe({ this->PressAt[0], this->Window->GetSize()[1] - 1 - this->PressAt[1] });
}

void Inspector::Probe(Pixel at)
{
  this->ProbedPixel = at;
  this->Reprobe();
  this->Window->Render();
}

void Inspector::ClearProbe()
{
  this->ProbedPixel.reset();
  this->Probed.reset();
  this->DrawArrows();
  this->Window->Render();
  std::cout << "shadelab: probe: cleared" << std::endl;
  if (this->ProbeChanged)
  {
    this->ProbeChanged();
  }
}

// Explains the probed pixel again as the view shows it now (not in the
// comparison layout, whose panels are not render's picture); whether a
// pixel is probed.
bool Inspector::Reprobe()
{
  if (!this->ProbedPixel)
  {
    return false;
  }
  this->Probed.reset();
  const BuiltScene* shown =
    this->State.Compare || this->Slots.empty() ? nullptr : this->Slots.front().Scenes.GetShown();
  const Pixel at = *this->ProbedPixel;
  const SceneOptions scene = this->ShownScene();
  if (shown && at.X >= 0 && at.Y >= 0 && at.X < scene.Size.Width && at.Y < scene.Size.Height)
  {
    // The window's pixel without the arrows over it, and the shadow maps
    // baked, whose texels are read in the window's context (shadow_map_agrees).
    this->DrawArrows();
    this->Window->Render();
    this->Window->MakeCurrent();
    const PixelProber prober(
      scene, shown->Mesh, this->Camera, scene.Size, shown->Images, shown->Casters.get());
    PixelProbe probe = prober.Probe(at);
    vtkNew<vtkUnsignedCharArray> rgb;
    this->Window->GetPixelData(
      at.X, scene.Size.Height - 1 - at.Y, at.X, scene.Size.Height - 1 - at.Y, 0, rgb, 0);
    for (int c = 0; c < 3; ++c)
    {
      probe.Rendered[c] = rgb->GetValue(c) / 255.0;
    }
    probe.RenderedFrom = "the window's 8-bit pixel, read without the arrows";
    this->Probed = probe;
    std::cout << "shadelab: probe: " << JsonText(ProbeJson(probe)) << std::endl;
  }
  this->DrawArrows();
  if (this->ProbeChanged)
  {
    this->ProbeChanged();
  }
  return true;
}

// N once, and L and H or R per light, from the probed surface point; none
// without a probe, off the mesh or for the unlit rule.
void Inspector::DrawArrows()
{
  vtkRenderer* panel = this->Slots.empty() ? nullptr : this->Slots.front().Renderer.Get();
  for (const ProbeArrow& arrow : this->Arrows)
  {
    if (panel)
    {
      panel->RemoveActor(arrow.Actor);
    }
  }
  this->Arrows.clear();
  if (!panel || !this->Probed || !this->Probed->Hit || this->Probed->Rule == Shading::None)
  {
    return;
  }
  vtkNew<vtkArrowSource> arrow;
  arrow->SetTipResolution(16);
  arrow->SetShaftResolution(12);
  vtkNew<vtkPolyDataMapper> shape;
  shape->SetInputConnection(arrow->GetOutputPort());
  const IlluminationTerms& t = this->Probed->Shaded.Terms;
  const double length = ArrowLength(this->Bounds);
  const auto add = [&](const std::string& name, const Vec3& direction, char color)
  {
    if (direction != Vec3{})
    {
      this->Arrows.push_back(
        { name, MakeArrow(shape, t.P, direction, length, ProbeArrowColor(color)) });
      panel->AddActor(this->Arrows.back().Actor);
    }
  };
  add("N", t.N, 'N');
  const std::string specular = UsesHalfVector(this->Probed->Model) ? "H" : "R";
  for (std::size_t l = 0; l < t.Lights.size(); ++l)
  {
    const std::string number = std::to_string(l + 1);
    add("L" + number, t.Lights[l].L, 'L');
    add(specular + number, t.Lights[l].HR, 'H');
  }
}
}
