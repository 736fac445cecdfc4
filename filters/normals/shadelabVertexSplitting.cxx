#include "shadelabVertexSplitting.h"

#include "shadelabBuckets.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <numeric>

namespace shadelab::normals
{
namespace
{
// Which edges separate the faces on their two sides (1 a separating edge):
// boundary and feature edges, and edges of duplicated faces. Once per edge,
// on both cores, before the walks around vertices.
std::vector<char> SeparatingEdges(const MeshConnectivity& c, double cosFeature)
{
  const TriMesh& mesh = c.Mesh;
  std::vector<char> separating(mesh.n_edges());
  vtkSMPTools::For(0, static_cast<vtkIdType>(separating.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const auto a = mesh.face_handle(TriMesh::HalfedgeHandle(static_cast<int>(2 * e)));
        const auto b = mesh.face_handle(TriMesh::HalfedgeHandle(static_cast<int>(2 * e + 1)));
        separating[e] = !a.is_valid() || !b.is_valid() ||
          OpenMesh::dot(c.FaceNormal[a.idx()], c.FaceNormal[b.idx()]) < cosFeature;
      }
    });
  // An edge that OpenMesh holds as manifold may have more faces in the
  // input, duplicated ones: it is non-manifold, and separates too.
  for (size_t f = 0; f < c.CopyOf.size(); f += 3)
  {
    for (size_t k = 0; k < 3; ++k)
    {
      const TriMesh::HalfedgeHandle h =
        mesh.find_halfedge(TriMesh::VertexHandle(static_cast<int>(c.CopyOf[f + k])),
          TriMesh::VertexHandle(static_cast<int>(c.CopyOf[f + (k + 1) % 3])));
      if (h.is_valid())
      {
        separating[h.idx() / 2] = 1;
      }
    }
  }
  return separating;
}

struct FanFace
{
  int Face;           // -1 for the gap of a boundary
  bool SeparatesNext; // from the next face round the fan
};

// Walks the fan of OpenMesh vertex vi, a vertex of input point i: its runs
// of faces between separations are numbered on from `runs` in the faces'
// corners at i (for now). `fan` is room for the walk.
void NumberRuns(const MeshConnectivity& c, const std::vector<char>& separating, vtkIdType i, int vi,
  std::vector<FanFace>& fan, int& runs, Id* cornerPoint)
{
  const TriMesh& mesh = c.Mesh;
  const TriMesh::HalfedgeHandle start = mesh.halfedge_handle(TriMesh::VertexHandle(vi));
  if (!start.is_valid())
  {
    return; // no face
  }
  // Outgoing halfedges in turn (h -> next(opposite(h))): the face of the
  // next one lies across the edge of this one. The first run starts after
  // the last separation (a closed smooth fan has none and is one run).
  fan.clear();
  TriMesh::HalfedgeHandle h = start;
  do
  {
    fan.push_back({ mesh.face_handle(h).idx(), separating[h.idx() / 2] != 0 });
    h = mesh.cw_rotated_halfedge_handle(h);
  } while (h != start);
  const size_t n = fan.size();
  size_t begin = 0;
  for (size_t j = 0; j < n; ++j)
  {
    if (fan[j].SeparatesNext)
    {
      begin = j + 1;
      break;
    }
  }
  bool inRun = false;
  for (size_t j = 0; j < n; ++j)
  {
    const FanFace& face = fan[(begin + j) % n];
    if (face.Face >= 0)
    {
      if (!inRun)
      {
        inRun = true;
        ++runs;
      }
      // The corner's number in the face: copies are made three at a time
      // in corner order; an original vertex is found by its id (a face
      // that repeats an id was duplicated).
      const Id* ids = c.TriangleIds() + 3 * face.Face;
      const int k = vi >= c.Points ? (vi - c.Points) % 3 : ids[0] == i ? 0 : ids[1] == i ? 1 : 2;
      cornerPoint[3 * face.Face + k] = runs - 1;
    }
    inRun = inRun && !face.SeparatesNext;
  }
}

// On both cores: the runs round the fans of each input point's vertices
// (vertex i, then its copies in order), numbered 0, 1, ... per point in the
// corners and counted.
std::vector<int> CountRuns(
  const MeshConnectivity& c, const std::vector<char>& separating, Id* cornerPoint)
{
  const vtkIdType points = c.Points;
  const Buckets copies(c.CopyOf.data(), static_cast<vtkIdType>(c.CopyOf.size()), points);
  std::vector<int> runs(points, 0);
  vtkSMPTools::For(0, points,
    [&](vtkIdType firstPoint, vtkIdType endPoint)
    {
      std::vector<FanFace> fan;
      for (vtkIdType i = firstPoint; i < endPoint; ++i)
      {
        NumberRuns(c, separating, i, static_cast<int>(i), fan, runs[i], cornerPoint);
        for (vtkIdType k = copies.First[i]; k < copies.First[i + 1]; ++k)
        {
          NumberRuns(c, separating, i, static_cast<int>(points + copies.Items[k]), fan, runs[i],
            cornerPoint);
        }
      }
    });
  return runs;
}
}

void SplitVertices(const MeshConnectivity& c, double cosFeature, std::vector<vtkIdType>& source,
  Id* cornerPoint, std::vector<bool>& split)
{
  const vtkIdType points = c.Points;
  source.resize(points);
  std::iota(source.begin(), source.end(), 0);
  split.assign(points, false);
  const std::vector<int> runs = CountRuns(c, SeparatingEdges(c, cosFeature), cornerPoint);

  // Then the output points: input point i keeps its number for its first
  // run; its other runs become new points, appended in input order.
  std::vector<Id> firstNew(points);
  for (vtkIdType i = 0; i < points; ++i)
  {
    firstNew[i] = static_cast<Id>(source.size());
    split[i] = runs[i] > 1;
    source.insert(source.end(), std::max(runs[i] - 1, 0), i);
  }
  const Id* tri = c.TriangleIds();
  vtkSMPTools::For(0, 3 * c.Faces(),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const Id run = cornerPoint[k];
        cornerPoint[k] = run == 0 ? tri[k] : firstNew[tri[k]] + run - 1;
      }
    });
}
}
