#include "scene/scene.h"

#include "scene/camera.h"
#include "shadelabMeshTriangles.h"
#include "shadelabShadowCasters.h"
#include "shadelabTriangleMesh.h"
#include "vtkShadelabPolyDataMapper.h"
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

std::vector<Light> ResolvedLights(std::vector<Light> lights, const SceneOptions& options)
{
  for (Light& light : lights)
  {
    if (GeometryOf(light.Kind).Position)
    {
      light.Attenuation = light.Attenuation.value_or(options.Attenuation);
    }
    // Shadows are global illumination's own: ray traced, every light casts.
    light.Shadows =
      light.Shadows.value_or(options.Shadows || options.ShadingRule == Shading::Raytrace);
  }
  return lights;
}

std::vector<Light> EffectiveLights(const SceneOptions& options, const Vec3& cameraPosition)
{
  if (!options.Lights.empty())
  {
    return ResolvedLights(options.Lights, options);
  }
  Light atCamera; // the lecture: one white point light, usually at the viewpoint
  atCamera.Kind = LightKind::Point;
  atCamera.Position = cameraPosition;
  return ResolvedLights({ atCamera }, options);
}

IlluminationInputs WorldIllumination(const SceneOptions& options, const std::vector<Light>& lights)
{
  IlluminationInputs in;
  in.Surface = options.EffectiveMaterial();
  in.Ambient = options.Ambient;
  in.Model = options.ReflectionModel;
  for (const Light& light : lights)
  {
    in.Lights.push_back(ToFrame(light));
  }
  return in;
}

IlluminationInputs CameraIllumination(
  const SceneOptions& options, const std::vector<Light>& lights, vtkCamera* camera)
{
  IlluminationInputs in = WorldIllumination(options, lights);
  in.Orthographic = camera->GetParallelProjection();
  camera->GetPosition(in.Eye.data());
  camera->GetDirectionOfProjection(in.ViewDirection.data());
  return in;
}

BuiltScene BuildScene(const SceneOptions& options, vtkPolyData* mesh, vtkRenderer* renderer,
  const BuiltScene* reuse, const SceneImages& images, const OwnStages& stages)
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
  return BuildActor(options, EffectiveLights(options, eye), mesh, renderer, reuse, images, stages);
}

namespace
{
bool SameRelief(const std::optional<NormalMap>& a, const std::optional<NormalMap>& b)
{
  return a.has_value() == b.has_value() &&
    (!a ||
      (a->Map.Image == b->Map.Image && a->Map.WrapS == b->Map.WrapS &&
        a->Map.WrapT == b->Map.WrapT && a->Map.Filter == b->Map.Filter && a->Scale == b->Scale));
}

// Whether two parts are drawn alike: the same coefficients, texture and normal map.
bool SameLook(const ScenePart& a, const ScenePart& b)
{
  const Material &m = a.Surface, &n = b.Surface;
  const SurfaceTexture &t = a.Texture, &u = b.Texture;
  return m.Ka == n.Ka && m.Kd == n.Kd && m.Ks == n.Ks && m.Ns == n.Ns &&
    m.Translucency == n.Translucency && t.Kd == u.Kd && t.Ka == u.Ka &&
    t.Map.Image == u.Map.Image && t.Map.WrapS == u.Map.WrapS && t.Map.WrapT == u.Map.WrapT &&
    t.Map.Filter == u.Map.Filter && SameRelief(a.Relief, b.Relief);
}

// The parts with triangles, grouped by the material and texture they are
// drawn with: one actor per look, so that parts without their own material
// share the default.
std::vector<std::vector<int>> PartsByLook(const std::vector<ScenePart>& parts)
{
  std::vector<std::vector<int>> groups;
  std::vector<const ScenePart*> looks;
  for (const ScenePart& part : parts)
  {
    if (part.Triangles == 0)
    {
      continue;
    }
    const auto same = std::find_if(
      looks.begin(), looks.end(), [&part](const ScenePart* p) { return SameLook(*p, part); });
    if (same == looks.end())
    {
      looks.push_back(&part);
      groups.push_back({ part.Index });
    }
    else
    {
      groups[same - looks.begin()].push_back(part.Index);
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
  vtkPolyData* mesh, vtkRenderer* renderer, const BuiltScene* reuse, const SceneImages& images,
  const OwnStages& stages)
{
  BuiltScene scene;
  scene.Mesh = mesh;
  const std::vector<Light> resolved = ResolvedLights(lights, options);
  const std::vector<ScenePart> parts = SceneParts(options, mesh, images);
  const std::vector<std::vector<int>> groups = PartsByLook(parts);
  // The same mesh, rule and grouping: every actor keeps its buffers and program.
  const bool takeOver = reuse && reuse->Mesh == mesh && !reuse->Drawn.empty() &&
    reuse->Drawn.front().Shading->GetFeatures().Rule == options.ShadingRule &&
    std::equal(groups.begin(), groups.end(), reuse->Drawn.begin(), reuse->Drawn.end(),
      [](const std::vector<int>& group, const DrawnParts& drawn) { return group == drawn.Parts; });
  scene.Images = images;
  // Every triangle casts, whichever actor draws it (the actors draw the
  // mesh where it is: world coordinates).
  std::shared_ptr<ShadowCasters>& casters = scene.Casters;
  // Ray traced, its rays cast the shadows: the shaders draw no maps.
  if (options.ShadingRule != Shading::Raytrace &&
    std::any_of(resolved.begin(), resolved.end(), CastsShadows))
  {
    casters = reuse && reuse->Casters && reuse->Mesh == mesh &&
        reuse->Casters->GetSize() == options.ShadowMapSize
      ? reuse->Casters
      : std::make_shared<ShadowCasters>(PointsOf(mesh), TrianglesOf(mesh), options.ShadowMapSize);
  }
  for (std::size_t g = 0; g < groups.size(); ++g)
  {
    DrawnParts drawn;
    drawn.Parts = groups[g];
    drawn.Shading = vtkSmartPointer<vtkShadelabShading>::New();
    drawn.Shading->SetIllumination(options.ShadingRule, options.ReflectionModel,
      parts[drawn.Parts.front()].Surface, options.Ambient, resolved);
    drawn.Shading->SetVertexKd(UsesVertexKd(options, mesh));
    drawn.Shading->SetTexture(parts[drawn.Parts.front()].Texture);
    drawn.Shading->SetEnvironment(SceneEnvironment(options, images));
    drawn.Shading->SetNormalMap(parts[drawn.Parts.front()].Relief);
    drawn.Shading->SetBehindLines(options.Edges || options.NormalGlyphs);
    drawn.Shading->SetFog(options.Fogging, options.OpaqueBackground());
    drawn.Shading->SetRepresentation(options.Drawn, options.LineWidth, options.PointSize);
    drawn.Shading->SetShadows(casters);
    drawn.Shading->SetSpecularForm(options.Form);
    drawn.Shading->SetOwnStages(stages);
    const vtkShadelabShading* previous = nullptr;
    if (takeOver)
    {
      drawn.Actor = reuse->Drawn[g].Actor;
      previous = reuse->Drawn[g].Shading;
    }
    else
    {
      // A part's triangles share the whole mesh's points and normals, so
      // that the parts meet as the one mesh would.
      auto mapper = vtkSmartPointer<vtkShadelabPolyDataMapper>::New();
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
