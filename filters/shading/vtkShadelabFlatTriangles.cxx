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
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>
#include <vtkTypeInt64Array.h>

vtkStandardNewMacro(vtkShadelabFlatTriangles);

namespace
{
// The output's connectivity (`out`, 3 ids a triangle) and, for each output
// point, the input point it copies (`sources`): the used input points first,
// in their order, then one copy for each triangle whose last vertex an
// earlier triangle took, in the triangles' order. Returns the number of
// copies, or -1 (and nothing assigned) when an id names no input point.
template <typename InId, typename OutId>
vtkIdType AssignProvokingPoints(
  const InId* in, vtkIdType triangles, vtkIdType inputPoints, OutId* out, vtkIdList* sources)
{
  std::vector<vtkIdType> kept(inputPoints, -1);
  for (vtkIdType i = 0; i < 3 * triangles; ++i)
  {
    if (in[i] < 0 || static_cast<vtkIdType>(in[i]) >= inputPoints)
    {
      return -1;
    }
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
  // Counted first, so that the sources are allocated once, at their size.
  std::vector<bool> owned(inputPoints, false);
  vtkIdType copies = 0;
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    copies += owned[in[3 * t + 2]] ? 1 : 0;
    owned[in[3 * t + 2]] = true;
  }
  sources->SetNumberOfIds(used + copies);
  vtkIdType* source = sources->GetPointer(0);
  for (vtkIdType p = 0; p < inputPoints; ++p)
  {
    if (kept[p] >= 0)
    {
      source[kept[p]] = p;
    }
  }
  std::fill(owned.begin(), owned.end(), false);
  vtkIdType next = used;
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    const InId* ids = in + 3 * t;
    out[3 * t] = static_cast<OutId>(kept[ids[0]]);
    out[3 * t + 1] = static_cast<OutId>(kept[ids[1]]);
    if (!owned[ids[2]])
    {
      owned[ids[2]] = true;
      out[3 * t + 2] = static_cast<OutId>(kept[ids[2]]);
    }
    else
    {
      source[next] = ids[2];
      out[3 * t + 2] = static_cast<OutId>(next++);
    }
  }
  return copies;
}

// Each triangle's unit normal of (p1 - p0) x (p2 - p0), in double from the
// input's points, cast to float, at its provoking (last) output point;
// normals must hold zeros.
struct FaceNormalsAtProvokingPoints
{
  template <typename PointArray, typename InId, typename OutId>
  void operator()(
    PointArray* points, const InId* in, const OutId* out, vtkIdType triangles, float* normals) const
  {
    const auto xyz = vtk::DataArrayTupleRange<3>(points);
    for (vtkIdType t = 0; t < triangles; ++t)
    {
      double p[3][3];
      for (int k = 0; k < 3; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          p[k][c] = static_cast<double>(xyz[in[3 * t + k]][c]);
        }
      }
      double e1[3], e2[3], n[3];
      vtkMath::Subtract(p[1], p[0], e1);
      vtkMath::Subtract(p[2], p[0], e2);
      vtkMath::Cross(e1, e2, n);
      vtkMath::Normalize(n); // leaves (0,0,0) as it is
      float* provoking = normals + 3 * static_cast<vtkIdType>(out[3 * t + 2]);
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

// input's triangles (`in`, its connectivity) with provoking points of their
// own into output, its connectivity in OutIds; returns the number of copies,
// or -1 (and output untouched) when a triangle names no input point.
template <typename OutIds, typename InId>
vtkIdType Build(vtkPolyData* input, const InId* in, vtkPolyData* output)
{
  using OutId = typename OutIds::ValueType;
  const vtkIdType triangles = input->GetPolys()->GetNumberOfCells();
  auto offsets = vtkSmartPointer<OutIds>::New();
  auto connectivity = vtkSmartPointer<OutIds>::New();
  offsets->SetNumberOfValues(triangles + 1);
  connectivity->SetNumberOfValues(3 * triangles);
  OutId* offset = offsets->GetPointer(0);
  for (vtkIdType i = 0; i <= triangles; ++i)
  {
    offset[i] = static_cast<OutId>(3 * i);
  }
  OutId* out = connectivity->GetPointer(0);
  auto sources = vtkSmartPointer<vtkIdList>::New();
  const vtkIdType copies =
    AssignProvokingPoints(in, triangles, input->GetNumberOfPoints(), out, sources.Get());
  if (copies < 0)
  {
    return copies;
  }
  const vtkIdType points = sources->GetNumberOfIds();

  auto positions = vtkSmartPointer<vtkPoints>::New();
  positions->SetData(Gathered(input->GetPoints()->GetData(), sources));
  output->SetPoints(positions);
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
  sources = nullptr; // freed before the normals take their memory

  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName(shadelab::FaceNormalArrayName);
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(points);
  std::fill_n(normals->GetPointer(0), 3 * points, 0.0f);
  const FaceNormalsAtProvokingPoints faceNormals;
  vtkDataArray* xyz = input->GetPoints()->GetData();
  if (!vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::Reals>::Execute(
        xyz, faceNormals, in, out, triangles, normals->GetPointer(0)))
  {
    faceNormals(xyz, in, out, triangles, normals->GetPointer(0));
  }
  output->GetPointData()->AddArray(normals);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  output->SetPolys(cells);
  return copies;
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
  // 32-bit ids where they fit (the output has fewer than 3T points): half
  // the memory of VTK's default 64-bit ids, the same index buffer.
  auto build = [&](const auto* in)
  {
    return 3 * triangles <= VTK_TYPE_INT32_MAX ? Build<vtkTypeInt32Array>(input, in, output)
                                               : Build<vtkTypeInt64Array>(input, in, output);
  };
  this->NumberOfCopies = polys->IsStorage64Bit()
    ? build(polys->GetConnectivityArray64()->GetPointer(0))
    : build(polys->GetConnectivityArray32()->GetPointer(0));
  if (this->NumberOfCopies < 0)
  {
    this->NumberOfCopies = 0;
    vtkErrorMacro("a triangle names a point that the mesh does not have");
    return 0;
  }
  return 1;
}

void vtkShadelabFlatTriangles::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfCopies: " << this->NumberOfCopies << "\n";
}
