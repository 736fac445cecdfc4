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

/** Fog at one surface point: what it took and what it made. */
struct FogAt
{
  FogMode Mode = FogMode::None;
  // P's distance from the camera's position along its unit view direction
  // (OpenGL's eye-space depth, -z in view coordinates), for both projections.
  double Depth = 0;
  // How much of the colour is left at Depth: clamp((End - d)/(End - Start),
  // 0, 1), exp(-Density*d) or exp(-(Density*d)^2); 1 without fog.
  double Factor = 1;
  Rgb Color{};  // the fog's: its own, or the background's
  Rgb Before{}; // the shaded colour C
  Rgb After{};  // f*C + (1 - f)*Color
  // Towards a transparent background (no colour of its own): the colour
  // stays (After = Before) and the coverage goes, the surface's a becoming
  // f*a, composited in depth order as translucency is.
  bool Transparent = false;
};

/**
 * `fog` over colour C at surface point P, seen from `eye` along the unit
 * `viewDirection`, towards its colour or else `background` (none: a
 * transparent one).
 */
FogAt FogOver(const Fog& fog, const Rgb& C, const Vec3& P, const Vec3& eye,
  const Vec3& viewDirection, const std::optional<Rgb>& background);
}

#endif
