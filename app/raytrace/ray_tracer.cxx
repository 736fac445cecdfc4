#include "raytrace/ray_tracer.h"

#include "scene/scene.h"
#include "shadelabMeshTriangles.h"
#include "shadelabParallelRows.h"
#include "shadelabVec3.h"

#include <vtkCamera.h>

#include <algorithm>

namespace shadelab
{
RayTracer::~RayTracer() = default;

RayTracer::RayTracer(
  const SceneOptions& options, vtkPolyData* mesh, vtkCamera* camera, const SceneImages& images)
  : Size(options.Size)
  , Reflections(options.Reflections)
  , Camera(PinholeCameraOf(camera))
  , Surfaces(options, mesh, images)
  , Rays(std::make_unique<RayScene>(PointsOf(mesh), TrianglesOf(mesh)))
  , Fogging(options.Fogging)
  , Background(options.OpaqueBackground())
{
  this->Lights = EffectiveLights(options, this->Camera.Position);
  this->View = CameraIllumination(options, this->Lights, camera);
  this->View.Reaches = [this](std::size_t l, const Vec3& P, const Vec3& N)
  { return this->Rays->LightReaches(P, N, this->Lights[l]); };
}

namespace
{
// Sources' weights times factor, from the first one on.
void Weigh(std::vector<RayTracer::Source>& sources, std::size_t first, const Rgb& factor)
{
  for (std::size_t k = first; k < sources.size(); ++k)
  {
    sources[k].Weight = sources[k].Weight * factor;
  }
}
}

RayTracer::Surface RayTracer::LightHit(const Ray& ray, const RayScene::Hit& hit,
  const IlluminationInputs& view, int bounces, bool camera, std::vector<Source>* sources) const
{
  using namespace vec3;
  const TriangleCorners& corners = this->Rays->GetTriangles()[hit.Triangle];
  const std::vector<Vec3>& points = this->Rays->GetPoints();
  const Vec3 across = cross(points[corners[1]] - points[corners[0]],
    points[corners[2]] - points[corners[0]]); // the face's normal, counter-clockwise
  // Front: counter-clockwise as the ray sees it, as the rasteriser decides
  // for the camera's rays.
  const bool front = dot(across, ray.Direction) < 0;
  const IlluminationInputs in = this->Surfaces.InputsOf(view, hit.Triangle);
  Surface s;
  s.Local = ShadeTriangleFragment(
    in, Shading::Phong, this->Surfaces.Fragment(corners, hit.Weights, front, points));
  s.Ks = s.Local.Ks.value_or(in.Surface.Ks);
  s.Color = s.Local.Color;
  s.Opacity = in.Surface.Translucency;
  const std::size_t first = sources ? sources->size() : 0;
  if (sources)
  {
    Source own;
    own.Bounce = this->Reflections - bounces;
    own.Triangle = hit.Triangle;
    own.Point = s.Local.Point;
    own.Distance = hit.T;
    own.Opacity = s.Opacity;
    own.Local = s.Local;
    own.Color = s.Local.Color;
    own.Weight = { 1, 1, 1 };
    sources->push_back(own);
  }
  const Vec3& N = s.Local.Terms.N; // as lit: unit, turned towards the viewer; 0 for none
  if (bounces > 0 && std::max({ s.Ks[0], s.Ks[1], s.Ks[2] }) > 0 && dot(N, N) > 0)
  {
    const Vec3 R = ray.Direction - (2 * dot(ray.Direction, N)) * N;
    // The mirror sees what lies in front of the face: a shading normal that
    // leans off the face can reflect into it, and there it sees nothing.
    const Vec3 outward = (front ? 1.0 : -1.0) * normalize(across);
    if (dot(R, outward) > 0)
    {
      s.Mirror =
        Ray{ s.Local.Point + (ShadowRayOffset * this->Rays->Diagonal()) * outward, normalize(R) };
      IlluminationInputs from = this->View;
      from.Orthographic = false;
      from.Eye = s.Mirror->Origin;
      const std::size_t mirrored = sources ? sources->size() : 0;
      s.Reflected =
        this->Trace(*s.Mirror, 0, from, bounces - 1, this->Beyond(), false, sources).Color;
      s.Color = s.Color + s.Ks * s.Reflected;
      if (sources)
      {
        Weigh(*sources, mirrored, s.Ks);
      }
    }
  }
  if (camera && this->Fogging.Mode != FogMode::None)
  {
    // Depth cueing: by the eye-space depth of the camera ray's hit, as the
    // raster rules fog each fragment; a reflection is part of that colour.
    s.Fogged = FogOver(this->Fogging, s.Color, s.Local.Point, this->View.Eye,
      this->View.ViewDirection, this->Background);
    s.Color = s.Fogged->After;
    s.Opacity *= s.Fogged->Transparent ? s.Fogged->Factor : 1;
    if (sources && !s.Fogged->Transparent)
    {
      const double f = s.Fogged->Factor;
      Weigh(*sources, first, { f, f, f });
      Source fog;
      fog.What = Source::Fog;
      fog.Point = s.Local.Point;
      fog.Distance = hit.T;
      fog.Color = s.Fogged->Color;
      fog.Weight = { 1 - f, 1 - f, 1 - f };
      sources->push_back(fog);
    }
  }
  return s;
}

Covered RayTracer::Trace(const Ray& ray, double tMin, const IlluminationInputs& view, int bounces,
  const Covered& behind, bool camera, std::vector<Source>* sources) const
{
  std::vector<Layer> translucent; // nearest first
  Covered last = behind;
  double through = 1; // the product of the nearer surfaces' (1 - a)
  // Straight on through translucent surfaces (no refraction): each one's T
  // is beyond the last, so the walk ends.
  for (double t = tMin;;)
  {
    const RayScene::Hit hit = this->Rays->First(ray, t);
    const std::size_t first = sources ? sources->size() : 0;
    if (hit.Triangle < 0)
    {
      if (sources)
      {
        Source background;
        background.What = Source::Background;
        background.Bounce = this->Reflections - bounces;
        background.Through = static_cast<int>(translucent.size());
        background.Color = behind.Color;
        background.Weight = { through, through, through };
        sources->push_back(background);
      }
      break;
    }
    t = hit.T;
    const Surface s = this->LightHit(ray, hit, view, bounces, camera, sources);
    // Composite's weights: a * (the nearer (1 - a)), the opaque one's 1 * them.
    const double share = through * std::min(s.Opacity, 1.0);
    if (sources)
    {
      Weigh(*sources, first, { share, share, share });
      for (std::size_t k = first; k < sources->size(); ++k)
      {
        (*sources)[k].Through += (*sources)[k].Bounce == this->Reflections - bounces
          ? static_cast<int>(translucent.size())
          : 0;
      }
    }
    if (s.Opacity >= 1)
    {
      last = { s.Color, 1 };
      break;
    }
    through *= 1 - s.Opacity;
    translucent.push_back({ s.Color, s.Opacity });
  }
  return Composite(translucent, last);
}

Covered RayTracer::Explain(
  int width, int height, double x, double y, std::vector<Source>& sources) const
{
  sources.clear();
  const Covered sample = this->Trace(PictureRay(this->Camera, width, height, x, y), 0, this->View,
    this->Reflections, this->Beyond(), true, &sources);
  for (Source& source : sources)
  {
    source.Adds = source.Weight * source.Color;
  }
  return sample;
}

Covered RayTracer::Sample(int width, int height, double x, double y) const
{
  return this->Trace(PictureRay(this->Camera, width, height, x, y), 0, this->View,
    this->Reflections, this->Beyond(), true);
}

Covered RayTracer::Beyond() const
{
  return this->Background ? Covered{ *this->Background, 1 } : Covered{ { 0, 0, 0 }, 0 };
}

FloatImage RayTracer::Picture(int samples) const
{
  FloatImage image = this->Blank(samples);
  this->TraceRows(image, 0, image.Height);
  return samples > 1 ? BoxAverage(image, samples) : image;
}

FloatImage RayTracer::Blank(int samples) const
{
  FloatImage image;
  image.Width = this->Size.Width * samples;
  image.Height = this->Size.Height * samples;
  image.Rgba.resize(static_cast<std::size_t>(image.Width) * image.Height * 4);
  return image;
}

void RayTracer::TraceRows(FloatImage& image, int first, int last) const
{
  ForEachRow(first, last,
    [&](int y)
    {
      // Bottom row first, as OpenGL reads them; picture y from the top.
      float* out =
        image.Rgba.data() + static_cast<std::size_t>(image.Height - 1 - y) * image.Width * 4;
      for (int x = 0; x < image.Width; ++x, out += 4)
      {
        const Covered c = this->Sample(image.Width, image.Height, x + 0.5, y + 0.5);
        std::copy(c.Color.begin(), c.Color.end(), out);
        out[3] = static_cast<float>(c.Alpha);
      }
    });
}
}
