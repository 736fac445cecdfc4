/**
 * @brief   the vertex normals' sums on all cores, each point's in its faces' order
 *
 * SumFaceNormals adds each face's weighted unit normal into its corners'
 * points. Floating-point sums depend on their order, so every point
 * receives its terms face by face in the input's order, as on one core,
 * while contiguous chunks of faces are summed on the cores at once: the
 * bits do not depend on the thread count.
 */
#ifndef shadelabOrderedSums_h
#define shadelabOrderedSums_h

#include "shadelabNormalsMesh.h"

#include <vector>

namespace shadelab::normals
{
class MeshConnectivity;
struct OutputTopology;

// A vertex's weighted sum of face normals, with the sum of the weights: a
// sum far shorter than its terms is the rounding left of terms that cancel
// (a face and its reverse), and its direction means nothing.
struct Sum
{
  Vec3 Normal{ 0, 0, 0 };
  double Weight = 0; // beside the normal: one cache line for both
};

/**
 * Each face's weighted unit normal (`weighting`, as SummedWeighting gives
 * it), summed into its corners' points of `topology`, and into
 * `cellNormals` (3 floats a face) unless null. `chunkCount` chunks of faces
 * (0: one per thread; at most 254).
 */
std::vector<Sum> SumFaceNormals(const MeshConnectivity& c, const OutputTopology& topology,
  int weighting, int chunkCount, float* cellNormals);
}

#endif
