// The desktop inspector's picture: `shadelab view`'s VTK side, drawn into
// the Qt window's 3D view (desktop/inspector_window.h) by VTK's native
// backend (shadelab-view, without the OSMesa linkage). The mesh is shown
// under the lecture's shaders and every setting changes live, by a key or
// the control panel, both through ViewState; the comparison layout shows
// compare's panels with one camera. Its parts: inspector.cxx starts it and
// follows the camera, inspector_panels.cxx lays out the panels,
// inspector_overlay.cxx draws the HUD and the help, inspector_keys.cxx acts
// on the keys, inspector_pictures.cxx reads the window back (screenshots,
// the difference cell).
#ifndef shadelab_inspector_h
#define shadelab_inspector_h

#include "commands/view_command.h"
#include "core/errors.h"
#include "core/milliseconds.h"
#include "desktop/view_keys.h"
#include "desktop/vtkShadelabInteractorStyle.h"
#include "image/comparison_picture.h"
#include "image/image_writer_process.h"
#include "probe/pixel_probe.h"
#include "raytrace/ray_tracer.h"
#include "scene/mesh_cache.h"
#include "scene/own_stage_files.h"
#include "scene/scene_cache.h"
#include "scene/shader_sources.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkLightWidget.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTexture.h>

#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

class vtkShadelabPeelingPass;

namespace shadelab
{
// The `l` key's cycle. Lights other than the given ones follow the camera,
// as the lecture's light "at the viewpoint" does.
enum class LightMode
{
  Given,         // the light list (--light, then the panel's), fixed in the world
  PointAtCamera, // the lecture's default
  Directional,   // shining along the view direction
  Spot           // at the camera, along the view direction
};

/** The mode as the HUD and the control panel name it. */
const char* Describe(LightMode mode);

/** shadelab-MESHSTEM-001.EXTENSION, or the first number not taken in the current folder. */
std::string NumberedName(const std::string& mesh, const std::string& extension);

/** picture (bottom row first) as VTK's 8-bit RGB image, quantised as files are. */
vtkSmartPointer<vtkImageData> ToVtkImage(const FloatImage& picture);

/** A raytrace panel's scene as phong draws it until its picture is whole. */
SceneOptions TracingPreview(const SceneOptions& scene);

/** value with `digits` decimals, as the HUD and the drag's timing print it. */
std::string Fixed(double value, int digits);

/** The probe's arrow colours (the probe panel's legend): 'N', 'L', and 'H'
 * for H or R. */
Rgb ProbeArrowColor(char vector);

// What the picture shows: the keys and the control panel change it.
struct ViewState
{
  SceneOptions Scene; // the command line's, then as changed
  LightMode Lights = LightMode::PointAtCamera;
  bool Ambient = true, Diffuse = true, Specular = true;
  bool Reflected = true; // the environment's term, where the scene has one
  bool Relief = true;    // the normal map, where the scene has one
  bool Glyphs = false, Edges = false, Compare = false, Help = false;
  // The stages of one's own (empty: the generated stage) and the rule they
  // draw: the files --vertex-shader and --fragment-shader name, then as the
  // shader panel applies them. Panels of other rules draw their own.
  OwnStages Stages;
  Shading StagesRule = Shading::Phong;
};

class Inspector
{
public:
  Inspector(const ViewOptions& options, const std::string& commandLine);

  /** The mesh, the comparison's plan and the camera, checked before any
   * window opens; 0, or the exit code of what is wrong (reported). */
  int Load();
  /** The render window that the Qt widget shows; Start once it does. */
  vtkGenericOpenGLRenderWindow* GetWindow() { return this->Window; }
  void Start();
  /** --measure-drag: times a simulated drag and prints it. */
  int MeasureDrag();

  const ViewState& GetState() const { return this->State; }
  /** Shows `state`, and tells Changed. */
  void SetState(const ViewState& state);
  /** SetState of the state as `edit` changes it. */
  void Edit(const std::function<void(ViewState&)>& edit);
  /** The GLSL that drew the (first) panel's mesh in the last frame. */
  const ShaderSources& GetShownShaders() const { return this->ShownShaders; }
  /** The mesh has normals of its own: the first of the normals' choices. */
  bool HasFileNormals() const { return this->FileNormals; }
  /** The mesh file gives a part a normal map of its own. */
  bool HasFileNormalMaps() const { return this->FileNormalMaps; }
  /** A light of `kind` where the camera is, shining along the view. */
  Light LightAtCamera(LightKind kind) const;
  /** The handle that drags the light list's light `index` in the 3D view
   * (a point or spot light, while the list lights the picture); -1: none. */
  void ShowLightHandle(int index);

  /** Acts on `key` (as Qt names it: "1", "Escape", ...) if the key table
   * has it; whether it does. */
  bool OnKey(const std::string& key);
  /** The key table's `action` (`which`: the key's place in its row). */
  void Do(ViewAction action, int which = 0);

  /** The scene `render` takes to make the picture the view shows now:
   * the camera as it is, the lights that follow it and the terms turned
   * off written out (the single panel's: the comparison layout aside). */
  SceneOptions ShownScene() const;
  /** ShownScene as a `shadelab render` command line, quoted for a shell. */
  std::string RenderCommand() const;
  /** ShownScene as a scene file at path (its output MESHSTEM.png); says
   * where, or reports why not. Both save the stages first (SaveStages). */
  void SaveScene(const std::string& path);

  // The stages of one's own (inspector_stages.cxx): the shader panel's.
  /**
   * Draws `edits` for the view's rule (an empty stage: the one that draws
   * now) and gives the driver's errors, none when they draw; refused, the
   * stages that drew before draw again.
   */
  std::vector<StageErrorLine> ApplyStages(const OwnStages& edits);
  /** The generated stages again; the files given are named no more. */
  void RevertStages();
  /**
   * Writes the stages of one's own not written yet, to the files they came
   * from or to new ones (shadelab-MESHSTEM-001.vert, .frag), which Copy
   * command and Save scene then name; whether all were (else reported).
   */
  bool SaveStages();

  // The probe: one pixel of the single view explained (probe/pixel_probe.h),
  // its N, L and H or R drawn as arrows at the surface point, explained
  // again whenever the picture changes, until cleared.
  /** Explains pixel `at` (X from the left, Y from the top) of the view. */
  void Probe(Pixel at);
  void ClearProbe();
  /** The probed pixel explained as the view shows it now, if any. */
  const std::optional<PixelProbe>& GetProbe() const { return this->Probed; }
  struct ProbeArrow
  {
    std::string Name; // "N", "L1", "H1" or "R1", ... (the light's number)
    vtkSmartPointer<vtkActor> Actor;
  };
  const std::vector<ProbeArrow>& GetProbeArrows() const { return this->Arrows; }

  /**
   * The words after `shadelab` that profile the single view's picture along
   * the line from `from` to `to` (pixels from the top left): the scene Copy
   * command writes (the stages of one's own saved first), the comparison's
   * modes. Empty when the stages could not be saved (reported).
   */
  std::vector<std::string> ProfileArguments(Pixel from, Pixel to);
  /** A profile's line drawn (the k key, then a drag), its ends from the top left. */
  std::function<void(Pixel from, Pixel to)> ProfileLine;

  std::function<void()> Changed;                // after a key or SetState changed the state
  std::function<void()> ProbeChanged;           // after a probe, its update or its clearing
  std::function<void()> Quit;                   // the quit key
  std::function<void(const std::string&)> Copy; // text for the clipboard

private:
  // A raytrace panel of the comparison layout: phong draws it while the
  // camera moves; once it rests, it is ray traced a band of rows at a time
  // (the label shows how far) and the picture is shown over the panel.
  struct Tracing
  {
    SceneOptions Scene; // the panel's
    std::string Label;
    vtkSmartPointer<vtkRenderer> Renderer; // over the panel's: the picture
    vtkSmartPointer<vtkImageActor> Picture;
    std::vector<double> Traced;        // what the picture is of (TracedView), or empty
    std::unique_ptr<RayTracer> Tracer; // while it traces
    FloatImage Image;
    int Row = 0; // the next row to trace
    Clock::time_point Started;
  };

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
    vtkSmartPointer<vtkShadelabPeelingPass> Peeling; // its translucent step
    vtkSmartPointer<vtkTextActor> Label;
    SceneCache Scenes;
    std::map<vtkPolyData*, vtkSmartPointer<vtkActor>> Glyphs, Edges;
    std::unique_ptr<Tracing> Traced; // a raytrace panel's
    // --background environment: the environment behind the panel, and
    // its picture (OverEnvironment of nothing) for the camera and size it
    // was last painted for (none: paint at the next draw). The camera's
    // rays, not its modification time, which a clipping range moves too.
    std::optional<EnvironmentMap> Behind;
    vtkSmartPointer<vtkTexture> BehindPicture;
    std::optional<PinholeCamera> BehindCamera;
    std::array<int, 2> BehindSize{};
  };

  // inspector.cxx: start-up, the camera and the lights that follow it, the
  // drag's timing.
  void SetUpWindow();
  void ObserveFrames();
  void ObserveDrags();
  std::vector<Light> CameraLights(const SceneOptions& scene) const;
  void FollowCamera();
  void ResetCamera();
  void Show(bool layout);

  // inspector_panels.cxx: the panels, one or compare's grid.
  void Apply();
  void MakeSlots(std::size_t count, int columns, bool difference);
  void ShowExtras(Slot& slot, const SceneOptions& scene, vtkPolyData* shown);
  // Before a panel's renderer draws: its environment behind it, painted
  // again where the camera or the panel's size changed.
  void PaintBehind(vtkObject* renderer, unsigned long, void*);
  // At each frame's end (a program is built at its first draw, which Qt's
  // first paint may make): stages of one's own that the driver refused
  // (the generated ones drew instead), their errors on stderr when they
  // change and the first in the HUD, which shows it from the next frame.
  void ReportStageErrors();
  // The first panel's scene whose stages of one's own the driver refused, or null.
  const BuiltScene* RefusingScene() const;
  vtkActor* GlyphsOf(Slot& slot, vtkPolyData* mesh);
  vtkActor* EdgesOf(Slot& slot, vtkPolyData* mesh);

  // inspector_overlay.cxx: the texts over the panels.
  void SetUpOverlay();
  void UpdateHud();

  // inspector_keys.cxx: the key table's actions.
  bool Act(ViewAction action, int which);
  void StepMaterial(int step);
  void NextLights();
  void NextWeighting();

  // inspector_probe.cxx: the probe and its arrows.
  void ObserveClicks();
  void OnPress();
  void OnRelease();
  bool Reprobe();
  void DrawArrows();

  // inspector_command.cxx: the picture as a command.
  void CopyCommand();

  // inspector_stages.cxx: the scene's stage files, named for the driver's errors.
  SceneOptions StageNames() const;

  // inspector_tracing.cxx: the raytrace panels.
  void ShowTracing(Slot& slot, const Panel& panel);
  std::vector<double> TracedView(const Slot& slot) const;
  void FollowTracing();
  void TraceStep();

  // inspector_profile.cxx: the profile's line, drawn over the view.
  void ArmProfileLine();
  void DrawProfileLine(const int from[2], const int to[2], bool released);

  // inspector_pictures.cxx: the window's pixels read back.
  FloatImage GrabWindow();
  void RefreshDifference();
  void Screenshot();

  const ViewOptions Options; // the command line's
  std::string CommandLine;
  ViewState State;
  bool Dragging = false;
  bool FileNormals = false;    // the mesh has normals of its own: the first of `w`'s cycle
  bool FileNormalMaps = false; // a part of the mesh has its own normal map
  std::string Problem;         // the last thing that went wrong, shown in the HUD
  std::vector<InputProblem> StageProblems; // the refused stages' errors, as reported last
  OwnStages Saved;                         // what the stage files State names hold (SaveStages)
  MeshCache Meshes{ DecodingThrough(this->Writer) }; // Writer: declared below, started when used
  double Bounds[6] = {};
  vtkPoints* Points = nullptr; // the mesh's, which the camera is fitted to (held by Meshes)
  vtkIdType Triangles = 0;

  vtkNew<vtkGenericOpenGLRenderWindow> Window;
  vtkRenderWindowInteractor* Interactor = nullptr; // the Qt widget's
  vtkNew<vtkShadelabInteractorStyle> Style;
  vtkNew<vtkLightWidget> LightHandle;
  int HandleLight = -1;         // the light list's light the handle drags
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
  ShaderSources ShownShaders;
  ShaderSourceWatch ShaderWatch{ [this](const ShaderSources& s) { this->ShownShaders = s; } };
  std::optional<Pixel> ProbedPixel; // until cleared
  std::optional<PixelProbe> Probed;
  std::vector<ProbeArrow> Arrows;
  int PressAt[2] = {};
  bool PressControl = false;
  int TraceTimer = -1;     // the timer that will call TraceStep, if any
  vtkNew<vtkActor2D> Line; // the profile's, until the next or a change of the view
};
}

#endif
