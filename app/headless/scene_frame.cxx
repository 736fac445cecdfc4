#include "headless/scene_frame.h"

#include "headless/headless_renderer.h"
#include "raytrace/ray_tracer.h"
#include "scene/scene_parts.h"

#include <vtkRenderer.h>

namespace shadelab
{
std::pair<std::string, std::string> RayTraceProblem(const SceneOptions& options)
{
  if (options.ShadingRule != Shading::Raytrace)
  {
    return {};
  }
  const auto refused = [](const std::string& option) {
    return std::pair{ option, "--shading raytrace traces the surface alone, without it" };
  };
  if (options.Drawn != Representation::Surface)
  {
    return refused(std::string("--representation ") + ToString(options.Drawn));
  }
  if (options.Edges)
  {
    return refused("--edges");
  }
  if (options.NormalGlyphs)
  {
    return refused("--normal-glyphs");
  }
  if (!options.Environment.empty())
  {
    return { options.Environment,
      "--shading raytrace reflects the mesh by its rays, not an environment map" };
  }
  if (const auto& relief = options.Relief())
  {
    return { relief->Image,
      std::string("--shading raytrace reflects its rays about the mesh's "
                  "normals, not a ") +
        (options.BumpMap ? "bump map's" : "normal map's") };
  }
  for (const std::string* stage : { &options.VertexShader, &options.FragmentShader })
  {
    if (!stage->empty())
    {
      return { *stage, "--shading raytrace traces rays on the CPU and runs no shader stage" };
    }
  }
  return {};
}

std::string SceneFrame(const SceneOptions& options, const BuiltScene& scene,
  HeadlessRenderer& renderer, FloatImage& frame)
{
  if (options.ShadingRule != Shading::Raytrace)
  {
    const std::optional<EnvironmentMap> behind =
      options.EnvironmentBackground ? SceneEnvironment(options, scene.Images) : std::nullopt;
    frame = renderer.Render(behind ? &*behind : nullptr);
    return renderer.GetError();
  }
  const RayTracer tracer(
    options, scene.Mesh, renderer.GetRenderer()->GetActiveCamera(), scene.Images);
  frame = tracer.Picture(options.Supersampling);
  return {};
}
}
