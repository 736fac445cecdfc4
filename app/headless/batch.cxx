#include "headless/batch.h"

#include "core/errors.h"
#include "core/exit_without_teardown.h"
#include "core/heap_policy.h"
#include "core/interruption.h"
#include "core/phase_timer.h"
#include "core/progress_bar.h"
#include "headless/headless_renderer.h"
#include "headless/scene_frame.h"
#include "headless/shader_dump.h"
#include "image/image_writer_process.h"
#include "image/metadata.h"
#include "scene/camera.h"
#include "scene/mesh_cache.h"
#include "scene/overlays.h"
#include "scene/own_stage_files.h"
#include "scene/scene.h"
#include "scene/scene_cache.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <deque>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <tuple>
#include <utility>

namespace shadelab
{
namespace
{
// How many pictures may be with the writer, submitted and not collected:
// enough that encoding (one thread a picture in the writer) keeps pace with
// rendering on two cores; each holds its pixels, so few (doc/benchmarks-log.md,
// "Many shots").
constexpr std::size_t PicturesInFlight = 3;

// Where a shot's pictures go in its file: every frame of an animation, or one.
FramePlace FramesOf(const Shot& shot)
{
  return { 0, static_cast<std::uint32_t>(shot.Animation ? shot.Scene.Orbit : 1),
    shot.Scene.FramesPerSecond };
}

// Per picture size: one context, and the scenes built in it for the
// current mesh, one per rule, whose actors keep their uploaded buffers.
struct Context
{
  explicit Context(MeshCache& meshes)
    : Scenes(meshes)
  {
  }
  std::unique_ptr<HeadlessRenderer> Renderer;
  SceneCache Scenes;
};

// The shots of one batch, each rendered in its size's context and handed
// to the writer, which encodes it while the next one renders.
class Batch
{
public:
  Batch(const BatchOptions& o, const std::string& commandLine)
    : Options(o)
    , CommandLine(commandLine)
    , Timer(o.Verbose)
  {
  }

  // One shot: skipped, failed (and reported) or submitted to the writer.
  void Run(const Shot& shot)
  {
    std::error_code exists;
    if (this->Options.SkipExisting && std::filesystem::exists(shot.Output, exists))
    {
      ++this->Skipped;
      return;
    }
    if (!this->PrepareFolder(shot))
    {
      return;
    }
    const LoadedMesh& loaded = this->Meshes.Get(shot.Scene); // times "read" and "normals"
    if (!loaded.Mesh)
    {
      this->Fail(shot, shot.Scene.Mesh, loaded.Error);
      return;
    }
    Context* context = this->ContextFor(shot);
    if (!context)
    {
      return;
    }
    HeadlessRenderer& renderer = *context->Renderer;
    // Another mesh: the previous one's buffers go.
    context->Scenes.ForgetOtherMeshes(loaded.Mesh, renderer.GetRenderer());
    // An animation's frames, each handed to the writer as the next renders.
    for (FramePlace frame = FramesOf(shot); frame.Index < frame.Count; ++frame.Index)
    {
      if (frame.Index > 0 && Interruption())
      {
        this->FailFrame(shot, frame, shot.Output, "interrupted before its last frame: not written");
        return;
      }
      const SceneOptions scene =
        shot.Animation ? OrbitFrame(shot.Scene, static_cast<int>(frame.Index)) : shot.Scene;
      const SceneCache::Shown shown = context->Scenes.Show(scene, renderer.GetRenderer());
      if (!shown.Scene)
      {
        this->FailFrame(shot, frame, shown.Input, shown.Error);
        return;
      }
      if (!this->RenderAndSubmit(shot, scene, frame, *shown.Scene, renderer))
      {
        return;
      }
    }
  }

  // The last pictures, written.
  void Finish() { (void)this->CollectUntil(0); }

  std::size_t Failed = 0, Skipped = 0;

private:
  // One line per failure (per error of a shader stage), naming the shot
  // when there is a scene file.
  void Fail(const Shot& shot, const std::vector<InputProblem>& problems)
  {
    ++this->Failed;
    for (const auto& [input, problem] : problems)
    {
      ReportError(shot.Label.empty() ? input : shot.Label + ": " + input, problem);
    }
  }
  void Fail(const Shot& shot, const std::string& input, const std::string& problem)
  {
    this->Fail(shot, { { input, problem } });
  }

  // A shot that fails at one of its frames: the frame before, still with
  // the writer, is collected first, so that a shot fails once.
  void FailFrame(
    const Shot& shot, const FramePlace& frame, const std::vector<InputProblem>& problems)
  {
    if (frame.Index == 0 || this->CollectUntil(0))
    {
      this->Fail(shot, problems);
    }
  }
  void FailFrame(
    const Shot& shot, const FramePlace& frame, const std::string& input, const std::string& problem)
  {
    this->FailFrame(shot, frame, { { input, problem } });
  }

  // An output template (a scene file's, or many meshes') may name folders
  // per mesh or rule: they are made as needed. A single render's folder must
  // exist.
  bool PrepareFolder(const Shot& shot)
  {
    const std::filesystem::path folder = std::filesystem::path(shot.Output).parent_path();
    std::error_code made;
    if (shot.MakeFolders && !folder.empty() && !std::filesystem::create_directories(folder, made) &&
      made)
    {
      // Why it could not be made (a read-only file system, say), rather than
      // what that left: no folder.
      this->Fail(
        shot, shot.Output, "cannot make the folder " + folder.string() + ": " + made.message());
      return false;
    }
    if (const std::string error = ImageWriterProcess::CheckFolder(shot.Output); !error.empty())
    {
      this->Fail(shot, shot.Output, error);
      return false;
    }
    return true;
  }

  // The context for the shot's picture size and supersampling, started on
  // first use; null (and reported) when it cannot start.
  Context* ContextFor(const Shot& shot)
  {
    const SceneOptions& s = shot.Scene;
    ImageSize rendered;
    if (const std::string error = RenderedSize(s, rendered); !error.empty())
    {
      this->Fail(shot, "render", error);
      return nullptr;
    }
    Context& context =
      this->Contexts.try_emplace({ s.Size.Width, s.Size.Height, s.Supersampling }, this->Meshes)
        .first->second;
    if (!context.Renderer)
    {
      context.Renderer = std::make_unique<HeadlessRenderer>();
      if (const std::string error =
            context.Renderer->Start(s.Size.Width, s.Size.Height, s.Supersampling);
          !error.empty())
      {
        context.Renderer.reset();
        this->Fail(shot, "render", error);
        return nullptr;
      }
      this->Timer.Lap("context");
    }
    return &context;
  }

  // Renders the shot's picture (scene, its frame) and submits it; false
  // when the shot failed (and was reported).
  bool RenderAndSubmit(const Shot& shot, const SceneOptions& options, const FramePlace& frame,
    const BuiltScene& scene, HeadlessRenderer& renderer)
  {
    std::unique_ptr<ShaderDump> dump;
    if (!this->Options.DumpShaders.empty())
    {
      // The first material's program: the others differ at most in their specular code.
      dump = std::make_unique<ShaderDump>(scene.Drawn.front().Actor->GetMapper(),
        this->Options.DumpShaders,
        std::string(ToString(options.ShadingRule)) + "-" + ToString(options.ReflectionModel));
    }
    if (auto [input, error] = RayTraceProblem(options); !error.empty())
    {
      this->FailFrame(shot, frame, input, error);
      return false;
    }
    const SceneOverlays overlays(options, scene.Mesh, this->Meshes, renderer.GetRenderer());
    renderer.SetMaximumNumberOfPeels(options.Peels);
    // An 8-bit file's picture is rendered in 8 bits, the same bytes for less;
    // a ray-traced one is quantised by the writer, as a float one is.
    // So is one laid over the environment, in float.
    const bool eightBit = ResolvePixelType(shot.Output, shot.Scene.Pixels) == PixelType::UInt8 &&
      options.ShadingRule != Shading::Raytrace && !options.EnvironmentBackground;
    FloatImage image;
    Image8 image8;
    std::string error;
    if (eightBit)
    {
      image8 = renderer.RenderEightBit(options.TransparentBackground);
      error = renderer.GetError();
    }
    else
    {
      error = SceneFrame(options, scene, renderer, image);
      image.Alpha = options.TransparentBackground;
    }
    this->Timer.Lap("frame");
    if (!error.empty())
    {
      this->FailFrame(shot, frame, "render", error);
      return false;
    }
    // Stages of one's own that the driver refused drew nothing: no picture.
    if (const std::vector<InputProblem> refused = StageErrorLines(options, scene); !refused.empty())
    {
      this->FailFrame(shot, frame, refused);
      return false;
    }
    if (dump && !dump->GetError().empty())
    {
      this->FailFrame(shot, frame, dump->GetErrorFile(), dump->GetError());
      return false;
    }
    const auto metadata = DescribePicture(this->CommandLine, options,
      renderer.GetRenderer()->GetActiveCamera(), scene.Mesh, shot.Label);
    // Pictures encoded while this one rendered. An animation's frames go
    // one at a time: its previous frame's failure ends the shot. Other
    // pictures are encoded beside each other, a few at a time.
    const bool collected =
      this->CollectUntil(frame.Count > 1 ? 0 : PicturesInFlight - 1) || frame.Index == 0;
    if (!collected)
    {
      return false;
    }
    if (const std::string error = eightBit
          ? this->Writer.Submit(shot.Output, std::move(image8), metadata, frame)
          : this->Writer.Submit(shot.Output, image, shot.Scene.Pixels, metadata, frame);
        !error.empty())
    {
      this->Fail(shot, shot.Output, error);
      return false;
    }
    this->Writing.push_back(&shot);
    return true;
  }

  // The pictures submitted before, oldest first, once the writer has
  // written them (or taken them, an animation's frames), until at most
  // `left` are in flight; false when the last one collected failed (and was
  // reported), each failure for its own shot.
  bool CollectUntil(std::size_t left)
  {
    bool written = true;
    for (; this->Writing.size() > left; this->Writing.pop_front())
    {
      const std::string error = this->Writer.Collect();
      if (!error.empty())
      {
        this->Fail(*this->Writing.front(), this->Writing.front()->Output, error);
      }
      written = error.empty();
      // -v's "write": for one shot its writing, in a batch the wait for it.
      this->Timer.Lap("write");
    }
    return written;
  }

  const BatchOptions& Options;
  const std::string& CommandLine;
  PhaseTimer Timer;
  ImageWriterProcess Writer;       // started first: it binds OpenImageIO while we render
  std::deque<const Shot*> Writing; // submitted to the writer, not yet collected, oldest first
  MeshCache Meshes{ DecodingThrough(this->Writer), &this->Timer };
  std::map<std::tuple<int, int, int>, Context> Contexts; // width, height, supersampling
};

// This shard's shots: those whose index mod the count is the shard's index.
std::vector<const Shot*> ShardOf(const std::vector<Shot>& shots, const BatchOptions& o)
{
  std::vector<const Shot*> mine;
  for (std::size_t i = 0; i < shots.size(); ++i)
  {
    if (static_cast<int>(i % o.ShardCount) == o.ShardIndex)
    {
      mine.push_back(&shots[i]);
    }
  }
  return mine;
}
}

int RenderShots(
  const std::vector<Shot>& shots, const BatchOptions& o, const std::string& commandLine)
{
  const std::vector<const Shot*> mine = ShardOf(shots, o);
  if (!o.DumpShaders.empty())
  {
    if (const std::string error = ShaderDump::PrepareFolder(o.DumpShaders); !error.empty())
    {
      return ReportError(o.DumpShaders, error);
    }
  }
  // Before anything renders: what a shot's file format needs besides a picture.
  for (const Shot* shot : mine)
  {
    if (const std::string error = ImageWriterProcess::CheckEncoder(shot->Output, FramesOf(*shot));
        !error.empty())
    {
      return ReportError(shot->Output, error);
    }
  }
  // A picture's float read-back (33 MB at 1080p) is larger than glibc's
  // largest mmap threshold, so each came from fresh pages, faulted in and
  // zeroed, and went back on free: with the 8-bit pixels sent, a quarter of
  // a 1080p batch's CPU time in the kernel. Kept in the heap instead, the
  // next picture reuses them (doc/benchmarks-log.md, "Many shots"); so do an 8-bit
  // file's smaller buffers from the start. Only up to the
  // largest picture: a large mesh's arrays stay mapped, so that each goes
  // back to the system when freed rather than raising the heap's peak.
  std::size_t largestPicture = 0;
  for (const Shot* shot : mine)
  {
    if (ImageSize rendered; RenderedSize(shot->Scene, rendered).empty())
    {
      largestPicture = std::max(largestPicture,
        static_cast<std::size_t>(rendered.Width) * rendered.Height * 4 * sizeof(float));
    }
  }
  KeepBlocksInHeapUpTo(largestPicture + (std::size_t{ 1 } << 20));
  Batch batch(o, commandLine);
  ProgressBar progress(static_cast<long long>(mine.size()), o.Quiet || mine.size() < 2);
  std::size_t done = 0;
  for (; done < mine.size() && !Interruption(); ++done)
  {
    progress.Show(static_cast<long long>(done), mine[done]->Output);
    batch.Run(*mine[done]);
  }
  batch.Finish();
  progress.Finish();
  if (const int signal = Interruption())
  {
    std::cerr << "shadelab: interrupted (" << SignalName(signal) << ") after " << done << " of "
              << mine.size() << " shots: " << done - batch.Failed - batch.Skipped << " written, "
              << batch.Skipped << " skipped, " << batch.Failed
              << " failed; every picture there is whole; --skip-existing renders the rest"
              << std::endl;
    return 128 + signal;
  }
  if (batch.Failed > 0 && mine.size() > 1)
  {
    std::cerr << "shadelab: " << batch.Failed << " of " << mine.size() << " shots failed"
              << std::endl;
  }
  if (batch.Failed > 0)
  {
    return ExitFailure;
  }
  // Every picture is on disk and answered for: nothing is left but freeing.
  return ExitWithoutTeardown(0);
}
}
