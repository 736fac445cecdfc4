// The inputs of the lecture's illumination model (DESIGN.md, "The
// illumination model"): materials, lights, and the shading and reflection
// rules. Plain data, shared by the shader generator, the CPU oracle and the
// program.
#ifndef shadelabIllumination_h
#define shadelabIllumination_h

#include <array>
#include <string>
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
  Phong
};

enum class Reflection
{
  BlinnPhong,
  Phong
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

struct Light
{
  LightKind Kind = LightKind::Point;
  Vec3 Position{};  // point and spot, world coordinates
  Vec3 Direction{}; // directional and spot: the direction the light shines along
  Rgb Color{ 1, 1, 1 };
  double HalfAngleDeg = 0; // spot cut-off
  double Exponent = 0;     // spot fall-off (cos angle)^e; 0 is a hard-edged cone
};

const char* ToString(Shading shading);
const char* ToString(Reflection reflection);
const char* ToString(LightKind kind);

/**
 * The lecture's material table (data/materials.json, compiled in), in the
 * table's order.
 */
const std::vector<Material>& LectureMaterials();

/** The table's material called name, or nullptr. */
const Material* FindLectureMaterial(const std::string& name);
}

#endif
