// The inspector's start-up, its run, and the camera the lights follow
// (desktop/inspector.h).
#include "desktop/inspector.h"

#include "core/errors.h"
#include "scene/camera.h"
#include "scene/comparison_panels.h"
#include "vtkShadelabShading.h"

#include <vtkAutoInit.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkLightRepresentation.h>

#include <algorithm>
#include <cmath>
#include <iostream>

// The OpenGL classes, the default styles and text through FreeType come
// from these modules' object factories.
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingUI);
VTK_MODULE_INIT(vtkInteractionStyle);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace shadelab
{
namespace
{
void Observe(vtkObject* subject, unsigned long event,
  void (*callback)(vtkObject*, unsigned long, void* self, void*), void* self)
{
  vtkNew<vtkCallbackCommand> command;
  command->SetCallback(callback);
  command->SetClientData(self);
  subject->AddObserver(event, command);
}
}

Inspector::Inspector(const ViewOptions& options, const std::string& commandLine)
  : Options(options)
  , CommandLine(commandLine)
{
  this->State.Scene = options.Scene;
  this->State.Glyphs = options.Scene.NormalGlyphs;
  this->State.Edges = options.Scene.Edges;
  this->State.Compare = options.Compare;
}

void Inspector::Start()
{
  this->SetUpWindow();
  this->SetUpOverlay();
  this->ObserveFrames();
  this->ObserveDrags();
  this->ObserveClicks();
  Observe(
    this->Interactor, vtkCommand::TimerEvent,
    [](vtkObject*, unsigned long, void* self, void* timer)
    {
      auto* inspector = static_cast<Inspector*>(self);
      if (*static_cast<int*>(timer) == inspector->TraceTimer)
      {
        inspector->TraceStep();
      }
    },
    this);
  this->Apply();
  this->ResetCamera(); // the panels' aspect
  this->Window->Render();
  this->RefreshDifference();
}

void Inspector::SetState(const ViewState& state)
{
  const bool layout = state.Compare != this->State.Compare;
  this->State = state;
  this->Show(layout);
}

void Inspector::Edit(const std::function<void(ViewState&)>& edit)
{
  ViewState state = this->State;
  edit(state);
  this->SetState(state);
}

// Draws the state as it is now; `layout`: the panels' grid changed, and
// with it their aspect.
void Inspector::Show(bool layout)
{
  this->Apply();
  if (layout)
  {
    this->ResetCamera();
  }
  this->Reprobe();
  this->Window->Render();
  this->RefreshDifference();
  if (this->Changed)
  {
    this->Changed();
  }
}

int Inspector::Load()
{
  const SceneOptions& scene = this->Options.Scene;
  const LoadedMesh& loaded = this->Meshes.Get(scene);
  if (!loaded.Mesh)
  {
    return ReportError(scene.Mesh, loaded.Error);
  }
  try
  {
    PlanComparison(this->Options.Panels, scene);
  }
  catch (const std::invalid_argument& e)
  {
    std::cerr << "shadelab: error: view: " << e.what() << " (see shadelab view --help)"
              << std::endl;
    return ExitUsage;
  }
  loaded.Mesh->GetBounds(this->Bounds);
  this->Points = loaded.Mesh->GetPoints();
  this->Triangles = loaded.Mesh->GetNumberOfPolys();
  this->FileNormals = loaded.NormalsFromFile;
  this->FileNormalMaps = FileMapsNormals(loaded.Mesh);
  this->State.Lights = scene.Lights.empty() ? LightMode::PointAtCamera : LightMode::Given;
  if (auto [input, error] = ReadOwnStages(scene, this->State.Stages); !error.empty())
  {
    return ReportError(input, error);
  }
  this->State.StagesRule = scene.ShadingRule;
  this->Saved = this->State.Stages;
  if (const std::string error = ApplyCamera(scene, this->Points,
        static_cast<double>(scene.Size.Width) / scene.Size.Height, this->Camera);
      !error.empty())
  {
    return ReportError("camera", error);
  }
  return 0;
}

void Inspector::SetUpWindow()
{
  const SceneOptions& scene = this->Options.Scene;
  // No multisampling: the pixels are the shading rule's alone, as headless.
  this->Window->SetMultiSamples(0);
  // The wireframe's lines drawn by OpenGL at any width --line-width takes,
  // never by VTK's wide-line geometry shader, which does not pass the
  // generated stages' own values on (flat's lines came out unlit); VTK read
  // the range as 1 in Qt's context here, where Mesa draws them wider.
  this->Window->SetForceMaximumHardwareLineWidth(MaxLineWidth);
  this->Window->SetNumberOfLayers(2);
  // Cleared first each frame: a grid's empty cells would keep stale pixels.
  this->Backdrop->SetBackground(scene.Background.data());
  this->Backdrop->InteractiveOff();
  this->Window->AddRenderer(this->Backdrop);
  this->Overlay->SetLayer(1);
  this->Overlay->InteractiveOff(); // the mouse goes to the panel beneath
  this->Window->AddRenderer(this->Overlay);
  this->DifferenceRenderer->AddActor(this->DifferenceImage);
  this->DifferenceRenderer->GetActiveCamera()->ParallelProjectionOn();
  this->DifferenceRenderer->InteractiveOff();
  this->DifferenceImage->InterpolateOff(); // its pixels as computed

  this->Interactor = this->Window->GetInteractor();
  this->Interactor->SetInteractorStyle(this->Style);
  this->LightHandle->SetInteractor(this->Interactor);
  this->LightHandle->CreateDefaultRepresentation();
  // A drag moves the light: its position, a spot's direction kept.
  Observe(
    this->LightHandle, vtkCommand::InteractionEvent,
    [](vtkObject*, unsigned long, void* self, void*)
    {
      auto* inspector = static_cast<Inspector*>(self);
      const int index = inspector->HandleLight;
      inspector->Edit(
        [inspector, index](ViewState& s)
        {
          if (index >= 0 && index < static_cast<int>(s.Scene.Lights.size()))
          {
            inspector->LightHandle->GetLightRepresentation()->GetLightPosition(
              s.Scene.Lights[index].Position.data());
          }
        });
    },
    this);
}

void Inspector::ShowLightHandle(int index)
{
  const std::vector<Light>& lights = this->State.Scene.Lights;
  const bool shown = index >= 0 && index < static_cast<int>(lights.size()) &&
    this->State.Lights == LightMode::Given && !this->State.Compare &&
    GeometryOf(lights[index].Kind).Position;
  this->HandleLight = shown ? index : -1;
  if (!shown)
  {
    this->LightHandle->EnabledOff();
    return;
  }
  Light light = lights[index]; // a copy: VTK's setters take double*
  vtkLightRepresentation* handle = this->LightHandle->GetLightRepresentation();
  handle->SetRenderer(this->Slots.front().Renderer);
  this->LightHandle->SetCurrentRenderer(this->Slots.front().Renderer);
  handle->SetPositional(GeometryOf(light.Kind).Cone);
  Vec3 focal;
  for (int i = 0; i < 3; ++i)
  {
    focal[i] = light.Position[i] + light.Direction[i];
  }
  handle->SetFocalPoint(focal.data());
  handle->SetConeAngle(light.HalfAngleDeg);
  handle->SetLightColor(light.Color.data());
  handle->SetLightPosition(light.Position.data());
  this->LightHandle->EnabledOn();
}

// Each frame's time for the HUD; the lights follow the camera.
void Inspector::ObserveFrames()
{
  Observe(
    this->Window, vtkCommand::StartEvent,
    [](vtkObject*, unsigned long, void* self, void*)
    {
      auto* inspector = static_cast<Inspector*>(self);
      inspector->FrameStart = Clock::now();
      inspector->FollowCamera();
    },
    this);
  Observe(
    this->Window, vtkCommand::EndEvent,
    [](vtkObject*, unsigned long, void* self, void*)
    {
      auto* inspector = static_cast<Inspector*>(self);
      inspector->FrameMs.push_back(Milliseconds(inspector->FrameStart));
      if (inspector->FrameMs.size() > 10)
      {
        inspector->FrameMs.pop_front();
      }
      inspector->ReportStageErrors();
      inspector->UpdateHud(); // shows in the next frame
      inspector->FollowTracing();
    },
    this);
}

// The drag-time rule: the cheaper rule from press to release.
void Inspector::ObserveDrags()
{
  Observe(
    this->Style, vtkCommand::StartInteractionEvent,
    [](vtkObject*, unsigned long, void* self, void*)
    {
      auto* inspector = static_cast<Inspector*>(self);
      inspector->Dragging = true;
      inspector->DifferenceImage->VisibilityOff(); // until the release: it would lag
      if (inspector->Options.InteractiveShading)
      {
        inspector->Apply();
      }
    },
    this);
  Observe(
    this->Style, vtkCommand::EndInteractionEvent,
    [](vtkObject*, unsigned long, void* self, void*)
    {
      auto* inspector = static_cast<Inspector*>(self);
      inspector->Dragging = false;
      if (inspector->Options.InteractiveShading)
      {
        inspector->Apply();
      }
      // The probed pixel shows another point of the surface now.
      if (inspector->Reprobe() || inspector->Options.InteractiveShading)
      {
        inspector->Window->Render();
      }
      inspector->FollowTracing(); // the camera rests: trace
      inspector->RefreshDifference();
    },
    this);
}

Light Inspector::LightAtCamera(LightKind kind) const
{
  Vec3 eye, focal;
  this->Camera->GetPosition(eye.data());
  this->Camera->GetFocalPoint(focal.data());
  Light light;
  light.Kind = kind;
  light.Position = eye;
  light.Direction = { focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2] };
  light.HalfAngleDeg = 8;
  light.Exponent = 4;
  return light;
}

std::vector<Light> Inspector::CameraLights(const SceneOptions& scene) const
{
  switch (this->State.Lights)
  {
    case LightMode::Given:
      return scene.Lights;
    case LightMode::PointAtCamera:
      return { this->LightAtCamera(LightKind::Point) };
    case LightMode::Directional:
      return { this->LightAtCamera(LightKind::Directional) };
    case LightMode::Spot:
      return { this->LightAtCamera(LightKind::Spot) };
  }
  return scene.Lights;
}

void Inspector::FollowCamera()
{
  if (this->State.Lights == LightMode::Given)
  {
    return;
  }
  const std::vector<Light> lights =
    ResolvedLights(CameraLights(this->State.Scene), this->State.Scene);
  for (Slot& slot : this->Slots)
  {
    if (const BuiltScene* shown = slot.Scenes.GetShown())
    {
      for (const DrawnParts& drawn : shown->Drawn)
      {
        drawn.Shading->SetLightPlacement(lights);
      }
    }
  }
}

void Inspector::ResetCamera()
{
  const int* size = this->Window->GetSize();
  const double aspect = (static_cast<double>(size[0]) / this->Columns) /
    (static_cast<double>(std::max(size[1], 1)) / this->Rows);
  ApplyCamera(this->Options.Scene, this->Points, aspect, this->Camera); // checked at start
  this->Slots.front().Renderer->ResetCameraClippingRange(this->Bounds);
}

int Inspector::MeasureDrag()
{
  const int* size = this->Window->GetSize();
  const int frames = this->Options.MeasureDrag;
  // A drag left to right through the middle, 2 pixels a frame (a slow,
  // steady rotation), through the interactor as the mouse would.
  const auto drag = [this, size](int moves)
  {
    const int x = size[0] / 4, y = size[1] / 2;
    this->Interactor->SetEventInformationFlipY(x, y);
    this->Interactor->InvokeEvent(vtkCommand::LeftButtonPressEvent);
    const auto start = Clock::now();
    for (int i = 1; i <= moves; ++i)
    {
      this->Interactor->SetEventInformationFlipY(x + 2 * i, y);
      this->Interactor->InvokeEvent(vtkCommand::MouseMoveEvent);
    }
    const double ms = Milliseconds(start);
    this->Interactor->InvokeEvent(vtkCommand::LeftButtonReleaseEvent);
    return ms / moves;
  };
  drag(5); // compiles the drag-time rule's program
  const double dragging = drag(frames);
  const auto start = Clock::now();
  for (int i = 0; i < frames; ++i)
  {
    this->Window->Render();
  }
  const double still = Milliseconds(start) / frames;
  const SceneOptions& s = this->State.Scene;
  std::cout << "size " << size[0] << "x" << size[1] << ", " << this->Triangles << " triangles, "
            << ToString(s.ShadingRule) << ": dragging ("
            << ToString(this->Options.InteractiveShading.value_or(s.ShadingRule)) << ") "
            << Fixed(dragging, 1) << " ms/frame, " << Fixed(1000 / dragging, 1)
            << " frames/s; still " << Fixed(still, 1) << " ms/frame, " << Fixed(1000 / still, 1)
            << " frames/s";
  // The first given point or spot light moved a little each frame through
  // the edit the light handle makes on a drag (its InteractionEvent), each
  // move drawing the full rule: the handle's own picking is not timed.
  const auto movable = std::find_if(s.Lights.begin(), s.Lights.end(),
    [](const Light& light) { return GeometryOf(light.Kind).Position; });
  if (this->State.Lights == LightMode::Given && movable != s.Lights.end())
  {
    const auto index = static_cast<std::size_t>(movable - s.Lights.begin());
    const double step = 0.002 *
      std::hypot(this->Bounds[1] - this->Bounds[0], this->Bounds[3] - this->Bounds[2],
        this->Bounds[5] - this->Bounds[4]);
    const auto lightStart = Clock::now();
    for (int i = 0; i < frames; ++i)
    {
      this->Edit(
        [index, step](ViewState& state) { state.Scene.Lights[index].Position[0] += step; });
    }
    const double light = Milliseconds(lightStart) / frames;
    std::cout << "; moving a light " << Fixed(light, 1) << " ms/frame, " << Fixed(1000 / light, 1)
              << " frames/s";
  }
  std::cout << std::endl;
  return 0;
}
}
