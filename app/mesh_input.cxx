#include "mesh_input.h"

#include "errors.h"
#include "vtkShadelabMeshNormals.h"
#include "vtkShadelabMeshReader.h"

#include <vtkExecutive.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace shadelab
{
vtkSmartPointer<vtkPolyData> ComputeNormals(vtkPolyData* mesh, const std::string& weighting)
{
  auto normals = vtkSmartPointer<vtkShadelabMeshNormals>::New();
  normals->SetInputData(mesh);
  normals->SetWeightingByName(weighting.c_str());
  if (!normals->GetExecutive()->Update())
  {
    return nullptr;
  }
  return normals->GetOutput();
}

LoadedMesh LoadMesh(const SceneOptions& options)
{
  LoadedMesh result;
  auto reader = vtkSmartPointer<vtkShadelabMeshReader>::New();
  reader->SetFileName(options.Mesh.c_str());
  // Computed normals are smooth across an OBJ's vn seams only if the
  // vertices are not split by the file's normals in the first place.
  reader->SetReadNormals(options.Normals != NormalsMode::Compute);
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
