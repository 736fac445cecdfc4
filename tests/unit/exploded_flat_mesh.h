// Flat shading's mesh as it was before vtkShadelabFlatTriangles shared
// points: every triangle its own three points, each carrying the face
// normal, the colours and texture coordinates of its corner. The reference
// that the shared-point mesh is held against, field by field and picture by
// picture.
#ifndef shadelab_exploded_flat_mesh_h
#define shadelab_exploded_flat_mesh_h

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace shadelab
{
/** mesh (triangles only) exploded as above, points of its point type. */
vtkSmartPointer<vtkPolyData> ExplodedFlatMesh(vtkPolyData* mesh);
}

#endif
