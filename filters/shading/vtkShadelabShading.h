/**
 * @class   vtkShadelabShading
 * @brief   the lecture's illumination model and shading rules on a VTK actor
 *
 * Installs the GLSL that shadelabShaderSource generates for the scene as
 * shader replacements on an actor's vtkOpenGLShaderProperty, and before each
 * draw sets its uniforms: the material, Ia, and the lights moved into view
 * coordinates in double on the CPU (the shaders compute in view
 * coordinates, so meshes far from the origin light as well as near it).
 *
 * VTK drops the normal and view-position plumbing from its shaders when no
 * light is on, so Attach() also switches on one light of zero intensity in
 * the renderer; VTK's own lighting code is replaced and never runs.
 */
#ifndef vtkShadelabShading_h
#define vtkShadelabShading_h

#include "shadelab_filtersModule.h" // the export macro

#include "shadelabFaceNormalTexture.h"
#include "shadelabOwnStages.h"
#include "shadelabShaderSource.h"
#include "shadelabShadingOracle.h"

#include <memory>
#include <optional>

#include <vtkObject.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>
#include <vtkWrappingHints.h>

class vtkActor;
class vtkCallbackCommand;
class vtkMatrix4x4;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;

namespace shadelab
{
class ShadowCasters;
}

class SHADELAB_FILTERS_EXPORT vtkShadelabShading : public vtkObject
{
public:
  static vtkShadelabShading* New();
  vtkTypeMacro(vtkShadelabShading, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The scene: rule, reflection model, material, Ia, lights in world coordinates. */
  void SetIllumination(shadelab::Shading rule, shadelab::Reflection model,
    const shadelab::Material& material, const shadelab::Rgb& ambient,
    const std::vector<shadelab::Light>& lights);

  /**
   * Moves the lights without changing the code: `lights` are of the kinds
   * and number SetIllumination gave (a light that follows the camera).
   */
  void SetLightPlacement(const std::vector<shadelab::Light>& lights);

  /**
   * Whether kd comes per vertex from the mesh's colours (point data
   * "Colors") instead of the material (ShaderFeatures::VertexKd).
   */
  void SetVertexKd(bool fromColors);

  /**
   * kd and/or ka times a texel of texture.Map at the mesh's texture
   * coordinates (point data "TextureCoordinates"), per fragment under every
   * rule (ShaderFeatures::KdTexture, KaTexture); the material's kd and ka are
   * the factors; ks likewise where texture.Ks (KsTexture, SurfaceTexture::TexelKs). The image goes
   * to OpenGL as a float texture with the map's wrap and filter, once per image and render window.
   */
  void SetTexture(const shadelab::SurfaceTexture& texture);

  /**
   * Environment reflections (ShaderFeatures::Environment): ks * E(R) added
   * where the rule lights; the map's Frame takes world coordinates to the
   * environment's. None (the default): the code has none. Not wrapped.
   */
  VTK_WRAPEXCLUDE void SetEnvironment(const std::optional<shadelab::EnvironmentMap>& environment);

  /**
   * A normal map (ShaderFeatures::NormalMap) read in the frame of the mesh's
   * tangents (point data TangentsArrayName, shadelabVertexTangents.h) at its
   * texture coordinates: it perturbs the normal where the rule takes it.
   * None (the default): the code has none. Not wrapped.
   */
  VTK_WRAPEXCLUDE void SetNormalMap(const std::optional<shadelab::NormalMap>& map);

  ///@{
  /**
   * The scene part by part, for wrappers such as Python that cannot pass
   * SetIllumination's C++ types: each call changes one part and keeps the
   * others (a new vtkShadelabShading: phong, blinn, black material, no Ia, no
   * lights). The rule, model and material are named as on the command line
   * (the material from the lecture's table); an unknown name returns false
   * and changes nothing. Lights are white, in world coordinates. Call Attach
   * after the last change.
   */
  bool SetShadingRuleByName(const char* name);
  bool SetReflectionModelByName(const char* name);
  bool SetMaterialByName(const char* name);
  void SetAmbientIntensity(double red, double green, double blue);
  void AddPointLight(double x, double y, double z);
  /** A light shining along (x, y, z). */
  void AddDirectionalLight(double x, double y, double z);
  void RemoveAllLights();
  ///@}

  /**
   * Whether lines are drawn over the surface (edges, normal glyphs): its
   * depth then goes back by a polygon offset so that they show
   * (ShaderFeatures::BehindLines). Default off, and off the code has none.
   */
  void SetBehindLines(bool behind);

  /**
   * Fog over every fragment (ShaderFeatures::Fog), towards its colour, or
   * without one towards `background` (none: transparent, the fragment's
   * coverage taken down, drawn in the translucent step). Default none, and
   * none the code has none.
   */
  VTK_WRAPEXCLUDE void SetFog(
    const shadelab::Fog& fog, const std::optional<shadelab::Rgb>& background);

  /**
   * Draws the mesh's surface, or its edges as lines `lineWidth` pixels wide,
   * or its points as squares `pointSize` pixels wide, each once and lit by
   * the same rule (ShaderFeatures::Drawn, DrawnElements), through a
   * vtkShadelabPolyDataMapper (EachElementOnce: flat reads a face normal
   * per element). Default the surface, whose code has none of it.
   */
  VTK_WRAPEXCLUDE void SetRepresentation(
    shadelab::Representation drawn, double lineWidth = 1, double pointSize = 1);

  /**
   * Shadows: what casts them (the scene's actors share it), for the lights
   * whose Shadows is on (ShaderFeatures::Shadows); their maps are baked at
   * the first draw that needs them. None (the default): no light casts
   * any, and the code has none of it.
   */
  VTK_WRAPEXCLUDE void SetShadows(std::shared_ptr<shadelab::ShadowCasters> casters);

  /** How the specular term is written (ShaderFeatures::Form). Default stable. */
  VTK_WRAPEXCLUDE void SetSpecularForm(shadelab::SpecularForm form);

  /**
   * Stages of one's own that replace the generated ones on the actor's
   * mapper (vtkShadelabPolyDataMapper::SetOwnStages). Default none.
   */
  VTK_WRAPEXCLUDE void SetOwnStages(const shadelab::OwnStages& stages) { this->Own = stages; }

  /** What the generated code depends on. */
  const shadelab::ShaderFeatures& GetFeatures() const { return this->Features; }

  /** Use the all-features baseline program instead (for measurements). */
  void SetAllFeatures(bool all);

  /**
   * The mesh as the rule reads it: none and flat lose the point normals
   * they do not use (flat reads its triangles' face normals, computed as
   * they are uploaded), except that flat's points keep them (or get zeros),
   * which VTK gives a view position only with point normals; gouraud and
   * phong keep the mesh as it is. Not
   * wrapped (VTK 9.1's Python cannot return a vtkSmartPointer): from Python
   * the mesh goes to the mapper as it is.
   */
  VTK_WRAPEXCLUDE vtkSmartPointer<vtkPolyData> PrepareMesh(vtkPolyData* mesh) const;

  /**
   * Installs the replacements on actor; renderer gives the camera and lights.
   * `previous`, the shading that last drew actor, lets an actor whose code
   * stays the same (another material, other light positions) keep its
   * compiled program and uploaded buffers.
   */
  void Attach(vtkActor* actor, vtkRenderer* renderer, const vtkShadelabShading* previous = nullptr);

protected:
  vtkShadelabShading();
  ~vtkShadelabShading() override;

private:
  vtkShadelabShading(const vtkShadelabShading&) = delete;
  void operator=(const vtkShadelabShading&) = delete;

  void SetUniforms(vtkShaderProgram* program);
  void BindTexture(vtkShaderProgram* program);
  void BindEnvironment(vtkShaderProgram* program, const double viewRotation[3][3]);
  void BindNormalMap(vtkShaderProgram* program);
  void BindFaceNormals(vtkShaderProgram* program);
  void AddLight(const shadelab::Light& light);
  void BindShadowMaps(vtkShaderProgram* program, vtkMatrix4x4* view);
  // Features.Shadows from the lights and the casters.
  void UpdateShadowFeatures();

  shadelab::ShaderFeatures Features;
  shadelab::OwnStages Own;
  shadelab::Material Surface;
  shadelab::Rgb Ambient{};
  std::vector<shadelab::Light> Lights;
  shadelab::SurfaceTexture Texture;
  std::shared_ptr<shadelab::ShadowCasters> Casters;
  shadelab::Fog FogSetting;
  double LineWidth = 1, PointSize = 1;
  shadelab::Rgb FogColour{};
  // Texture.Map in OpenGL, made at the first draw; a shading that takes over
  // an actor takes this over too when its image and window are the same.
  vtkSmartPointer<vtkTextureObject> TextureObject;
  std::optional<shadelab::EnvironmentMap> Environment;
  // Environment->Map in OpenGL, made and taken over as TextureObject is.
  vtkSmartPointer<vtkTextureObject> EnvironmentObject;
  std::optional<shadelab::NormalMap> Relief;
  // Relief->Map in OpenGL, made and taken over as TextureObject is.
  vtkSmartPointer<vtkTextureObject> ReliefObject;
  // Flat's face normals in OpenGL, made at the first draw of
  // FaceNormalsMesh (not owned) for its window.
  shadelab::FaceNormalTexture FaceNormals;
  vtkPolyData* FaceNormalsMesh = nullptr;
  shadelab::Representation FaceNormalsDrawn = shadelab::Representation::Surface;
  vtkTimeStamp FaceNormalsTime;
  // Not owned, and either may go first (a Python script drops its actor
  // before its shading): weak, so that neither is used once gone.
  vtkWeakPointer<vtkActor> Actor; // its mapper holds the observer
  vtkWeakPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkCallbackCommand> Observer;
};

#endif
