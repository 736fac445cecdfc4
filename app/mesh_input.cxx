#include "mesh_input.h"

#include "vtkShadelabMeshReader.h"
#include "vtkShadelabOutputWindow.h"

#include <vtkExecutive.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkTriangleMeshPointNormals.h>

namespace shadelab
{
namespace
{
std::string FirstVtkError(const char* fallback)
{
  auto* window = vtkShadelabOutputWindow::SafeDownCast(vtkOutputWindow::GetInstance());
  return window && !window->GetFirstError().empty() ? window->GetFirstError() : fallback;
}
}

// Until the OpenMesh filter (issue 4): VTK's unweighted average
// (vtkPolyDataNormals, no splitting, no reorientation, so vertices stay as
// they are) or its area-weighted one.
vtkSmartPointer<vtkPolyData> ComputeNormals(vtkPolyData* mesh, const std::string& weighting)
{
  vtkSmartPointer<vtkPolyDataAlgorithm> filter;
  if (weighting == "area")
  {
    filter = vtkSmartPointer<vtkTriangleMeshPointNormals>::New();
  }
  else
  {
    auto normals = vtkSmartPointer<vtkPolyDataNormals>::New();
    normals->SplittingOff();
    normals->ConsistencyOff();
    normals->ComputeCellNormalsOff();
    filter = normals;
  }
  filter->SetInputData(mesh);
  if (!filter->GetExecutive()->Update())
  {
    return nullptr;
  }
  return filter->GetOutput();
}

LoadedMesh LoadMesh(const SceneOptions& options)
{
  LoadedMesh result;
  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(options.Mesh.c_str());
  if (!reader->GetExecutive()->Update())
  {
    result.Error = FirstVtkError("cannot be read");
    return result;
  }
  vtkSmartPointer<vtkPolyData> mesh = reader->GetOutput();
  result.NormalsFromFile = mesh->GetPointData()->GetNormals() != nullptr;

  if (options.Normals == NormalsMode::File && !result.NormalsFromFile)
  {
    result.Error = "has no vertex normals (--normals file)";
    return result;
  }
  const bool lit = options.ShadingRule == Shading::Gouraud || options.ShadingRule == Shading::Phong;
  const bool compute = options.Normals == NormalsMode::Compute ||
    (options.Normals == NormalsMode::Auto && !result.NormalsFromFile);
  if (lit && compute)
  {
    mesh = ComputeNormals(mesh, options.Weighting);
    if (!mesh)
    {
      result.Error = "normals: " + FirstVtkError("cannot be computed");
      return result;
    }
    result.NormalsFromFile = false;
  }
  result.Mesh = mesh;
  return result;
}
}
