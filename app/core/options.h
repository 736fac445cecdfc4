// The settings' values (doc/design.md, "Command line"): what decides a
// picture, and the parsers of their text. The table of settings
// (settings/settings_table.cxx) declares them on every command.
#ifndef shadelab_options_h
#define shadelab_options_h

#include "shadelabFog.h"
#include "shadelabIllumination.h"
#include "shadelabRepresentation.h"
#include "shadelabTexture.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
enum class NormalsMode
{
  Auto,   // the file's normals when it has them, else computed
  File,   // the file's normals; an error when it has none
  Compute // always computed
};

template <>
struct NameTable<NormalsMode>
{
  static constexpr std::array<std::pair<NormalsMode, const char*>, 3> Entries{
    { { NormalsMode::Auto, "auto" }, { NormalsMode::File, "file" },
      { NormalsMode::Compute, "compute" } }
  };
};

enum class PixelType
{
  Auto, // float for formats made for it (EXR, HDR, PFM), else 8-bit
  UInt8,
  UInt16,
  Half,
  Float
};

template <>
struct NameTable<PixelType>
{
  static constexpr std::array<std::pair<PixelType, const char*>, 5> Entries{
    { { PixelType::Auto, "auto" }, { PixelType::UInt8, "uint8" }, { PixelType::UInt16, "uint16" },
      { PixelType::Half, "half" }, { PixelType::Float, "float" } }
  };
};

/** --up: the world axis that points up on the screen when the camera is fitted. */
enum class UpAxis
{
  PlusX,
  MinusX,
  PlusY,
  MinusY,
  PlusZ,
  MinusZ
};

template <>
struct NameTable<UpAxis>
{
  static constexpr std::array<std::pair<UpAxis, const char*>, 6> Entries{ { { UpAxis::PlusX, "+X" },
    { UpAxis::MinusX, "-X" }, { UpAxis::PlusY, "+Y" }, { UpAxis::MinusY, "-Y" },
    { UpAxis::PlusZ, "+Z" }, { UpAxis::MinusZ, "-Z" } } };
};

/** --view: where a fitted camera looks from, about the up axis. */
enum class ViewPreset
{
  Front,
  Back,
  Left,
  Right,
  Top,
  Bottom,
  Iso
};

template <>
struct NameTable<ViewPreset>
{
  static constexpr std::array<std::pair<ViewPreset, const char*>, 7> Entries{
    { { ViewPreset::Front, "front" }, { ViewPreset::Back, "back" }, { ViewPreset::Left, "left" },
      { ViewPreset::Right, "right" }, { ViewPreset::Top, "top" }, { ViewPreset::Bottom, "bottom" },
      { ViewPreset::Iso, "iso" } }
  };
};

/** --fit: how missing camera settings are fitted to the mesh. */
enum class FitMode
{
  Sphere, // the bounding sphere fills the narrower view angle, as VTK's ResetCamera
  Tight   // the points' projection fills the picture
};

template <>
struct NameTable<FitMode>
{
  static constexpr std::array<std::pair<FitMode, const char*>, 2> Entries{
    { { FitMode::Sphere, "sphere" }, { FitMode::Tight, "tight" } }
  };
};

struct ImageSize
{
  int Width = 1024;
  int Height = 768;
};

/** A pixel of a picture: X from the left, Y from the top, from 0. */
struct Pixel
{
  int X = 0;
  int Y = 0;
};

/**
 * An image with a scale, IMAGE[:SCALE] (--normal-map, --bump-map): the scale is what
 * follows the last ':' where that is a number, else 1 and the whole text
 * is the image.
 */
struct ScaledImage
{
  std::string Image;
  double Scale = 1;

  bool operator==(const ScaledImage& o) const
  {
    return this->Image == o.Image && this->Scale == o.Scale;
  }
};

/** --normal-map none: no part has a normal map, not even the mesh file's own. */
constexpr const char* NoNormalMap = "none";

/** How vertex normals are computed (vtkShadelabMeshNormals's settings). */
struct NormalsSettings
{
  std::string Weighting = "angle";
  std::optional<double> FeatureAngle; // split at edges sharper than this, degrees
  bool Orient = false;                // make the faces' orientation consistent first
};

/** --shadow-map-size's default: 2048 texels a side. */
constexpr int DefaultShadowMapSize = 2048;

/** Everything that decides what a picture shows. */
struct SceneOptions
{
  std::string Mesh;
  Shading ShadingRule = Shading::Phong;
  Reflection ReflectionModel = Reflection::BlinnPhong;
  std::string MaterialName = "chrome";
  bool MaterialGiven = false; // --material: it replaces the file's materials and colours
  std::optional<Rgb> Ka, Kd, Ks;
  std::optional<double> Ns;
  // --translucency: every part's a (Material::Translucency), composited in
  // depth order (vtkShadelabPeelingPass), at most Peels layers (0: all).
  std::optional<double> Translucency;
  int Peels = 0;
  // --texture: an image whose texel is kd and ka of the whole mesh (times
  // --kd and --ka when given), looked up at its texture coordinates.
  std::string Texture;
  TextureWrap TextureWrapping = TextureWrap::Repeat;
  TextureFilter TextureFiltering = TextureFilter::Bilinear;
  // --environment: an equirectangular image of the surroundings, which the
  // surface reflects as ks * E(R) (shadelabEnvironment.h), looked up with
  // TextureFiltering; its up is EnvironmentUp, or else Up.
  std::string Environment;
  std::optional<UpAxis> EnvironmentUp;
  // --normal-map: a tangent-space normal map (shadelabNormalMap.h) over
  // the whole mesh at its texture coordinates, its x and y times Scale,
  // looked up with TextureWrapping and TextureFiltering.
  // NoNormalMap as its image: no normal map at all, not the files' either.
  std::optional<ScaledImage> NormalMap;
  // --bump-map: a height map (shadelabNormalMap.h, Height), its Scale the
  // height of white in texels' widths, which perturbs the normal in
  // NormalMap's place (a scene gives one of the two at most).
  std::optional<ScaledImage> BumpMap;
  // How the shaders write the specular term: stable, or the lecture's expressions as written.
  SpecularForm Form = SpecularForm::Stable;
  // --vertex-shader, --fragment-shader: files of complete GLSL that replace
  // the generated stage of the scene's rule (scene/own_stage_files.h).
  std::string VertexShader;
  std::string FragmentShader;
  // OpenGL's default global ambient: the lecture's table is OpenGL's classic
  // material table, whose ka values were chosen for it.
  Rgb Ambient{ 0.2, 0.2, 0.2 };
  std::vector<Light> Lights; // empty: one white point light at the camera
  // Point and spot lights' Il / (C0 + C1*d + C2*d^2) where a light has no
  // attenuation of its own (EffectiveLights); 1,0,0 is none.
  Vec3 Attenuation = NoAttenuation;
  // --shadows: each light without a choice of its own (Light::Shadows)
  // casts hard shadows, through maps of ShadowMapSize texels a side.
  bool Shadows = false;
  int ShadowMapSize = DefaultShadowMapSize;
  // --shading raytrace: the mirror reflections a ray follows, one after another.
  int Reflections = 2;
  Fog Fogging; // --fog: none by default
  // --representation: the surface, or its edges or points lit by the same
  // rule (DrawnElements), as lines and squares this many pixels wide.
  Representation Drawn = Representation::Surface;
  int LineWidth = 1;
  int PointSize = 1;
  ImageSize Size;
  int Supersampling = 1; // --ssaa N: N x N samples per pixel, box-averaged in float
  std::optional<Vec3> CameraPosition, CameraFocalPoint, CameraViewUp;
  UpAxis Up = UpAxis::PlusY;
  ViewPreset View = ViewPreset::Front;
  double Azimuth = 0, Elevation = 0; // degrees, turning the camera about the focal point
  double Zoom = 1;                   // vtkCamera::Zoom: the view angle (or scale) divided by it
  FitMode Fit = FitMode::Sphere;
  int Orbit = 0;               // --orbit N: N frames turning once about the up axis; 0: one picture
  double FramesPerSecond = 25; // an --orbit animation's (.gif, .mp4)
  double ViewAngle = 30;
  bool Orthographic = false;
  std::optional<double> ParallelScale;
  Rgb Background{ 0, 0, 0 };
  bool TransparentBackground = false; // --background transparent: alpha 0 where no surface is
  // --background environment: --environment behind the mesh, along each
  // pixel's ray (shadelabEnvironmentBackground.h); drawn as transparent,
  // then laid over it.
  bool EnvironmentBackground = false;
  bool Edges = false; // the triangles' edges over the shading
  Rgb EdgeColor{ 0.05, 0.05, 0.05 };
  double EdgeWidth = 1;      // pixels
  bool NormalGlyphs = false; // a line along each vertex normal
  NormalsMode Normals = NormalsMode::Auto;
  NormalsSettings Computed; // how normals are computed, when they are
  // --allow-outside-references: the files a mesh names (MTL, maps, glTF
  // buffers and images) may lie outside its folder. The user's trust, from
  // the command line only: a scene file cannot give itself this.
  bool AllowOutsideReferences = false;
  PixelType Pixels = PixelType::Auto; // how a picture's file stores its pixels

  /**
   * The material after the --ka/--kd/--ks/--ns overrides; with --texture,
   * ka and kd are the texel's factors: 1 unless --ka, --kd give them.
   */
  Material EffectiveMaterial() const;

  /** m with the coefficients that --ka/--kd/--ks/--ns (and --texture's factors) give replaced. */
  Material Overridden(Material m) const;

  /** --material, --kd or --texture: the mesh's vertex colours are not its kd. */
  bool OverridesKd() const
  {
    return this->MaterialGiven || this->Kd.has_value() || !this->Texture.empty();
  }

  /** The background's colour, or none where it is transparent or the environment. */
  std::optional<Rgb> OpaqueBackground() const
  {
    return this->TransparentBackground || this->EnvironmentBackground
      ? std::nullopt
      : std::optional<Rgb>(this->Background);
  }

  /** --normal-map none: the parts draw no normal map, the file's included. */
  bool NoNormalMaps() const { return this->NormalMap && this->NormalMap->Image == NoNormalMap; }
  /**
   * The map of the normal given: --normal-map's (but none), else
   * --bump-map's (a height map), else none.
   */
  const std::optional<ScaledImage>& Relief() const
  {
    return this->NormalMap && !this->NoNormalMaps() ? this->NormalMap : this->BumpMap;
  }
  std::optional<ScaledImage>& Relief()
  {
    return this->NormalMap && !this->NoNormalMaps() ? this->NormalMap : this->BumpMap;
  }

  /**
   * The parts draw a normal or bump map: one given, or the mesh file's own
   * (`fileMaps`, FileMapsNormals) unless --normal-map none.
   */
  bool MapsNormals(bool fileMaps) const
  {
    return this->Relief() || (fileMaps && !this->NoNormalMaps());
  }

  /** Fog with no colour over a transparent background: it takes coverage away (FogAt). */
  bool FogsTowardsTransparent() const
  {
    return this->Fogging.Mode != FogMode::None && !this->Fogging.Color && !this->OpaqueBackground();
  }
};

struct RenderOptions
{
  SceneOptions Scene;              // its Mesh unused: the meshes are Meshes
  std::vector<std::string> Meshes; // files, folders, globs
  std::string Output;              // with a scene file: an output template for every shot
  std::string DumpShaders;         // a folder, or empty
  bool Verbose = false;
  std::string SceneFile; // --scene: the shots come from this JSON file
  bool PrintSchema = false;
  bool Quiet = false;
  bool SkipExisting = false;
  int ShardIndex = 0; // --shard I/N
  int ShardCount = 1;
};

/** "I/N" with 0 <= I < N: the shard index and count. */
std::pair<int, int> ParseShard(const std::string& text);

/** The lecture's material names, in its table's order. */
std::vector<std::string> LectureMaterialNames();

/** "Mesh file: .obj .ply ...": a command's MESH help, from the formats the reader knows. */
std::string MeshFileHelp();

/** text's parts between the separators (one empty part for empty text). */
std::vector<std::string> Split(const std::string& text, char separator);

// Value parsers (option_parsers.cxx), exposed for tests. Each throws
// std::invalid_argument with a message that names what is wrong with the text.
Vec3 ParseVec3(const std::string& text);
Vec3 ParseDirection(const std::string& text); // a Vec3 of non-zero length
double ParseNonNegative(const std::string& text);
Rgb ParseRgb(const std::string& text);
Vec3 ParseAttenuation(const std::string& text); // C0,C1,C2: none negative, not all zero
// none | linear:START,END[:R,G,B] | exp:DENSITY[:R,G,B] | exp2:DENSITY[:R,G,B]
Fog ParseFog(const std::string& text);
ImageSize ParseSize(const std::string& text);
ScaledImage ParseScaledImage(const std::string& text); // IMAGE[:SCALE]
Pixel ParsePixel(const std::string& text);             // "X,Y", each a whole number >= 0
// KIND:...[@C0,C1,C2][+shadows|+no-shadows]
Light ParseLight(const std::string& text);
double ParseNumber(const std::string& text);

/**
 * What the headless backend renders for o: Size times Supersampling a side;
 * an error text when that is beyond the limits below, else "".
 */
std::string RenderedSize(const SceneOptions& o, ImageSize& rendered);

/** The largest supersampling, N x N samples a pixel. */
constexpr int MaxSupersampling = 8;
// Aliased lines and points as OpenGL draws them without VTK's geometry
// shader (which would not pass the generated stages' values on): OpenGL
// 3.2 promises no more than 1, Mesa's llvmpipe draws up to 255.
constexpr int MaxLineWidth = 16;
constexpr int MaxPointSize = 64;
/** The most --peels a limit may give (more would be no limit for any mesh drawn). */
constexpr int MaxPeels = 10000;
/** The most --shadow-map-size takes: OpenGL's limit may be lower (checked as the maps are made). */
constexpr int MaxShadowMapSize = 32768;
/**
 * The most --reflections takes: each bounce weighs by ks, and after 64 of
 * ks <= 0.9 (every material of the lecture's table) what is left is below
 * an 8-bit step (0.9^64 < 1/255).
 */
constexpr int MaxReflections = 64;

/** The most frames of an --orbit (a tenth of a degree apart) and frames a second. */
constexpr int MaxOrbitFrames = 3600;
constexpr int MaxFramesPerSecond = 120;

/** The largest image side and area: the float read-back of 8192x8192 is 1 GiB. */
constexpr int MaxImageSide = 16384;
constexpr long long MaxImagePixels = 8192LL * 8192LL;
}

#endif
