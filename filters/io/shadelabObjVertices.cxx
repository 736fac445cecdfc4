#include "shadelabObjVertices.h"

#include <functional>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace shadelab
{
namespace
{
// What a point holds besides its position: a corner's vt and vn (ObjNoIndex
// where they are not read). Corners of one vertex with different ones need
// points of their own.
struct CornerAttributes
{
  vtkIdType Texture = ObjNoIndex;
  vtkIdType Normal = ObjNoIndex;

  bool operator==(const CornerAttributes& other) const
  {
    return this->Texture == other.Texture && this->Normal == other.Normal;
  }
};

struct SplitKey
{
  vtkIdType Vertex;
  CornerAttributes Attributes;

  bool operator==(const SplitKey& other) const
  {
    return this->Vertex == other.Vertex && this->Attributes == other.Attributes;
  }
};

struct SplitKeyHash
{
  std::size_t operator()(const SplitKey& key) const
  {
    const std::hash<vtkIdType> hash;
    return (hash(key.Vertex) * 1000003 ^ hash(key.Attributes.Texture)) * 1000003 ^
      hash(key.Attributes.Normal);
  }
};
}

void SplitVertices(ObjCorners& corners, bool texture, bool normals, PolygonMesh& mesh)
{
  mesh.Colors = std::move(corners.Colors); // a vertex's, copies' appended below
  if (!texture && !normals)
  {
    mesh.Points = std::move(corners.Vertices); // nothing to split by
    return;
  }
  const std::size_t vertexCount = corners.Vertices.size() / 3;
  std::vector<CornerAttributes> point(vertexCount);
  std::vector<bool> used(vertexCount, false);
  std::vector<vtkIdType> copied; // the file vertex of each appended point
  std::unordered_map<SplitKey, vtkIdType, SplitKeyHash> splitPoints;
  mesh.Points = std::move(corners.Vertices);
  for (std::size_t c = 0; c < corners.VertexIds.size(); ++c)
  {
    const vtkIdType v = corners.VertexIds[c];
    const CornerAttributes corner{ texture ? corners.TextureIds[c] : ObjNoIndex,
      normals ? corners.NormalIds[c] : ObjNoIndex };
    if (!used[v])
    {
      used[v] = true;
      point[v] = corner;
    }
    else if (!(point[v] == corner))
    {
      const auto [it, added] =
        splitPoints.try_emplace(SplitKey{ v, corner }, static_cast<vtkIdType>(point.size()));
      if (added)
      {
        mesh.Points.insert(mesh.Points.end(),
          { mesh.Points[3 * v], mesh.Points[3 * v + 1], mesh.Points[3 * v + 2] });
        if (!mesh.Colors.empty())
        {
          const float* colour = &mesh.Colors[4 * v];
          mesh.Colors.insert(mesh.Colors.end(), { colour[0], colour[1], colour[2], colour[3] });
        }
        point.push_back(corner);
        copied.push_back(v);
      }
      corners.VertexIds[c] = it->second;
    }
  }
  for (const CornerAttributes& p : point)
  {
    for (int k = 0; texture && k < 2; ++k)
    {
      mesh.TextureCoordinates.push_back(
        p.Texture == ObjNoIndex ? 0.0f : corners.TextureCoordinates[2 * p.Texture + k]);
    }
    for (int k = 0; normals && k < 3; ++k)
    {
      mesh.Normals.push_back(p.Normal == ObjNoIndex ? 0.0f : corners.Normals[3 * p.Normal + k]);
    }
  }
  if (!copied.empty())
  {
    mesh.FileVertices.resize(vertexCount);
    std::iota(mesh.FileVertices.begin(), mesh.FileVertices.end(), vtkIdType{ 0 });
    mesh.FileVertices.insert(mesh.FileVertices.end(), copied.begin(), copied.end());
  }
}
}
