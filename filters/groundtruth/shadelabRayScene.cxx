#include "shadelabRayScene.h"

#include "shadelabVec3.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace shadelab
{
namespace
{
// Embree traverses in float, relative to the scene's centre, from where the
// ray enters the scene's box (so that a far origin costs no precision). Each
// triangle's box is widened by this share of the diagonal, 5 times the
// float ray's largest deviation from the double one inside the box (about
// 2e-7 of the diagonal), so that no triangle the double ray meets is pruned.
constexpr double BoxPadding = 1e-6;

float Down(double v)
{
  return std::nextafter(static_cast<float>(v), -std::numeric_limits<float>::infinity());
}

float Up(double v)
{
  return std::nextafter(static_cast<float>(v), std::numeric_limits<float>::infinity());
}

// Embree's intersect context, extended with the candidate test (Embree's
// documented way to give a callback its own data).
struct CastContext
{
  RTCIntersectContext Base;
  // A candidate triangle: returns the T (double, along the caller's ray)
  // beyond which no further candidate counts, -inf to stop.
  const std::function<double(std::int64_t)>* Test;
  double Shift;   // the float ray's T is the double ray's less this
  double Padding; // of T, as of the boxes
};

float FloatFar(double t, const CastContext& c)
{
  return t == HUGE_VAL ? std::numeric_limits<float>::infinity() : Up(t - c.Shift + 2 * c.Padding);
}
}

struct RayScene::Embree
{
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  double Padding = 0;

  ~Embree()
  {
    if (this->Scene)
    {
      rtcReleaseScene(this->Scene);
    }
    if (this->Device)
    {
      rtcReleaseDevice(this->Device);
    }
  }
};

RayScene::RayScene(std::vector<Vec3> points, std::vector<TriangleCorners> triangles)
  : Points(std::move(points))
  , Triangles(std::move(triangles))
  , Bvh(std::make_unique<Embree>())
{
  Vec3 low{ HUGE_VAL, HUGE_VAL, HUGE_VAL }, high{ -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (const Vec3& p : this->Points)
  {
    for (int c = 0; c < 3; ++c)
    {
      low[c] = std::min(low[c], p[c]);
      high[c] = std::max(high[c], p[c]);
    }
  }
  if (!this->Points.empty())
  {
    this->Centre = 0.5 * (low + high);
    this->Size = length(high - low);
  }
  this->Bvh->Padding = BoxPadding * this->Size + std::numeric_limits<double>::min();

  this->Bvh->Device = rtcNewDevice(nullptr);
  if (!this->Bvh->Device)
  {
    throw std::runtime_error("Embree: no device");
  }
  this->Bvh->Scene = rtcNewScene(this->Bvh->Device);
  RTCGeometry geometry = rtcNewGeometry(this->Bvh->Device, RTC_GEOMETRY_TYPE_USER);
  rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(this->Triangles.size()));
  rtcSetGeometryUserData(geometry, this);
  rtcSetGeometryBoundsFunction(
    geometry,
    [](const RTCBoundsFunctionArguments* args)
    {
      const auto* self = static_cast<const RayScene*>(args->geometryUserPtr);
      const TriangleCorners& t = self->Triangles[args->primID];
      const double pad = self->Bvh->Padding;
      double low[3], high[3];
      for (int c = 0; c < 3; ++c)
      {
        const double a = self->Points[t[0]][c], b = self->Points[t[1]][c],
                     d = self->Points[t[2]][c];
        low[c] = std::min({ a, b, d }) - self->Centre[c] - pad;
        high[c] = std::max({ a, b, d }) - self->Centre[c] + pad;
      }
      RTCBounds* box = args->bounds_o;
      box->lower_x = Down(low[0]);
      box->lower_y = Down(low[1]);
      box->lower_z = Down(low[2]);
      box->upper_x = Up(high[0]);
      box->upper_y = Up(high[1]);
      box->upper_z = Up(high[2]);
    },
    nullptr);
  rtcSetGeometryIntersectFunction(geometry,
    [](const RTCIntersectFunctionNArguments* args)
    {
      auto* c = reinterpret_cast<CastContext*>(args->context);
      auto* ray = &reinterpret_cast<RTCRayHit*>(args->rayhit)->ray;
      ray->tfar = std::min(ray->tfar, FloatFar((*c->Test)(args->primID), *c));
    });
  rtcSetGeometryOccludedFunction(geometry,
    [](const RTCOccludedFunctionNArguments* args)
    {
      auto* c = reinterpret_cast<CastContext*>(args->context);
      auto* ray = reinterpret_cast<RTCRay*>(args->ray);
      const double t = (*c->Test)(args->primID);
      ray->tfar = t == -HUGE_VAL ? -std::numeric_limits<float>::infinity() : ray->tfar;
    });
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(this->Bvh->Scene, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(this->Bvh->Scene);
}

RayScene::~RayScene() = default;

// Clips the ray to the scene's padded box (in double) and casts what is left
// as a float ray from where it enters; Embree calls test on each triangle
// whose box the float ray meets.
void RayScene::Cast(const Ray& ray, double tMin, double tMax,
  const std::function<double(std::int64_t)>& test, bool any) const
{
  const double pad = this->Bvh->Padding;
  double enter = tMin, exit = tMax;
  for (int c = 0; c < 3; ++c)
  {
    double low = -0.5 * this->Size - pad, high = 0.5 * this->Size + pad;
    const double o = ray.Origin[c] - this->Centre[c], d = ray.Direction[c];
    if (d == 0)
    {
      if (o < low || o > high)
      {
        return;
      }
      continue;
    }
    double t0 = (low - o) / d, t1 = (high - o) / d;
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    enter = std::max(enter, t0 - pad);
    exit = std::min(exit, t1 + pad);
  }
  if (!(enter <= exit))
  {
    return;
  }
  CastContext context;
  rtcInitIntersectContext(&context.Base);
  context.Test = &test;
  context.Shift = std::max(enter, 0.0);
  context.Padding = pad;
  RTCRayHit cast{};
  RTCRay& r = cast.ray;
  r.org_x = static_cast<float>(ray.Origin[0] + context.Shift * ray.Direction[0] - this->Centre[0]);
  r.org_y = static_cast<float>(ray.Origin[1] + context.Shift * ray.Direction[1] - this->Centre[1]);
  r.org_z = static_cast<float>(ray.Origin[2] + context.Shift * ray.Direction[2] - this->Centre[2]);
  r.dir_x = static_cast<float>(ray.Direction[0]);
  r.dir_y = static_cast<float>(ray.Direction[1]);
  r.dir_z = static_cast<float>(ray.Direction[2]);
  r.tnear = std::max(0.0f, Down(tMin - context.Shift - 2 * pad));
  r.tfar = FloatFar(tMax, context);
  r.mask = ~0u;
  r.flags = 0;
  cast.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  if (any)
  {
    rtcOccluded1(this->Bvh->Scene, &context.Base, &r);
  }
  else
  {
    rtcIntersect1(this->Bvh->Scene, &context.Base, &cast);
  }
}

TriangleHit RayScene::Intersect(const Ray& ray, std::int64_t t) const
{
  const TriangleCorners& c = this->Triangles[t];
  return IntersectTriangle(ray, this->Points[c[0]], this->Points[c[1]], this->Points[c[2]]);
}

RayScene::Hit RayScene::First(const Ray& ray, double tMin, double tMax) const
{
  Hit first;
  first.T = tMax;
  const std::function<double(std::int64_t)> test = [&](std::int64_t t)
  {
    const TriangleHit h = this->Intersect(ray, t);
    // Nearer, or as near and earlier in the mesh: the order does not depend
    // on the order Embree visits the candidates in.
    if (h.Inside && h.T > tMin &&
      (h.T < first.T || (h.T == first.T && (first.Triangle < 0 || t < first.Triangle))))
    {
      first = { t, h.T, h.Weights };
    }
    return first.T;
  };
  this->Cast(ray, tMin, tMax, test, false);
  if (first.Triangle < 0)
  {
    first.T = 0;
  }
  return first;
}

bool RayScene::Blocked(const Ray& ray, double tMin, double tMax) const
{
  bool blocked = false;
  const std::function<double(std::int64_t)> test = [&](std::int64_t t)
  {
    const TriangleHit h = this->Intersect(ray, t);
    blocked = blocked || (h.Inside && h.T > tMin && h.T <= tMax);
    return blocked ? -HUGE_VAL : tMax;
  };
  this->Cast(ray, tMin, tMax, test, true);
  return blocked;
}

bool RayScene::LightReaches(const Vec3& point, const Vec3& normal, const Light& light) const
{
  const Vec3 origin = point + (ShadowRayOffset * this->Size) * normal;
  Vec3 towards = -light.Direction;
  double distance = HUGE_VAL;
  if (GeometryOf(light.Kind).Position)
  {
    towards = light.Position - origin;
    distance = length(towards);
  }
  if (!(dot(towards, normal) > 0))
  {
    return false; // the light is behind the surface, or at it
  }
  const Ray ray{ origin, normalize(towards) };
  return !this->Blocked(ray, 0, distance);
}
}
