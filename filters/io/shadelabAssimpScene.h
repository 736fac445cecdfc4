/**
 * @brief   an assimp scene as shadelab's mesh, parts and textures, checked
 *
 * vtkShadelabAssimpReader's second half: what assimp's importer handed back
 * (after its Triangulate, SortByPType and PreTransformVertices) turned into a
 * PolygonMesh (shadelabTriangleMesh.h) and the parts' materials and textures
 * (shadelabPartMaterials.h), refusing what the own readers refuse in a file:
 * counts the memory cannot take, faces that are not triangles, indices out
 * of range, non-finite coordinates, normals, texture coordinates and
 * material numbers.
 */
#ifndef shadelabAssimpScene_h
#define shadelabAssimpScene_h

#include "shadelabPartMaterials.h"
#include "shadelabTriangleMesh.h"

#include <string>
#include <vector>

struct aiScene;

namespace shadelab
{
struct AssimpMesh
{
  PolygonMesh Mesh; // one part per assimp mesh of triangles
  std::vector<PartMaterial> Parts;
  std::vector<Texture> Textures;
  std::vector<std::string> Warnings;
};

/**
 * The triangles of `scene` (meshes of points or lines dropped), each mesh a
 * part with its material; normals only where readNormals and every mesh has
 * them. A texture that a material names is resolved against meshFile's
 * folder (shadelab::ResolveReference, with allowOutside). Throws
 * MeshReadError on the first problem, "no triangles" for a scene without.
 */
AssimpMesh ConvertAssimpScene(
  const aiScene& scene, const std::string& meshFile, bool readNormals, bool allowOutside);
}

#endif
