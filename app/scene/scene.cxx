#include "scene/scene.h"

#include "scene/camera.h"
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

BuiltScene BuildActor(const SceneOptions& options, const std::vector<Light>& lights,
  vtkPolyData* mesh, vtkRenderer* renderer, const BuiltScene* reuse,
  std::shared_ptr<const TextureImage> texture)
{
  BuiltScene scene;
  scene.Mesh = mesh;
  scene.Shading = vtkSmartPointer<vtkShadelabShading>::New();
  scene.Shading->SetIllumination(options.ShadingRule, options.ReflectionModel,
    options.EffectiveMaterial(), options.Ambient, lights);
  scene.Shading->SetVertexKd(UsesVertexKd(options, mesh));
  scene.Texture = texture;
  scene.Shading->SetTexture(SceneTexture(options, std::move(texture)));
  const vtkShadelabShading* previous = nullptr;
  if (reuse && reuse->Actor && reuse->Mesh == mesh &&
    reuse->Shading->GetFeatures().Rule == options.ShadingRule)
  {
    scene.Actor = reuse->Actor;
    scene.Actor->GetMapper()->RemoveObservers(vtkCommand::UpdateShaderEvent);
    previous = reuse->Shading;
  }
  else
  {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(scene.Shading->PrepareMesh(mesh));
    mapper->ScalarVisibilityOff();
    scene.Actor = vtkSmartPointer<vtkActor>::New();
    scene.Actor->SetMapper(mapper);
  }
  renderer->AddActor(scene.Actor);
  scene.Shading->Attach(scene.Actor, renderer, previous);
  return scene;
}
}
