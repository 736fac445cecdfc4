#include "shadelabFaceOrientation.h"

#include "shadelabBuckets.h"

#include <utility>
#include <vector>

namespace shadelab::normals
{
namespace
{
// True when face g has the directed edge a -> b.
bool HasEdge(const Id* g, Id a, Id b)
{
  return (g[0] == a && g[1] == b) || (g[1] == a && g[2] == b) || (g[2] == a && g[0] == b);
}

// The one face other than f on edge a-b, or -1: none (boundary) or several
// (non-manifold) pass no orientation on.
vtkIdType OtherFaceOnEdge(const Id* tri, const Buckets& around, vtkIdType f, Id a, Id b)
{
  vtkIdType other = -1;
  int count = 0;
  for (vtkIdType i = around.First[a]; i < around.First[a + 1]; ++i)
  {
    const vtkIdType g = around.Items[i] / 3;
    const Id* ids = tri + 3 * g;
    if (g != f && g != other && (ids[0] == b || ids[1] == b || ids[2] == b))
    {
      other = g;
      ++count;
    }
  }
  return count == 1 ? other : -1;
}
}

bool OrientConsistently(Id* tri, vtkIdType faces, vtkIdType points)
{
  // The face corners at each point (corner c is in face c / 3).
  const Buckets around(tri, 3 * faces, points);

  bool reversed = false;
  std::vector<bool> reached(faces, false);
  std::vector<vtkIdType> queue;
  for (vtkIdType seed = 0; seed < faces; ++seed)
  {
    if (reached[seed])
    {
      continue;
    }
    reached[seed] = true;
    queue.assign(1, seed);
    while (!queue.empty())
    {
      const vtkIdType f = queue.back();
      queue.pop_back();
      for (int k = 0; k < 3; ++k)
      {
        const Id a = tri[3 * f + k];
        const Id b = tri[3 * f + (k + 1) % 3];
        const vtkIdType other = a == b ? -1 : OtherFaceOnEdge(tri, around, f, a, b);
        if (other < 0 || reached[other])
        {
          continue;
        }
        reached[other] = true;
        Id* ids = tri + 3 * other;
        if (HasEdge(ids, a, b))
        {
          std::swap(ids[1], ids[2]);
          reversed = true;
        }
        queue.push_back(other);
      }
    }
  }
  return reversed;
}
}
