#include "scene/scene.h"

#include "scene/camera.h"
#include "scene/scene_parts.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabShading.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <algorithm>

namespace shadelab
{
bool UsesVertexKd(const SceneOptions& options, vtkPolyData* mesh)
{
  return !options.OverridesKd() && mesh->GetPointData()->GetArray(ColorsArrayName);
}

std::vector<Light> EffectiveLights(const SceneOptions& options, const Vec3& cameraPosition)
{
  if (!options.Lights.empty())
  {
    return options.Lights;
  }
  Light atCamera; // the lecture: one white point light, usually at the viewpoint
  atCamera.Kind = LightKind::Point;
  atCamera.Position = cameraPosition;
  return { atCamera };
}

SurfaceTexture SceneTexture(
  const SceneOptions& options, std::shared_ptr<const TextureImage> texture)
{
  SurfaceTexture t;
  if (!options.Texture.empty() && texture)
  {
    t.Map.Image = std::move(texture);
    t.Map.WrapS = t.Map.WrapT = options.TextureWrapping;
    t.Map.Filter = options.TextureFiltering;
    t.Kd = t.Ka = true;
  }
  return t;
}

IlluminationInputs WorldIllumination(const SceneOptions& options, const std::vector<Light>& lights,
  std::shared_ptr<const TextureImage> texture)
{
  IlluminationInputs in;
  in.Surface = options.EffectiveMaterial();
  in.Texture = SceneTexture(options, std::move(texture));
  in.Ambient = options.Ambient;
  in.Model = options.ReflectionModel;
  for (const Light& light : lights)
  {
    in.Lights.push_back(ToFrame(light));
  }
  return in;
}

BuiltScene BuildScene(const SceneOptions& options, vtkPolyData* mesh, vtkRenderer* renderer,
  const BuiltScene* reuse, std::shared_ptr<const TextureImage> texture)
{
  BuiltScene scene;
  scene.Mesh = mesh;
  renderer->SetBackground(options.Background.data());
  double bounds[6];
  mesh->GetBounds(bounds);
  const double aspect = static_cast<double>(options.Size.Width) / options.Size.Height;
  vtkCamera* camera = renderer->GetActiveCamera();
  scene.Error = ApplyCamera(options, mesh->GetPoints(), aspect, camera);
  if (!scene.Error.empty())
  {
    return scene;
  }
  renderer->ResetCameraClippingRange(bounds);
  Vec3 eye;
  camera->GetPosition(eye.data());
  return BuildActor(
    options, EffectiveLights(options, eye), mesh, renderer, reuse, std::move(texture));
}

namespace
{
bool SameCoefficients(const Material& a, const Material& b)
{
  return a.Ka == b.Ka && a.Kd == b.Kd && a.Ks == b.Ks && a.Ns == b.Ns;
}

// The parts with triangles, grouped by the material they are drawn with:
// one actor per material, so that parts without their own share the default.
std::vector<std::vector<int>> PartsByMaterial(const std::vector<ScenePart>& parts)
{
  std::vector<std::vector<int>> groups;
  std::vector<const Material*> materials;
  for (const ScenePart& part : parts)
  {
    if (part.Triangles == 0)
    {
      continue;
    }
    const auto same = std::find_if(materials.begin(), materials.end(),
      [&part](const Material* m) { return SameCoefficients(*m, part.Surface); });
    if (same == materials.end())
    {
      materials.push_back(&part.Surface);
      groups.push_back({ part.Index });
    }
    else
    {
      groups[same - materials.begin()].push_back(part.Index);
    }
  }
  if (groups.empty())
  {
    groups.push_back({ 0 }); // no triangles: still one actor, as a mesh without parts has
  }
  return groups;
}
}

BuiltScene BuildActor(const SceneOptions& options, const std::vector<Light>& lights,
  vtkPolyData* mesh, vtkRenderer* renderer, const BuiltScene* reuse,
  std::shared_ptr<const TextureImage> texture)
{
  BuiltScene scene;
  scene.Mesh = mesh;
  const std::vector<ScenePart> parts = SceneParts(options, mesh);
  const std::vector<std::vector<int>> groups = PartsByMaterial(parts);
  // The same mesh, rule and grouping: every actor keeps its buffers and program.
  const bool takeOver = reuse && reuse->Mesh == mesh && !reuse->Drawn.empty() &&
    reuse->Drawn.front().Shading->GetFeatures().Rule == options.ShadingRule &&
    std::equal(groups.begin(), groups.end(), reuse->Drawn.begin(), reuse->Drawn.end(),
      [](const std::vector<int>& group, const DrawnParts& drawn) { return group == drawn.Parts; });
  scene.Texture = texture;
  const SurfaceTexture surfaceTexture = SceneTexture(options, std::move(texture));
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    DrawnParts drawn;
    drawn.Parts = groups[g];
    drawn.Shading = vtkSmartPointer<vtkShadelabShading>::New();
    drawn.Shading->SetIllumination(options.ShadingRule, options.ReflectionModel,
      parts[drawn.Parts.front()].Surface, options.Ambient, lights);
    drawn.Shading->SetVertexKd(UsesVertexKd(options, mesh));
    drawn.Shading->SetTexture(surfaceTexture);
    const vtkShadelabShading* previous = nullptr;
    if (takeOver)
    {
      drawn.Actor = reuse->Drawn[g].Actor;
      drawn.Actor->GetMapper()->RemoveObservers(vtkCommand::UpdateShaderEvent);
      previous = reuse->Drawn[g].Shading;
    }
    else
    {
      // A part's triangles share the whole mesh's points and normals, so
      // that the parts meet as the one mesh would.
      auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
      mapper->SetInputData(
        drawn.Shading->PrepareMesh(groups.size() == 1 ? vtkSmartPointer<vtkPolyData>(mesh)
                                                      : TrianglesOfParts(mesh, drawn.Parts)));
      mapper->ScalarVisibilityOff();
      drawn.Actor = vtkSmartPointer<vtkActor>::New();
      drawn.Actor->SetMapper(mapper);
    }
    renderer->AddActor(drawn.Actor);
    drawn.Shading->Attach(drawn.Actor, renderer, previous);
    scene.Drawn.push_back(drawn);
  }
  return scene;
}
}
