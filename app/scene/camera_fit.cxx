#include "scene/camera_fit.h"

#include <vtkCamera.h>
#include <vtkMath.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace shadelab
{
namespace
{
constexpr double Infinity = std::numeric_limits<double>::infinity();

double Dot(const Vec3& a, const Vec3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// v turned by radians about the unit axis (Rodrigues' formula).
Vec3 Turned(const Vec3& v, const Vec3& axis, double radians)
{
  const double c = std::cos(radians), s = std::sin(radians), along = (1 - c) * Dot(axis, v);
  Vec3 across;
  vtkMath::Cross(axis.data(), v.data(), across.data());
  return { c * v[0] + s * across[0] + along * axis[0], c * v[1] + s * across[1] + along * axis[1],
    c * v[2] + s * across[2] + along * axis[2] };
}

// The screen's axes and the view direction: Right = Forward x Up, as VTK's.
struct Basis
{
  Vec3 Right, Up, Forward;
};

// A point in a basis, relative to the focal point: X right, Y up, Z depth.
struct Projected
{
  std::vector<double> X, Y, Z;
};

Projected Project(const std::vector<Vec3>& points, const Basis& b)
{
  Projected p;
  p.X.reserve(points.size());
  p.Y.reserve(points.size());
  p.Z.reserve(points.size());
  for (const Vec3& v : points)
  {
    p.X.push_back(Dot(v, b.Right));
    p.Y.push_back(Dot(v, b.Up));
    p.Z.push_back(Dot(v, b.Forward));
  }
  return p;
}

// c minimising max_i |x_i - c| / w_i (every w_i > 0): the centre of the axis
// that does not limit a perspective fit, where the two extreme points are at
// equal angles from the view axis. The largest (x_i - c) / w_i falls and the
// largest (c - x_i) / w_i rises as c grows: bisection until they meet, to
// the double's precision.
double WeightedCentre(const std::vector<double>& x, const std::vector<double>& w)
{
  double lo = *std::min_element(x.begin(), x.end());
  double hi = *std::max_element(x.begin(), x.end());
  while (true)
  {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi)
    {
      return mid;
    }
    double above = -Infinity, below = -Infinity;
    for (std::size_t i = 0; i < x.size(); ++i)
    {
      above = std::max(above, (x[i] - mid) / w[i]);
      below = std::max(below, (mid - x[i]) / w[i]);
    }
    (above > below ? lo : hi) = mid;
  }
}

// The frustum's planes through the camera at (cx, cy, depth) are
// |x - cx| = s (z - depth) horizontally and |y - cy| = t (z - depth)
// vertically. For one axis both planes touch the points when
// cx - s depth = max(x - s z) and cx + s depth = min(x + s z): the depth
// this axis needs, and its centre.
struct AxisFit
{
  double Depth, Centre;
};

AxisFit FitAxis(const std::vector<double>& x, const std::vector<double>& z, double slope)
{
  double low = -Infinity, high = Infinity;
  for (std::size_t i = 0; i < x.size(); ++i)
  {
    low = std::max(low, x[i] - slope * z[i]);
    high = std::min(high, x[i] + slope * z[i]);
  }
  return { (high - low) / (2 * slope), (low + high) / 2 };
}

// Perspective, the centre free: the camera as far forward as the limiting
// axis allows, centred on the other. Returns false when the points have no
// extent on the screen.
bool FitPerspectiveFree(const Projected& p, double s, double t, double scale, Vec3& offset)
{
  const AxisFit across = FitAxis(p.X, p.Z, s), upward = FitAxis(p.Y, p.Z, t);
  const double depth = std::min(across.Depth, upward.Depth);
  const double nearest = *std::min_element(p.Z.begin(), p.Z.end());
  if (!(nearest - depth > 1e-9 * scale))
  {
    return false;
  }
  std::vector<double> w(p.Z.size());
  std::transform(p.Z.begin(), p.Z.end(), w.begin(), [depth](double z) { return z - depth; });
  const bool acrossLimits = across.Depth <= upward.Depth;
  offset = { acrossLimits ? across.Centre : WeightedCentre(p.X, w),
    acrossLimits ? WeightedCentre(p.Y, w) : upward.Centre, depth };
  return true;
}
}

void FitTight(
  const SceneOptions& o, vtkPoints* points, double aspect, const Vec3& turnAxis, vtkCamera* camera)
{
  const bool freeCentre = !o.CameraFocalPoint && !o.CameraPosition && o.Orbit < 2;
  const bool freeDistance = !o.Orthographic && !o.CameraPosition;
  const bool freeScale = o.Orthographic && !o.ParallelScale;
  if (!points || points->GetNumberOfPoints() == 0 || !(freeCentre || freeDistance || freeScale))
  {
    return;
  }
  Vec3 focal, up, forward, right;
  camera->GetFocalPoint(focal.data());
  camera->GetViewUp(up.data());
  camera->GetDirectionOfProjection(forward.data());
  vtkMath::Cross(forward.data(), up.data(), right.data());
  vtkMath::Normalize(right.data());
  vtkMath::Cross(right.data(), forward.data(), up.data());

  std::vector<Vec3> relative(static_cast<std::size_t>(points->GetNumberOfPoints()));
  double scale = 0; // the points' size, for what "no extent" means
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    Vec3& v = relative[static_cast<std::size_t>(i)];
    points->GetPoint(i, v.data());
    for (int k = 0; k < 3; ++k)
    {
      v[k] -= focal[k];
    }
    scale = std::max(scale, std::sqrt(Dot(v, v)));
  }
  // An orbit's frames: the camera turned about the axis through the focal
  // point; each frame's view is projected in turn (they are not all kept).
  Vec3 axis = turnAxis;
  vtkMath::Normalize(axis.data());
  const int frames = std::max(o.Orbit, 1);
  const auto view = [&](int k)
  {
    const double turn = 2 * vtkMath::Pi() * k / frames;
    return Project(
      relative, { Turned(right, axis, turn), Turned(up, axis, turn), Turned(forward, axis, turn) });
  };

  const double t = std::tan(vtkMath::RadiansFromDegrees(camera->GetViewAngle()) / 2);
  const double s = t * aspect;
  Vec3 offset{ 0, 0, 0 }; // the new camera's, in (right, up, forward) about the old focal point
  if (o.Orthographic)
  {
    double half = 0; // the parallel scale that holds every frame's view
    for (int k = 0; k < frames; ++k)
    {
      const Projected p = view(k);
      const auto [left, rightmost] = std::minmax_element(p.X.begin(), p.X.end());
      const auto [bottom, top] = std::minmax_element(p.Y.begin(), p.Y.end());
      if (freeCentre)
      {
        offset = { (*left + *rightmost) / 2, (*bottom + *top) / 2, 0 };
      }
      half = std::max({ half, std::max(*top - offset[1], offset[1] - *bottom),
        std::max(*rightmost - offset[0], offset[0] - *left) / aspect });
    }
    if (!(half > 1e-9 * scale))
    {
      return;
    }
    if (freeScale)
    {
      camera->SetParallelScale(half);
    }
  }
  else if (freeCentre)
  {
    if (!FitPerspectiveFree(view(0), s, t, scale, offset))
    {
      return;
    }
  }
  else
  {
    // The centre stays: the distance at which every point of every frame's
    // view is inside, |x| <= s (z + distance) and |y| <= t (z + distance).
    double distance = -Infinity, spread = 0;
    for (int k = 0; k < frames; ++k)
    {
      const Projected p = view(k);
      for (std::size_t i = 0; i < p.X.size(); ++i)
      {
        const double need = std::max(std::fabs(p.X[i]) / s, std::fabs(p.Y[i]) / t);
        spread = std::max(spread, need);
        distance = std::max(distance, need - p.Z[i]);
      }
    }
    if (!(spread > 1e-9 * scale) || !(distance > 0))
    {
      return; // no extent, or a focal point the camera would have to pass
    }
    offset[2] = -distance;
  }

  Vec3 newFocal, position;
  camera->GetPosition(position.data());
  const double depth = o.Orthographic ? 0 : offset[2] + camera->GetDistance();
  for (int k = 0; k < 3; ++k)
  {
    const double shift = offset[0] * right[k] + offset[1] * up[k];
    newFocal[k] = focal[k] + shift;
    // Orthographic: the camera keeps its distance (the light at the camera stays as far).
    position[k] += shift + depth * forward[k];
  }
  camera->SetFocalPoint(newFocal.data());
  camera->SetPosition(position.data());
}
}
