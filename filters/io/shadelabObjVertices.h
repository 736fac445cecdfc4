/**
 * @brief   an OBJ file's vertices as points: one per v, vt and vn its faces use
 *
 * An OBJ face corner names a vertex (v) and, apart, its texture coordinate
 * (vt) and normal (vn); a VTK point holds all three. SplitVertices makes one
 * point per distinct (v, vt, vn) that the corners use, as far as vt and vn
 * are read: point i stays vertex i with the vt and vn of its first use,
 * further combinations are appended after the file's vertices in the order
 * of the corners that need them, and where there are such copies every
 * point gets its file vertex (PolygonMesh::FileVertices), so that normals
 * can be computed on the file's vertices (vtkShadelabMeshNormals). A vertex
 * that no face uses gets a zero normal and texture coordinates 0 0, as
 * does a corner without a vt or vn where others have one.
 */
#ifndef shadelabObjVertices_h
#define shadelabObjVertices_h

#include "shadelabTriangleMesh.h"

#include <vtkType.h>

#include <vector>

namespace shadelab
{
/** A corner's vt or vn where it has none. */
constexpr vtkIdType ObjNoIndex = -1;

/** What an OBJ file defines and how its faces' corners refer to it. */
struct ObjCorners
{
  std::vector<double> Vertices;          // x y z per v
  std::vector<float> Colors;             // r g b a per v, or empty
  std::vector<float> TextureCoordinates; // s t per vt
  std::vector<float> Normals;            // x y z per vn
  std::vector<vtkIdType> VertexIds;      // 0-based, per corner
  std::vector<vtkIdType> TextureIds;     // 0-based or ObjNoIndex, per corner
  std::vector<vtkIdType> NormalIds;      // 0-based or ObjNoIndex, per corner
};

/**
 * Moves `corners` into `mesh`: the points, their colours (a copy's its
 * vertex's), texture coordinates (if `texture`), normals (if `normals`)
 * and file vertices; corners.VertexIds
 * become the corners' point ids.
 */
void SplitVertices(ObjCorners& corners, bool texture, bool normals, PolygonMesh& mesh);
}

#endif
