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

#include "shadelabShaderSource.h"
#include "shadelabShadingOracle.h"

#include <vtkObject.h>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkCallbackCommand;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;

class vtkShadelabShading : public vtkObject
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

  /** What the generated code depends on. */
  const shadelab::ShaderFeatures& GetFeatures() const { return this->Features; }

  /** Use the all-features baseline program instead (for measurements). */
  void SetAllFeatures(bool all);

  /**
   * The mesh as the rule reads it: flat gets its triangles exploded with face
   * normals (vtkShadelabFlatTriangles), none and flat lose the point normals
   * they do not use; gouraud and phong keep the mesh as it is.
   */
  vtkSmartPointer<vtkPolyData> PrepareMesh(vtkPolyData* mesh) const;

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

  shadelab::ShaderFeatures Features;
  shadelab::Material Surface;
  shadelab::Rgb Ambient{};
  std::vector<shadelab::Light> Lights;
  vtkActor* Actor = nullptr;       // not owned: the actor owns its mapper, which holds the observer
  vtkRenderer* Renderer = nullptr; // not owned
  vtkSmartPointer<vtkCallbackCommand> Observer;
};

#endif
