#include "vtkShadelabFlatTriangles.h"

#include "shadelabShaderSource.h"
#include "shadelabTriangleMesh.h"

#include <algorithm>
#include <vector>

#include <vtkArrayDispatch.h>
#include <vtkCellArray.h>
#include <vtkDataArrayRange.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
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

namespace
{
// The output's connectivity (`out`, 3 ids a triangle) and, for each output
// point, the input point it copies (`sources`): the used input points first,
// in their order, then one copy for each triangle whose last vertex an
// earlier triangle took. Returns the number of copies.
template <typename Id>
vtkIdType AssignProvokingPoints(
  const Id* in, vtkIdType triangles, vtkIdType inputPoints, vtkIdType* out, vtkIdList* sources)
{
  std::vector<vtkIdType> kept(inputPoints, -1);
  for (vtkIdType i = 0; i < 3 * triangles; ++i)
  {
    kept[in[i]] = 0;
  }
  vtkIdType used = 0;
  for (vtkIdType& k : kept)
  {
    if (k == 0)
    {
      k = used++;
    }
  }
  std::vector<bool> owned(inputPoints, false);
  std::vector<vtkIdType> copied; // the input point of each copy
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    const Id* ids = in + 3 * t;
    out[3 * t] = kept[ids[0]];
    out[3 * t + 1] = kept[ids[1]];
    if (!owned[ids[2]])
    {
      owned[ids[2]] = true;
      out[3 * t + 2] = kept[ids[2]];
    }
    else
    {
      out[3 * t + 2] = used + static_cast<vtkIdType>(copied.size());
      copied.push_back(ids[2]);
    }
  }
  sources->SetNumberOfIds(used + static_cast<vtkIdType>(copied.size()));
  vtkIdType* source = sources->GetPointer(0);
  for (vtkIdType p = 0; p < inputPoints; ++p)
  {
    if (kept[p] >= 0)
    {
      source[kept[p]] = p;
    }
  }
  std::copy(copied.begin(), copied.end(), source + used);
  return static_cast<vtkIdType>(copied.size());
}

// Each triangle's unit normal of (p1 - p0) x (p2 - p0), in double, cast to
// float, at its provoking (last) point; normals must hold zeros.
struct FaceNormalsAtProvokingPoints
{
  template <typename PointArray>
  void operator()(PointArray* points, const vtkIdType* ids, vtkIdType triangles, float* normals)
  {
    const auto xyz = vtk::DataArrayTupleRange<3>(points);
    for (vtkIdType t = 0; t < triangles; ++t, ids += 3)
    {
      double p[3][3];
      for (int k = 0; k < 3; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          p[k][c] = static_cast<double>(xyz[ids[k]][c]);
        }
      }
      double e1[3], e2[3], n[3];
      vtkMath::Subtract(p[1], p[0], e1);
      vtkMath::Subtract(p[2], p[0], e2);
      vtkMath::Cross(e1, e2, n);
      vtkMath::Normalize(n); // leaves (0,0,0) as it is
      float* provoking = normals + 3 * ids[2];
      for (int c = 0; c < 3; ++c)
      {
        provoking[c] = static_cast<float>(n[c]);
      }
    }
  }
};

// The tuples of `array` at `sources`, in an array of its own type and name.
vtkSmartPointer<vtkDataArray> Gathered(vtkDataArray* array, vtkIdList* sources)
{
  vtkSmartPointer<vtkDataArray> gathered;
  gathered.TakeReference(array->NewInstance());
  gathered->SetName(array->GetName());
  gathered->SetNumberOfComponents(array->GetNumberOfComponents());
  gathered->SetNumberOfTuples(sources->GetNumberOfIds());
  array->GetTuples(sources, gathered);
  return gathered;
}
}

int vtkShadelabFlatTriangles::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->NumberOfCopies = 0;

  vtkCellArray* polys = input->GetPolys();
  const vtkIdType triangles = polys->GetNumberOfCells();
  if (polys->GetNumberOfConnectivityIds() != 3 * triangles ||
    (triangles > 0 && polys->GetMaxCellSize() != 3))
  {
    vtkErrorMacro("flat shading needs triangles only");
    return 0;
  }
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(triangles + 1);
  connectivity->SetNumberOfValues(3 * triangles);
  vtkIdType* offset = offsets->GetPointer(0);
  for (vtkIdType i = 0; i <= triangles; ++i)
  {
    offset[i] = 3 * i;
  }
  auto sources = vtkSmartPointer<vtkIdList>::New();
  const vtkIdType inputPoints = input->GetNumberOfPoints();
  vtkIdType* ids = connectivity->GetPointer(0);
  this->NumberOfCopies = polys->IsStorage64Bit()
    ? AssignProvokingPoints(
        polys->GetConnectivityArray64()->GetPointer(0), triangles, inputPoints, ids, sources)
    : AssignProvokingPoints(
        polys->GetConnectivityArray32()->GetPointer(0), triangles, inputPoints, ids, sources);

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(Gathered(input->GetPoints()->GetData(), sources));
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName(shadelab::FaceNormalArrayName);
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(sources->GetNumberOfIds());
  std::fill_n(normals->GetPointer(0), 3 * sources->GetNumberOfIds(), 0.0f);
  FaceNormalsAtProvokingPoints faceNormals;
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(
        points->GetData(), faceNormals, ids, triangles, normals->GetPointer(0)))
  {
    faceNormals(points->GetData(), ids, triangles, normals->GetPointer(0));
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);

  output->SetPoints(points);
  output->SetPolys(cells);
  output->GetPointData()->AddArray(normals);
  // What the rules read per vertex besides the normal: kd from the colours,
  // the texture coordinates; a copy takes its input point's, which the
  // fragments interpolate as before.
  for (const char* name : { shadelab::ColorsArrayName, shadelab::TextureCoordinatesArrayName })
  {
    if (vtkDataArray* array = input->GetPointData()->GetArray(name))
    {
      output->GetPointData()->AddArray(Gathered(array, sources));
    }
  }
  return 1;
}

void vtkShadelabFlatTriangles::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfCopies: " << this->NumberOfCopies << "\n";
}
