#include "vtkShadelabMeshNormals.h"

#include "shadelabCornerWeights.h"
#include "shadelabFileVertices.h"
#include "shadelabMeshConnectivity.h"
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

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
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

// A vertex's weighted sum of face normals, with the sum of the weights: a
// sum far shorter than its terms is the rounding left of terms that cancel
// (a face and its reverse), and its direction means nothing.
struct Sum
{
  Vec3 Normal{ 0, 0, 0 };
  double Weight = 0; // beside the normal: one cache line for both
};

// The terms of the sums: each face's unit normal and its corners' weights,
// from the face geometry and the weights stored beside the connectivity, or
// computed as they are needed (the same functions on the same values, so
// the same bits).
class FaceTerms
{
public:
  FaceTerms(const MeshConnectivity& c, int weighting)
    : C(c)
    , Weighting(weighting)
    , CornerWeights(shadelab::normals::HasCornerWeights(weighting))
    , StoredWeights(c.StoredCornerWeights(weighting))
    , StoredGeometry(!c.FaceNormal.empty())
    , XYZ(c.XYZ->GetPointer(0))
    , Triangles(c.TriangleIds())
  {
  }

  /** Face f's unit normal (zero for no area); returns its doubled area. */
  double Normal(vtkIdType f, Vec3& normal) const
  {
    if (this->StoredGeometry)
    {
      normal = this->C.FaceNormal[f];
      return this->C.DoubleArea[f];
    }
    return shadelab::normals::FaceGeometry(this->XYZ, this->Triangles, f, normal);
  }

  /** The weights of face f's 3 corners, for its doubled area `area2`. */
  void Weights(vtkIdType f, double area2, double weights[3]) const
  {
    double own[3];
    const double* corner = nullptr;
    if (this->CornerWeights && this->StoredWeights)
    {
      corner = this->StoredWeights + 3 * f;
    }
    else if (this->CornerWeights)
    {
      shadelab::normals::ComputeCornerWeights(
        this->Weighting, this->XYZ, this->Triangles, &area2, f, f + 1, own);
      corner = own;
    }
    for (int k = 0; k < 3; ++k)
    {
      weights[k] = shadelab::normals::CornerWeight(this->Weighting, area2, corner, k);
    }
  }

private:
  const MeshConnectivity& C;
  const int Weighting;
  const bool CornerWeights;
  const double* StoredWeights;
  const bool StoredGeometry;
  const double* XYZ;
  const Id* Triangles;
};

// One term into a sum: one expression wherever a term is added.
void AddTerm(Sum& sum, double weight, const Vec3& normal)
{
  sum.Normal += weight * normal;
  sum.Weight += weight;
}

// A point's owning chunk is a byte; this one for a point in no face.
constexpr std::uint8_t NoOwner = 255;

// The chunks of faces that the sum splits the faces into: one per thread
// unless `chunks` says, at most one a face, and fewer than NoOwner.
int SumChunkCount(int chunks, vtkIdType faces)
{
  const vtkIdType wanted = chunks > 0 ? chunks : vtkSMPTools::GetEstimatedNumberOfThreads();
  return static_cast<int>(
    std::clamp<vtkIdType>(std::min<vtkIdType>(wanted, faces), 1, NoOwner - 1));
}

// Each face's weighted unit normal, summed into its corners' points, and
// into `cellNormals` (3 floats a face) unless null. Floating-point sums
// depend on their order, so every point receives its terms face by face in
// the input's order, as on one core, while `chunks` contiguous chunks of
// faces are summed on the cores at once: a point belongs to the chunk of
// its first face, which adds its terms from its own faces in order; a
// later chunk's terms of a point it does not own are deferred, and added
// after all chunks, chunk by chunk in order (on the cores too, by ranges
// of points). On a coherent mesh (scans, subdivisions) only points along
// the chunks' borders are deferred; on a shuffled one most of a later
// chunk's are, and the sum takes about as long as on one core.
std::vector<Sum> SumFaceNormals(const MeshConnectivity& c, const OutputTopology& topology,
  int weighting, int chunkCount, float* cellNormals)
{
  const Id* corners =
    topology.Connectivity ? topology.Connectivity->GetPointer(0) : c.TriangleIds();
  const FaceTerms terms(c, weighting);
  const vtkIdType faces = c.Faces();
  const int chunks = SumChunkCount(chunkCount, faces);
  const auto chunkBegin = [faces, chunks](int chunk) { return faces * chunk / chunks; };

  // Each point's owner: the lowest chunk that has a corner on it.
  std::vector<std::atomic<std::uint8_t>> owner(chunks > 1 ? topology.Points : 0);
  if (chunks > 1)
  {
    vtkSMPTools::For(0, topology.Points,
      [&](vtkIdType begin, vtkIdType end)
      {
        for (vtkIdType i = begin; i < end; ++i)
        {
          owner[i].store(NoOwner, std::memory_order_relaxed);
        }
      });
    vtkSMPTools::For(0, chunks, 1,
      [&](vtkIdType first, vtkIdType last)
      {
        for (auto chunk = static_cast<std::uint8_t>(first); chunk < last; ++chunk)
        {
          for (vtkIdType i = 3 * chunkBegin(chunk); i < 3 * chunkBegin(chunk + 1); ++i)
          {
            std::atomic<std::uint8_t>& o = owner[corners[i]];
            std::uint8_t current = o.load(std::memory_order_relaxed);
            while (chunk < current &&
              !o.compare_exchange_weak(current, chunk, std::memory_order_relaxed))
            {
            }
          }
        }
      });
  }

  std::vector<Sum> sum(topology.Points);
  std::vector<std::vector<Id>> deferred(chunks); // corners 3 f + k, in order
  vtkSMPTools::For(0, chunks, 1,
    [&](vtkIdType first, vtkIdType last)
    {
      for (auto chunk = static_cast<int>(first); chunk < last; ++chunk)
      {
        std::vector<Id>& later = deferred[chunk];
        for (vtkIdType f = chunkBegin(chunk); f < chunkBegin(chunk + 1); ++f)
        {
          bool owns[3];
          for (int k = 0; k < 3; ++k)
          {
            owns[k] =
              chunks == 1 || owner[corners[3 * f + k]].load(std::memory_order_relaxed) == chunk;
          }
          if (!cellNormals && !owns[0] && !owns[1] && !owns[2])
          {
            // Nothing to add here: the deferred pass computes the face.
            for (int k = 0; k < 3; ++k)
            {
              later.push_back(static_cast<Id>(3 * f + k));
            }
            continue;
          }
          Vec3 normal;
          const double area2 = terms.Normal(f, normal);
          if (cellNormals)
          {
            for (int k = 0; k < 3; ++k)
            {
              cellNormals[3 * f + k] = static_cast<float>(normal[k]);
            }
          }
          if (area2 == 0)
          {
            continue; // a face of no area adds nothing
          }
          double weights[3];
          terms.Weights(f, area2, weights);
          for (int k = 0; k < 3; ++k)
          {
            if (owns[k])
            {
              AddTerm(sum[corners[3 * f + k]], weights[k], normal);
            }
            else
            {
              later.push_back(static_cast<Id>(3 * f + k));
            }
          }
        }
      }
    });

  // The deferred terms, chunk by chunk in order: on the cores at once too,
  // each taking the points of one range of ids (a point's terms stay on one
  // core, in order); a face with corners in two ranges is computed twice.
  vtkSMPTools::For(0, chunks, 1,
    [&](vtkIdType first, vtkIdType last)
    {
      const vtkIdType begin = topology.Points * first / chunks;
      const vtkIdType end = topology.Points * last / chunks;
      vtkIdType face = -1; // the last deferred corner's face, and its terms
      Vec3 normal(0, 0, 0);
      double area2 = 0;
      double weights[3] = { 0, 0, 0 };
      for (const std::vector<Id>& later : deferred)
      {
        for (const Id corner : later)
        {
          const Id point = corners[corner];
          if (point < begin || point >= end)
          {
            continue;
          }
          if (corner / 3 != face)
          {
            face = corner / 3;
            area2 = terms.Normal(face, normal);
            if (area2 != 0)
            {
              terms.Weights(face, area2, weights);
            }
          }
          if (area2 != 0)
          {
            AddTerm(sum[point], weights[corner % 3], normal);
          }
        }
      }
    });
  return sum;
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
