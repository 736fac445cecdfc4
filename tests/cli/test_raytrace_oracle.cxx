// The ray-traced rule against the double-precision oracle (doc/design.md,
// "Ray tracing"): `--shading raytrace` pictures equal what the oracle's
// own rays give (shadelabPixelRays for the camera's, shadelabRayScene for
// shadows and mirrors):
// - where nothing global happens (a plane sees neither itself nor a
//   shadow), the phong rule's picture: every light kind, textures, parts,
//   vertex colours, fog, attenuation, translucent layers, a transparent
//   background, back faces, far from the origin;
// - a square over the grid shadows it under each light kind, and a torus
//   itself (mirroring itself too), exactly where the oracle's shadow rays
//   say (the band left out is 1e-9 of the scene);
// - a mirror-like grid shows the square's underside where the oracle's
//   reflected ray meets it, and where the test's own geometry says so.
#include "oracle_scene.h"

#include <gtest/gtest.h>

using namespace shadelab_test;

namespace
{
Scene Traced(Scene s)
{
  s.Rule = Shading::Raytrace;
  s.ShadowedAtLeast = 0;
  return s;
}

Scene Shadowed(const Light& light)
{
  Scene s = Traced({});
  s.Geometry.Cells = 12;
  s.Size = 192;
  s.Geometry.Occluder = true;
  s.Lights = { light };
  s.ShadowedAtLeast = 100;
  return s;
}

// A grid whose ks is large, under the square: the grid's mirror image of
// the square's underside, lit by the ambient alone from there, and its
// image of the grid again at the second bounce.
Scene Mirror(int reflections)
{
  Scene s = Shadowed(Point({ 0.6, 0.6, 1.4 }));
  s.Geometry.Bump = 0; // flat: each cell's reflected rays are parallel
  s.Surface.Ks = { 0.75, 0.8125, 0.875 };
  s.Reflections = reflections;
  return s;
}

std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);
  add("plain", Traced({}));
  add("coloured_lights", Traced(ColouredLights()));
  {
    Scene s = Traced({});
    s.Textured = true;
    add("textured", s);
    s.Textured = false;
    s.Parts = ThreeParts();
    add("parts", s);
    s.Parts.clear();
    s.Geometry.VertexColors = true;
    add("vertex_colors", s);
  }
  {
    Scene s = Traced(ColouredLights());
    s.Attenuation = { 0.5, 0.25, 0.125 };
    add("attenuation", s);
    s.Attenuation = shadelab::NoAttenuation;
    s.Fog.Mode = shadelab::FogMode::Linear;
    s.Fog.Start = 9.5;
    s.Fog.End = 10.75;
    add("fog", s);
    s.Fog = {};
    s.Geometry.BackFaces = true;
    add("back_faces", s);
    s.Geometry.BackFaces = false;
    s.Offset = { 1e5, -2e5, 5e4 };
    add("far_from_origin", s);
  }
  {
    // Light straight through translucent layers, every one composited
    // (--peels is the raster's trade); no mirrors, which the oracle's
    // mirror leaves to opaque scenes.
    Scene s = Traced({});
    s.Geometry.Sheets = { 2, 0, 1 };
    s.Translucency = 0.5;
    s.Reflections = 0;
    add("translucent_sheets", s);
    s.TransparentBackground = true;
    add("translucent_sheets_transparent_background", s);
  }
  const std::pair<const char*, Light> lights[] = { { "point", Point({ 0.6, 0.6, 1.4 }) },
    { "directional", Directional({ -0.9, -0.7, -1 }) },
    { "spot", Spot({ 0.6, 0.6, 1.4 }, { -0.5, -0.5, -1 }, 50, 1) } };
  for (const auto& [name, light] : lights)
  {
    add(std::string("shadow_") + name, Shadowed(light));
  }
  {
    Scene s = Shadowed(Point({ -0.1, 1.0, 0.9 }));
    s.Geometry.Occluder = false;
    s.Geometry.Wall = true;
    add("shadow_of_a_wall", s);
    s = Shadowed(Point({ 0.6, 0.6, 1.4 }));
    s.Scale = 1e-4;
    add("shadow_tiny", s);
    s.Scale = 1e4;
    add("shadow_huge", s);
  }
  {
    // Self-shadowing, and the torus's mirror images of itself.
    Scene s = Shadowed(Directional({ 0.4, -1, -0.15 }));
    s.Geometry.Occluder = false;
    s.Geometry.Torus = true;
    s.ShadowedAtLeast = 50; // a smaller shadow than the square's
    add("torus", s);
  }
  add("mirror_one_bounce", Mirror(1));
  add("mirror_two_bounces", Mirror(2));
  return cases;
}

class RaytraceOracle : public testing::TestWithParam<Case>
{
};
}

TEST_P(RaytraceOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Scenes, RaytraceOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });

// Where the mirror shows the square, by the test's own geometry: the
// camera looks straight down at the plane z = x/4 - y/8, so a pixel's
// reflected ray leaves its point P along R = (0, 0, -1) + 2 n_z n (n the
// plane's unit normal) and meets the square's plane z = 0.6 at P + tR. Where
// that lies inside the square (and the square does not hide P), one bounce
// adds exactly ks * ka * Ia: the square's underside faces away from the
// light above it, so the ambient alone lights it. Elsewhere the mirror sees
// the black background and adds nothing. Two pixels either side of the
// region's edge are left out.
TEST(RaytraceMirror, ShowsTheSquareWhereTheReflectedRayMeetsIt)
{
  const Scene one = Mirror(1), none = Mirror(0);
  TempDir dirOne, dirNone;
  std::string error;
  const Image withMirror = Render(one, dirOne, error);
  ASSERT_EQ(error, "");
  const Image without = Render(none, dirNone, error);
  ASSERT_EQ(error, "");
  const Vec3 n = normalize(Vec3{ -one.Geometry.SlopeX, -one.Geometry.SlopeY, 1 });
  const Vec3 R = Vec3{ 0, 0, -1 } + 2 * n[2] * n;
  const double pixel = 2 * ParallelScale / one.Size, margin = 2 * pixel;
  const auto inside = [](double x, double y, double by)
  { return x > -0.45 + by && x < 0.25 - by && y > -0.2 + by && y < 0.5 - by; };
  Rgb adds;
  for (int c = 0; c < 3; ++c)
  {
    adds[c] = one.Surface.Ks[c] * one.Surface.Ka[c] * one.Ambient[c];
  }
  std::size_t reflecting = 0, plain = 0;
  for (int y = 0; y < one.Size; ++y)
  {
    for (int x = 0; x < one.Size; ++x)
    {
      const double px = (x + 0.5) * pixel - ParallelScale, py = ParallelScale - (y + 0.5) * pixel;
      if (std::abs(px) > 1 - margin || std::abs(py) > 1 - margin || inside(px, py, -margin))
      {
        continue; // off the grid, or the square (or its edge) over it
      }
      const Vec3 P{ px, py, one.Geometry.SlopeX * px + one.Geometry.SlopeY * py };
      const Vec3 Q = P + ((0.6 - P[2]) / R[2]) * R;
      const bool sees = inside(Q[0], Q[1], margin);
      if (!sees && inside(Q[0], Q[1], -margin))
      {
        continue; // the reflection's edge
      }
      const Rgb got = Got(withMirror, x, y), base = Got(without, x, y);
      for (int c = 0; c < 3; ++c)
      {
        const double expected = sees ? adds[c] : 0;
        ASSERT_NEAR(got[c] - base[c], expected, 1e-6)
          << PixelName(x, y) << " channel " << c << (sees ? ": sees the square" : ": sees nothing");
      }
      ++(sees ? reflecting : plain);
    }
  }
  std::cout << "[mirror] " << reflecting << " pixels show the square, " << plain << " nothing"
            << std::endl;
  EXPECT_GT(reflecting, 1000u);
  EXPECT_GT(plain, 1000u);
}
