#include "shadelabPictureElements.h"

#include "shadelabTriangleIndexBuffer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shadelab
{
PictureElements::PictureElements(const PictureTriangles& mesh, Representation drawn, int pixels)
  : Mesh(mesh)
  , Drawn(drawn)
  , HalfWidth(0.5 * pixels)
{
  // The triangles OpenGL draws: not those with two corners at one position.
  std::vector<unsigned int> corners, kept;
  const std::vector<Vec3>& p = mesh.GetPoints();
  for (std::size_t t = 0; t < mesh.GetTriangles().size(); ++t)
  {
    const TriangleCorners& c = mesh.GetTriangles()[t];
    if (IsDrawn(p[c[0]], p[c[1]], p[c[2]]))
    {
      kept.push_back(static_cast<unsigned int>(t));
      for (std::int64_t corner : c)
      {
        corners.push_back(static_cast<unsigned int>(corner));
      }
    }
  }
  this->Elements = ElementsOf(drawn, corners);
  // Owners as indices into the mesh's own triangles.
  for (unsigned int& owner : this->Elements.Owners)
  {
    owner = kept[owner];
  }
}

double PictureElements::Inside(std::size_t e, double x, double y, double& t) const
{
  const std::vector<unsigned int>& c = this->Elements.Corners;
  if (this->Drawn == Representation::Points)
  {
    const auto& p = this->Mesh.Projected(c[e]);
    t = 1;
    return this->HalfWidth - std::max(std::abs(x - p[0]), std::abs(y - p[1]));
  }
  const auto& a = this->Mesh.Projected(c[2 * e]);
  const auto& b = this->Mesh.Projected(c[2 * e + 1]);
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  if (!(dx * dx + dy * dy > 0))
  {
    return -std::numeric_limits<double>::infinity();
  }
  // OpenGL's aliased line, as a column (x-major) or row of `width`
  // fragments at each step along its major axis: covered where the point
  // lies between the ends along that axis and within half the width of the
  // line along the other. Each fragment takes the data of the line at its
  // step, t along the major axis (OpenGL's wide lines; Mesa's for every
  // width, measured to 5e-6 pixel, where the projection onto the line that
  // OpenGL gives 1-pixel lines differs by up to a third of a pixel).
  const auto along = [&](bool xMajor, double& at)
  {
    const double major = xMajor ? dx : dy;
    at = (xMajor ? x - a[0] : y - a[1]) / major;
    const double across = xMajor ? y - (a[1] + at * dy) : x - (a[0] + at * dx);
    // The diamond-exit rule may move an end by up to half a pixel: no
    // nearer to an end than that is sure either way.
    constexpr double EndSlack = 0.5;
    const double ends = std::min(at, 1 - at) * std::abs(major);
    const double sure = ends > EndSlack ? ends - EndSlack : ends < -EndSlack ? ends + EndSlack : 0;
    return std::min(this->HalfWidth - std::abs(across), sure);
  };
  // At 45 degrees either axis may be the major one in the rasteriser's
  // float coordinates: only what both agree on is sure.
  if (std::abs(std::abs(dx) - std::abs(dy)) <= 1e-6 * (std::abs(dx) + std::abs(dy)))
  {
    double other = 0;
    const double x = along(true, t), y = along(false, other);
    return x > 0 || y > 0 ? 0 : std::max(x, y);
  }
  return along(std::abs(dx) >= std::abs(dy), t);
}

PictureElements::Hit PictureElements::Under(double x, double y) const
{
  Hit hit;
  const bool orthographic = this->Mesh.GetCamera().Orthographic;
  const std::vector<unsigned int>& c = this->Elements.Corners;
  const std::size_t per = this->Drawn == Representation::Points ? 1 : 2;
  double nearest = std::numeric_limits<double>::infinity();
  double hitWeight = 1;
  hit.Margin = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < this->Elements.Owners.size(); ++e)
  {
    double t = 0;
    const double inside = this->Inside(e, x, y, t);
    if (inside <= 0)
    {
      hit.Margin = std::min(hit.Margin, -inside);
      continue;
    }
    hit.Margin = std::min(hit.Margin, inside);
    // The second end's weight, perspective-correct, and the depth there.
    const double za = this->Mesh.Projected(c[per * e])[2];
    const double zb = this->Mesh.Projected(c[per * e + per - 1])[2];
    const double w = orthographic || per == 1 ? t : (t / zb) / ((1 - t) / za + t / zb);
    const double depth = (1 - w) * za + w * zb;
    if (depth < nearest)
    {
      if (hit.Element >= 0)
      {
        hit.Margin = 0; // two elements cover it: which shows is the rasteriser's
      }
      nearest = depth;
      hit.Element = static_cast<std::int64_t>(e);
      hitWeight = w;
    }
    else
    {
      hit.Margin = 0;
    }
  }
  if (hit.Element < 0)
  {
    return hit;
  }
  hit.Owner = this->Elements.Owners[hit.Element];
  const TriangleCorners& owner = this->Mesh.GetTriangles()[hit.Owner];
  const auto last = static_cast<std::int64_t>(c[per * hit.Element + per - 1]);
  int k = 0;
  while (owner[k] != last)
  {
    ++k;
  }
  // Turned, the cyclic order (and so the face's normal) kept: the
  // provoking corner last, an edge's first end before it.
  hit.Corners = { owner[(k + 1) % 3], owner[(k + 2) % 3], owner[k] };
  hit.Weights = per == 1 ? std::array<double, 3>{ 0, 0, 1 }
                         : std::array<double, 3>{ 0, 1 - hitWeight, hitWeight };
  return hit;
}
}
