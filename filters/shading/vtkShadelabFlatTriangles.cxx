#include "vtkShadelabFlatTriangles.h"

#include "shadelabShaderSource.h"
#include "shadelabTriangleMesh.h"

#include <array>
#include <utility>
#include <vector>

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

vtkStandardNewMacro(vtkShadelabFlatTriangles);

int vtkShadelabFlatTriangles::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);

  vtkCellArray* polys = input->GetPolys();
  const vtkIdType triangles = polys->GetNumberOfCells();
  if (polys->GetNumberOfConnectivityIds() != 3 * triangles)
  {
    vtkErrorMacro("flat shading needs triangles only");
    return 0;
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(3 * triangles);
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName(shadelab::FaceNormalArrayName);
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(3 * triangles);

  // What the rules read per vertex besides the normal: kd from the colours,
  // the texture coordinates; each corner takes its vertex's.
  std::vector<std::pair<vtkDataArray*, vtkSmartPointer<vtkDataArray>>> carried;
  for (const char* name : { shadelab::ColorsArrayName, shadelab::TextureCoordinatesArrayName })
  {
    if (vtkDataArray* array = input->GetPointData()->GetArray(name))
    {
      vtkSmartPointer<vtkDataArray> corners;
      corners.TakeReference(array->NewInstance());
      corners->SetName(name);
      corners->SetNumberOfComponents(array->GetNumberOfComponents());
      corners->SetNumberOfTuples(3 * triangles);
      carried.emplace_back(array, corners);
    }
  }

  vtkIdType npts = 0;
  const vtkIdType* ids = nullptr;
  vtkIdType next = 0;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      input->GetPoint(ids[k], p[k]);
      points->SetPoint(next + k, p[k]);
      for (auto& [array, corners] : carried)
      {
        corners->SetTuple(next + k, ids[k], array);
      }
    }
    double e1[3], e2[3], n[3];
    vtkMath::Subtract(p[1], p[0], e1);
    vtkMath::Subtract(p[2], p[0], e2);
    vtkMath::Cross(e1, e2, n);
    vtkMath::Normalize(n); // leaves (0,0,0) as it is
    for (int k = 0; k < 3; ++k)
    {
      normals->SetTypedTuple(next + k,
        std::array<float, 3>{
          static_cast<float>(n[0]), static_cast<float>(n[1]), static_cast<float>(n[2]) }
          .data());
    }
    next += 3;
  }
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(triangles + 1);
  connectivity->SetNumberOfValues(3 * triangles);
  for (vtkIdType i = 0; i <= triangles; ++i)
  {
    offsets->SetValue(i, 3 * i);
  }
  for (vtkIdType i = 0; i < 3 * triangles; ++i)
  {
    connectivity->SetValue(i, i);
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);

  output->SetPoints(points);
  output->SetPolys(cells);
  output->GetPointData()->AddArray(normals);
  for (auto& [array, corners] : carried)
  {
    output->GetPointData()->AddArray(corners);
  }
  return 1;
}

void vtkShadelabFlatTriangles::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
