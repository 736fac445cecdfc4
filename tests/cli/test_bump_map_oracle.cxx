// Bump (height) maps through the lecture's equation, pixel by pixel:
// orthographic renders by `shadelab render --bump-map` of the test grid
// against the double-precision oracle, which tilts the normal by the
// height's differences one texel apart (shadelabNormalMap.h) where each
// rule takes the normal, in the frame of the grid's tangent (GridTangent);
// a height ramp against its tilt worked out here on its own; and a sphere
// of our own with a checker bump map in its MTL, against probe's oracle.
// probe's explanation and OBJ's bump statements are test_normal_map_oracle's,
// with the normal maps'.
//
// The tolerance is the standard one (1e-4 relative), as for normal maps:
// the heights are float texels, filtered in float as the textures are, and
// their differences are taken in float from the same lookups.
#include "probe_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace shadelab_test;
using shadelab::TextureFilter;
using shadelab::TextureWrap;

namespace
{
std::vector<Case> Cases()
{
  std::vector<Case> cases;
  const auto add = CaseAdder(cases);
  for (Shading r : LitRules)
  {
    const std::string rule = ToString(r);
    Scene s;
    s.Rule = r;
    s.NormalMap = NormalMapKind::Heights;
    for (TextureFilter filter : { TextureFilter::Nearest, TextureFilter::Bilinear })
    {
      s.Filter = filter;
      add(rule + "_heights_" + ToString(filter), s);
    }
    s.NormalScale = -2.5;
    s.Wrap = TextureWrap::Clamp;
    add(rule + "_scale_negative_clamped", s);
    s.NormalScale = 1.5;
    s.Wrap = TextureWrap::Mirror;
    s.Geometry.BackFaces = true;
    add(rule + "_mirrored_back_faces", s);
    s.Wrap = TextureWrap::Repeat;
    s.Geometry.BackFaces = false;
    s.Environment = EnvironmentKind::Pattern;
    add(rule + "_environment", s);
  }
  return cases;
}

class BumpMapOracle : public testing::TestWithParam<Case>
{
};
}

TEST_P(BumpMapOracle, MatchesTheCpuOracle)
{
  ExpectMatchesOracle(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, BumpMapOracle, testing::ValuesIn(Cases()),
  [](const testing::TestParamInfo<Case>& info) { return info.param.Name; });

// A height ramp, RampStep/255 a texel along s and none along t, on a plane:
// wherever the height and the height one texel along s are both read
// within the ramp (not across its wrap), their difference is RampStep/255,
// and the picture equals the plane whose file normals are tilted by
// (-scale RampStep/255, 0, 1) along (T, B, N), the tangent written out here
// on its own. Phong, which takes the map at each pixel; with the nearest
// texel (any s in the first three columns) and bilinear (s between the
// first and the third texel centre, where the filter is linear); within
// float's rounding of the two ways to the same normal (1e-5). The picture's
// metadata names the bump map.
TEST(BumpMap, AHeightRampTiltsTheNormalsAsItsSlopeWould)
{
  GridSpec plane;
  plane.Bump = 0;
  const Vec3 n = normalize(Vec3{ -plane.SlopeX, -plane.SlopeY, 1 });
  const Vec3 dPds = Vec3{ 1, 0, plane.SlopeX };
  const Vec3 t = normalize(dPds - dot(n, dPds) * n);
  const Vec3 b = cross(n, t);
  constexpr double Scale = 3;
  const Vec3 tilted = normalize(-Scale * RampStep / 255.0 * t + 0 * b + n);
  for (TextureFilter filter : { TextureFilter::Nearest, TextureFilter::Bilinear })
  {
    SCOPED_TRACE(ToString(filter));
    Scene mapped;
    mapped.Rule = Shading::Phong;
    mapped.Geometry = plane;
    mapped.NormalMap = NormalMapKind::Ramp;
    mapped.NormalScale = Scale;
    mapped.Filter = filter;
    Scene geometry = mapped;
    geometry.NormalMap = NormalMapKind::None;
    geometry.Geometry.EveryNormal = tilted;
    TempDir dir;
    std::string error;
    const Image a = Render(mapped, dir, error);
    ASSERT_EQ(error, "");
    const json described = json::parse(a.Description);
    EXPECT_EQ(described.at("bump_map").at("scale"), Scale);
    EXPECT_FALSE(described.contains("normal_map"));
    const Image g = Render(geometry, dir, error);
    ASSERT_EQ(error, "");
    ASSERT_EQ(a.Pixels.size(), g.Pixels.size());
    const Oracle oracle(mapped);
    const double margin = 0.01; // of s, against float texture coordinates
    const double low = filter == TextureFilter::Nearest ? 0 : 0.5 / TextureSide;
    const double high = filter == TextureFilter::Nearest ? 3.0 / TextureSide : 1.5 / TextureSide;
    double largest = 0;
    int compared = 0;
    for (int y = 0; y < mapped.Size; ++y)
    {
      for (int x = 0; x < mapped.Size; ++x)
      {
        const Expected e = oracle.At(x, y);
        const double s = e.TexCoord[0] - std::floor(e.TexCoord[0]);
        if (e.What != Expected::Interior || s < low + margin || s > high - margin)
        {
          continue;
        }
        ++compared;
        for (int c = 0; c < 3; ++c)
        {
          const std::size_t i = (static_cast<std::size_t>(y) * mapped.Size + x) * a.Channels + c;
          largest = std::max(largest, static_cast<double>(std::abs(a.Pixels[i] - g.Pixels[i])));
        }
      }
    }
    EXPECT_LT(largest, 1e-5);
    EXPECT_GT(compared, 500);
  }
}

namespace
{
// A UV sphere of radius 1 as OBJ (positions, texture coordinates: s the
// longitude over [0, 1], t the latitude from the south pole; normals),
// `rings` x 2 `rings` quads, each two triangles, its MTL's material `m`
// with `statement`.
std::string SphereObj(int rings, const std::string& statement, const TempDir& dir)
{
  constexpr double Pi = 3.14159265358979323846;
  std::ostringstream obj;
  obj << "mtllib sphere.mtl\nusemtl m\n";
  const int columns = 2 * rings;
  for (int i = 0; i <= rings; ++i)
  {
    for (int j = 0; j <= columns; ++j)
    {
      const double theta = Pi * i / rings - Pi / 2, phi = 2 * Pi * j / columns;
      const Vec3 p{ std::cos(theta) * std::sin(phi), std::sin(theta),
        std::cos(theta) * std::cos(phi) };
      obj << "v " << Num(p[0]) << " " << Num(p[1]) << " " << Num(p[2]) << "\nvn " << Num(p[0])
          << " " << Num(p[1]) << " " << Num(p[2]) << "\nvt "
          << Num(static_cast<double>(j) / columns) << " " << Num(static_cast<double>(i) / rings)
          << "\n";
    }
  }
  const auto corner = [columns](int i, int j)
  {
    const std::string k = std::to_string(i * (columns + 1) + j + 1);
    return " " + k + "/" + k + "/" + k;
  };
  for (int i = 0; i < rings; ++i)
  {
    for (int j = 0; j < columns; ++j)
    {
      obj << "f" << corner(i, j) << corner(i, j + 1) << corner(i + 1, j + 1) << "\nf"
          << corner(i + 1, j + 1) << corner(i + 1, j) << corner(i, j) << "\n";
    }
  }
  WriteText(dir / "sphere.mtl",
    "newmtl m\nKa 0.1 0.1 0.1\nKd 0.6 0.5 0.4\nKs 0.5 0.5 0.5\nNs 40\n" + statement + "\n");
  WriteText(dir / "sphere.obj", obj.str());
  return (dir / "sphere.obj").string();
}
}

// A checker bump map on a sphere, from an OBJ's bump statement (a grey
// image: a height map): at every third pixel, probe finds the bump map
// where the rule took the normal, the checker's edges tilt it, and the
// render is within the standard bound of the oracle there (pixels within
// 1.5 px of an edge, or near a switch of a light's case, aside). The
// sphere's tangents are the program's (shadelabVertexTangents), which
// probe reads as the shaders do.
TEST(BumpMapFiles, ACheckerBumpOnASphereMatchesTheOracle)
{
  TempDir dir;
  std::vector<unsigned char> checker;
  constexpr int Side = 8;
  for (int i = 0; i < Side * Side; ++i)
  {
    const unsigned char h = ((i % Side + i / Side) % 2) ? 190 : 60;
    checker.insert(checker.end(), { h, h, h });
  }
  WriteImage8(dir / "checker.png", Side, Side, checker);
  const std::string sphere = SphereObj(12, "bump -bm 0.7 checker.png", dir);
  std::vector<std::array<int, 2>> pixels;
  for (int y = 2; y < 240; y += 3)
  {
    for (int x = 2; x < 240; x += 3)
    {
      pixels.push_back({ x, y });
    }
  }
  for (Shading r : LitRules)
  {
    SCOPED_TRACE(ToString(r));
    std::string error;
    const std::vector<json> probes = Probe({ sphere, "--size", "240x240", "--shading", ToString(r),
                                             "--light", "directional:-0.4,-0.5,-1" },
      pixels, error);
    ASSERT_EQ(error, "");
    int mapped = 0, tilted = 0;
    double worst = 0;
    for (const json& p : probes)
    {
      bool near = p.contains("lights") && NearACase(p.at("lights"));
      for (const json& v : p.value("vertices", json::array()))
      {
        near = near || (v.contains("lights") && NearACase(v.at("lights")));
      }
      if (!p.at("hit").get<bool>() || p.at("edge_distance").get<double>() < 1.5 || near)
      {
        continue;
      }
      const json& at = r == Shading::Gouraud ? p.at("vertices")[0] : p;
      if (at.contains("bump_map"))
      {
        ++mapped;
        const Vec3 v = Vec(at.at("bump_map").at("tangent_space"));
        tilted += std::abs(v[0]) + std::abs(v[1]) > 0.1;
      }
      worst = std::max(worst, ExpectWithinTheBound(Vec(p.at("rendered")), Vec(p.at("oracle"))));
    }
    EXPECT_GT(mapped, 400);
    EXPECT_GT(tilted, 100);
    RecordProperty(std::string("worst_") + ToString(r), std::to_string(worst));
  }
}
