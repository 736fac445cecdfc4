/**
 * @brief   splits vertices at feature, boundary and non-manifold edges
 *
 * The faces around each vertex are grouped into runs between separating
 * edges: edges where adjacent faces' unit normals have a dot product below
 * the feature angle's cosine, boundary edges, and non-manifold edges (as in
 * vtkPolyDataNormals). Each run beyond the first becomes a new point.
 */
#ifndef shadelabVertexSplitting_h
#define shadelabVertexSplitting_h

#include "shadelabMeshConnectivity.h"

#include <vector>

namespace shadelab::normals
{
/**
 * Gives each output point's input point (`source`: the input's points,
 * then the new ones, appended in the order of the points they split), each
 * face corner's output point (`cornerPoint`, 3 a face), and which input
 * points were split.
 */
void SplitVertices(const MeshConnectivity& mesh, double cosFeature, std::vector<vtkIdType>& source,
  Id* cornerPoint, std::vector<bool>& split);
}

#endif
