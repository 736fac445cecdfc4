#include "shadelabOrderedSums.h"

#include "shadelabCornerWeights.h"
#include "shadelabMeshConnectivity.h"
#include "shadelabOutputTopology.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <atomic>
#include <cstdint>

namespace shadelab::normals
{
namespace
{
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
    , CornerWeights(HasCornerWeights(weighting))
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
    return FaceGeometry(this->XYZ, this->Triangles, f, normal);
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
      ComputeCornerWeights(this->Weighting, this->XYZ, this->Triangles, &area2, f, f + 1, own);
      corner = own;
    }
    for (int k = 0; k < 3; ++k)
    {
      weights[k] = CornerWeight(this->Weighting, area2, corner, k);
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
}
