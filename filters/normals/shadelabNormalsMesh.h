/**
 * @brief   the OpenMesh mesh that vtkShadelabMeshNormals builds
 *
 * Double points: the normals are computed in double and stored as float.
 * Point ids are numbered as OpenMesh numbers its handles (int): half the
 * memory of vtkIdType for the largest arrays; bigger meshes are refused.
 */
#ifndef shadelabNormalsMesh_h
#define shadelabNormalsMesh_h

#include <vtkType.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace shadelab::normals
{
struct MeshTraits : public OpenMesh::DefaultTraits
{
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;
using Vec3 = OpenMesh::Vec3d;
using Id = int;

/** Point i of packed x y z coordinates. */
inline Vec3 PointAt(const double* xyz, vtkIdType i)
{
  return Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
}
}

#endif
