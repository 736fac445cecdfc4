#include "vtkShadelabMeshNormals.h"

#include "shadelabCornerWeights.h"
#include "shadelabFileVertices.h"
#include "shadelabMeshConnectivity.h"
#include "shadelabOrderedSums.h"
#include "shadelabOutputTopology.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>
#include <vtkTypeInt32Array.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkShadelabMeshNormals);

using shadelab::normals::FileVertices;
using shadelab::normals::Id;
using shadelab::normals::MeshConnectivity;
using shadelab::normals::OutputTopology;
using shadelab::normals::Sum;
using shadelab::normals::TriMesh;
using shadelab::normals::Vec3;

// The connectivity of the last input, and what identifies that input.
struct vtkShadelabMeshNormals::Cache
{
  vtkPolyData* Input = nullptr; // identity only, never dereferenced
  vtkMTimeType InputTime = 0;
  bool Consistency = false;
  FileVertices Files; // the input's points of each file vertex, welded in Mesh
  MeshConnectivity Mesh;
};

namespace
{
// A vertex normal's sum this much shorter than the sum of its weights is
// taken as zero: terms that cancel leave about 1e-16 of them in rounding,
// pointing anywhere, and a real normal is never this close to cancelling.
constexpr double CancelledSum = 1e-12;

// The input's triangles as 3 point ids a face, or an error: its own
// 32-bit ids, checked in place, unless they are 64-bit or `copy` asks for
// ids to rewrite; then a copy, made as they are checked.
struct TriangleIds
{
  template <typename CellState>
  void operator()(CellState& state, vtkIdType points, bool copy,
    vtkSmartPointer<vtkTypeInt32Array>& ids, std::string& error) const
  {
    const auto* offsets = state.GetOffsets()->GetPointer(0);
    const auto* connectivity = state.GetConnectivity()->GetPointer(0);
    const vtkIdType faces = state.GetOffsets()->GetNumberOfValues() - 1;
    Id* out = nullptr;
    if constexpr (std::is_same_v<typename CellState::ArrayType, vtkTypeInt32Array>)
    {
      ids = state.GetConnectivity();
    }
    if (copy || !ids)
    {
      ids = vtkSmartPointer<vtkTypeInt32Array>::New();
      ids->SetNumberOfValues(3 * faces);
      out = ids->GetPointer(0);
    }
    for (vtkIdType f = 0; f < faces; ++f)
    {
      if (offsets[f + 1] - offsets[f] != 3)
      {
        error = "polygon " + std::to_string(f) + " has " +
          std::to_string(offsets[f + 1] - offsets[f]) + " vertices (triangles only)";
        return;
      }
      for (int k = 0; k < 3; ++k)
      {
        const vtkIdType id = connectivity[3 * f + k];
        if (id < 0 || id >= points)
        {
          error = "triangle " + std::to_string(f) + " refers to point " + std::to_string(id) +
            " of " + std::to_string(points);
          return;
        }
        if (out)
        {
          out[3 * f + k] = static_cast<Id>(id);
        }
      }
    }
  }
};

// The input's triangles (TriangleIds, a copy if `copy`); an error message
// if it has other polygons or ids, or is too large for OpenMesh.
std::string ReadTriangles(
  vtkPolyData* input, bool copy, vtkSmartPointer<vtkTypeInt32Array>& triangles)
{
  // OpenMesh numbers vertices and halfedges (3 a face, and copies) in int.
  const vtkIdType limit = std::numeric_limits<Id>::max() / 2;
  const vtkIdType points = input->GetNumberOfPoints();
  const vtkIdType cornerCount = input->GetPolys()->GetNumberOfConnectivityIds();
  if (points > limit || cornerCount > limit)
  {
    return "too large for OpenMesh's int handles: " + std::to_string(points) + " points, " +
      std::to_string(cornerCount) + " triangle corners";
  }
  std::string error;
  input->GetPolys()->Visit(TriangleIds{}, points, copy, triangles, error);
  return error;
}

// OpenMesh's Loop limit normal where it is one: at an interior vertex whose
// whole fan is one smooth piece of a manifold mesh (not split, in no
// duplicated face). Per vertex, on both cores.
void SetLoopNormals(
  const MeshConnectivity& c, const OutputTopology& topology, std::vector<Sum>& sum)
{
  // OpenMesh makes its table of Loop weights on first use: here, before
  // the cores share it.
  OpenMesh::LoopSchemeMaskDoubleSingleton::Instance();
  const TriMesh& mesh = c.Mesh;
  vtkSMPTools::For(0, c.Points,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const TriMesh::VertexHandle v(static_cast<int>(i));
        if (mesh.is_boundary(v) || mesh.valence(v) < 3 || c.InDuplicatedFace[i] ||
          (!topology.Split.empty() && topology.Split[i]))
        {
          continue;
        }
        TriMesh::Normal n;
        // Unnormalised, and on the side of the faces' normals (OpenMesh
        // crosses its tangents as cross(t_w, t_v) for that).
        mesh.calc_vertex_normal_loop(v, n);
        sum[i] = { n, 0 };
      }
    });
}

// A float triple for each of `count` points or cells, named as VTK's normals.
vtkSmartPointer<vtkFloatArray> NormalsArray(vtkIdType count)
{
  auto normals = vtkSmartPointer<vtkFloatArray>::New();
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(count);
  return normals;
}

// The sums as unit normals, (0,0,0) where they cancelled or overflowed;
// each point's on its own, so the cores share them.
vtkSmartPointer<vtkFloatArray> UnitNormals(const std::vector<Sum>& sum)
{
  const auto count = static_cast<vtkIdType>(sum.size());
  vtkSmartPointer<vtkFloatArray> normals = NormalsArray(count);
  float* out = normals->GetPointer(0);
  vtkSMPTools::For(0, count,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double length = sum[i].Normal.norm();
        const bool defined = length > CancelledSum * sum[i].Weight && std::isfinite(length);
        const Vec3 n = defined ? sum[i].Normal / length : Vec3(0, 0, 0);
        for (int k = 0; k < 3; ++k)
        {
          out[3 * i + k] = static_cast<float>(n[k]);
        }
      }
    });
  return normals;
}

}

vtkShadelabMeshNormals::vtkShadelabMeshNormals() = default;
vtkShadelabMeshNormals::~vtkShadelabMeshNormals() = default;

bool vtkShadelabMeshNormals::SetWeightingByName(const char* name)
{
  const auto weighting = name ? shadelab::FromName<Weightings>(name) : std::nullopt;
  if (weighting)
  {
    this->SetWeighting(*weighting);
  }
  return weighting.has_value();
}

void vtkShadelabMeshNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << shadelab::ToString(static_cast<Weightings>(this->Weighting))
     << "\n";
  os << indent << "Splitting: " << (this->Splitting ? "On" : "Off") << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Consistency: " << (this->Consistency ? "On" : "Off") << "\n";
  os << indent << "ComputeCellNormals: " << (this->ComputeCellNormals ? "On" : "Off") << "\n";
  os << indent << "SumChunks: " << this->SumChunks << "\n";
  os << indent << "NumberOfDuplicatedFaces: " << this->NumberOfDuplicatedFaces << "\n";
  os << indent << "NumberOfConnectivityBuilds: " << this->NumberOfConnectivityBuilds << "\n";
}

int vtkShadelabMeshNormals::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input->GetPoints() && input->GetNumberOfPolys() == 0)
  {
    return 1; // nothing to compute normals for: an empty output, as vtkPolyDataNormals gives
  }

  // Only splitting and Loop normals walk OpenMesh's connectivity; summed
  // normals read the face geometry alone, so they are the same without it.
  const bool connect = this->Splitting || this->Weighting == Loop;
  if (!this->Cached || this->Cached->Input != input ||
    this->Cached->InputTime != input->GetMTime() || this->Cached->Consistency != this->Consistency)
  {
    this->Cached.reset();
    auto cache = std::make_unique<Cache>();
    const std::string fileError = cache->Files.Read(input);
    // Welding and orienting rewrite the ids: in a copy, not in the input.
    vtkSmartPointer<vtkTypeInt32Array> triangles;
    std::string error = ReadTriangles(input, this->Consistency || cache->Files.Active(), triangles);
    if (error.empty())
    {
      error = fileError;
    }
    if (!error.empty())
    {
      vtkErrorMacro(<< error);
      return 0;
    }
    if (cache->Files.Active())
    {
      cache->Files.Welded(triangles->GetPointer(0), triangles->GetNumberOfValues());
    }
    cache->Input = input;
    cache->InputTime = input->GetMTime();
    cache->Consistency = this->Consistency;
    cache->Mesh.Build(input, this->Consistency, std::move(triangles),
      shadelab::normals::SummedWeighting(this->Weighting), connect);
    if (cache->Files.Active() && cache->Mesh.Reversed)
    {
      cache->Files.FollowOrientation(cache->Mesh.TriangleIds());
    }
    this->Cached = std::move(cache);
    ++this->NumberOfConnectivityBuilds;
  }
  MeshConnectivity& mesh = this->Cached->Mesh;
  if (connect)
  {
    mesh.Connect();
  }
  this->NumberOfDuplicatedFaces = connect ? mesh.DuplicatedFaces : 0;

  OutputTopology topology =
    shadelab::normals::MakeTopology(mesh, this->Splitting, this->FeatureAngle);
  vtkSmartPointer<vtkFloatArray> cellNormals =
    this->ComputeCellNormals ? NormalsArray(mesh.Faces()) : nullptr;
  std::vector<Sum> sum =
    SumFaceNormals(mesh, topology, shadelab::normals::SummedWeighting(this->Weighting),
      this->SumChunks, cellNormals ? cellNormals->GetPointer(0) : nullptr);
  if (this->Weighting == Loop)
  {
    SetLoopNormals(mesh, topology, sum);
  }

  vtkSmartPointer<vtkFloatArray> normals = UnitNormals(sum);
  if (this->Cached->Files.Active())
  {
    topology = shadelab::normals::Unweld(this->Cached->Files, mesh, topology, normals);
  }

  output->GetPointData()->CopyNormalsOff();
  output->GetCellData()->CopyNormalsOff();
  output->GetCellData()->PassData(input->GetCellData());
  shadelab::normals::SetOutputMesh(input, topology, output);
  output->GetPointData()->SetNormals(normals);
  if (cellNormals)
  {
    output->GetCellData()->SetNormals(cellNormals);
  }
  return 1;
}
