#include "vtkShadelabShading.h"

#include "shadelabShadowCasters.h"
#include "shadelabTriangleMesh.h"
#include "shadelabVertexTangents.h"
#include "vtkShadelabPolyDataMapper.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkLight.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkOpenGLShaderProperty.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <vector>

vtkStandardNewMacro(vtkShadelabShading);

using namespace shadelab;

namespace
{
// The light's kind as the all-features program's shadelabLightKind codes it.
int KindCode(LightKind kind)
{
  switch (kind)
  {
    case LightKind::Point:
      return 0;
    case LightKind::Directional:
      return 1;
    case LightKind::Spot:
      return 2;
  }
  return 0;
}
}

vtkShadelabShading::vtkShadelabShading()
  : Observer(vtkSmartPointer<vtkCallbackCommand>::New())
{
  this->Observer->SetClientData(this);
  this->Observer->SetCallback(
    [](vtkObject*, unsigned long, void* self, void* program) {
      static_cast<vtkShadelabShading*>(self)->SetUniforms(static_cast<vtkShaderProgram*>(program));
    });
}

vtkShadelabShading::~vtkShadelabShading()
{
  if (this->Actor && this->Actor->GetMapper())
  {
    this->Actor->GetMapper()->RemoveObserver(this->Observer);
  }
}

void vtkShadelabShading::SetIllumination(Shading rule, Reflection model, const Material& material,
  const Rgb& ambient, const std::vector<Light>& lights)
{
  this->Features.Rule = rule;
  this->Features.Model = model;
  this->Features.Lights.clear();
  for (const Light& light : lights)
  {
    this->Features.Lights.push_back(light.Kind);
  }
  this->Features.Attenuation = std::any_of(lights.begin(), lights.end(), Attenuated);
  this->Features.Specular = material.Ks[0] != 0 || material.Ks[1] != 0 || material.Ks[2] != 0;
  this->Features.Translucent = material.Translucency < 1;
  this->Surface = material;
  this->Ambient = ambient;
  this->Lights = lights;
  this->UpdateShadowFeatures();
  this->Modified();
}

void vtkShadelabShading::SetShadows(std::shared_ptr<ShadowCasters> casters)
{
  this->Casters = std::move(casters);
  this->UpdateShadowFeatures();
  this->Modified();
}

void vtkShadelabShading::UpdateShadowFeatures()
{
  this->Features.Shadows.clear();
  if (this->Casters && std::any_of(this->Lights.begin(), this->Lights.end(), CastsShadows))
  {
    std::transform(this->Lights.begin(), this->Lights.end(),
      std::back_inserter(this->Features.Shadows), CastsShadows);
  }
}

bool vtkShadelabShading::SetShadingRuleByName(const char* name)
{
  const auto rule = FromName<Shading>(name ? name : "");
  if (rule)
  {
    this->SetIllumination(*rule, this->Features.Model, this->Surface, this->Ambient, this->Lights);
  }
  return rule.has_value();
}

bool vtkShadelabShading::SetReflectionModelByName(const char* name)
{
  const auto model = FromName<Reflection>(name ? name : "");
  if (model)
  {
    this->SetIllumination(this->Features.Rule, *model, this->Surface, this->Ambient, this->Lights);
  }
  return model.has_value();
}

bool vtkShadelabShading::SetMaterialByName(const char* name)
{
  const Material* material = FindLectureMaterial(name ? name : "");
  if (material)
  {
    this->SetIllumination(
      this->Features.Rule, this->Features.Model, *material, this->Ambient, this->Lights);
  }
  return material != nullptr;
}

void vtkShadelabShading::SetAmbientIntensity(double red, double green, double blue)
{
  this->SetIllumination(this->Features.Rule, this->Features.Model, this->Surface,
    Rgb{ red, green, blue }, this->Lights);
}

void vtkShadelabShading::AddPointLight(double x, double y, double z)
{
  Light light;
  light.Kind = LightKind::Point;
  light.Position = { x, y, z };
  this->AddLight(light);
}

void vtkShadelabShading::AddDirectionalLight(double x, double y, double z)
{
  Light light;
  light.Kind = LightKind::Directional;
  light.Direction = { x, y, z };
  this->AddLight(light);
}

void vtkShadelabShading::AddLight(const Light& light)
{
  auto lights = this->Lights;
  lights.push_back(light);
  this->SetIllumination(
    this->Features.Rule, this->Features.Model, this->Surface, this->Ambient, lights);
}

void vtkShadelabShading::RemoveAllLights()
{
  this->SetIllumination(
    this->Features.Rule, this->Features.Model, this->Surface, this->Ambient, {});
}

void vtkShadelabShading::SetLightPlacement(const std::vector<Light>& lights)
{
  const bool sameKinds = lights.size() == this->Lights.size() &&
    std::equal(lights.begin(), lights.end(), this->Lights.begin(),
      [](const Light& a, const Light& b)
      { return a.Kind == b.Kind && CastsShadows(a) == CastsShadows(b); }) &&
    std::any_of(lights.begin(), lights.end(), Attenuated) == this->Features.Attenuation;
  if (!sameKinds)
  {
    vtkErrorMacro(
      "SetLightPlacement: other kinds of lights, attenuation or shadows need SetIllumination");
    return;
  }
  this->Lights = lights;
}

void vtkShadelabShading::SetVertexKd(bool fromColors)
{
  this->Features.VertexKd = fromColors;
  this->Modified();
}

void vtkShadelabShading::SetTexture(const SurfaceTexture& texture)
{
  this->Texture = texture;
  this->Features.KdTexture = texture.Used() && texture.Kd;
  this->Features.KaTexture = texture.Used() && texture.Ka;
  this->Features.KsTexture = texture.Used() && texture.Ks;
  this->Modified();
}

void vtkShadelabShading::SetEnvironment(const std::optional<EnvironmentMap>& environment)
{
  this->Environment = environment;
  this->Features.Environment = environment.has_value();
  this->Modified();
}

void vtkShadelabShading::SetNormalMap(const std::optional<NormalMap>& map)
{
  this->Relief = map;
  this->Features.NormalMap = map.has_value();
  this->Features.BumpMap = map && map->Height;
  this->Modified();
}

void vtkShadelabShading::SetFog(const Fog& fog, const std::optional<Rgb>& background)
{
  this->Features.Fog = fog.Mode;
  this->Features.FogTowardsTransparent = fog.Mode != FogMode::None && !fog.Color && !background;
  this->FogSetting = fog;
  this->FogColour = fog.Color.value_or(background.value_or(Rgb{}));
  this->Modified();
}

void vtkShadelabShading::SetRepresentation(Representation drawn, double lineWidth, double pointSize)
{
  this->Features.Drawn = drawn;
  this->LineWidth = lineWidth;
  this->PointSize = pointSize;
  this->Modified();
}

void vtkShadelabShading::SetBehindLines(bool behind)
{
  this->Features.BehindLines = behind;
  this->Modified();
}

void vtkShadelabShading::SetSpecularForm(SpecularForm form)
{
  this->Features.Form = form;
  this->Modified();
}

void vtkShadelabShading::SetAllFeatures(bool all)
{
  this->Features.AllFeatures = all;
  this->Modified();
}

vtkSmartPointer<vtkPolyData> vtkShadelabShading::PrepareMesh(vtkPolyData* mesh) const
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(mesh);
  if (this->Features.Rule == Shading::Flat && this->Features.Drawn == Representation::Points)
  {
    // VTK 9.1 gives points the view-position plumbing flat needs only when
    // they have point normals (GetNeedToRebuildShaders): unused zeros then.
    if (!copy->GetPointData()->GetNormals())
    {
      auto zeros = vtkSmartPointer<vtkFloatArray>::New();
      zeros->SetNumberOfComponents(3);
      zeros->SetNumberOfTuples(copy->GetNumberOfPoints());
      zeros->Fill(0);
      copy->GetPointData()->SetNormals(zeros);
    }
  }
  else if (this->Features.Rule == Shading::None || this->Features.Rule == Shading::Flat)
  {
    copy->GetPointData()->SetNormals(nullptr);
  }
  return copy;
}

void vtkShadelabShading::Attach(
  vtkActor* actor, vtkRenderer* renderer, const vtkShadelabShading* previous)
{
  if (this->Actor && this->Actor->GetMapper())
  {
    this->Actor->GetMapper()->RemoveObserver(this->Observer);
  }
  this->Actor = actor;
  this->Renderer = renderer;

  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
  // The same code on the same actor: touching the replacements or the
  // attribute mapping would make VTK rebuild the program and the buffers.
  if (!previous || previous->Actor != actor || !(previous->Features == this->Features))
  {
    auto* shaders = vtkOpenGLShaderProperty::SafeDownCast(actor->GetShaderProperty());
    shaders->ClearAllShaderReplacements();
    for (const ShaderReplacement& r : GenerateShaderReplacements(this->Features))
    {
      if (r.Vertex)
      {
        shaders->AddVertexShaderReplacement(r.Tag, true, r.Code, false);
      }
      else
      {
        shaders->AddFragmentShaderReplacement(r.Tag, true, r.Code, false);
      }
    }
    mapper->RemoveAllVertexAttributeMappings();
    if (this->Features.VertexKd)
    {
      mapper->MapDataArrayToVertexAttribute(
        VertexKdAttributeName, ColorsArrayName, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    }
    if (this->Features.ReadsTexel() || this->Features.MapsNormals())
    {
      mapper->MapDataArrayToVertexAttribute(TextureCoordinateAttributeName,
        TextureCoordinatesArrayName, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    }
    if (this->Features.MapsNormals())
    {
      mapper->MapDataArrayToVertexAttribute(
        TangentAttributeName, TangentsArrayName, vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
    }
  }
  if (previous)
  {
    // The uploaded images the shading before drew with, where they are
    // this one's too and the window the same.
    const auto takeOver = [renderer](const vtkSmartPointer<vtkTextureObject>& before,
                            const TextureImage* beforeImage, const TextureImage* image,
                            vtkSmartPointer<vtkTextureObject>& object)
    {
      if (before && image && beforeImage == image &&
        before->GetContext() == renderer->GetRenderWindow())
      {
        object = before;
      }
    };
    const auto imageOf = [](const std::optional<EnvironmentMap>& e)
    { return e ? e->Map.Image.get() : nullptr; };
    takeOver(previous->TextureObject, previous->Texture.Map.Image.get(),
      this->Texture.Map.Image.get(), this->TextureObject);
    takeOver(previous->EnvironmentObject, imageOf(previous->Environment),
      imageOf(this->Environment), this->EnvironmentObject);
    const auto reliefOf = [](const std::optional<NormalMap>& m)
    { return m ? m->Map.Image.get() : nullptr; };
    takeOver(previous->ReliefObject, reliefOf(previous->Relief), reliefOf(this->Relief),
      this->ReliefObject);
  }
  if (previous && previous->Actor == actor)
  {
    // The actor's uniforms are this shading's now; other observers of the
    // mapper (the window's shader panel) stay.
    mapper->RemoveObserver(previous->Observer);
  }
  mapper->AddObserver(vtkCommand::UpdateShaderEvent, this->Observer);
  if (auto* ours = vtkShadelabPolyDataMapper::SafeDownCast(mapper))
  {
    ours->SetEachElementOnce(this->Features.Drawn != Representation::Surface);
    ours->SetOwnStages(this->Own);
  }
  vtkProperty* property = actor->GetProperty();
  property->LightingOn();
  property->SetRepresentation(this->Features.Drawn == Representation::Points ? VTK_POINTS
      : this->Features.Drawn == Representation::Wireframe                    ? VTK_WIREFRAME
                                                                             : VTK_SURFACE);
  property->SetLineWidth(static_cast<float>(this->LineWidth));
  property->SetPointSize(static_cast<float>(this->PointSize));
  // The shader's opacity; below 1 the actor is drawn in the translucent step.
  property->SetOpacity(this->Surface.Translucency);
  // Fog towards transparent makes every fragment translucent.
  actor->SetForceTranslucent(this->Features.FogTowardsTransparent);

  auto dark = vtkSmartPointer<vtkLight>::New();
  dark->SetIntensity(0);
  dark->SwitchOn();
  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  renderer->AddLight(dark);
}

void vtkShadelabShading::SetUniforms(vtkShaderProgram* program)
{
  if (!this->Actor || !this->Renderer)
  {
    return;
  }
  // World to view coordinates, in double.
  vtkMatrix4x4* view = this->Renderer->GetActiveCamera()->GetModelViewTransformMatrix();
  double rotation[3][3];
  shadelab::Vec3 translation; // qualified: a unity batch may see shadelab::normals::Vec3 too
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      rotation[i][j] = view->GetElement(i, j);
    }
    translation[i] = view->GetElement(i, 3);
  }
  auto toFloat = [](const std::array<double, 3>& v) -> std::array<float, 3> {
    return { static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]) };
  };
  program->SetUniform3f("shadelabKa", toFloat(this->Surface.Ka).data());
  program->SetUniform3f("shadelabKd", toFloat(this->Surface.Kd).data());
  if (this->Features.ReadsTexel())
  {
    program->SetUniform3f("shadelabKaFactor", toFloat(this->Surface.Ka).data());
    program->SetUniform3f("shadelabKdFactor", toFloat(this->Surface.Kd).data());
    program->SetUniform3f("shadelabKsFactor", toFloat(this->Surface.Ks).data());
    program->SetUniform3f("shadelabKsScale", toFloat(this->Texture.KsScale).data());
    this->BindTexture(program);
  }
  program->SetUniform3f("shadelabKs", toFloat(this->Surface.Ks).data());
  program->SetUniformf("shadelabNs", static_cast<float>(this->Surface.Ns));
  program->SetUniform3f("shadelabIa", toFloat(this->Ambient).data());
  program->SetUniformi(
    "shadelabOrthographic", this->Renderer->GetActiveCamera()->GetParallelProjection() ? 1 : 0);

  const int n = static_cast<int>(this->Lights.size());
  if (n > 0)
  {
    std::vector<std::array<float, 3>> colors, positions, directions;
    std::vector<std::array<float, 3>> attenuations;
    std::vector<float> cutoffs, exponents;
    for (const Light& light : this->Lights)
    {
      const FrameLight f = ToFrame(light, rotation, translation);
      attenuations.push_back(toFloat(f.Attenuation));
      colors.push_back(toFloat(f.Color));
      positions.push_back(toFloat(f.Position));
      directions.push_back(toFloat(f.Direction));
      cutoffs.push_back(static_cast<float>(f.CosCutoff));
      exponents.push_back(static_cast<float>(f.Exponent));
    }
    using Triple = const float(*)[3];
    program->SetUniform3fv("shadelabLightColor", n, reinterpret_cast<Triple>(colors.data()));
    program->SetUniform3fv("shadelabLightPosition", n, reinterpret_cast<Triple>(positions.data()));
    program->SetUniform3fv(
      "shadelabLightDirection", n, reinterpret_cast<Triple>(directions.data()));
    program->SetUniform1fv("shadelabLightCosCutoff", n, cutoffs.data());
    program->SetUniform1fv("shadelabLightExponent", n, exponents.data());
    if (this->Features.Attenuation)
    {
      program->SetUniform3fv(
        "shadelabLightAttenuation", n, reinterpret_cast<Triple>(attenuations.data()));
    }
  }
  if (this->Features.Reflects())
  {
    this->BindEnvironment(program, rotation);
  }
  if (this->Features.MapsNormals())
  {
    this->BindNormalMap(program);
  }
  if (!this->Features.Shadows.empty())
  {
    this->BindShadowMaps(program, view);
  }
  if (this->Features.Fog != FogMode::None)
  {
    program->SetUniform3f("shadelabFogColor", toFloat(this->FogColour).data());
    program->SetUniformf("shadelabFogStart", static_cast<float>(this->FogSetting.Start));
    program->SetUniformf("shadelabFogEnd", static_cast<float>(this->FogSetting.End));
    program->SetUniformf("shadelabFogDensity", static_cast<float>(this->FogSetting.Density));
  }
  if (this->Features.AllFeatures)
  {
    std::vector<int> kinds;
    for (const Light& light : this->Lights)
    {
      kinds.push_back(KindCode(light.Kind));
    }
    program->SetUniformi("shadelabLightCount", std::min(n, AllFeaturesMaxLights));
    program->SetUniform1iv("shadelabLightKind", static_cast<int>(kinds.size()), kinds.data());
    program->SetUniformi("shadelabReflection", UsesHalfVector(this->Features.Model) ? 0 : 1);
  }

  if (this->Features.Rule == Shading::Flat)
  {
    // Model to view for normals: the inverse transpose of the 3x3 part of
    // view x actor.
    auto modelView = vtkSmartPointer<vtkMatrix4x4>::New();
    vtkMatrix4x4::Multiply4x4(view, this->Actor->GetMatrix(), modelView);
    auto normalMatrix = vtkSmartPointer<vtkMatrix3x3>::New();
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        normalMatrix->SetElement(i, j, modelView->GetElement(i, j));
      }
    }
    // vtkShaderProgram::SetUniformMatrix hands GL the elements row by row
    // as if they were columns, so GLSL receives the transpose of what is
    // passed: pass the inverse, and the shader gets the inverse transpose.
    normalMatrix->Invert();
    program->SetUniformMatrix("shadelabNormalMatrix", normalMatrix);
    this->BindFaceNormals(program);
  }
}

void vtkShadelabShading::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Rule: " << ToString(this->Features.Rule) << "\n";
  os << indent << "Model: " << ToString(this->Features.Model) << "\n";
  os << indent << "Lights: " << this->Lights.size() << "\n";
  os << indent << "Specular: " << this->Features.Specular << "\n";
  os << indent << "VertexKd: " << this->Features.VertexKd << "\n";
  os << indent << "KdTexture: " << this->Features.KdTexture << "\n";
  os << indent << "KaTexture: " << this->Features.KaTexture << "\n";
  os << indent << "KsTexture: " << this->Features.KsTexture << "\n";
  os << indent << "Environment: " << this->Features.Environment << "\n";
  os << indent << "NormalMap: " << this->Features.NormalMap << "\n";
}
