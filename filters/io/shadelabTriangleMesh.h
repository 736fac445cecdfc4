/**
 * @brief   the last step that every mesh reader shares
 *
 * A parser collects points, optional point attributes, faces and triangle
 * strips in a PolygonMesh; ToPolyData() wraps them as vtkPolyData, and
 * MakeTriangleMesh() checks that data (from a parser or from VTK's own
 * readers) and turns it into what every shadelab reader outputs: double
 * points (float where a binary file stores 32-bit floats), triangles only, the point normals, if
 * any, as the float array "Normals", and where the file has them the vertex colours, texture
 * coordinates, the file's vertex of each point and the part each triangle comes from (the arrays
 * named below), for the materials and textures that go with them (shadelabPartMaterials.h).
 */
#ifndef shadelabTriangleMesh_h
#define shadelabTriangleMesh_h

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <vector>

class vtkPolyData;

namespace shadelab
{
/**
 * Point data: vertex colours, float RGBA in 0..1 as the file gives them (no
 * colour-space conversion; a file without alpha gets 1).
 */
constexpr const char* ColorsArrayName = "Colors";
/**
 * Point data, also the active texture coordinates: float s t with VTK's
 * (OpenGL's) origin at the image's bottom-left; formats that count t from
 * the top (glTF) are turned over by their reader.
 */
constexpr const char* TextureCoordinatesArrayName = "TextureCoordinates";
/** Cell data: int, the part of the file that each triangle comes from (glTF: primitive). */
constexpr const char* PartArrayName = "Part";
/**
 * Point data (vtkIdType): the file's vertex that each point is, where a
 * reader made several points of one vertex (an OBJ vertex used with
 * different vt or vn); absent where every point is its own vertex. Point
 * i < the file's vertex count is vertex i itself, so the value is also the
 * number of the point whose copy this is. vtkShadelabMeshNormals computes
 * normals on these vertices, so that a texture's seams do not crease them.
 */
constexpr const char* FileVertexArrayName = "FileVertex";

struct PolygonMesh
{
  std::vector<double> Points; // x y z per point
  // A binary file stores x y z as 32-bit floats: the points stay float (exactly
  // the file's values, in half the memory of double).
  bool FloatPoints = false;
  std::vector<float> Normals;            // nx ny nz per point, or empty
  std::vector<float> Colors;             // r g b a per point, or empty
  std::vector<float> TextureCoordinates; // s t per point, or empty
  std::vector<vtkIdType> FileVertices;   // the file's vertex of each point, or empty
  // Face i is FaceIds[FaceOffsets[i]] .. FaceIds[FaceOffsets[i + 1] - 1].
  std::vector<vtkIdType> FaceOffsets{ 0 };
  std::vector<vtkIdType> FaceIds;
  std::vector<vtkIdType> StripOffsets{ 0 };
  std::vector<vtkIdType> StripIds;
  // The part of each face, then of each strip (VTK's cell order); or empty.
  std::vector<int> Parts;
};

/**
 * The parser's arrays as vtkPolyData: points, point and cell attributes,
 * polys and strips (in 32-bit storage where their numbers fit). Each array
 * of `mesh` is freed as soon as it is copied.
 */
vtkSmartPointer<vtkPolyData> ToPolyData(PolygonMesh&& mesh);

/**
 * Checks `polygons` and writes the triangle mesh into `triangles`. Throws
 * MeshReadError on non-finite points or normals, normals that are not one
 * 3-vector per point, faces or strips with fewer than 3 vertices or with an
 * index out of range, and when no triangle results ("no triangles": vertices
 * and lines are dropped). Faces of 4+ vertices are triangulated by VTK's ear
 * cutting (right for concave ones), strips with alternating orientation; the
 * zero-area triangles that strips use to join runs are dropped, those of
 * faces kept. The colours, texture coordinates, file vertices (in range)
 * and parts (by the names above, with those types and sizes; other arrays
 * are dropped) go along:
 * each triangle has the part of its face or strip. Vertices, faces and
 * strips are numbered from `firstNumber` in messages (1 for OBJ, 0 for the
 * rest).
 */
void MakeTriangleMesh(vtkPolyData* polygons, vtkPolyData* triangles, vtkIdType firstNumber = 0);
}

#endif
