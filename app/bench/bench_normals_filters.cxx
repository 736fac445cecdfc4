#include "bench/bench_normals.h"

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

namespace shadelab
{
namespace bench_normals
{
const char* WeightingName(int weighting)
{
  return ToString(static_cast<vtkShadelabMeshNormals::Weightings>(weighting));
}

vtkSmartPointer<vtkPolyDataNormals> VtkNormals(vtkPolyData* mesh, bool defaults)
{
  auto filter = vtkSmartPointer<vtkPolyDataNormals>::New();
  filter->SetInputData(mesh);
  if (!defaults)
  {
    filter->SplittingOff();
    filter->ConsistencyOff();
    filter->ComputeCellNormalsOff();
  }
  return filter;
}

vtkSmartPointer<vtkShadelabMeshNormals> OurNormals(
  vtkPolyData* mesh, int weighting, bool splitting, bool consistency)
{
  auto filter = vtkSmartPointer<vtkShadelabMeshNormals>::New();
  filter->SetInputData(mesh);
  filter->SetWeighting(weighting);
  filter->SetSplitting(splitting);
  filter->SetFeatureAngle(30);
  filter->SetConsistency(consistency);
  return filter;
}

bool HasPointNormals(vtkAlgorithm* filter)
{
  vtkPolyData* output = vtkPolyData::SafeDownCast(filter->GetOutputDataObject(0));
  return output && output->GetPointData()->GetNormals() &&
    output->GetPointData()->GetNormals()->GetNumberOfTuples() == output->GetNumberOfPoints();
}
}
}
