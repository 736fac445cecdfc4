// vtkShadelabShading's OpenGL resources bound for a draw: the texture, the
// environment, the face normals and the shadow maps, each made (or remade) for the window
// that draws and kept active, its unit reserved, while the shading draws.
#include "vtkShadelabShading.h"

#include "shadelabShadowCasters.h"
#include "shadelabTriangleMesh.h"

#include <vtkActor.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderer.h>
#include <vtkShaderProgram.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

using namespace shadelab;

namespace
{
int WrapMode(TextureWrap w)
{
  switch (w)
  {
    case TextureWrap::Repeat:
      return vtkTextureObject::Repeat;
    case TextureWrap::Clamp:
      return vtkTextureObject::ClampToEdge;
    case TextureWrap::Mirror:
      return vtkTextureObject::MirroredRepeat;
  }
  return vtkTextureObject::Repeat;
}

int FilterMode(TextureFilter f)
{
  switch (f)
  {
    case TextureFilter::Bilinear:
      return vtkTextureObject::Linear;
    case TextureFilter::Nearest:
      return vtkTextureObject::Nearest;
  }
  return vtkTextureObject::Linear;
}
}

void vtkShadelabShading::BindShadowMaps(vtkShaderProgram* program, vtkMatrix4x4* view)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(this->Renderer->GetRenderWindow());
  // View coordinates back to the world's, in double.
  auto toWorld = vtkSmartPointer<vtkMatrix4x4>::New();
  vtkMatrix4x4::Invert(view, toWorld);
  for (std::size_t l = 0; l < this->Features.Shadows.size(); ++l)
  {
    if (!this->Features.Shadows[l])
    {
      continue;
    }
    std::string problem;
    const ShadowMap* map = this->Casters->MapOf(l, this->Lights[l], window, problem);
    if (!map)
    {
      vtkErrorMacro(<< problem);
      return;
    }
    vtkTextureObject* texture = this->Casters->TextureOf(l);
    // Kept active (its unit reserved) while the shading draws.
    texture->Activate();
    const std::string index = std::to_string(l);
    program->SetUniformi((ShadowMapSamplerName + index).c_str(), texture->GetTextureUnit());
    auto worldToMap = vtkSmartPointer<vtkMatrix4x4>::New();
    worldToMap->DeepCopy(map->GetWorldToMap().data());
    auto frame = vtkSmartPointer<vtkMatrix4x4>::New();
    vtkMatrix4x4::Multiply4x4(worldToMap, toWorld, frame);
    // GLSL receives the transpose of what SetUniformMatrix is given.
    frame->Transpose();
    program->SetUniformMatrix((ShadowFrameName + index).c_str(), frame);
    program->SetUniform4f((ShadowBiasName + index).c_str(), map->GetBias().data());
  }
}

void vtkShadelabShading::BindFaceNormals(vtkShaderProgram* program)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(this->Renderer->GetRenderWindow());
  vtkPolyData* mesh = vtkPolyData::SafeDownCast(this->Actor->GetMapper()->GetInput());
  if (!this->FaceNormals.Texture || this->FaceNormals.Texture->GetContext() != window ||
    this->FaceNormalsMesh != mesh || this->FaceNormalsTime < mesh->GetMTime() ||
    this->FaceNormalsDrawn != this->Features.Drawn)
  {
    if (const std::string problem =
          UploadFaceNormals(mesh, this->Features.Drawn, window, this->FaceNormals);
        !problem.empty())
    {
      vtkErrorMacro(<< problem);
      return;
    }
    this->FaceNormalsMesh = mesh;
    this->FaceNormalsDrawn = this->Features.Drawn;
    this->FaceNormalsTime.Modified();
  }
  // Kept active (its unit reserved) while the shading draws.
  this->FaceNormals.Texture->Activate();
  program->SetUniformi(FaceNormalSamplerName, this->FaceNormals.Texture->GetTextureUnit());
}

namespace
{
// map in OpenGL as `object` (made for window where it is not yet), its
// sampler's settings sent at every draw (an object taken over from the
// shading before, the same image, may have had others), kept active (its
// unit reserved) while the shading draws, and named to the program's `sampler`.
void BindMap(vtkShaderProgram* program, vtkOpenGLRenderWindow* window, const TextureMap& map,
  vtkSmartPointer<vtkTextureObject>& object, const char* sampler)
{
  if (!object || object->GetContext() != window)
  {
    object = vtkSmartPointer<vtkTextureObject>::New();
    object->SetContext(window);
    // 32-bit float texels: the decoded image as it is, no 8-bit rounding.
    object->SetInternalFormat(GL_RGB32F);
    object->Create2DFromRaw(map.Image->Width, map.Image->Height, 3, VTK_FLOAT,
      const_cast<float*>(map.Image->Pixels.data()));
  }
  const int filter = FilterMode(map.Filter);
  object->SetWrapS(WrapMode(map.WrapS));
  object->SetWrapT(WrapMode(map.WrapT));
  object->SetMinificationFilter(filter);
  object->SetMagnificationFilter(filter);
  object->Activate();
  program->SetUniformi(sampler, object->GetTextureUnit());
}
}

void vtkShadelabShading::BindTexture(vtkShaderProgram* program)
{
  BindMap(program, vtkOpenGLRenderWindow::SafeDownCast(this->Renderer->GetRenderWindow()),
    this->Texture.Map, this->TextureObject, TextureSamplerName);
}

void vtkShadelabShading::BindNormalMap(vtkShaderProgram* program)
{
  BindMap(program, vtkOpenGLRenderWindow::SafeDownCast(this->Renderer->GetRenderWindow()),
    this->Relief->Map, this->ReliefObject, NormalMapSamplerName);
  program->SetUniformf(NormalScaleName, static_cast<float>(this->Relief->Scale));
}

void vtkShadelabShading::BindEnvironment(vtkShaderProgram* program, const double viewRotation[3][3])
{
  BindMap(program, vtkOpenGLRenderWindow::SafeDownCast(this->Renderer->GetRenderWindow()),
    this->Environment->Map, this->EnvironmentObject, EnvironmentSamplerName);
  // View coordinates to the environment's: its Frame (from the world's)
  // times the view's rotation transposed (view to world). GLSL receives
  // the transpose of what SetUniformMatrix is given: it is given that.
  auto frame = vtkSmartPointer<vtkMatrix3x3>::New();
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double e = 0;
      for (int k = 0; k < 3; ++k)
      {
        e += this->Environment->Frame[i][k] * viewRotation[j][k];
      }
      frame->SetElement(j, i, e);
    }
  }
  program->SetUniformMatrix(EnvironmentFrameName, frame);
}
