#include "shadelabMeshConnectivity.h"

#include "shadelabCornerWeights.h"
#include "shadelabFaceOrientation.h"

#include <vtkFloatArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <array>
#include <cmath>
#include <future>

namespace shadelab::normals
{
namespace
{
// Disables OpenMesh's error stream for a scope: a refused face is expected
// here and handled, not an error to print.
class QuietOpenMesh
{
public:
  QuietOpenMesh()
    : WasEnabled(omerr().is_enabled())
  {
    omerr().disable();
  }
  ~QuietOpenMesh()
  {
    if (this->WasEnabled)
    {
      omerr().enable();
    }
  }

private:
  bool WasEnabled;
};
}

// Out of line: this is the one file that builds an OpenMesh mesh (see
// filters/CMakeLists.txt).
MeshConnectivity::MeshConnectivity() = default;
MeshConnectivity::~MeshConnectivity() = default;

void MeshConnectivity::Build(vtkPolyData* input, bool consistency,
  vtkSmartPointer<vtkTypeInt32Array> triangles, int weighting, bool connect)
{
  this->Points = input->GetNumberOfPoints();
  this->Triangles = std::move(triangles);
  this->Reversed =
    consistency && OrientConsistently(this->Triangles->GetPointer(0), this->Faces(), this->Points);

  vtkDataArray* points = input->GetPoints()->GetData();
  this->XYZ = vtkDoubleArray::FastDownCast(points);
  if (!this->XYZ)
  {
    this->XYZ = vtkSmartPointer<vtkDoubleArray>::New();
    vtkFloatArray* floats = vtkFloatArray::FastDownCast(points);
    if (floats)
    {
      // The readers' usual points: converted on all cores (exact, as
      // DeepCopy's conversion is).
      this->XYZ->SetNumberOfComponents(3);
      this->XYZ->SetNumberOfTuples(this->Points);
      const float* from = floats->GetPointer(0);
      double* to = this->XYZ->GetPointer(0);
      vtkSMPTools::For(0, 3 * this->Points,
        [from, to](vtkIdType begin, vtkIdType end)
        { std::copy(from + begin, from + end, to + begin); });
    }
    else
    {
      this->XYZ->DeepCopy(points);
    }
  }
  if (!connect)
  {
    return;
  }
  // The face geometry needs no connectivity: it is computed on a second
  // thread while OpenMesh builds hers (add_face is most of the time), on
  // one core, as the other is busy with add_face. A future, so that it is
  // waited for even if the build throws.
  auto computed = std::async(std::launch::async,
    [this, weighting]
    {
      this->StoreFaceGeometry(false);
      if (HasCornerWeights(weighting))
      {
        this->StoreCornerWeights(weighting);
      }
    });
  this->AddFaces();
  computed.get();
  this->Connected = true;
}

void MeshConnectivity::Connect()
{
  if (!this->Connected)
  {
    this->StoreFaceGeometry(true);
    this->AddFaces();
    this->Connected = true;
  }
}

// The input's points as OpenMesh's first vertices, then its faces, with
// copies of their vertices for those that OpenMesh refuses.
void MeshConnectivity::AddFaces()
{
  const double* p = this->XYZ->GetPointer(0);
  const vtkIdType faces = this->Faces();
  TriMesh& mesh = this->Mesh;
  mesh.reserve(this->Points, 3 * faces / 2 + 3, faces);
  mesh.resize(this->Points, 0, 0);
  for (vtkIdType i = 0; i < this->Points; ++i)
  {
    mesh.set_point(TriMesh::VertexHandle(static_cast<int>(i)), PointAt(p, i));
  }
  this->InDuplicatedFace.assign(this->Points, false);

  QuietOpenMesh quiet;
  for (vtkIdType f = 0; f < faces; ++f)
  {
    const Id* ids = this->TriangleIds() + 3 * f;
    std::array<TriMesh::VertexHandle, 3> corner;
    for (int k = 0; k < 3; ++k)
    {
      corner[k] = TriMesh::VertexHandle(static_cast<int>(ids[k]));
    }
    // A repeated vertex would corrupt OpenMesh's connectivity; add_face
    // itself refuses complex edges and vertices without changing the mesh.
    const bool repeated = ids[0] == ids[1] || ids[1] == ids[2] || ids[2] == ids[0];
    if (!repeated && mesh.add_face(corner[0], corner[1], corner[2]).is_valid())
    {
      continue;
    }
    // Refused: the face gets copies of its vertices, so it still has
    // normals (and keeps its number: face f stays OpenMesh face f).
    for (int k = 0; k < 3; ++k)
    {
      // From the input: a reference into OpenMesh's points would dangle
      // when add_vertex moves them.
      corner[k] = mesh.add_vertex(PointAt(p, ids[k]));
      this->CopyOf.push_back(ids[k]);
      this->InDuplicatedFace[ids[k]] = true;
    }
    mesh.add_face(corner[0], corner[1], corner[2]);
    ++this->DuplicatedFaces;
  }
}

void MeshConnectivity::StoreFaceGeometry(bool parallel)
{
  const double* xyz = this->XYZ->GetPointer(0);
  const vtkIdType faces = this->Faces();
  this->FaceNormal.resize(faces);
  this->DoubleArea.resize(faces);
  const Id* tri = this->TriangleIds();
  Vec3* faceNormal = this->FaceNormal.data();
  double* doubleArea = this->DoubleArea.data();
  // Independent per face, so cores can share it.
  const auto compute = [=](vtkIdType begin, vtkIdType end)
  {
    for (vtkIdType f = begin; f < end; ++f)
    {
      doubleArea[f] = FaceGeometry(xyz, tri, f, faceNormal[f]);
    }
  };
  if (parallel)
  {
    vtkSMPTools::For(0, faces, compute);
  }
  else
  {
    compute(0, faces);
  }
}

void MeshConnectivity::StoreCornerWeights(int weighting)
{
  const vtkIdType faces = this->Faces();
  this->CornerWeight.resize(3 * faces);
  // The input's points: OpenMesh's may grow meanwhile (Build).
  ComputeCornerWeights(weighting, this->XYZ->GetPointer(0), this->TriangleIds(),
    this->DoubleArea.data(), 0, faces, this->CornerWeight.data());
  this->WeightsOf = weighting;
}
}
