#include "headless/batch.h"

#include "core/errors.h"
#include "core/milliseconds.h"
#include "core/progress_bar.h"
#include "headless/headless_renderer.h"
#include "headless/shader_dump.h"
#include "image/image_writer_process.h"
#include "image/metadata.h"
#include "scene/mesh_cache.h"
#include "scene/scene.h"
#include "scene/scene_cache.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include <signal.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>

namespace shadelab
{
namespace
{
volatile std::sig_atomic_t Interrupted = 0; // the signal that asked us to stop

// SIGINT and SIGTERM set Interrupted while it lives; the old handlers come back after.
class InterruptCatcher
{
public:
  InterruptCatcher()
  {
    Interrupted = 0;
    struct sigaction action = {};
    action.sa_handler = [](int signal) { Interrupted = signal; };
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &this->OldInt);
    sigaction(SIGTERM, &action, &this->OldTerm);
  }
  ~InterruptCatcher()
  {
    sigaction(SIGINT, &this->OldInt, nullptr);
    sigaction(SIGTERM, &this->OldTerm, nullptr);
  }

private:
  struct sigaction OldInt = {}, OldTerm = {};
};

class PhaseTimer
{
public:
  explicit PhaseTimer(bool enabled)
    : Enabled(enabled)
  {
  }
  void Lap(const char* phase)
  {
    const auto now = std::chrono::steady_clock::now();
    if (this->Enabled)
    {
      std::cerr << "shadelab: " << phase << " " << Milliseconds(this->Last, now) << " ms\n";
    }
    this->Last = now;
  }

private:
  bool Enabled;
  std::chrono::steady_clock::time_point Last = std::chrono::steady_clock::now();
};
}

int RenderShots(
  const std::vector<Shot>& shots, const BatchOptions& o, const std::string& commandLine)
{
  PhaseTimer timer(o.Verbose);
  std::vector<const Shot*> mine;
  for (std::size_t i = 0; i < shots.size(); ++i)
  {
    if (static_cast<int>(i % o.ShardCount) == o.ShardIndex)
    {
      mine.push_back(&shots[i]);
    }
  }
  // One line per failure, naming the shot when there is a scene file.
  std::size_t failed = 0;
  const auto fail = [&failed](
                      const Shot& shot, const std::string& input, const std::string& problem)
  {
    ++failed;
    ReportError(shot.Label.empty() ? input : shot.Label + ": " + input, problem);
  };
  if (!o.DumpShaders.empty())
  {
    if (const std::string error = ShaderDump::PrepareFolder(o.DumpShaders); !error.empty())
    {
      return ReportError(o.DumpShaders, error);
    }
  }

  const InterruptCatcher catcher;
  ImageWriterProcess writer;     // started first: it binds OpenImageIO while we render
  const Shot* writing = nullptr; // submitted to the writer, not yet collected
  const auto collect = [&]()
  {
    if (writing)
    {
      if (const std::string error = writer.Collect(); !error.empty())
      {
        fail(*writing, writing->Output, error);
      }
      writing = nullptr;
      timer.Lap("write");
    }
  };
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
  MeshCache meshes;
  std::map<std::pair<int, int>, Context> contexts;
  ProgressBar progress(static_cast<long long>(mine.size()), o.Quiet || mine.size() < 2);
  std::size_t done = 0, skipped = 0;
  for (; done < mine.size() && !Interrupted; ++done)
  {
    const Shot& shot = *mine[done];
    progress.Show(static_cast<long long>(done), shot.Output);
    std::error_code exists;
    if (o.SkipExisting && std::filesystem::exists(shot.Output, exists))
    {
      ++skipped;
      continue;
    }
    // A scene file's output template may name folders per mesh or rule:
    // they are made as needed. A single render's folder must exist.
    std::error_code made;
    if (!shot.Label.empty() && !std::filesystem::path(shot.Output).parent_path().empty())
    {
      std::filesystem::create_directories(std::filesystem::path(shot.Output).parent_path(), made);
    }
    if (const std::string error = ImageWriterProcess::CheckFolder(shot.Output); !error.empty())
    {
      fail(shot, shot.Output, error);
      continue;
    }
    const LoadedMesh& loaded = meshes.Get(shot.Scene);
    timer.Lap("mesh");
    if (!loaded.Mesh)
    {
      fail(shot, shot.Scene.Mesh, loaded.Error);
      continue;
    }
    Context& context =
      contexts.try_emplace({ shot.Scene.Size.Width, shot.Scene.Size.Height }, meshes).first->second;
    if (!context.Renderer)
    {
      context.Renderer = std::make_unique<HeadlessRenderer>();
      if (const std::string error =
            context.Renderer->Start(shot.Scene.Size.Width, shot.Scene.Size.Height);
          !error.empty())
      {
        context.Renderer.reset();
        fail(shot, "render", error);
        continue;
      }
      timer.Lap("context");
    }
    HeadlessRenderer& renderer = *context.Renderer;
    // Another mesh: the previous one's buffers go.
    context.Scenes.ForgetOtherMeshes(loaded.Mesh, renderer.GetRenderer());
    const SceneCache::Shown shown = context.Scenes.Show(shot.Scene, renderer.GetRenderer());
    if (!shown.Scene)
    {
      fail(shot, shown.Input, shown.Error);
      continue;
    }
    std::unique_ptr<ShaderDump> dump;
    if (!o.DumpShaders.empty())
    {
      dump = std::make_unique<ShaderDump>(shown.Scene->Actor->GetMapper(), o.DumpShaders,
        std::string(ToString(shot.Scene.ShadingRule)) + "-" + ToString(shot.Scene.ReflectionModel));
    }
    const FloatImage image = renderer.Render();
    timer.Lap("frame");
    if (!renderer.GetError().empty())
    {
      fail(shot, "render", renderer.GetError());
      continue;
    }
    if (dump && !dump->GetError().empty())
    {
      fail(shot, dump->GetErrorFile(), dump->GetError());
      continue;
    }
    const auto metadata = DescribePicture(
      commandLine, shot.Scene, renderer.GetRenderer()->GetActiveCamera(), shot.Label);
    collect(); // the previous picture, encoded while this one rendered
    if (const std::string error = writer.Submit(shot.Output, image, shot.Pixels, metadata);
        !error.empty())
    {
      fail(shot, shot.Output, error);
      continue;
    }
    writing = &shot;
  }
  collect();
  progress.Finish();
  if (Interrupted)
  {
    std::cerr << "shadelab: interrupted (" << (Interrupted == SIGINT ? "SIGINT" : "SIGTERM")
              << ") after " << done << " of " << mine.size()
              << " shots: " << done - failed - skipped << " written, " << skipped << " skipped, "
              << failed << " failed; every picture there is whole; --skip-existing renders the rest"
              << std::endl;
    return 128 + Interrupted;
  }
  if (failed > 0 && mine.size() > 1)
  {
    std::cerr << "shadelab: " << failed << " of " << mine.size() << " shots failed" << std::endl;
  }
  return failed > 0 ? ExitFailure : 0;
}
}
