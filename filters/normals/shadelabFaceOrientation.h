/**
 * @brief   consistent face orientation, as vtkPolyDataNormals's Consistency
 *
 * Works on the triangles' point ids, not on OpenMesh: OpenMesh refuses
 * exactly the inconsistent faces this must see.
 */
#ifndef shadelabFaceOrientation_h
#define shadelabFaceOrientation_h

#include "shadelabNormalsMesh.h"

namespace shadelab::normals
{
/**
 * Reverses faces (`faces` of 3 point ids each in `triangles`) so that neighbours
 * across each manifold edge use the edge in opposite directions, spreading
 * out from the lowest-numbered face of each edge-connected part. Returns
 * whether a face was reversed.
 */
bool OrientConsistently(Id* triangles, vtkIdType faces, vtkIdType points);
}

#endif
