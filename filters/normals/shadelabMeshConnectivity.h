/**
 * @brief   OpenMesh's connectivity and the face geometry of one input
 *
 * What vtkShadelabMeshNormals keeps between updates of the same input: a
 * change of weighting or of feature angle recomputes normals from it
 * without rebuilding it. The face geometry (normals, areas, corner
 * weights) needs no connectivity and is all that summed vertex normals
 * read; OpenMesh's mesh is built only when splitting or Loop normals ask
 * for it (Connect), so it never changes a summed normal. OpenMesh vertex
 * i < Points is input point i, and OpenMesh face f is input face f. Faces
 * that OpenMesh refuses (they would make a non-manifold edge or vertex, or
 * they repeat a vertex) get copies of their vertices, appended after the
 * input's points.
 */
#ifndef shadelabMeshConnectivity_h
#define shadelabMeshConnectivity_h

#include "shadelabNormalsMesh.h"
#include "shadelabVec3.h"

#include <vtkDoubleArray.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>

#include <vector>

class vtkPolyData;

namespace shadelab::normals
{
/**
 * Face f's unit normal (zero if it has no area) and its doubled area
 * |e1 x e2| (zero for no area, or an overflowing cross product), from the
 * points `xyz` and the faces' 3 point ids each `triangles`: the project's
 * one face normal (shadelab::FaceNormal), stored or not. The copies between
 * OpenMesh's and shadelab's vectors of 3 doubles compile away.
 */
inline double FaceGeometry(const double* xyz, const Id* triangles, vtkIdType f, Vec3& unitNormal)
{
  const auto point = [xyz](vtkIdType i) {
    return shadelab::Vec3{ xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2] };
  };
  shadelab::Vec3 unit;
  const double doubleArea = shadelab::FaceNormal(
    point(triangles[3 * f]), point(triangles[3 * f + 1]), point(triangles[3 * f + 2]), unit);
  unitNormal = Vec3(unit[0], unit[1], unit[2]);
  return doubleArea;
}

class MeshConnectivity
{
public:
  MeshConnectivity();
  ~MeshConnectivity();

  vtkIdType Points = 0; // OpenMesh vertex i < Points is input point i
  // 3 input point ids a face, as oriented: the input's own 32-bit ids,
  // shared, where nothing rewrites them; a copy otherwise.
  vtkSmartPointer<vtkTypeInt32Array> Triangles;
  bool Reversed = false;              // Consistency reversed some faces (in a copy)
  bool Connected = false;             // Mesh, CopyOf and the rest below are built
  TriMesh Mesh;                       // face f is input face f
  std::vector<Id> CopyOf;             // OpenMesh vertex Points + i copies CopyOf[i]
  std::vector<bool> InDuplicatedFace; // per input point
  vtkIdType DuplicatedFaces = 0;

  vtkSmartPointer<vtkDoubleArray> XYZ; // the input's points, in double
  // Per face (FaceGeometry), stored with the connectivity only (splitting
  // reads them there); without it the sum computes each face's as it adds
  // it, which keeps a large mesh's 4 doubles a face out of memory.
  std::vector<Vec3> FaceNormal;
  std::vector<double> DoubleArea;

  /**
   * Takes the input's points and its `triangles` (3 point ids a face;
   * oriented consistently first if `consistency`, so then a copy of the
   * input's); if `connect`, also builds
   * OpenMesh's connectivity with the stored face geometry and the corner
   * weights of `weighting` (on a second thread meanwhile). Without it, no
   * pass over the faces: the sum makes the one it needs.
   */
  void Build(vtkPolyData* input, bool consistency, vtkSmartPointer<vtkTypeInt32Array> triangles,
    int weighting, bool connect);

  vtkIdType Faces() const { return this->Triangles->GetNumberOfValues() / 3; }
  const Id* TriangleIds() const { return this->Triangles->GetPointer(0); }

  /** Builds OpenMesh's connectivity and stores the face geometry, unless done. */
  void Connect();

  /**
   * The weight of each face corner (3 a face) for the Angle or Max
   * weighting where Build computed them beside OpenMesh's build (the time
   * is free there); null otherwise: the sum then weighs each face as it
   * adds it, which keeps a large mesh's 3 doubles a face out of memory.
   */
  const double* StoredCornerWeights(int weighting) const
  {
    return this->WeightsOf == weighting ? this->CornerWeight.data() : nullptr;
  }

private:
  MeshConnectivity(const MeshConnectivity&) = delete;
  void operator=(const MeshConnectivity&) = delete;

  void StoreFaceGeometry(bool parallel);
  void AddFaces();

  void StoreCornerWeights(int weighting);

  int WeightsOf = -1;               // the weighting CornerWeight is for
  std::vector<double> CornerWeight; // 3 a face
};
}

#endif
