// The mesh's surface as a scene lights it, in world coordinates: each
// triangle's part (material, texture), its corners' vertex normals, vertex
// kd and texture coordinates, and a point of it shaded by the oracle. What
// `probe` explains under a pixel and what the ray-traced rule lights at
// each ray's hit, from the same data.
#ifndef shadelab_scene_surface_h
#define shadelab_scene_surface_h

#include "core/options.h"
#include "scene/scene_parts.h"
#include "shadelabPixelRays.h"
#include "shadelabTriangleFragment.h"

#include <vector>

class vtkPolyData;

namespace shadelab
{
class SceneSurface
{
public:
  /** `mesh` as BuiltScene::Mesh holds it, its textures' images `images`. */
  SceneSurface(const SceneOptions& options, vtkPolyData* mesh, const SceneImages& images);

  /** The part cell t is of, as drawn. */
  const ScenePart& PartOf(std::int64_t t) const { return this->Parts[this->CellParts[t]]; }

  /**
   * The fragment of the triangle with these corners (as drawn, or turned)
   * at barycentric weights w, facing the viewer (front) or not.
   */
  TriangleFragment Fragment(const TriangleCorners& corners, const std::array<double, 3>& w,
    bool front, const std::vector<Vec3>& points) const;

  /**
   * `in` with cell t's part's material, texture and normal map, and the
   * environment: what lights t.
   */
  IlluminationInputs InputsOf(IlluminationInputs in, std::int64_t t) const;

  bool HasNormals() const { return !this->Normals.empty(); }
  bool VertexKd() const { return !this->Kd.empty(); }
  bool Textured() const { return !this->TexCoords.empty(); }
  const std::vector<ScenePart>& GetParts() const { return this->Parts; }

private:
  std::vector<ScenePart> Parts;                 // as drawn
  std::vector<int> CellParts;                   // the part of each cell
  std::optional<EnvironmentMap> Environment;    // in world coordinates
  std::vector<Vec3> Normals;                    // per point, when the mesh has them
  std::vector<Rgb> Kd;                          // per point, when its colours are kd
  std::vector<std::array<double, 2>> TexCoords; // per point, when a texture or normal map is read
  std::vector<Tangent> Tangents;                // per point, when the mesh has them
};
}

#endif
