// The tangents a normal map is read in the frame of (shadelabNormalMap.h):
// per point, from the triangles' texture coordinates, as glTF's TANGENT
// (xyz along the texture's s, w the handedness).
#ifndef shadelabVertexTangents_h
#define shadelabVertexTangents_h

#include <vtkSmartPointer.h>

class vtkFloatArray;
class vtkPolyData;

namespace shadelab
{
/** Point data: float x, y, z, w (VertexTangents), where a normal map is drawn. */
constexpr const char* TangentsArrayName = "Tangents";

/**
 * Each point's tangent for mesh's triangles (polygons as fans) and texture
 * coordinates (point data TextureCoordinatesArrayName, which it must have):
 *
 * - a triangle's tangent T = dP/ds and bitangent B = dP/dt solve the
 *   positions' edges for the texture coordinates' (Lengyel's); its
 *   handedness is the sign of (n x T).B, n its face normal; a triangle whose
 *   texture coordinates span no area has none;
 * - a point's handedness is the sign of its triangles' handedness summed
 *   with their corners' angles as weights, and its tangent the unit sum of
 *   the unit tangents of those triangles of that handedness, each times its
 *   corner's angle, over every point with the same position and normal
 *   (point data normals, where the mesh has them): points split only by
 *   their texture coordinates, at a seam, get one tangent, so that the seam
 *   shows no crease (MikkTSpace, glTF's reference, splits them there).
 *
 * A point with no tangent gets (0, 0, 0, 1), and the normal map leaves its
 * normal as it is. Named TangentsArrayName.
 */
vtkSmartPointer<vtkFloatArray> VertexTangents(vtkPolyData* mesh);
}

#endif
