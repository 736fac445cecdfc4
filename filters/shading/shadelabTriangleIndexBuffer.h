/**
 * @brief   the index buffer of a surface's triangles, as VTK 9.1 makes it
 *
 * vtkOpenGLIndexBufferObject::AppendTriangleIndexBuffer reads each cell
 * through an iterator that copies a 32-bit cell into a list first, and
 * grows its vector by doubling: at 17.8M triangles about 0.8 s and 213 MB
 * of copies, a third of the first frame. AppendTriangleIndices makes the
 * same indices, read in place and written into a vector sized once.
 */
#ifndef shadelabTriangleIndexBuffer_h
#define shadelabTriangleIndexBuffer_h

#include <vector>

class vtkCellArray;
class vtkDataArray;

namespace shadelab
{
/**
 * Whether VTK draws the triangle of these corners (3-tuples compared in the
 * points' own type): not when two of them are at one position. VTK's index
 * buffer leaves the others out, so gl_PrimitiveID does not count them.
 */
template <typename Tuple>
bool IsDrawn(const Tuple& a, const Tuple& b, const Tuple& c)
{
  return a != b && a != c && b != c;
}

/**
 * Appends the triangles of `polys` to `indices` as AppendTriangleIndexBuffer
 * does (no offset, no edge values): each cell of 3 or more ids as a fan from
 * its first corner, in cell order, those IsDrawn() keeps. Returns false, and
 * appends nothing, where the points are neither float nor double.
 */
bool AppendTriangleIndices(
  vtkCellArray* polys, vtkDataArray* points, std::vector<unsigned int>& indices);
}

#endif
