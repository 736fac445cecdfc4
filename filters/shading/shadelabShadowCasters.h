// What casts a scene's shadows (--shadows): every triangle of its mesh in
// world coordinates, whatever part, material or representation draws it
// (the oracle's occluders are the same), and each shadow-casting light's
// map of them, baked at the first draw that needs it and again when the
// light moves or the window changes. The actors of a scene share one.
#ifndef shadelabShadowCasters_h
#define shadelabShadowCasters_h

#include "shadelabShadowMaps.h"

#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include <memory>
#include <string>
#include <vector>

class vtkOpenGLRenderWindow;
class vtkTextureObject;

namespace shadelab
{
class ShadowCasters
{
public:
  /** The triangles (world coordinates), and the maps' size in texels a side. */
  ShadowCasters(std::vector<Vec3> points, std::vector<TriangleCorners> triangles, int size);
  ~ShadowCasters();
  ShadowCasters(const ShadowCasters&) = delete;
  ShadowCasters& operator=(const ShadowCasters&) = delete;

  /**
   * Light l's map, as `light` stands now, in window's context (current:
   * the draw's), baked if it is not yet; nullptr with `error` set where it
   * cannot be (a size over OpenGL's limit).
   */
  const ShadowMap* MapOf(
    std::size_t l, const Light& light, vtkOpenGLRenderWindow* window, std::string& error);

  /** Map l as the last draw baked it, or nullptr. */
  const ShadowMap* Baked(std::size_t l) const;

  /** Map l's texture for binding, made by MapOf. */
  vtkTextureObject* TextureOf(std::size_t l) const;

  int GetSize() const { return this->Size; }

private:
  struct LightMap
  {
    std::unique_ptr<ShadowMap> Map;
    Light For;
    vtkSmartPointer<vtkTextureObject> Texture;
  };
  std::vector<Vec3> Points;
  std::vector<TriangleCorners> Triangles;
  int Size;
  std::vector<LightMap> Maps;
  vtkWeakPointer<vtkOpenGLRenderWindow> Window;
};
}

#endif
