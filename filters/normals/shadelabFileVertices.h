/**
 * @brief   normals on the file's vertices of points that a reader split
 *
 * A reader splits a file's vertex into several points where its corners
 * differ in what a point holds besides its position: an OBJ vertex at a
 * texture's seam (different vt) or a normal's (different vn). Normals
 * computed on those points would crease at every seam, and a texture's
 * seams are no feature of the surface. So where the input has the point
 * data "FileVertex" (shadelabTriangleMesh.h), vtkShadelabMeshNormals welds
 * the points of each file vertex onto the lowest-numbered of them
 * (Welded()), computes the normals on the welded triangles exactly as it
 * would for a file without the seams, and then gives each input point the
 * normal of its file vertex (Unweld()): the texture coordinates stay split,
 * the normals do not differ.
 */
#ifndef shadelabFileVertices_h
#define shadelabFileVertices_h

#include "shadelabNormalsMesh.h"

#include <vtkFloatArray.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkPolyData;

namespace shadelab::normals
{
/** The points of each file vertex, and the input's own triangles beside the welded ones. */
class FileVertices
{
public:
  /**
   * Reads the input's FileVertex; without it the welding is off (Active()
   * false). An error message if it is not one number of a point per point.
   */
  std::string Read(vtkPolyData* input);

  bool Active() const { return !this->Weld.empty(); }

  /** The input's `count` triangle ids (3 a face) welded in place; keeps the input's own. */
  void Welded(Id* triangles, vtkIdType count);

  /**
   * Reverses the input's own triangles as Consistency reversed the welded
   * ones (`oriented`: its second and third corner swapped). A face whose two
   * corners are one file vertex has no area, so which of them comes first
   * does not matter.
   */
  void FollowOrientation(const Id* oriented);

  /**
   * The output from the welded one's: `cornerPoint` (3 a face) the welded
   * output point of each corner, `points` the input's point count,
   * `normals` the welded output points' normals. Gives each corner's output
   * point (`corners`), each output point's input point (`source`: the
   * input's points, then copies) and, in `normals`, the output points'
   * normals. An input point keeps its number for the welded point of its
   * first corner; a corner of it at another welded point (feature-angle
   * splitting split its file vertex) gets a copy, one per such pair. Points
   * that no face uses take their file vertex's normal.
   */
  void Unweld(const Id* cornerPoint, vtkIdType points, vtkSmartPointer<vtkFloatArray>& normals,
    std::vector<Id>& corners, std::vector<vtkIdType>& source) const;

private:
  std::vector<Id> Weld;    // per input point: the lowest-numbered point of its file vertex
  std::vector<Id> Corners; // the input's own triangles, as oriented
};
}

#endif
