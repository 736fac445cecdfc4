#include "probe/pixel_probe.h"

#include "scene/scene.h"
#include "shadelabMeshTriangles.h"
#include "shadelabRayScene.h"
#include "shadelabShadowCasters.h"
#include "shadelabTriangleMesh.h"
#include "shadelabVec3.h"

#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace shadelab
{
PixelProber::~PixelProber() = default;

PixelProber::PixelProber(const SceneOptions& options, vtkPolyData* mesh, vtkCamera* camera,
  ImageSize size, const SceneImages& images, const ShadowCasters* casters)
  : Triangles(PinholeCameraOf(camera), size.Width, size.Height, PointsOf(mesh), TrianglesOf(mesh))
  , Surface(options, mesh, images)
  , Casters(casters)
{
  Vec3 eye;
  camera->GetPosition(eye.data());
  PixelProbe& s = this->Scene;
  s.Size = size;
  s.Rule = options.ShadingRule;
  s.Model = options.ReflectionModel;
  s.Form = options.Form;
  s.Surface = options.EffectiveMaterial();
  s.Ia = options.Ambient;
  s.Lights = EffectiveLights(options, eye); // as BuildScene lights it, or the ray tracer
  if (options.ShadingRule == Shading::Raytrace)
  {
    this->Tracer = std::make_unique<RayTracer>(options, mesh, camera, images);
    s.Reflections = options.Reflections;
  }
  s.Background = options.Background;
  s.Orthographic = camera->GetParallelProjection();
  this->In = CameraIllumination(options, s.Lights, camera);
  this->Fogging = options.Fogging;
  this->Translucent = AnyTranslucent(this->Surface.GetParts()) || options.FogsTowardsTransparent();
  this->Background = options.OpaqueBackground();
  if (options.EnvironmentBackground)
  {
    this->Behind = SceneEnvironment(options, images);
    this->Camera = PinholeCameraOf(camera);
  }
  s.Peels = options.Peels;
  if (options.Drawn != Representation::Surface)
  {
    s.Drawn = options.Drawn;
    this->ElementPixels =
      options.Drawn == Representation::Points ? options.PointSize : options.LineWidth;
    this->Elements =
      std::make_unique<PictureElements>(this->Triangles, s.Drawn, this->ElementPixels);
  }
  if (std::any_of(s.Lights.begin(), s.Lights.end(), CastsShadows))
  {
    if (!this->Tracer)
    {
      this->OwnRays =
        std::make_unique<RayScene>(this->Triangles.GetPoints(), this->Triangles.GetTriangles());
    }
    this->Rays = this->Tracer ? &this->Tracer->GetRays() : this->OwnRays.get();
    // The prober stays where it is made (no copy, no move): `this` holds.
    this->In.Reaches = [this](std::size_t l, const Vec3& P, const Vec3& N)
    {
      using namespace vec3;
      const Light& light = this->Scene.Lights[l];
      const bool reaches = this->Rays->LightReaches(P, N, light);
      PixelProbe::ShadowCheck& check = this->Checks[l];
      ++check.Rays;
      if (const ShadowMap* map = this->Casters ? this->Casters->Baked(l) : nullptr)
      {
        const Vec3 L = GeometryOf(light.Kind).Position ? normalize(light.Position - P)
                                                       : normalize(-1.0 * light.Direction);
        check.MapRead = true;
        check.MapDisagrees +=
          map->Lit(P, dot(this->SlopeFace.value_or(N), L), length(P - this->In.Eye)) != reaches;
      }
      return reaches;
    };
  }
  s.VertexKd = this->Surface.VertexKd();
  s.Textured = this->Surface.Textured();
  s.HasNormals = this->Surface.HasNormals();
}

PixelProbe PixelProber::Probe(Pixel at) const
{
  PixelProbe p = this->Scene;
  p.At = at;
  if (this->Behind)
  {
    p.Behind = EnvironmentBehind(
      *this->Behind, this->Camera, p.Size.Width, p.Size.Height, at.X + 0.5, at.Y + 0.5);
    p.Background = p.Behind->Texel;
  }
  TriangleCorners corners;
  if (!this->Locate(at, p, corners))
  {
    return p;
  }
  this->Shade(p, corners);
  if (this->Tracer)
  {
    p.Traced =
      this->Tracer->Explain(p.Size.Width, p.Size.Height, at.X + 0.5, at.Y + 0.5, p.Sources);
  }
  else if (this->Translucent && !p.Element)
  {
    this->Composite(p);
  }
  return p;
}

void PixelProber::Shade(PixelProbe& p, const TriangleCorners& corners) const
{
  const bool front = p.Fragment.Front;
  p.Fragment =
    this->Surface.Fragment(corners, p.Fragment.Weights, front, this->Triangles.GetPoints());
  for (int k = 0; k < 3; ++k)
  {
    p.Corners[k] = corners[k];
  }
  const ScenePart& part = this->Surface.PartOf(p.Triangle);
  p.Part = part.Index;
  p.PartName = part.Name;
  p.Source = part.Source;
  p.Surface = part.Surface;
  p.Textured = p.Textured && part.Texture.Used();
  const IlluminationInputs in = this->Surface.InputsOf(this->In, p.Triangle);
  this->Checks.assign(p.Lights.size(), {});
  this->SlopeFace.reset();
  if (RasterRule(p.Rule) == Shading::Phong && !p.Element)
  {
    Vec3 unit;
    FaceNormal(p.Fragment.Positions[0], p.Fragment.Positions[1], p.Fragment.Positions[2], unit);
    this->SlopeFace = p.Fragment.Front ? unit : -unit;
  }
  p.Shaded = p.Element ? ShadeElementFragment(in, p.Rule, p.Fragment)
                       : ShadeTriangleFragment(in, p.Rule, p.Fragment);
  p.Shadows = this->Checks;
  if (this->Fogging.Mode != FogMode::None)
  {
    // Per fragment under every rule: at the point under the pixel centre
    // (flat's too, which is lit at its provoking vertex).
    p.Fogged = FogOver(this->Fogging, p.Shaded.Color, p.Shaded.Point, this->In.Eye,
      this->In.ViewDirection, this->Background);
    p.Shaded.Color = p.Fogged->After;
  }
}

void PixelProber::Composite(PixelProbe& p) const
{
  std::vector<Layer> translucent;
  // Transparent: black with no coverage.
  Covered behind = this->Background ? Covered{ *this->Background, 1 }
    : p.Behind                      ? Covered{ p.Behind->Texel, 1 }
                                    : Covered{ { 0, 0, 0 }, 0 };
  for (const PictureTriangles::Hit& hit : this->Triangles.Through(p.At.X + 0.5, p.At.Y + 0.5))
  {
    PixelProbe layer = this->Scene;
    layer.Triangle = hit.Triangle;
    layer.Fragment.Weights = hit.Weights;
    layer.Fragment.Front = hit.Front;
    this->Shade(layer, this->Triangles.GetTriangles()[hit.Triangle]);
    // Fog towards transparent takes the coverage down by its factor.
    const double a = layer.Surface.Translucency *
      (layer.Fogged && layer.Fogged->Transparent ? layer.Fogged->Factor : 1);
    Vec3 point{};
    double depth = 0;
    for (int c = 0; c < 3; ++c)
    {
      for (int k = 0; k < 3; ++k)
      {
        point[c] += layer.Fragment.Weights[k] * layer.Fragment.Positions[k][c];
      }
      depth += (point[c] - this->In.Eye[c]) * this->In.ViewDirection[c];
    }
    p.Layers.push_back({ hit.Triangle, layer.Part, hit.Front, a, layer.Shaded.Color, depth });
    if (a >= 1)
    {
      behind = { layer.Shaded.Color, 1 };
      break;
    }
    translucent.push_back({ layer.Shaded.Color, a });
  }
  p.Composited = shadelab::Composite(translucent, behind, p.Peels);
  double through = 1; // the nearer layers' product of (1 - a)
  for (std::size_t k = 0; k < p.Layers.size(); ++k)
  {
    PixelProbe::Layer& l = p.Layers[k];
    const bool opaque = l.Opacity >= 1;
    l.LeftOut = !opaque && p.Peels > 0 && k >= static_cast<std::size_t>(p.Peels);
    if (l.LeftOut)
    {
      continue; // adds nothing
    }
    for (int c = 0; c < 3; ++c)
    {
      l.Adds[c] = through * (opaque ? 1 : l.Opacity) * l.Color[c];
    }
    through *= 1 - l.Opacity;
  }
}

bool PixelProber::Locate(Pixel at, PixelProbe& p, TriangleCorners& corners) const
{
  const double x = at.X + 0.5, y = at.Y + 0.5;
  if (this->Elements)
  {
    const PictureElements::Hit hit = this->Elements->Under(x, y);
    p.EdgeDistance = hit.Margin;
    if (hit.Element < 0)
    {
      return false;
    }
    PixelProbe::DrawnElement& e = p.Element.emplace();
    e.Pixels = this->ElementPixels;
    const DrawnElements& all = this->Elements->GetElements();
    const std::size_t per = p.Drawn == Representation::Points ? 1 : 2;
    e.Index = hit.Element;
    for (std::size_t k = 0; k < per; ++k)
    {
      e.Points.push_back(all.Corners[per * hit.Element + k]);
    }
    p.Hit = true;
    p.Triangle = hit.Owner;
    corners = hit.Corners;
    p.Fragment.Weights = hit.Weights;
    return true;
  }
  const PictureTriangles::Hit hit = this->Triangles.Under(x, y);
  p.EdgeDistance = hit.EdgeDistance;
  if (hit.Triangle < 0)
  {
    return false;
  }
  p.Hit = true;
  p.Triangle = hit.Triangle;
  corners = this->Triangles.GetTriangles()[hit.Triangle];
  p.Fragment.Weights = hit.Weights;
  p.Fragment.Front = hit.Front;
  return true;
}
}
