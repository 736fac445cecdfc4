// The inputs of the lecture's illumination model (doc/design.md, "The
// illumination model"): materials, lights, and the shading and reflection
// rules. Plain data, shared by the shader generator, the CPU oracle and the
// program.
#ifndef shadelabIllumination_h
#define shadelabIllumination_h

#include "shadelabNames.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace shadelab
{
using Vec3 = std::array<double, 3>;
using Rgb = std::array<double, 3>;

enum class Shading
{
  None,
  Flat,
  Gouraud,
  Phong,
  // The lecture's global illumination: each pixel's ray, its first hit lit
  // as phong lights a fragment, with shadow rays, mirror reflections and the
  // light through translucent surfaces (RayTracedPicture). Not a raster rule.
  Raytrace
};

template <>
struct NameTable<Shading>
{
  static constexpr std::array<std::pair<Shading, const char*>, 5> Entries{
    { { Shading::None, "none" }, { Shading::Flat, "flat" }, { Shading::Gouraud, "gouraud" },
      { Shading::Phong, "phong" }, { Shading::Raytrace, "raytrace" } }
  };
};

/** The rules that light, cheapest first (the lecture's order of cost). */
constexpr std::array<Shading, 3> LitRules{ Shading::Flat, Shading::Gouraud, Shading::Phong };

enum class Reflection
{
  BlinnPhong,
  Phong
};

template <>
struct NameTable<Reflection>
{
  static constexpr std::array<std::pair<Reflection, const char*>, 2> Entries{
    { { Reflection::BlinnPhong, "blinn" }, { Reflection::Phong, "phong" } }
  };
};

/**
 * How the shaders write the specular term (the oracle computes it in
 * double either way): stable, or literally as the lecture writes it.
 */
enum class SpecularForm
{
  Stable,
  Literal
};

template <>
struct NameTable<SpecularForm>
{
  static constexpr std::array<std::pair<SpecularForm, const char*>, 2> Entries{
    { { SpecularForm::Stable, "stable" }, { SpecularForm::Literal, "literal" } }
  };
};

struct Material
{
  std::string Name;
  Rgb Ka{};
  Rgb Kd{};
  Rgb Ks{};
  double Ns = 0;
  double Translucency = 1;
};

enum class LightKind
{
  Point,
  Directional,
  Spot
};

template <>
struct NameTable<LightKind>
{
  static constexpr std::array<std::pair<LightKind, const char*>, 3> Entries{
    { { LightKind::Point, "point" }, { LightKind::Directional, "directional" },
      { LightKind::Spot, "spot" } }
  };
};

/**
 * What a light of a kind has: a position (point, spot), a direction it
 * shines along (directional, spot), a cone (spot). Every branch on a light's
 * kind asks this, so a new kind is one switch to extend.
 */
struct LightGeometry
{
  bool Position;
  bool Direction;
  bool Cone;
};

LightGeometry GeometryOf(LightKind kind);

/**
 * The raster rule that draws rule: itself, and phong for raytrace, whose
 * rays' hits are lit as phong lights a fragment (the shaders draw raytrace's
 * scene as phong: the window's view while it traces, the camera's fit).
 */
Shading RasterRule(Shading rule);

/** Whether the rule lights with vertex normals (gouraud, phong), which a mesh needs then. */
bool UsesVertexNormals(Shading rule);

/** Whether the model's specular vector is H, the half vector (Blinn-Phong), not R (Phong). */
bool UsesHalfVector(Reflection model);

struct Light
{
  LightKind Kind = LightKind::Point;
  Vec3 Position{};  // point and spot, world coordinates
  Vec3 Direction{}; // directional and spot: the direction the light shines along
  Rgb Color{ 1, 1, 1 };
  double HalfAngleDeg = 0; // spot cut-off
  double Exponent = 0;     // spot fall-off (cos angle)^e; 0 is a hard-edged cone
  // Point and spot: Il is divided by C0 + C1*d + C2*d^2, d the distance from
  // the light in world units. Its own coefficients; none: the scene's
  // (EffectiveLights), for this library NoAttenuation.
  std::optional<Vec3> Attenuation;
  // Whether it casts shadows: its own choice; none: the scene's
  // (EffectiveLights), for this library none.
  std::optional<bool> Shadows;
};

/** Whether the light casts shadows (its own Shadows, resolved). */
inline bool CastsShadows(const Light& light)
{
  return light.Shadows.value_or(false);
}

/** C0, C1, C2 = 1, 0, 0: no attenuation, and no code for it. */
constexpr Vec3 NoAttenuation{ 1, 0, 0 };

/** Whether the light's Il falls off with distance: a point or spot light whose coefficients are not
 * NoAttenuation. */
bool Attenuated(const Light& light);

/**
 * The lecture's material table (data/materials.json, compiled in), in the
 * table's order.
 */
const std::vector<Material>& LectureMaterials();

/** The table's material called name, or nullptr. */
const Material* FindLectureMaterial(const std::string& name);
}

#endif
