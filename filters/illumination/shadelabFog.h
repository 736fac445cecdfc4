// The lecture's atmospheric effect: fog over the shaded colour, per
// fragment under every rule (doc/design.md, "Fog"). Plain data and the
// double-precision equations that the generated GLSL mirrors
// (shadelabShaderSource.cxx, FogSource).
#ifndef shadelabFog_h
#define shadelabFog_h

#include "shadelabIllumination.h"

#include <array>
#include <optional>
#include <utility>

namespace shadelab
{
enum class FogMode
{
  None,
  Linear,
  Exp,
  Exp2
};

template <>
struct NameTable<FogMode>
{
  static constexpr std::array<std::pair<FogMode, const char*>, 4> Entries{
    { { FogMode::None, "none" }, { FogMode::Linear, "linear" }, { FogMode::Exp, "exp" },
      { FogMode::Exp2, "exp2" } }
  };
};

struct Fog
{
  FogMode Mode = FogMode::None;
  double Start = 0, End = 1; // linear: f falls from 1 at Start to 0 at End (End > Start)
  double Density = 0;        // exp, exp2: >= 0
  std::optional<Rgb> Color;  // none: the background's

  bool operator==(const Fog& o) const
  {
    return this->Mode == o.Mode && this->Start == o.Start && this->End == o.End &&
      this->Density == o.Density && this->Color == o.Color;
  }
  bool operator!=(const Fog& o) const { return !(*this == o); }
};

/**
 * The depth that fog takes: P's distance from the camera's position along
 * its unit view direction (OpenGL's eye-space depth, -z in view
 * coordinates), for both projections.
 */
double FogDepth(const Vec3& P, const Vec3& eye, const Vec3& viewDirection);

/**
 * How much of the shaded colour is left at depth d (the point's distance
 * along the camera's view direction from the camera's position):
 * clamp((End - d)/(End - Start), 0, 1), exp(-Density*d) or
 * exp(-(Density*d)^2); 1 without fog.
 */
double FogFactor(const Fog& fog, double depth);

/** The colour after fog: f*C + (1 - f)*F, F the fog's colour. */
Rgb Fogged(const Rgb& colour, double factor, const Rgb& fogColour);
}

#endif
