/**
 * @brief   which meshes a glTF document shows, and where
 *
 * The default scene is `scene`, else the first of `scenes`; a document
 * without scenes shows every node that is no other node's child, and one
 * without nodes every mesh as it is. Each node's world transform is its
 * parents' times its own: `matrix` (column-major, as glTF stores it) or
 * translation * rotation * scale (the rotation a unit quaternion x y z w,
 * normalised here). A node reached twice (a cycle, a child of two parents,
 * a scene root that is also a child) is an error, as is a node with both a
 * matrix and TRS.
 */
#ifndef shadelabGLTFScene_h
#define shadelabGLTFScene_h

#include "shadelabGLTFDocument.h"

#include <array>
#include <cstdint>
#include <vector>

namespace shadelab::gltf
{
/** A 4x4 transform, row-major: element (r, c) is [4 * r + c]. */
using Matrix = std::array<double, 16>;

// The upper 3x3 of a world transform: where positions go and how normals
// turn (by the inverse transpose, i.e. the cofactors over the determinant).
class WorldTransform
{
public:
  explicit WorldTransform(const Matrix& m);

  /** A mirroring transform turns triangles round: glTF keeps their front in front. */
  bool Mirrors() const { return this->Determinant < 0; }

  /** Appends the transformed point p. */
  void Point(const float* p, std::vector<double>& out) const;

  /** Appends the transformed, renormalised normal n. */
  void Normal(const float* n, std::vector<float>& out) const;

private:
  const Matrix& M;
  double Cofactor[9];
  double Determinant;
};

struct MeshInstance
{
  std::uint64_t Mesh = 0;
  Matrix World{};
};

/** The default scene's meshes with their world transforms, nodes depth-first in file order. */
std::vector<MeshInstance> SceneMeshes(const Json& root);
}

#endif
