// The face normals that flat shading reads, one per triangle drawn.
#ifndef shadelabFaceNormals_h
#define shadelabFaceNormals_h

#include <vtkType.h>

class vtkPolyData;

namespace shadelab
{
/**
 * Triangles [first, first + count) of mesh's polys, in their order: each
 * drawn one's unit normal (shadelab::FaceNormal, in double from the points),
 * cast to float, three floats a triangle into `normals`; returns how many
 * triangles it wrote. VTK 9.1's index buffer (vtkOpenGLIndexBufferObject)
 * leaves out a triangle with two corners at the same position, so
 * gl_PrimitiveID counts only the others: so do these normals. The polys must
 * be triangles naming points of the mesh, as the readers make them.
 * Computed on every core; each triangle's value is its own, so the result
 * does not depend on how the work is split.
 */
vtkIdType ComputeFaceNormals(vtkPolyData* mesh, vtkIdType first, vtkIdType count, float* normals);
}

#endif
