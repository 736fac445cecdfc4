/**
 * @brief   the last step that every mesh reader shares
 *
 * A parser collects points, optional point normals, faces and triangle
 * strips in a PolygonMesh; ToPolyData() wraps them as vtkPolyData, and
 * MakeTriangleMesh() checks that data (from a parser or from VTK's own
 * readers) and turns it into what every shadelab reader outputs: double
 * points, triangles only, and the point normals, if any, as the float array
 * "Normals".
 */
#ifndef shadelabTriangleMesh_h
#define shadelabTriangleMesh_h

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <vector>

class vtkPolyData;

namespace shadelab
{
struct PolygonMesh
{
  std::vector<double> Points; // x y z per point
  std::vector<float> Normals; // nx ny nz per point, or empty
  // Face i is FaceIds[FaceOffsets[i]] .. FaceIds[FaceOffsets[i + 1] - 1].
  std::vector<vtkIdType> FaceOffsets{ 0 };
  std::vector<vtkIdType> FaceIds;
  std::vector<vtkIdType> StripOffsets{ 0 };
  std::vector<vtkIdType> StripIds;
};

/** The parser's arrays as vtkPolyData: points, normals, polys and strips. */
vtkSmartPointer<vtkPolyData> ToPolyData(const PolygonMesh& mesh);

/**
 * Checks `polygons` and writes the triangle mesh into `triangles`. Throws
 * MeshReadError on non-finite points or normals, normals that are not one
 * 3-vector per point, faces or strips with fewer than 3 vertices or with an
 * index out of range, and when no triangle results ("no triangles": vertices
 * and lines are dropped). Faces of 4+ vertices are triangulated by VTK's ear
 * cutting (right for concave ones), strips with alternating orientation; the
 * zero-area triangles that strips use to join runs are dropped, those of
 * faces kept. Vertices, faces and strips are numbered from
 * `firstNumber` in messages (1 for OBJ, 0 for the rest).
 */
void MakeTriangleMesh(vtkPolyData* polygons, vtkPolyData* triangles, vtkIdType firstNumber = 0);
}

#endif
