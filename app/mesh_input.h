// A mesh file in, ready to render: read by the filters library's reader,
// with the vertex normals that --normals and --weighting ask for.
#ifndef shadelab_mesh_input_h
#define shadelab_mesh_input_h

#include "options.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace shadelab
{
struct LoadedMesh
{
  vtkSmartPointer<vtkPolyData> Mesh; // null on error
  std::string Error;                 // one line, without the file name
  bool NormalsFromFile = false;
};

LoadedMesh LoadMesh(const SceneOptions& options);

/** mesh with vertex normals computed by vtkShadelabMeshNormals; null on failure. */
vtkSmartPointer<vtkPolyData> ComputeNormals(vtkPolyData* mesh, const std::string& weighting);
}

#endif
