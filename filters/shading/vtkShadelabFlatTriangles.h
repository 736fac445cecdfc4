/**
 * @class   vtkShadelabFlatTriangles
 * @brief   gives every triangle a provoking point of its own, carrying its face normal
 *
 * Flat shading (the lecture's rule) evaluates the equation once per triangle,
 * at its provoking vertex (the cell's last, GL's default), with the face
 * normal, in the vertex stage. A vertex shader sees one vertex at a time, so
 * no two triangles may share their last point. The cells keep their order
 * and their vertex order; walking them, a triangle whose last vertex no
 * earlier triangle owns takes it, and a later one gets a copy of that vertex
 * (same position, colour and texture coordinates) as its last point. The
 * point array shadelabFaceNormal holds, at each provoking point, the unit
 * normal of (p1 - p0) x (p2 - p0), computed in double ((0,0,0) for a
 * degenerate triangle); at the other points (0,0,0), which flat shading
 * never reads. Only the points that the triangles use are kept, so the
 * output's bounds are the triangles'. The vertex colours ("Colors", per-vertex
 * kd) and the texture coordinates ("TextureCoordinates", looked up per
 * fragment) go along; no other arrays. The copies (GetNumberOfCopies()) are
 * T minus the number of distinct last vertices, the least that keeps each
 * triangle's provoking vertex: 0.54T on the bunny, 0.66T on its 2-level Loop
 * subdivision, against 3T points if every triangle had three of its own.
 */
#ifndef vtkShadelabFlatTriangles_h
#define vtkShadelabFlatTriangles_h

#include <vtkPolyDataAlgorithm.h>

class vtkShadelabFlatTriangles : public vtkPolyDataAlgorithm
{
public:
  static vtkShadelabFlatTriangles* New();
  vtkTypeMacro(vtkShadelabFlatTriangles, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How many points of the last output are copies of a used input point. */
  vtkGetMacro(NumberOfCopies, vtkIdType);

protected:
  vtkShadelabFlatTriangles() = default;
  ~vtkShadelabFlatTriangles() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkShadelabFlatTriangles(const vtkShadelabFlatTriangles&) = delete;
  void operator=(const vtkShadelabFlatTriangles&) = delete;

  vtkIdType NumberOfCopies = 0;
};

#endif
