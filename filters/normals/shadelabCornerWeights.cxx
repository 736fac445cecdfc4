#include "shadelabCornerWeights.h"

#include <vtkMath.h>

#include <cmath>

namespace shadelab::normals
{
void ComputeCornerWeights(int weighting, const double* xyz, const Id* tri, const double* doubleArea,
  vtkIdType begin, vtkIdType end, double* w)
{
  for (vtkIdType f = begin; f < end; ++f)
  {
    const double area2 = doubleArea[f - begin];
    // Edge k runs from corner k to corner k + 1.
    const Vec3 p[3] = { PointAt(xyz, tri[3 * f]), PointAt(xyz, tri[3 * f + 1]),
      PointAt(xyz, tri[3 * f + 2]) };
    const Vec3 e[3] = { p[1] - p[0], p[2] - p[1], p[0] - p[2] };
    double* corner = w + 3 * (f - begin);
    if (area2 == 0)
    {
      corner[0] = corner[1] = corner[2] = 0; // a face of no area has no weight
    }
    else if (weighting == vtkShadelabMeshNormals::Max)
    {
      // Max 1999: |a x b| / (|a|^2 |b|^2) for the corner's edges a, b;
      // |a x b| is twice the area at every corner.
      const double l[3] = { e[0].sqrnorm(), e[1].sqrnorm(), e[2].sqrnorm() };
      corner[0] = area2 / (l[2] * l[0]);
      corner[1] = area2 / (l[0] * l[1]);
      corner[2] = area2 / (l[1] * l[2]);
    }
    else
    {
      // The angle between the corner's edges as atan2(|a x b|, a.b),
      // accurate at every size, unlike acos; the third from the sum pi.
      corner[0] = std::atan2(area2, -OpenMesh::dot(e[0], e[2]));
      corner[1] = std::atan2(area2, -OpenMesh::dot(e[1], e[0]));
      corner[2] = vtkMath::Pi() - corner[0] - corner[1];
    }
  }
}
}
