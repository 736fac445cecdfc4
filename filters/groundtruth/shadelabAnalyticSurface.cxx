#include "shadelabAnalyticSurface.h"

#include "shadelabVec3.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkMath.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace shadelab
{
namespace
{
constexpr double R = 1;                            // the torus's major radius
constexpr double r = AnalyticSurface::MinorRadius; // its tube radius

using Triangle = std::array<vtkIdType, 3>;

vtkSmartPointer<vtkPolyData> MakePolyData(
  const std::vector<Vec3>& points, const std::vector<Triangle>& triangles)
{
  auto xyz = vtkSmartPointer<vtkFloatArray>::New();
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    xyz->SetTuple(static_cast<vtkIdType>(i), points[i].data());
  }
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(static_cast<vtkIdType>(triangles.size() + 1));
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(3 * triangles.size()));
  for (std::size_t t = 0; t <= triangles.size(); ++t)
  {
    offsets->SetValue(static_cast<vtkIdType>(t), static_cast<vtkIdType>(3 * t));
  }
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      connectivity->SetValue(static_cast<vtkIdType>(3 * t + k), triangles[t][k]);
    }
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->SetPoints(vtkSmartPointer<vtkPoints>::New());
  mesh->GetPoints()->SetData(xyz);
  mesh->SetPolys(cells);
  return mesh;
}

// An icosahedron subdivided `times` times, each new vertex pushed onto the
// unit sphere: the most even triangles a sphere can have.
vtkSmartPointer<vtkPolyData> Icosphere(int times)
{
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> points = { { -1, g, 0 }, { 1, g, 0 }, { -1, -g, 0 }, { 1, -g, 0 }, { 0, -1, g },
    { 0, 1, g }, { 0, -1, -g }, { 0, 1, -g }, { g, 0, -1 }, { g, 0, 1 }, { -g, 0, -1 },
    { -g, 0, 1 } };
  for (Vec3& p : points)
  {
    p = normalize(p);
  }
  std::vector<Triangle> triangles = { { 0, 11, 5 }, { 0, 5, 1 }, { 0, 1, 7 }, { 0, 7, 10 },
    { 0, 10, 11 }, { 1, 5, 9 }, { 5, 11, 4 }, { 11, 10, 2 }, { 10, 7, 6 }, { 7, 1, 8 }, { 3, 9, 4 },
    { 3, 4, 2 }, { 3, 2, 6 }, { 3, 6, 8 }, { 3, 8, 9 }, { 4, 9, 5 }, { 2, 4, 11 }, { 6, 2, 10 },
    { 8, 6, 7 }, { 9, 8, 1 } };
  for (int pass = 0; pass < times; ++pass)
  {
    std::unordered_map<std::uint64_t, vtkIdType> middles;
    auto middle = [&](vtkIdType a, vtkIdType b)
    {
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
        static_cast<std::uint64_t>(std::max(a, b));
      const auto [it, added] = middles.try_emplace(key, static_cast<vtkIdType>(points.size()));
      if (added)
      {
        points.push_back(normalize(points[a] + points[b]));
      }
      return it->second;
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * triangles.size());
    for (const Triangle& t : triangles)
    {
      const vtkIdType ab = middle(t[0], t[1]), bc = middle(t[1], t[2]), ca = middle(t[2], t[0]);
      finer.push_back({ t[0], ab, ca });
      finer.push_back({ t[1], bc, ab });
      finer.push_back({ t[2], ca, bc });
      finer.push_back({ ab, bc, ca });
    }
    triangles.swap(finer);
  }
  return MakePolyData(points, triangles);
}

// The torus over a grid of nu steps around the axis by nv around the tube.
vtkSmartPointer<vtkPolyData> TorusGrid(int nu, int nv)
{
  std::vector<Vec3> points;
  points.reserve(static_cast<std::size_t>(nu) * nv);
  for (int i = 0; i < nu; ++i)
  {
    const double u = 2 * vtkMath::Pi() * i / nu;
    for (int j = 0; j < nv; ++j)
    {
      const double v = 2 * vtkMath::Pi() * j / nv;
      points.push_back({ (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u),
        r * std::sin(v) });
    }
  }
  auto id = [&](int i, int j) { return static_cast<vtkIdType>((i % nu) * nv + (j % nv)); };
  std::vector<Triangle> triangles;
  triangles.reserve(2 * points.size());
  for (int i = 0; i < nu; ++i)
  {
    for (int j = 0; j < nv; ++j)
    {
      // (du x dv) points out of the tube.
      triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return MakePolyData(points, triangles);
}

// The torus's signed distance: exact, so sphere tracing never steps through it.
double TorusDistance(const Vec3& p)
{
  const double q = std::hypot(p[0], p[1]) - R;
  return std::hypot(q, p[2]) - r;
}

// Where origin + t*direction enters the sphere of radius `radius` about the
// origin: {t_near, t_far}, or an empty result.
bool SphereSpan(const Vec3& origin, const Vec3& direction, double radius, double span[2])
{
  // |o + t d|^2 = radius^2 with |d| = 1: t^2 + 2 b t + c = 0.
  const double b = dot(origin, direction);
  // c = |o|^2 - radius^2, and the discriminant b^2 - c as |o - b d|^2 terms,
  // which do not cancel when the ray passes far from the centre.
  const Vec3 closest = origin - b * direction;
  const double h = radius * radius - dot(closest, closest);
  if (h < 0)
  {
    return false;
  }
  const double s = std::sqrt(h);
  span[0] = -b - s;
  span[1] = -b + s;
  return true;
}
}

const char* AnalyticSurface::GetName() const
{
  return this->Shape == Kind::Sphere ? "sphere" : "torus";
}

Vec3 AnalyticSurface::Normal(const Vec3& p) const
{
  if (this->Shape == Kind::Sphere)
  {
    return normalize(p);
  }
  // Away from the nearest point of the tube's centre circle.
  const double rho = std::hypot(p[0], p[1]);
  const Vec3 centre{ R * p[0] / rho, R * p[1] / rho, 0 };
  return normalize(p - centre);
}

RayHit AnalyticSurface::Intersect(const Vec3& origin, const Vec3& direction) const
{
  RayHit hit;
  double span[2];
  if (!SphereSpan(origin, direction, this->Shape == Kind::Sphere ? 1 : R + r, span) || span[1] <= 0)
  {
    return hit;
  }
  if (this->Shape == Kind::Sphere)
  {
    hit.T = span[0] > 0 ? span[0] : span[1];
  }
  else
  {
    // Sphere tracing from where the ray enters the bounding sphere: each step
    // is the distance to the surface, so the first hit cannot be skipped.
    double t = std::max(span[0], 0.0);
    const double tolerance = 1e-13;
    bool found = false;
    for (int step = 0; step < 4000 && t <= span[1]; ++step)
    {
      const double d = TorusDistance(origin + t * direction);
      if (d < tolerance)
      {
        found = true;
        break;
      }
      t += d;
    }
    if (!found)
    {
      return hit;
    }
    // A Newton step on the distance along the ray lands on the surface to
    // rounding (the ray is not tangent here: grazing rays converge too slowly
    // to arrive, and lie in the silhouette band that measurements exclude).
    const Vec3 p = origin + t * direction;
    const double slope = dot(this->Normal(p), direction);
    if (slope < -1e-3)
    {
      t -= TorusDistance(p) / slope;
    }
    hit.T = t;
  }
  hit.Hit = true;
  hit.Point = origin + hit.T * direction;
  hit.Normal = this->Normal(hit.Point);
  return hit;
}

long long AnalyticSurface::TriangleCount(int level) const
{
  if (this->Shape == Kind::Sphere)
  {
    return 80LL << (2 * level);
  }
  return 2 * (12LL << level) * (5LL << level);
}

vtkSmartPointer<vtkPolyData> AnalyticSurface::Tessellate(int level) const
{
  return this->Shape == Kind::Sphere ? Icosphere(level + 1) : TorusGrid(12 << level, 5 << level);
}
}
