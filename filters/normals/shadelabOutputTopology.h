/**
 * @brief   the output mesh of vtkShadelabMeshNormals: its points and triangles
 *
 * Where the output's points and triangles differ from the input's (points
 * split at separating edges, faces reversed by Consistency, points of a
 * file's vertices unwelded), and the output mesh assembled from them: the
 * input's arrays shared wherever they stay as they are.
 */
#ifndef shadelabOutputTopology_h
#define shadelabOutputTopology_h

#include "shadelabNormalsMesh.h"

#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>

#include <vector>

class vtkPolyData;

namespace shadelab::normals
{
class FileVertices;
class MeshConnectivity;

/** The output's points and triangles where they differ from the input's. */
struct OutputTopology
{
  vtkIdType Points = 0;
  // Each face corner's output point (3 a face); null when the output keeps
  // the input's triangles.
  vtkSmartPointer<vtkTypeInt32Array> Connectivity;
  std::vector<vtkIdType> Source; // each output point's input point, with splitting
  std::vector<bool> Split;       // per input point, with splitting
};

/**
 * Splits points at separating edges if `splitting` (FeatureAngle
 * `featureAngle` degrees), and takes the faces as oriented if Consistency
 * reversed some.
 */
OutputTopology MakeTopology(const MeshConnectivity& c, bool splitting, double featureAngle);

/**
 * With file vertices, the output's points and triangles from the welded
 * mesh's `welded`, and their normals from the welded points' `normals`
 * (FileVertices::Unweld).
 */
OutputTopology Unweld(const FileVertices& files, const MeshConnectivity& c,
  const OutputTopology& welded, vtkSmartPointer<vtkFloatArray>& normals);

/**
 * The output's triangles and points with their data: the input's unless
 * points were split or faces reversed, then copies of the split points
 * (with their data) after the input's; only the triangles are kept (verts,
 * lines and strips dropped).
 */
void SetOutputMesh(vtkPolyData* input, const OutputTopology& topology, vtkPolyData* output);
}

#endif
