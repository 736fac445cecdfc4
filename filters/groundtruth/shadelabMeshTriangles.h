// A VTK triangle mesh as the oracle's rays take it: its points in double and
// its triangles' corners in cell order.
#ifndef shadelabMeshTriangles_h
#define shadelabMeshTriangles_h

#include "shadelabPixelRays.h"

#include <vector>

class vtkPolyData;

namespace shadelab
{
std::vector<Vec3> PointsOf(vtkPolyData* mesh);

/**
 * The mesh's polygons in cell order. shadelab's readers give triangles
 * only; any other cell stands as point 0 three times, which no ray meets,
 * so that the indices stay the cells'.
 */
std::vector<TriangleCorners> TrianglesOf(vtkPolyData* mesh);
}

#endif
