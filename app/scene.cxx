#include "scene.h"

#include "camera.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

namespace shadelab
{
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

namespace
{
// VTK's own lighting stands in until the lecture's shaders (issue 3): it
// lights with the reflect-vector Phong term and ignores the renderer's
// ambient light, so Ia is folded into the ambient colour here.
void ApplyMaterial(const SceneOptions& options, vtkProperty* property)
{
  const Material m = options.EffectiveMaterial();
  if (options.ShadingRule == Shading::None)
  {
    // One fixed colour, no illumination: the diffuse colour, unlit.
    property->LightingOff();
    property->SetAmbient(0);
    property->SetDiffuse(1);
    property->SetDiffuseColor(m.Kd.data());
    property->SetSpecular(0);
    return;
  }
  property->SetInterpolation(options.ShadingRule == Shading::Flat ? VTK_FLAT
      : options.ShadingRule == Shading::Gouraud                   ? VTK_GOURAUD
                                                                  : VTK_PHONG);
  const double ambient[3] = { m.Ka[0] * options.Ambient[0], m.Ka[1] * options.Ambient[1],
    m.Ka[2] * options.Ambient[2] };
  property->SetAmbient(1);
  property->SetAmbientColor(ambient);
  property->SetDiffuse(1);
  property->SetDiffuseColor(m.Kd.data());
  property->SetSpecular(1);
  property->SetSpecularColor(m.Ks.data());
  property->SetSpecularPower(m.Ns);
}

vtkSmartPointer<vtkLight> ToVtkLight(const Light& light)
{
  auto l = vtkSmartPointer<vtkLight>::New();
  l->SetLightTypeToSceneLight();
  l->SetColor(light.Color.data());
  l->SetIntensity(1);
  switch (light.Kind)
  {
    case LightKind::Point:
      l->PositionalOn();
      l->SetConeAngle(180);
      l->SetPosition(light.Position.data());
      l->SetFocalPoint(light.Position[0], light.Position[1], light.Position[2] - 1);
      break;
    case LightKind::Directional:
      l->PositionalOff();
      l->SetPosition(0, 0, 0);
      l->SetFocalPoint(light.Direction.data());
      break;
    case LightKind::Spot:
      l->PositionalOn();
      l->SetPosition(light.Position.data());
      l->SetFocalPoint(light.Position[0] + light.Direction[0],
        light.Position[1] + light.Direction[1], light.Position[2] + light.Direction[2]);
      l->SetConeAngle(light.HalfAngleDeg);
      l->SetExponent(light.Exponent);
      break;
  }
  l->SetAttenuationValues(1, 0, 0); // no distance attenuation
  return l;
}
}

std::string BuildScene(const SceneOptions& options, vtkPolyData* mesh, vtkRenderer* renderer)
{
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(mesh);
  mapper->ScalarVisibilityOff();
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  ApplyMaterial(options, actor->GetProperty());
  renderer->AddActor(actor);
  renderer->SetBackground(options.Background.data());

  double bounds[6];
  mesh->GetBounds(bounds);
  const double aspect = static_cast<double>(options.Size.Width) / options.Size.Height;
  vtkCamera* camera = renderer->GetActiveCamera();
  const std::string error = ApplyCamera(options, bounds, aspect, camera);
  if (!error.empty())
  {
    return error;
  }
  renderer->ResetCameraClippingRange(bounds);

  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  renderer->TwoSidedLightingOn();
  Vec3 eye;
  camera->GetPosition(eye.data());
  for (const Light& light : EffectiveLights(options, eye))
  {
    renderer->AddLight(ToVtkLight(light));
  }
  return {};
}
}
