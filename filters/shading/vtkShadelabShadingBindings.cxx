// vtkShadelabShading's OpenGL resources bound for a draw: the texture, the
// face normals and the shadow maps, each made (or remade) for the window
// that draws and kept active, its unit reserved, while the shading draws.
#include "vtkShadelabShading.h"

#include "shadelabShadowCasters.h"
#include "shadelabTriangleMesh.h"

#include <vtkActor.h>
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

void vtkShadelabShading::BindTexture(vtkShaderProgram* program)
{
  auto* window = vtkOpenGLRenderWindow::SafeDownCast(this->Renderer->GetRenderWindow());
  const TextureMap& map = this->Texture.Map;
  if (!this->TextureObject || this->TextureObject->GetContext() != window)
  {
    this->TextureObject = vtkSmartPointer<vtkTextureObject>::New();
    this->TextureObject->SetContext(window);
    // 32-bit float texels: the decoded image as it is, no 8-bit rounding.
    this->TextureObject->SetInternalFormat(GL_RGB32F);
    this->TextureObject->Create2DFromRaw(map.Image->Width, map.Image->Height, 3, VTK_FLOAT,
      const_cast<float*>(map.Image->Pixels.data()));
  }
  // The sampler's settings at every draw: a texture taken over from the
  // shading before (the same image) may have had others. The object sends
  // them to OpenGL when they changed.
  const int filter = FilterMode(map.Filter);
  this->TextureObject->SetWrapS(WrapMode(map.WrapS));
  this->TextureObject->SetWrapT(WrapMode(map.WrapT));
  this->TextureObject->SetMinificationFilter(filter);
  this->TextureObject->SetMagnificationFilter(filter);
  // Kept active (its unit reserved) while the shading draws.
  this->TextureObject->Activate();
  program->SetUniformi(TextureSamplerName, this->TextureObject->GetTextureUnit());
}
