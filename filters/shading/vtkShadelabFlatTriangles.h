/**
 * @class   vtkShadelabFlatTriangles
 * @brief   gives every triangle its own three points, carrying its face normal
 *
 * Flat shading (the lecture's rule) evaluates the equation once per triangle,
 * at its provoking vertex, with the face normal, in the vertex stage. A
 * vertex shader sees one vertex at a time, so each triangle gets its own
 * three points, in the cell's order (the last one provokes), and the point
 * array shadelabFaceNormal holds the unit normal of (p1 - p0) x (p2 - p0),
 * computed in double; (0,0,0) for a degenerate triangle. The vertex colours
 * ("Colors", per-vertex kd) and the texture coordinates ("TextureCoordinates",
 * looked up per fragment) go along, each point with its corner's; no other
 * arrays.
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

protected:
  vtkShadelabFlatTriangles() = default;
  ~vtkShadelabFlatTriangles() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkShadelabFlatTriangles(const vtkShadelabFlatTriangles&) = delete;
  void operator=(const vtkShadelabFlatTriangles&) = delete;
};

#endif
