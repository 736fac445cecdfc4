#include "shadelabShadowCasters.h"

#include <vtkOpenGLRenderWindow.h>
#include <vtkTextureObject.h>
#include <vtk_glew.h>

namespace shadelab
{
namespace
{
// What a map depends on of its light.
bool SamePlace(const Light& a, const Light& b)
{
  return a.Kind == b.Kind && a.Position == b.Position && a.Direction == b.Direction;
}
}

ShadowCasters::ShadowCasters(
  std::vector<Vec3> points, std::vector<TriangleCorners> triangles, int size)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
  , Size(size)
{
}

ShadowCasters::~ShadowCasters()
{
  // The maps' OpenGL objects go with their context, where it still is.
  if (this->Window)
  {
    this->Window->MakeCurrent();
    for (LightMap& b : this->Maps)
    {
      if (b.Map)
      {
        b.Map->Release();
      }
    }
  }
}

const ShadowMap* ShadowCasters::MapOf(
  std::size_t l, const Light& light, vtkOpenGLRenderWindow* window, std::string& error)
{
  if (this->Window != window)
  {
    this->Maps.clear(); // another context's objects: not ours to free here
    this->Window = window;
  }
  if (this->Maps.size() <= l)
  {
    this->Maps.resize(l + 1);
  }
  LightMap& b = this->Maps[l];
  if (b.Map && SamePlace(b.For, light))
  {
    return b.Map.get();
  }
  GLint limit = 0;
  glGetIntegerv(
    GeometryOf(light.Kind).Position ? GL_MAX_CUBE_MAP_TEXTURE_SIZE : GL_MAX_TEXTURE_SIZE, &limit);
  if (this->Size > limit)
  {
    error = "--shadow-map-size " + std::to_string(this->Size) + " is over this OpenGL's limit of " +
      std::to_string(limit) + " texels";
    return nullptr;
  }
  if (!b.Map)
  {
    b.Map = std::make_unique<ShadowMap>();
  }
  error = b.Map->Bake(this->Points, this->Triangles, light, this->Size);
  if (!error.empty())
  {
    b.Map.reset();
    return nullptr;
  }
  b.For = light;
  b.Texture = vtkSmartPointer<vtkTextureObject>::New();
  b.Texture->SetContext(window);
  b.Texture->AssignToExistingTexture(
    b.Map->GetTexture(), b.Map->IsCube() ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D);
  // Read as stored: the nearest texel, nothing beyond the edge.
  b.Texture->SetMinificationFilter(vtkTextureObject::Nearest);
  b.Texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  b.Texture->SetWrapS(vtkTextureObject::ClampToEdge);
  b.Texture->SetWrapT(vtkTextureObject::ClampToEdge);
  b.Texture->SetWrapR(vtkTextureObject::ClampToEdge);
  return b.Map.get();
}

const ShadowMap* ShadowCasters::Baked(std::size_t l) const
{
  return l < this->Maps.size() ? this->Maps[l].Map.get() : nullptr;
}

vtkTextureObject* ShadowCasters::TextureOf(std::size_t l) const
{
  return l < this->Maps.size() ? this->Maps[l].Texture.Get() : nullptr;
}
}
