// The desktop inspector (issue 5): `shadelab view` in a window of VTK's
// native backend (shadelab-view, without the OSMesa linkage). The mesh is
// shown under the lecture's shaders and every setting changes live with a
// key; the comparison layout shows compare's panels with one camera.
#include "commands/view_command.h"
#include "core/errors.h"
#include "core/milliseconds.h"
#include "desktop/vtkShadelabInteractorStyle.h"
#include "desktop/x_display.h"
#include "image/comparison_picture.h"
#include "image/image_writer_process.h"
#include "image/metadata.h"
#include "scene/camera.h"
#include "scene/comparison_panels.h"
#include "scene/mesh_cache.h"
#include "scene/scene.h"
#include "scene/scene_cache.h"
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkBoundingBox.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkExtractEdges.h>
#include <vtkHedgeHog.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

// The native window, its interactor, the default styles and text through
// FreeType come from these modules' object factories.
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingUI);
VTK_MODULE_INIT(vtkInteractionStyle);
VTK_MODULE_INIT(vtkRenderingFreeType);

namespace shadelab
{
namespace
{
// The `l` key's cycle. Lights other than the given ones follow the camera,
// as the lecture's light "at the viewpoint" does.
enum class LightMode
{
  Given,         // --light, fixed in the world
  PointAtCamera, // the lecture's default
  Directional,   // shining along the view direction
  Spot           // at the camera, along the view direction
};

const char* ToString(LightMode mode)
{
  switch (mode)
  {
    case LightMode::Given:
      return "the given lights";
    case LightMode::PointAtCamera:
      return "point light at camera";
    case LightMode::Directional:
      return "directional light along the view";
    case LightMode::Spot:
      return "spot light at camera (8 deg, e 4)";
  }
  return "?";
}

const std::vector<std::string> Weightings = Names<vtkShadelabMeshNormals::Weightings>();

std::string Fixed(double value, int digits)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.*f", digits, value);
  return text;
}

class Inspector
{
public:
  Inspector(const ViewOptions& options, const std::string& commandLine)
    : Options(options)
    , CommandLine(commandLine)
    , CompareOn(options.Compare)
  {
  }

  int Run(void* display);

private:
  // A panel of the window: its renderer, and per rule and mesh the actor
  // built for it (hidden while another shows), so that switching back
  // reuses the compiled program and the uploaded buffers.
  struct Slot
  {
    explicit Slot(MeshCache& meshes)
      : Scenes(meshes)
    {
    }
    vtkSmartPointer<vtkRenderer> Renderer;
    vtkSmartPointer<vtkTextActor> Label;
    SceneCache Scenes;
    std::map<vtkPolyData*, vtkSmartPointer<vtkActor>> Glyphs, Edges;
  };

  void OnKey(const std::string& key);
  void Apply();
  void MakeSlots(std::size_t count, int columns, bool difference);
  void RefreshDifference();
  FloatImage GrabWindow();
  std::vector<Light> CameraLights(const SceneOptions& scene) const;
  void FollowCamera();
  void UpdateHud();
  void ResetCamera();
  void Screenshot();
  int MeasureDrag();
  vtkActor* GlyphsOf(Slot& slot, vtkPolyData* mesh);
  vtkActor* EdgesOf(Slot& slot, vtkPolyData* mesh);

  ViewOptions Options; // Options.Scene: the command line's, then as the keys change it
  std::string CommandLine;
  LightMode Lights = LightMode::PointAtCamera;
  bool Ambient = true, Diffuse = true, Specular = true;
  bool GlyphsOn = false, EdgesOn = false, CompareOn = false, HelpOn = false, Dragging = false;
  bool FileNormals = false; // the mesh has normals of its own: the first of `w`'s cycle
  std::string Problem;      // the last thing that went wrong, shown in the HUD
  MeshCache Meshes;
  double Bounds[6] = {};
  vtkIdType Triangles = 0;

  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderWindowInteractor> Interactor;
  vtkNew<vtkShadelabInteractorStyle> Style;
  vtkNew<vtkCamera> Camera;     // every panel's: linked cameras
  vtkNew<vtkRenderer> Backdrop; // the whole window, beneath the panels
  vtkNew<vtkRenderer> Overlay;
  vtkNew<vtkTextActor> Hud;
  vtkNew<vtkTextActor> Help;
  std::vector<Slot> Slots;
  Comparison Plan;             // what the comparison layout shows
  int Columns = 1, Rows = 1;   // the panels' grid
  bool DifferenceCell = false; // the last cell holds the difference of two panels
  vtkNew<vtkRenderer> DifferenceRenderer;
  vtkNew<vtkImageActor> DifferenceImage;
  Clock::time_point FrameStart;
  std::deque<double> FrameMs; // the last frames' times
  std::unique_ptr<ImageWriterProcess> Writer;
};

int Inspector::Run(void* display)
{
  SceneOptions& scene = this->Options.Scene;
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
  this->Triangles = loaded.Mesh->GetNumberOfPolys();
  this->FileNormals = loaded.NormalsFromFile;
  this->Lights = scene.Lights.empty() ? LightMode::PointAtCamera : LightMode::Given;
  if (const std::string error = ApplyCamera(scene, this->Bounds,
        static_cast<double>(scene.Size.Width) / scene.Size.Height, this->Camera);
      !error.empty())
  {
    return ReportError("camera", error);
  }

  this->Window->SetDisplayId(display);
  this->Window->SetSize(scene.Size.Width, scene.Size.Height);
  // No multisampling: the pixels are the shading rule's alone, as headless.
  this->Window->SetMultiSamples(0);
  this->Window->SetWindowName(
    ("shadelab - " + std::filesystem::path(scene.Mesh).filename().string()).c_str());
  this->Window->SetNumberOfLayers(2);
  // Cleared first each frame: a grid's empty cells would keep stale pixels.
  this->Backdrop->SetBackground(scene.Background.data());
  this->Backdrop->InteractiveOff();
  this->Window->AddRenderer(this->Backdrop);
  this->Overlay->SetLayer(1);
  this->Overlay->InteractiveOff(); // the mouse goes to the panel beneath
  this->Window->AddRenderer(this->Overlay);
  this->Hud->GetTextProperty()->SetFontSize(15);
  this->Hud->GetTextProperty()->SetColor(0.9, 0.9, 0.6);
  this->Hud->SetPosition(8, 8);
  this->Overlay->AddActor2D(this->Hud);
  this->Help->SetInput(ViewKeysHelp().c_str());
  this->Help->GetTextProperty()->SetFontSize(17);
  this->Help->GetTextProperty()->SetFontFamilyToCourier();
  this->Help->GetTextProperty()->SetBackgroundColor(0.05, 0.05, 0.1);
  this->Help->GetTextProperty()->SetBackgroundOpacity(0.85);
  this->Help->GetTextProperty()->SetJustificationToCentered();
  this->Help->GetTextProperty()->SetVerticalJustificationToCentered();
  this->Help->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  this->Help->SetPosition(0.5, 0.5);
  this->Help->VisibilityOff();
  this->Overlay->AddActor2D(this->Help);
  // Edges and glyphs drawn on the surface must win the depth test.
  vtkMapper::SetResolveCoincidentTopologyToPolygonOffset();

  this->Interactor->SetRenderWindow(this->Window);
  this->Interactor->SetInteractorStyle(this->Style);
  this->Style->SetKeyHandler([this](const std::string& key) { this->OnKey(key); });
  const auto observe = [](vtkObject* subject, unsigned long event, auto callback, void* self)
  {
    vtkNew<vtkCallbackCommand> command;
    command->SetCallback(callback);
    command->SetClientData(self);
    subject->AddObserver(event, command);
  };
  observe(
    this->Window, vtkCommand::StartEvent,
    [](vtkObject*, unsigned long, void* self, void*)
    {
      auto* inspector = static_cast<Inspector*>(self);
      inspector->FrameStart = Clock::now();
      inspector->FollowCamera();
    },
    this);
  observe(
    this->Window, vtkCommand::EndEvent,
    [](vtkObject*, unsigned long, void* self, void*)
    {
      auto* inspector = static_cast<Inspector*>(self);
      inspector->FrameMs.push_back(Milliseconds(inspector->FrameStart));
      if (inspector->FrameMs.size() > 10)
      {
        inspector->FrameMs.pop_front();
      }
      inspector->UpdateHud(); // shows in the next frame
    },
    this);
  // The drag-time rule: the cheaper rule from press to release.
  observe(
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
  observe(
    this->Style, vtkCommand::EndInteractionEvent,
    [](vtkObject*, unsigned long, void* self, void*)
    {
      auto* inspector = static_cast<Inspector*>(self);
      inspector->Dragging = false;
      if (inspector->Options.InteractiveShading)
      {
        inspector->Apply();
        inspector->Window->Render();
      }
      inspector->RefreshDifference();
    },
    this);

  this->DifferenceRenderer->AddActor(this->DifferenceImage);
  this->DifferenceRenderer->GetActiveCamera()->ParallelProjectionOn();
  this->DifferenceRenderer->InteractiveOff();
  this->DifferenceImage->InterpolateOff(); // its pixels as computed
  this->Apply();
  this->ResetCamera(); // the panels' aspect
  this->Interactor->Initialize();
  this->Window->Render();
  this->RefreshDifference();
  if (this->Options.MeasureDrag > 0)
  {
    return this->MeasureDrag();
  }
  std::cout << "shadelab: " << this->Window->GetWindowName() << ": press h for the keys"
            << std::endl;
  this->Interactor->Start();
  return 0;
}

std::vector<Light> Inspector::CameraLights(const SceneOptions& scene) const
{
  if (this->Lights == LightMode::Given)
  {
    return scene.Lights;
  }
  Vec3 eye, focal;
  this->Camera->GetPosition(eye.data());
  this->Camera->GetFocalPoint(focal.data());
  Light light;
  light.Position = eye;
  light.Direction = { focal[0] - eye[0], focal[1] - eye[1], focal[2] - eye[2] };
  light.Kind = this->Lights == LightMode::PointAtCamera ? LightKind::Point
    : this->Lights == LightMode::Directional            ? LightKind::Directional
                                                        : LightKind::Spot;
  light.HalfAngleDeg = 8;
  light.Exponent = 4;
  return { light };
}

void Inspector::FollowCamera()
{
  if (this->Lights == LightMode::Given)
  {
    return;
  }
  const std::vector<Light> lights = CameraLights(this->Options.Scene);
  for (Slot& slot : this->Slots)
  {
    if (const BuiltScene* shown = slot.Scenes.GetShown())
    {
      shown->Shading->SetLightPlacement(lights);
    }
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
    place(slot.Renderer, static_cast<int>(i));
    slot.Renderer->SetActiveCamera(this->Camera);
    slot.Renderer->SetBackground(this->Options.Scene.Background.data());
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

void Inspector::RefreshDifference()
{
  if (!this->DifferenceCell || this->Dragging)
  {
    return;
  }
  // The two panels as rendered, without the texts drawn over them.
  std::vector<vtkProp*> texts{ this->Hud, this->Help };
  for (Slot& slot : this->Slots)
  {
    texts.push_back(slot.Label);
  }
  std::vector<int> visible;
  for (vtkProp* text : texts)
  {
    visible.push_back(text->GetVisibility());
    text->VisibilityOff();
  }
  vtkRenderer* a = this->Slots[this->Plan.DifferenceA].Renderer;
  vtkRenderer* b = this->Slots[this->Plan.DifferenceB].Renderer;
  const int width = std::min(a->GetSize()[0], b->GetSize()[0]);
  const int height = std::min(a->GetSize()[1], b->GetSize()[1]);
  const FloatImage window = this->GrabWindow();
  // GetOrigin: the panel's lower left in the window's pixels.
  const auto crop = [&window, width, height](vtkRenderer* panel)
  {
    FloatImage cut{ width, height, {} };
    for (int y = 0; y < height; ++y)
    {
      const auto row = window.Rgba.begin() +
        4 * (static_cast<size_t>(panel->GetOrigin()[1] + y) * window.Width + panel->GetOrigin()[0]);
      cut.Rgba.insert(cut.Rgba.end(), row, row + 4 * width);
    }
    return cut;
  };
  const FloatImage pictureA = crop(a), pictureB = crop(b);
  for (std::size_t i = 0; i < texts.size(); ++i)
  {
    texts[i]->SetVisibility(visible[i]);
  }
  const Difference difference = CompareImages(pictureA, pictureB);
  // The comparison picture's own difference cell: label, heat map, colour bar.
  const FloatImage cell =
    ComposeComparison({ { &difference.Heat, this->Plan.DifferenceLabel } }, 1, &difference, 0);
  vtkNew<vtkImageData> image;
  image->SetDimensions(cell.Width, cell.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(image->GetScalarPointer());
  const std::vector<std::uint8_t> topDown = Quantise<std::uint8_t>(cell, 255);
  for (int y = 0; y < cell.Height; ++y) // VTK's images are bottom row first
  {
    std::copy_n(topDown.data() + static_cast<size_t>(cell.Height - 1 - y) * cell.Width * 3,
      cell.Width * 3, out + static_cast<size_t>(y) * cell.Width * 3);
  }
  this->DifferenceImage->SetInputData(image);
  this->DifferenceImage->VisibilityOn();
  // Fit the picture into the cell.
  this->DifferenceRenderer->ResetCamera();
  const int* cellSize = this->DifferenceRenderer->GetSize();
  this->DifferenceRenderer->GetActiveCamera()->SetParallelScale(0.5 *
    std::max(static_cast<double>(cell.Height),
      static_cast<double>(cell.Width) * cellSize[1] / std::max(cellSize[0], 1)));
  this->Window->Render();
}

// An unlit actor of lines' output, added to renderer.
vtkSmartPointer<vtkActor> AddLines(vtkRenderer* renderer, vtkAlgorithm* lines, const Rgb& colour)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(lines->GetOutputPort());
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->LightingOff();
  actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]);
  renderer->AddActor(actor);
  return actor;
}

vtkActor* Inspector::GlyphsOf(Slot& slot, vtkPolyData* mesh)
{
  auto& actor = slot.Glyphs[mesh];
  if (!actor)
  {
    vtkNew<vtkHedgeHog> hedgehog;
    hedgehog->SetInputData(mesh);
    hedgehog->SetVectorModeToUseNormal();
    // About twice the vertices' spacing (n points spread over the mesh's
    // extent), so that neighbours' glyphs barely overlap.
    const double diagonal = vtkBoundingBox(this->Bounds).GetDiagonalLength();
    const double spacing =
      diagonal / std::sqrt(static_cast<double>(std::max<vtkIdType>(mesh->GetNumberOfPoints(), 1)));
    hedgehog->SetScaleFactor(std::clamp(2 * spacing, 0.004 * diagonal, 0.05 * diagonal));
    actor = AddLines(slot.Renderer, hedgehog, { 0.2, 0.9, 1.0 });
  }
  return actor;
}

vtkActor* Inspector::EdgesOf(Slot& slot, vtkPolyData* mesh)
{
  auto& actor = slot.Edges[mesh];
  if (!actor)
  {
    vtkNew<vtkExtractEdges> edges;
    edges->SetInputData(mesh);
    actor = AddLines(slot.Renderer, edges, { 0.05, 0.05, 0.05 });
  }
  return actor;
}

void Inspector::Apply()
{
  SceneOptions base = this->Options.Scene;
  ShowTerms(base, this->Ambient, this->Diffuse, this->Specular);
  std::vector<Panel> panels;
  if (this->CompareOn)
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
  this->MakeSlots(panels.size(), this->CompareOn ? this->Plan.Columns : 0,
    this->CompareOn && this->Plan.DifferenceA >= 0);
  this->Problem.clear();
  for (std::size_t i = 0; i < panels.size(); ++i)
  {
    Slot& slot = this->Slots[i];
    const SceneOptions& scene = panels[i].Scene;
    const std::vector<Light> lights = CameraLights(scene);
    const SceneCache::Shown shown = slot.Scenes.Show(scene, slot.Renderer, &lights);
    if (!shown.Scene)
    {
      this->Problem = shown.Error;
      continue;
    }
    for (auto* extras : { &slot.Glyphs, &slot.Edges })
    {
      for (auto& [mesh, actor] : *extras)
      {
        actor->VisibilityOff();
      }
    }
    if (this->GlyphsOn)
    {
      // The vertex normals that gouraud and phong use, whatever this rule.
      SceneOptions lit = scene;
      lit.ShadingRule = Shading::Phong;
      if (vtkPolyData* normals = this->Meshes.Get(lit).Mesh)
      {
        this->GlyphsOf(slot, normals)->VisibilityOn();
      }
    }
    if (this->EdgesOn)
    {
      this->EdgesOf(slot, shown.Mesh->Mesh)->VisibilityOn();
    }
    slot.Label->SetInput(panels[i].Label.c_str());
    slot.Label->SetVisibility(this->CompareOn);
  }
  this->Help->SetVisibility(this->HelpOn);
  this->UpdateHud();
}

void Inspector::UpdateHud()
{
  const SceneOptions& s = this->Options.Scene;
  const Material m = s.EffectiveMaterial();
  std::ostringstream hud;
  hud << (this->CompareOn ? "compare: " + this->Options.Panels.Modes
                          : std::string(ToString(s.ShadingRule)) + " shading")
      << " | " << (s.ReflectionModel == Reflection::BlinnPhong ? "Blinn-Phong" : "Phong") << " | "
      << m.Name << " (ns " << Fixed(m.Ns, 1) << ") | " << ToString(this->Lights) << "\n";
  hud << this->Triangles << " triangles | normals: "
      << (s.Normals != NormalsMode::Compute && this->FileNormals ? "from the file"
                                                                 : s.Computed.Weighting.c_str())
      << " | terms:" << (this->Ambient ? " ambient" : "") << (this->Diffuse ? " diffuse" : "")
      << (this->Specular ? " specular" : "") << "\n";
  double mean = 0;
  for (double ms : this->FrameMs)
  {
    mean += ms / this->FrameMs.size();
  }
  hud << Fixed(mean, 1) << " ms/frame";
  if (this->Options.InteractiveShading && !this->CompareOn)
  {
    hud << " | while dragging: " << ToString(*this->Options.InteractiveShading)
        << (this->Dragging ? " (now)" : "");
  }
  hud << " | h: keys";
  if (!this->Problem.empty())
  {
    hud << "\n" << this->Problem;
  }
  this->Hud->SetInput(hud.str().c_str());
}

void Inspector::ResetCamera()
{
  const int* size = this->Window->GetSize();
  const double aspect = (static_cast<double>(size[0]) / this->Columns) /
    (static_cast<double>(std::max(size[1], 1)) / this->Rows);
  ApplyCamera(this->Options.Scene, this->Bounds, aspect, this->Camera); // checked at start
  this->Slots.front().Renderer->ResetCameraClippingRange(this->Bounds);
}

void Inspector::OnKey(const std::string& key)
{
  SceneOptions& s = this->Options.Scene;
  const auto& materials = LectureMaterials();
  if (key == "q" || key == "Escape")
  {
    this->Interactor->TerminateApp();
    return;
  }
  if (key == "p")
  {
    this->Screenshot();
    return;
  }
  if (key.size() == 1 && key[0] >= '0' && key[0] <= '3')
  {
    s.ShadingRule = static_cast<Shading>(key[0] - '0');
  }
  else if (key == "b")
  {
    s.ReflectionModel =
      s.ReflectionModel == Reflection::BlinnPhong ? Reflection::Phong : Reflection::BlinnPhong;
  }
  else if (key == "m" || key == "M")
  {
    const auto current = std::find_if(materials.begin(), materials.end(),
      [&s](const Material& m) { return m.Name == s.MaterialName; });
    const int n = static_cast<int>(materials.size());
    const int index =
      current == materials.end() ? -1 : static_cast<int>(current - materials.begin());
    s.MaterialName = materials[(index + (key == "m" ? 1 : n - 1)) % n].Name;
    s.Ka.reset(); // the command line's coefficients were for its material
    s.Kd.reset();
    s.Ks.reset();
    s.Ns.reset();
  }
  else if (key == "l")
  {
    const bool given = !s.Lights.empty();
    int next = static_cast<int>(this->Lights) + 1;
    this->Lights = static_cast<LightMode>(next > static_cast<int>(LightMode::Spot)
        ? (given ? 0 : static_cast<int>(LightMode::PointAtCamera))
        : next);
  }
  else if (key == "+" || key == "=" || key == "-")
  {
    const double ns = s.EffectiveMaterial().Ns;
    s.Ns = key == "-" ? ns / 1.5 : std::max(1.0, ns * 1.5);
  }
  else if (key == "a" || key == "d" || key == "s")
  {
    bool& term = key == "a" ? this->Ambient : key == "d" ? this->Diffuse : this->Specular;
    term = !term;
  }
  else if (key == "w")
  {
    // The cycle: the file's normals (when it has them), then each weighting.
    const bool fromFile = s.Normals != NormalsMode::Compute && this->FileNormals;
    const auto at = std::find(Weightings.begin(), Weightings.end(), s.Computed.Weighting);
    if (fromFile)
    {
      s.Normals = NormalsMode::Compute;
      s.Computed.Weighting = Weightings.front();
    }
    else if (at == Weightings.end() || at + 1 == Weightings.end())
    {
      s.Computed.Weighting = Weightings.front();
      s.Normals = this->FileNormals ? NormalsMode::Auto : NormalsMode::Compute;
    }
    else
    {
      s.Computed.Weighting = *(at + 1);
    }
  }
  else if (key == "n")
  {
    this->GlyphsOn = !this->GlyphsOn;
  }
  else if (key == "e")
  {
    this->EdgesOn = !this->EdgesOn;
  }
  else if (key == "c")
  {
    this->CompareOn = !this->CompareOn;
    this->Apply();
    this->ResetCamera();
  }
  else if (key == "r")
  {
    this->ResetCamera();
  }
  else if (key == "h")
  {
    this->HelpOn = !this->HelpOn;
  }
  else
  {
    return;
  }
  this->Apply();
  this->Window->Render();
  this->RefreshDifference();
}

// The window's pixels as rendered now: 8-bit values as floats, which an
// 8-bit file gets back exactly.
FloatImage Inspector::GrabWindow()
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(this->Window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  grab->Update();
  vtkImageData* window = grab->GetOutput();
  const auto* rgb = static_cast<const unsigned char*>(window->GetScalarPointer());
  FloatImage image{ window->GetDimensions()[0], window->GetDimensions()[1], {} };
  image.Rgba.resize(static_cast<size_t>(image.Width) * image.Height * 4, 1);
  for (size_t i = 0; i < static_cast<size_t>(image.Width) * image.Height; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      image.Rgba[4 * i + c] = rgb[3 * i + c] / 255.0f;
    }
  }
  return image;
}

void Inspector::Screenshot()
{
  const std::string stem = std::filesystem::path(this->Options.Scene.Mesh).stem().string();
  std::string path;
  for (int n = 1; path.empty() || std::filesystem::exists(path); ++n)
  {
    char number[16];
    std::snprintf(number, sizeof number, "%03d", n);
    path = "shadelab-" + stem + "-" + number + ".png";
  }
  const FloatImage image = this->GrabWindow();
  if (!this->Writer)
  {
    this->Writer = std::make_unique<ImageWriterProcess>();
  }
  const std::string error = this->Writer->Write(path, image, PixelType::UInt8,
    DescribePicture(this->CommandLine, this->Options.Scene, this->Camera));
  if (!error.empty())
  {
    ReportError(path, error);
    return;
  }
  std::cout << "shadelab: screenshot " << std::filesystem::absolute(path).string() << std::endl;
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
  const SceneOptions& s = this->Options.Scene;
  std::cout << "size " << size[0] << "x" << size[1] << ", " << this->Triangles << " triangles, "
            << ToString(s.ShadingRule) << ": dragging ("
            << ToString(this->Options.InteractiveShading.value_or(s.ShadingRule)) << ") "
            << Fixed(dragging, 1) << " ms/frame, " << Fixed(1000 / dragging, 1)
            << " frames/s; still " << Fixed(still, 1) << " ms/frame, " << Fixed(1000 / still, 1)
            << " frames/s" << std::endl;
  return 0;
}
}

int RunView(const ViewOptions& options, const std::string& commandLine)
{
  std::string error;
  void* display = OpenXDisplay(error);
  if (!display)
  {
    return ReportError("view", error);
  }
  int code = 0;
  {
    Inspector inspector(options, commandLine);
    code = inspector.Run(display);
  }
  CloseXDisplay(display);
  return code;
}
}
