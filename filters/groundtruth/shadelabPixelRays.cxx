#include "shadelabPixelRays.h"

#include "shadelabVec3.h"

#include <vtkCamera.h>
#include <vtkMath.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab
{
namespace
{

// vtkCamera's frame: the view-up made orthogonal to the direction of view.
struct ViewFrame
{
  Vec3 Forward, Right, Up;
};

ViewFrame FrameOf(const PinholeCamera& c)
{
  ViewFrame f;
  f.Forward = normalize(c.FocalPoint - c.Position);
  f.Right = normalize(cross(f.Forward, c.ViewUp));
  f.Up = cross(f.Right, f.Forward);
  return f;
}

// Half the view's height at unit distance (perspective) or in world units
// (orthographic).
double HalfHeight(const PinholeCamera& c)
{
  return c.Orthographic ? c.ParallelScale : std::tan(c.ViewAngle * vtkMath::Pi() / 360);
}

// Distance from (x, y) to the segment from a to b, in the plane.
double SegmentDistance(
  double x, double y, const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  const double ex = b[0] - a[0], ey = b[1] - a[1];
  const double length2 = ex * ex + ey * ey;
  const double along =
    length2 > 0 ? std::clamp(((x - a[0]) * ex + (y - a[1]) * ey) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(x - (a[0] + along * ex), y - (a[1] + along * ey));
}
}

PinholeCamera PinholeCameraOf(vtkCamera* c)
{
  PinholeCamera p;
  c->GetPosition(p.Position.data());
  c->GetFocalPoint(p.FocalPoint.data());
  c->GetViewUp(p.ViewUp.data());
  p.ViewAngle = c->GetViewAngle();
  p.Orthographic = c->GetParallelProjection();
  p.ParallelScale = c->GetParallelScale();
  return p;
}

Ray PictureRay(const PinholeCamera& camera, int width, int height, double x, double y)
{
  const ViewFrame f = FrameOf(camera);
  const double half = HalfHeight(camera);
  // Normalised device coordinates, as glViewport maps them.
  const double h = (2 * x / width - 1) * half * width / height;
  const double v = (1 - 2 * y / height) * half;
  if (camera.Orthographic)
  {
    return { camera.Position + h * f.Right + v * f.Up, f.Forward };
  }
  return { camera.Position, normalize(f.Forward + h * f.Right + v * f.Up) };
}

TriangleHit IntersectTriangle(const Ray& ray, const Vec3& a, const Vec3& b, const Vec3& c)
{
  // Moller-Trumbore.
  TriangleHit hit;
  const Vec3 e1 = b - a, e2 = c - a;
  const Vec3 p = cross(ray.Direction, e2);
  const double det = dot(e1, p);
  if (det == 0 || !std::isfinite(det))
  {
    return hit;
  }
  const Vec3 s = ray.Origin - a;
  const Vec3 q = cross(s, e1);
  const double u = dot(s, p) / det, v = dot(ray.Direction, q) / det;
  hit.T = dot(e2, q) / det;
  hit.Weights = { 1 - u - v, u, v };
  hit.Inside = u >= 0 && v >= 0 && u + v <= 1 && hit.T > 0;
  return hit;
}

PictureTriangles::PictureTriangles(const PinholeCamera& camera, int width, int height,
  std::vector<Vec3> points, std::vector<TriangleCorners> triangles)
  : Camera(camera)
  , Width(width)
  , Height(height)
  , Points(std::move(points))
  , Triangles(std::move(triangles))
{
  const ViewFrame f = FrameOf(camera);
  this->Forward = f.Forward;
  const double half = HalfHeight(camera);
  const double aspect = static_cast<double>(width) / height;
  for (const Vec3& p : this->Points)
  {
    const Vec3 d = p - camera.Position;
    const double depth = dot(d, f.Forward);
    // The inverse of PictureRay.
    const double scale = camera.Orthographic ? half : half * depth;
    const double h = dot(d, f.Right) / (scale * aspect), v = dot(d, f.Up) / scale;
    this->Projections.push_back({ (h + 1) * width / 2, (1 - v) * height / 2, depth });
  }
  for (const TriangleCorners& t : this->Triangles)
  {
    const auto& a = this->Projections[t[0]];
    const auto& b = this->Projections[t[1]];
    const auto& c = this->Projections[t[2]];
    // A margin far below a pixel and far above the rounding of two routes
    // to the same point (the projection here, the ray's hit there).
    constexpr double Margin = 1e-6;
    this->Footprints.push_back({ std::min({ a[0], b[0], c[0] }) - Margin,
      std::max({ a[0], b[0], c[0] }) + Margin, std::min({ a[1], b[1], c[1] }) - Margin,
      std::max({ a[1], b[1], c[1] }) + Margin, std::min({ a[2], b[2], c[2] }),
      camera.Orthographic || (a[2] > 0 && b[2] > 0 && c[2] > 0) });
  }
}

Ray PictureTriangles::RayAt(double x, double y) const
{
  return PictureRay(this->Camera, this->Width, this->Height, x, y);
}

double PictureTriangles::EdgeDistance(std::size_t t, double x, double y) const
{
  const TriangleCorners& c = this->Triangles[t];
  const auto& a = this->Projections[c[0]];
  const auto& b = this->Projections[c[1]];
  const auto& d = this->Projections[c[2]];
  return std::min(
    { SegmentDistance(x, y, a, b), SegmentDistance(x, y, b, d), SegmentDistance(x, y, d, a) });
}

std::vector<std::pair<double, PictureTriangles::Hit>> PictureTriangles::Met(
  const Ray& ray, double x, double y) const
{
  std::vector<std::pair<double, Hit>> met;
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    const Footprint& f = this->Footprints[t];
    if (f.Projects && (x < f.Left || x > f.Right || y < f.Top || y > f.Bottom))
    {
      continue;
    }
    const TriangleCorners& c = this->Triangles[t];
    const Vec3 &a = this->Points[c[0]], &b = this->Points[c[1]], &d = this->Points[c[2]];
    const TriangleHit h = IntersectTriangle(ray, a, b, d);
    if (h.Inside)
    {
      Hit hit;
      hit.Triangle = static_cast<std::int64_t>(t);
      hit.Weights = h.Weights;
      hit.Front = dot(cross(b - a, d - a), ray.Direction) < 0;
      met.emplace_back(h.T, hit);
    }
  }
  return met;
}

double PictureTriangles::NearestEdge(double x, double y, double depth, std::int64_t met) const
{
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    const Footprint& f = this->Footprints[t];
    if (!f.Projects || !(f.Nearest < depth || static_cast<std::int64_t>(t) == met))
    {
      continue;
    }
    // The box is no nearer than any edge: skip triangles it puts too far.
    const double dx = std::max({ f.Left - x, x - f.Right, 0.0 });
    const double dy = std::max({ f.Top - y, y - f.Bottom, 0.0 });
    if (dx * dx + dy * dy < nearest * nearest)
    {
      nearest = std::min(nearest, this->EdgeDistance(t, x, y));
    }
  }
  return nearest;
}

PictureTriangles::Hit PictureTriangles::Under(double x, double y) const
{
  const Ray ray = this->RayAt(x, y);
  Hit hit;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [t, met] : this->Met(ray, x, y))
  {
    if (t < nearest)
    {
      nearest = t;
      hit = met;
    }
  }
  // The depth of the point met; only triangles with a corner nearer may cover it.
  const double depth = hit.Triangle < 0
    ? std::numeric_limits<double>::infinity()
    : dot(ray.Origin + nearest * ray.Direction - this->Camera.Position, this->Forward);
  hit.EdgeDistance = this->NearestEdge(x, y, depth, hit.Triangle);
  return hit;
}

std::vector<PictureTriangles::Hit> PictureTriangles::Through(double x, double y) const
{
  std::vector<std::pair<double, Hit>> met = this->Met(this->RayAt(x, y), x, y);
  // Nearest first; at the same distance, in draw order.
  std::stable_sort(met.begin(), met.end(),
    [](const std::pair<double, Hit>& a, const std::pair<double, Hit>& b)
    { return a.first < b.first; });
  const double edge = this->NearestEdge(x, y, std::numeric_limits<double>::infinity(), -1);
  std::vector<Hit> layers;
  for (auto& [t, hit] : met)
  {
    hit.EdgeDistance = edge;
    layers.push_back(hit);
  }
  return layers;
}
}
