#include "shadelabOutputTopology.h"

#include "shadelabFileVertices.h"
#include "shadelabMeshConnectivity.h"
#include "shadelabVertexSplitting.h"

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

namespace shadelab::normals
{
namespace
{
// The output's triangles: the input's unless points were split or faces
// reversed; only the triangles are kept (verts, lines and strips dropped).
void SetTriangles(vtkPolyData* input, const OutputTopology& topology, vtkPolyData* output)
{
  if (!topology.Connectivity)
  {
    output->SetPolys(input->GetPolys());
    return;
  }
  const vtkIdType faces = topology.Connectivity->GetNumberOfValues() / 3;
  auto offsets = vtkSmartPointer<vtkTypeInt32Array>::New();
  offsets->SetNumberOfValues(faces + 1);
  Id* offset = offsets->GetPointer(0);
  for (vtkIdType f = 0; f <= faces; ++f)
  {
    offset[f] = static_cast<Id>(3 * f);
  }
  auto polys = vtkSmartPointer<vtkCellArray>::New();
  polys->SetData(offsets, topology.Connectivity);
  output->SetPolys(polys);
}

// The output's points and their data: the input's, then copies of the
// split ones (with their data).
void SetPoints(vtkPolyData* input, const OutputTopology& topology, vtkPolyData* output)
{
  const vtkIdType points = input->GetNumberOfPoints();
  const vtkIdType outputPoints = topology.Points;
  if (outputPoints == points)
  {
    output->SetPoints(input->GetPoints());
    output->GetPointData()->PassData(input->GetPointData());
    return;
  }
  auto splitPoints = vtkSmartPointer<vtkPoints>::New();
  splitPoints->SetDataType(input->GetPoints()->GetDataType());
  splitPoints->SetNumberOfPoints(outputPoints);
  splitPoints->GetData()->InsertTuples(0, points, 0, input->GetPoints()->GetData());
  auto from = vtkSmartPointer<vtkIdList>::New();
  auto to = vtkSmartPointer<vtkIdList>::New();
  from->SetNumberOfIds(outputPoints - points);
  to->SetNumberOfIds(outputPoints - points);
  for (vtkIdType i = points; i < outputPoints; ++i)
  {
    from->SetId(i - points, topology.Source[i]);
    to->SetId(i - points, i);
  }
  splitPoints->GetData()->InsertTuples(to, from, input->GetPoints()->GetData());
  output->SetPoints(splitPoints);
  vtkPointData* pointData = output->GetPointData();
  pointData->CopyAllocate(input->GetPointData(), outputPoints);
  pointData->CopyData(input->GetPointData(), 0, points, 0);
  pointData->CopyData(input->GetPointData(), from, to);
}
}

OutputTopology MakeTopology(const MeshConnectivity& c, bool splitting, double featureAngle)
{
  OutputTopology topology;
  topology.Points = c.Points;
  if (!splitting && !c.Reversed)
  {
    return topology;
  }
  if (!splitting)
  {
    topology.Connectivity = c.Triangles; // the reversed copy, shared
    return topology;
  }
  topology.Connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  topology.Connectivity->SetNumberOfValues(3 * c.Faces());
  SplitVertices(c, std::cos(vtkMath::RadiansFromDegrees(featureAngle)), topology.Source,
    topology.Connectivity->GetPointer(0), topology.Split);
  topology.Points = static_cast<vtkIdType>(topology.Source.size());
  return topology;
}

OutputTopology Unweld(const FileVertices& files, const MeshConnectivity& c,
  const OutputTopology& welded, vtkSmartPointer<vtkFloatArray>& normals)
{
  const Id* cornerPoint =
    welded.Connectivity ? welded.Connectivity->GetPointer(0) : c.TriangleIds();
  std::vector<Id> corners;
  OutputTopology topology;
  files.Unweld(cornerPoint, c.Points, normals, corners, topology.Source);
  topology.Points = static_cast<vtkIdType>(topology.Source.size());
  topology.Connectivity = vtkSmartPointer<vtkTypeInt32Array>::New();
  topology.Connectivity->SetNumberOfValues(static_cast<vtkIdType>(corners.size()));
  std::copy(corners.begin(), corners.end(), topology.Connectivity->GetPointer(0));
  return topology;
}

void SetOutputMesh(vtkPolyData* input, const OutputTopology& topology, vtkPolyData* output)
{
  SetTriangles(input, topology, output);
  SetPoints(input, topology, output);
}
}
