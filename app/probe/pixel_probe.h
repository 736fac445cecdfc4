// Explaining a pixel (doc/design.md, "Explaining a pixel"): which triangle lies
// under pixel (X, Y) of the picture a scene makes, and how the lecture's
// equation gives its colour there under the scene's rule, from the mesh and
// camera as `render` draws them. What `shadelab probe` prints; the window
// can ask the same of a click.
#ifndef shadelab_pixel_probe_h
#define shadelab_pixel_probe_h

#include "core/options.h"
#include "raytrace/ray_tracer.h"
#include "scene/scene_parts.h"
#include "scene/scene_surface.h"
#include "shadelabEnvironmentBackground.h"
#include "shadelabPictureElements.h"
#include "shadelabPixelRays.h"
#include "shadelabTranslucency.h"
#include "shadelabTriangleFragment.h"

#include <vtkType.h>

#include <array>
#include <memory>
#include <optional>
#include <vector>

class vtkCamera;
class vtkPolyData;

namespace shadelab
{
class RayScene;
class ShadowCasters;

/** One pixel explained. */
struct PixelProbe
{
  Pixel At;
  ImageSize Size;
  Shading Rule = Shading::Phong;
  Reflection Model = Reflection::BlinnPhong;
  // How the rendered program wrote the specular term; the oracle computes
  // the same equation in double either way.
  SpecularForm Form = SpecularForm::Stable;
  Material Surface; // the hit triangle's part's, after the overrides
  Rgb Ia{};
  std::vector<Light> Lights; // as lit, in world coordinates
  // Shadows, per light: the oracle's shadow rays cast for the pixel (at
  // each point its rule lit, where the light would add a term) and, where
  // the picture's shadow maps could be read, at how many of them the map
  // decided otherwise.
  struct ShadowCheck
  {
    int Rays = 0;
    bool MapRead = false;
    int MapDisagrees = 0;
  };
  std::vector<ShadowCheck> Shadows;
  Rgb Background{}; // with the environment behind: E along the pixel's ray
  // --background environment: what the environment shows behind the pixel.
  std::optional<EnvironmentTerm> Behind;
  bool Orthographic = false;
  Representation Drawn = Representation::Surface;
  bool HasNormals = false; // the mesh has vertex normals (Fragment.Normals)
  bool VertexKd = false;   // kd from the mesh's vertex colours (Fragment.VertexKd)
  bool Textured = false;   // kd and ka times a texel (Fragment.TexCoords; Shaded.Texel)
  Rgb Rendered{};          // the picture's value at the pixel: the caller's to set
  // Where Rendered was read, as the text says it: the window reads its own 8-bit pixel.
  const char* RenderedFrom = "the float render at the pixel";
  // Pixels from its centre to the nearest edge that may cover it (with no
  // hit: of any triangle); drawn as edges or points, to where an element's
  // coverage may change (PictureElements::Hit::Margin).
  double EdgeDistance = 0;
  // Drawn as edges or points: the element drawn at the pixel, which
  // Triangle owns and Corners and Fragment describe turned (its provoking
  // point last, ShadeElementFragment).
  struct DrawnElement
  {
    int Pixels = 1;                // the line's width or the point's size
    std::int64_t Index = -1;       // in the order they are drawn (DrawnElements)
    std::vector<vtkIdType> Points; // the edge's two ends, or the point
  };
  std::optional<DrawnElement> Element;

  // The ray through the pixel's centre meets the mesh; the rest holds only then.
  bool Hit = false;
  vtkIdType Triangle = -1;            // its cell index
  std::array<vtkIdType, 3> Corners{}; // its point indices in draw order: the last provokes
  int Part = 0;                       // the mesh's part it is of (0 without parts)
  std::string PartName;               // that part's material's name in the file, or ""
  MaterialSource Source = MaterialSource::Default; // where Surface came from
  TriangleFragment Fragment;                       // positions, normals, weights, facing (world)
  ShadedFragment Shaded;                           // the rule's value and terms: the oracle
  // With fog, at the point under the pixel centre (FogOver); Shaded.Color
  // is its After.
  std::optional<FogAt> Fogged;

  // Translucency (a part with a < 1): every surface under the pixel
  // centre, nearest first, down to the first opaque one; the nearest is the
  // one explained above. Composited is what they make over that opaque one
  // (or the background) in depth order, the nearest Peels of them (0: all):
  // the oracle.
  struct Layer
  {
    vtkIdType Triangle = -1;
    int Part = 0;
    bool Front = true;
    double Opacity = 1; // a
    Rgb Color{};        // I, shaded (and fogged) as above
    double Depth = 0;   // of the point under the pixel centre, along the view direction
    // What it adds to the composite: a*I times the (1 - a) of every nearer
    // layer (the opaque one, I times them), 0 beyond --peels; these and the
    // background times every layer's (1 - a) sum to the oracle.
    Rgb Adds{};
    bool LeftOut = false; // beyond --peels
  };
  std::vector<Layer> Layers;
  int Peels = 0;
  std::optional<Covered> Composited;

  // Ray traced: the sample at the pixel centre (the oracle) and where its
  // light comes from, the surfaces its rays met and what each adds; the
  // rest explains the nearest surface's own light.
  std::optional<Covered> Traced;
  std::vector<RayTracer::Source> Sources;
  int Reflections = 0; // --reflections
};

/** The oracle's value at the pixel: traced, composited in depth order, or shaded. */
inline Rgb OracleOf(const PixelProbe& p)
{
  return p.Traced ? p.Traced->Color : p.Composited ? p.Composited->Color : p.Shaded.Color;
}

/** A scene's picture, ready to explain pixel after pixel. */
class PixelProber
{
public:
  /**
   * `mesh` is the mesh as read (BuiltScene::Mesh: triangles, with the
   * vertex normals the rule uses), `camera` the renderer's after the scene
   * was built, `size` the picture's, `images` its textures' images
   * (BuiltScene::Images): what `render` draws for options; `casters` its
   * shadow maps (BuiltScene::Casters), whose decisions each pixel's
   * ShadowCheck holds against the oracle's rays, read in the current context.
   */
  PixelProber(const SceneOptions& options, vtkPolyData* mesh, vtkCamera* camera, ImageSize size,
    const SceneImages& images = {}, const ShadowCasters* casters = nullptr);
  ~PixelProber();

  /** The pixel explained; its Rendered value left at 0. */
  PixelProbe Probe(Pixel at) const;

  PixelProber(const PixelProber&) = delete; // Elements refers to Triangles
  void operator=(const PixelProber&) = delete;

private:
  // Which triangle, or drawn as edges or points which element, is under the
  // pixel: the fragment's corners and weights, and p's Hit, Triangle and
  // EdgeDistance.
  bool Locate(Pixel at, PixelProbe& p, TriangleCorners& corners) const;
  // The fragment of p's triangle at its weights (corners as drawn, or
  // turned for an element), shaded by its part's material and fogged: p's
  // fragment, part, material and shading.
  void Shade(PixelProbe& p, const TriangleCorners& corners) const;
  // Translucency: p's layers and their composite.
  void Composite(PixelProbe& p) const;

  PixelProbe Scene; // what every pixel shares
  IlluminationInputs In;
  Fog Fogging;
  bool Translucent = false;      // a part drawn has a < 1, or fog takes coverage away
  std::optional<Rgb> Background; // none where it is transparent or the environment
  // --background environment: the environment, and the camera whose rays see it.
  std::optional<EnvironmentMap> Behind;
  PinholeCamera Camera;
  PictureTriangles Triangles;
  std::unique_ptr<PictureElements> Elements; // drawn as edges or points
  int ElementPixels = 1;                     // the lines' width or the points' size
  SceneSurface Surface;
  std::unique_ptr<RayTracer> Tracer; // raytrace: the picture's rays
  std::unique_ptr<RayScene> OwnRays; // shadows in a raster picture: the oracle's rays
  const RayScene* Rays = nullptr;    // shadows: the tracer's or OwnRays
  const ShadowCasters* Casters = nullptr;
  mutable std::vector<PixelProbe::ShadowCheck> Checks; // the pixel being shaded's
  // Its face's normal, the viewer's side, where the maps' bias slopes by
  // the face (phong's surface: ShaderFeatures::SlopesByFace).
  mutable std::optional<Vec3> SlopeFace;
};
}

#endif
