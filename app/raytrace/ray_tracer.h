// The ray-traced rule, --shading raytrace (doc/design.md, "Ray tracing"):
// the lecture's global illumination in double precision. Each sample's ray
// meets the mesh (Embree's hierarchy, each candidate tested in double); the
// hit is lit as phong lights a fragment, every light's shadow ray cast; a
// surface with ks adds ks times what its mirror reflection sees, up to
// --reflections bounces; a translucent one lets (1 - a) of what lies
// straight behind it through. Where nothing global happens its picture is
// the phong rule's.
#ifndef shadelab_ray_tracer_h
#define shadelab_ray_tracer_h

#include "core/options.h"
#include "image/image_pixels.h"
#include "scene/scene_surface.h"
#include "shadelabFog.h"
#include "shadelabRayScene.h"
#include "shadelabTranslucency.h"

#include <memory>
#include <optional>

class vtkCamera;
class vtkPolyData;

namespace shadelab
{
class RayTracer
{
public:
  /**
   * options' scene as BuildScene made it: `mesh` (BuiltScene::Mesh),
   * `camera` the renderer's, `images` its textures' (BuiltScene::Images),
   * lit by EffectiveLights (every light casting shadows unless it says not).
   */
  RayTracer(const SceneOptions& options, vtkPolyData* mesh, vtkCamera* camera,
    const SceneImages& images = {});
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  /**
   * The picture at options' size, samples x samples rays a pixel
   * (--ssaa) box-averaged as the raster's samples are, on every core; its
   * alpha the coverage (1 over an opaque background).
   */
  FloatImage Picture(int samples) const;
  /** Picture's image before a row is traced: samples x samples a pixel, black. */
  FloatImage Blank(int samples) const;
  /**
   * Rows [first, last) of `image` (from the top; stored bottom row first,
   * as OpenGL reads them) traced on every core: Picture a band at a time
   * (the window's raytrace panel, with its progress).
   */
  void TraceRows(FloatImage& image, int first, int last) const;

  /** What the camera's ray through picture point (x, y) of a width x height picture sees. */
  Covered Sample(int width, int height, double x, double y) const;

  /**
   * Where a sample's light comes from: each surface its rays met (the
   * camera's, the mirrors', through translucent ones), the background and
   * the fog, with what each adds to the sample.
   */
  struct Source
  {
    enum Kind
    {
      Surface,    // a surface's own light: the phong fragment, shadow rays cast
      Background, // what a ray that met nothing saw (Beyond)
      Fog         // the fog's colour, where the camera's ray was fogged
    } What = Surface;
    int Bounce = 0;  // mirror reflections before it: 0 on the camera's ray
    int Through = 0; // translucent surfaces before it on its ray
    std::int64_t Triangle = -1;
    Vec3 Point{};         // where its ray met it
    double Distance = 0;  // from its ray's origin (the camera's, or the mirror point)
    double Opacity = 1;   // its a
    ShadedFragment Local; // its own light, with each light's shadow ray's answer
    Rgb Color{};          // its own light (Local.Color), the background's or the fog's colour
    Rgb Weight{}; // what Color is multiplied by in the sample: the a, (1 - a), ks and f on the way
    Rgb Adds{};   // Weight * Color: these sum to the sample
  };

  /** The mesh's rays (the probe casts its shadow rays through them too). */
  const RayScene& GetRays() const { return *this->Rays; }

  /** Sample(width, height, x, y), and where its light comes from. */
  Covered Explain(int width, int height, double x, double y, std::vector<Source>& sources) const;

private:
  /**
   * The light coming back along ray from what it meets beyond tMin: every
   * surface on it composited in depth order over what lies behind
   * (`behind`: Beyond()), each surface lit from `view` (its eye the ray's
   * origin, or the camera) with `bounces` reflections left. `camera`: the
   * ray is the camera's, whose hits are fogged.
   */
  Covered Trace(const Ray& ray, double tMin, const IlluminationInputs& view, int bounces,
    const Covered& behind, bool camera, std::vector<Source>* sources = nullptr) const;

  /** A surface point's own light and its reflection's share, and its opacity. */
  struct Surface
  {
    ShadedFragment Local;        // the phong rule's fragment, shadow rays cast
    std::optional<Ray> Mirror;   // the reflected ray followed, if any
    Rgb Reflected{};             // what that ray saw
    Rgb Ks{};                    // what weighs it
    std::optional<FogAt> Fogged; // a camera ray's hit, with fog
    Rgb Color{};                 // Local + Ks * Reflected, fogged
    double Opacity = 1;          // a, fog towards transparent taking its share
  };

  /**
   * The hit of ray on triangle `hit` lit from `view`, bounces reflections
   * left; with sources, where its Color comes from, weighed within it.
   */
  Surface LightHit(const Ray& ray, const RayScene::Hit& hit, const IlluminationInputs& view,
    int bounces, bool camera, std::vector<Source>* sources = nullptr) const;

  /**
   * What a ray that meets nothing sees: the background, as in Whitted's
   * ray tracer (a mirror shows it too), or nothing where it is transparent.
   */
  Covered Beyond() const;

  ImageSize Size;
  int Reflections = 2;
  PinholeCamera Camera;
  SceneSurface Surfaces;
  std::unique_ptr<RayScene> Rays;
  std::vector<Light> Lights; // as lit, in world coordinates
  IlluminationInputs View;   // the camera's, every light casting shadows by the rays
  Fog Fogging;
  std::optional<Rgb> Background; // none where it is transparent
};
}

#endif
