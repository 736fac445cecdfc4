// A mesh's parts (the readers' cell data "Part" and the field data of their
// materials, filters/io/shadelabPartMaterials.h) with the material each is
// drawn with: the file's, unless the options override it (--material
// replaces every part's whole material, --ka/--kd/--ks/--ns that
// coefficient of every part); a part without a material of its own gets the
// options' material, as a mesh without parts does. Likewise its texture:
// the file's kd, ka and ks textures unless --material, --kd, --ka or --ks
// drop them, --texture's image (kd and ka) on every part where given.
#ifndef shadelab_scene_parts_h
#define shadelab_scene_parts_h

#include "core/options.h"
#include "shadelabEnvironment.h"
#include "shadelabNormalMap.h"
#include "shadelabPartMaterials.h"

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

class vtkPolyData;

namespace shadelab
{
/** Where a part's material comes from. */
enum class MaterialSource
{
  File,    // the mesh file's own (OBJ's MTL, glTF's)
  Default, // the part has none: the options' material (--material's default)
  Option   // --material, or all of --ka --kd --ks --ns, replaced it
};

template <>
struct NameTable<MaterialSource>
{
  static constexpr std::array<std::pair<MaterialSource, const char*>, 3> Entries{
    { { MaterialSource::File, "file" }, { MaterialSource::Default, "default" },
      { MaterialSource::Option, "option" } }
  };
};

/** One part of a mesh as drawn. */
struct ScenePart
{
  int Index = 0;           // the value of "Part" on its triangles; 0 for a mesh without parts
  std::string Name;        // its material's name in the file, "" without one
  vtkIdType Triangles = 0; // how many triangles it has
  Material Surface;        // what it is lit with, the overrides applied
  MaterialSource Source = MaterialSource::Default;
  std::vector<std::string> Overridden; // the coefficients options replaced: "ka", "kd", "ks", "ns"
  // What multiplies its kd, ka and ks: --texture's image, the file's or none;
  // the map's image is null where SceneParts was not given the images.
  SurfaceTexture Texture;
  std::string ImageName; // the texture's image file, "MESH (texture I)" for an embedded one
  int FileTexture = -1;  // the mesh file's texture drawn (MeshTextures' index), else -1
  // The normal or height map that perturbs its normals: --normal-map's or
  // --bump-map's (with the textures' wrap and filter), or the file's (OBJ
  // norm, bump, map_Bump, a height map where its image is grey; glTF
  // normalTexture) where the part has its own material; none without one.
  // Its image is null where SceneParts was not given the images.
  std::optional<NormalMap> Relief;
  int FileNormalTexture = -1; // the mesh file's texture that is its normal map, else -1
  bool FileBump = false;      // that map is a bump statement's: a height map where it is grey
};

/**
 * The decoded images of a scene's textures: --texture's, and the mesh
 * file's by MeshTextures' index (null where no part draws it).
 */
struct SceneImages
{
  std::shared_ptr<const TextureImage> Option;
  std::vector<std::shared_ptr<const TextureImage>> File;
  std::shared_ptr<const TextureImage> Environment; // --environment's
  std::shared_ptr<const TextureImage> NormalMap;   // --normal-map's or --bump-map's
};

/**
 * --environment's map as the scene draws it, in world coordinates: its
 * image, its longitude repeating and its latitude clamped, the textures'
 * filter, and its frame --environment-up's, or else --up's (FrameOf);
 * none without one.
 */
std::optional<EnvironmentMap> SceneEnvironment(
  const SceneOptions& options, const SceneImages& images);

/**
 * mesh's parts as options draw them, by index: one for a mesh without parts
 * (its triangles all of part 0). A part's texture takes its image from
 * `images`. One map per part: where a part's kd, ka and ks textures
 * differ, the first of kd's, ka's, ks's is drawn and the others are their
 * factors alone.
 */
std::vector<ScenePart> SceneParts(
  const SceneOptions& options, vtkPolyData* mesh, const SceneImages& images = {});

/** The image file of the mesh file's texture `index`, "MESH (texture I)" for an embedded one. */
std::string FileTextureName(
  const SceneOptions& options, const std::vector<Texture>& textures, int index);

/** A part with triangles has a < 1: the picture is composited in depth order. */
bool AnyTranslucent(const std::vector<ScenePart>& parts);

/** The part of each of mesh's cells, by cell index: all 0 for a mesh without parts. */
std::vector<int> PartOfCells(vtkPolyData* mesh);

/**
 * mesh with only the triangles whose part is in `parts` (ascending), its
 * points and point data shared (the same arrays, normals included): what
 * one part's actor draws.
 */
vtkSmartPointer<vtkPolyData> TrianglesOfParts(vtkPolyData* mesh, const std::vector<int>& parts);
}

#endif
