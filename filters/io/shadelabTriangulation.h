/**
 * @brief   a mesh's faces and strips as triangles, for shadelabTriangleMesh
 */
#ifndef shadelabTriangulation_h
#define shadelabTriangulation_h

#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <vector>

class vtkCellArray;
class vtkPoints;
class vtkPolyData;

namespace shadelab
{
/**
 * The triangles of the faces, then of the strips; `sources` gets the cell
 * (in VTK's numbering: faces, then strips) that each triangle comes from,
 * and stays empty where the faces are all triangles already.
 */
vtkSmartPointer<vtkCellArray> Triangulate(
  vtkPolyData* polygons, vtkPoints* points, std::vector<vtkIdType>& sources);
}

#endif
