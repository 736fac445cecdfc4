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

#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>

#include <vector>

class vtkPolyData;

namespace shadelab::normals
{
class MeshConnectivity
{
public:
  MeshConnectivity();
  ~MeshConnectivity();

  vtkIdType Points = 0;               // OpenMesh vertex i < Points is input point i
  std::vector<Id> Triangles;          // 3 input point ids a face, as oriented
  bool Reversed = false;              // Consistency reversed some faces
  bool Connected = false;             // Mesh, CopyOf and the rest below are built
  TriMesh Mesh;                       // face f is input face f
  std::vector<Id> CopyOf;             // OpenMesh vertex Points + i copies CopyOf[i]
  std::vector<bool> InDuplicatedFace; // per input point
  vtkIdType DuplicatedFaces = 0;

  vtkSmartPointer<vtkDoubleArray> XYZ;        // the input's points, in double
  std::vector<Vec3> FaceNormal;               // unit; zero for faces of no area
  std::vector<double> DoubleArea;             // |e1 x e2|; zero for faces of no area
  vtkSmartPointer<vtkFloatArray> CellNormals; // FaceNormal as the output stores it

  /**
   * Builds the face geometry from the input's points and its `triangles` (3
   * point ids a face; oriented consistently first if `consistency`), with
   * the corner weights of `weighting` ready, and OpenMesh's connectivity
   * too if `connect` (on a second thread meanwhile).
   */
  void Build(
    vtkPolyData* input, bool consistency, std::vector<Id>&& triangles, int weighting, bool connect);

  /** Builds OpenMesh's connectivity unless Build or an earlier call did. */
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

  void ComputeFaceNormals(bool parallel);
  void AddFaces();

  void StoreCornerWeights(int weighting);

  int WeightsOf = -1;               // the weighting CornerWeight is for
  std::vector<double> CornerWeight; // 3 a face
};
}

#endif
