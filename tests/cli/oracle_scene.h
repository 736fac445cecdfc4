// Planar scenes rendered by `shadelab render` and their expected pictures
// through the double-precision CPU oracle (filters/illumination/shadelabShadingOracle.h),
// interior pixels only: the machinery of the shading-oracle tests
// and of the extremes suite.
//
// Every scene is a grid of triangles over [-1, 1]^2 in local coordinates,
// on the plane z = SlopeX*x + SlopeY*y, seen by an orthographic camera on +Z
// (parallel scale 1.1, +Y up), written as OBJ with one `vn` per vertex so the
// normals and the triangles' vertex order are exactly the test's (as PLY
// with normals and uchar colours where the scene has vertex colours; with an
// MTL file and `usemtl` where its cells are parts of their own materials). A whole
// scene can be scaled and translated (mesh, lights, camera, parallel scale).
// The expected image follows doc/design.md's shading rules through the oracle's
// functions, in world coordinates: the ray through each pixel centre meets
// the mesh in double precision (filters/groundtruth/shadelabPixelRays.h) and
// the fragment it meets is shaded by its rule
// (filters/illumination/shadelabTriangleFragment.h), as `shadelab probe`
// explains a pixel.
#ifndef shadelab_oracle_scene_h
#define shadelab_oracle_scene_h

#include "cli_test_support.h"
#include "shadelabFog.h"
#include "shadelabPictureElements.h"
#include "shadelabPixelRays.h"
#include "shadelabRayScene.h"
#include "shadelabShadingOracle.h"
#include "shadelabTranslucency.h"
#include "shadelabTriangleFragment.h"
#include "shadelabVec3.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace shadelab_test
{
using namespace shadelab::vec3;
using shadelab::FrameLight;
using shadelab::IlluminationInputs;
using shadelab::Light;
using shadelab::LightKind;
using shadelab::LitRules;
using shadelab::Material;
using shadelab::normalize;
using shadelab::Reflection;
using shadelab::Rgb;
using shadelab::Shading;
using shadelab::ToString;
using shadelab::Vec3;

constexpr double Pi = 3.14159265358979323846;
// Local coordinates: the camera looks down -Z at the origin and shows 1.1
// units either side of it vertically.
constexpr double ParallelScale = 1.1;
// Pixels whose centre lies within this many pixels of a triangle's edge are
// not compared: rasterisation rules and attribute interpolation at edges are
// not what is tested. Nor, per fragment, those this close to a spot cone's
// boundary or another curve where a term switches on or off.
constexpr double EdgeMargin = 1.5;
// Drawn as edges or points: pixels whose centre lies within this many pixels
// of where an element's coverage ends (its footprint's boundary, another's)
// are not compared: the rasteriser's rules at a boundary are not what is
// tested, only the colour and the coverage away from it.
constexpr double ElementMargin = 0.25;

inline std::string Num(double v)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v); // round-trips through from_chars exactly
  return text;
}
inline std::string Triple(const std::array<double, 3>& v)
{
  return Num(v[0]) + "," + Num(v[1]) + "," + Num(v[2]);
}
inline std::string Show(const std::array<double, 3>& v)
{
  char text[96];
  std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", v[0], v[1], v[2]);
  return text;
}

// ---------------------------------------------------------------- scenes

struct Mesh
{
  std::vector<Vec3> Positions; // local coordinates
  std::vector<Vec3> Normals;   // per vertex, float-exact (what the reader keeps)
  std::vector<shadelab::TriangleCorners> Triangles; // draw order; the third is the provoking vertex
  std::vector<std::array<int, 3>> Colors;           // per vertex, 0..255, or empty
  std::vector<std::array<double, 2>> TexCoords;     // per vertex (s, t), float-exact
};

struct GridSpec
{
  int Cells = 4; // per side, over [-1, 1]^2
  // The plane z = SlopeX*x + SlopeY*y; powers of two keep every z exact in
  // float at an offset of 1e5 too.
  double SlopeX = 0.25;
  double SlopeY = -0.125;
  // Vertex normals: the face normal tilted by Bump*(x, y): < 0 a bowl (tilted
  // towards the centre), > 0 a dome, 0 the face normal.
  double Bump = -0.25;
  // Clockwise seen from the camera, normals pointing away from it: every
  // triangle is a back face, which two-sided lighting lights as the front.
  bool BackFaces = false;
  std::vector<std::array<int, 2>> ZeroNormals; // grid vertices (i, j) with `vn 0 0 0`
  // Each triangle (a, b, c) split at m = mid(a, b) + 1e-6 (c - mid(a, b))
  // into the sliver (a, b, m), of aspect ratio about 1e6, and (b, c, m),
  // (c, a, m): the same surface, with m provoking all three.
  bool Slivers = false;
  // Each triangle followed by degenerate ones: (a, a, b), a repeated
  // vertex; (a, mid(a, b), b), collinear, with a vertex of its own; and
  // (a, a', c) with a' = a + 1e-12 (b - a), a nearly coincident twin.
  bool Degenerate = false;
  // A colour per vertex (red, green, blue as PLY uchar), which is its kd
  // unless the scene overrides kd: neighbours differ strongly, so a wrong
  // vertex's colour or a wrong mix shows.
  bool VertexColors = false;
  // Translucency's layers: copies of the grid one behind the other, sheet k
  // moved by k*SheetStep (away from the camera and aside, so that the
  // sheets overlap in part), written in this order (a permutation of 0..n-1;
  // empty: the grid alone). Sheet k's colours are the grid's shifted by k.
  std::vector<int> Sheets;
  // A closed mesh instead of the grid: a cube of side 1.2 turned to show
  // three faces, each face two triangles with its own flat normals (a
  // translucent cube shows its far faces, lit as back faces, through them).
  bool Box = false;
  // Shadows: a square of half-size 0.35 over the grid (its corners at
  // z = 0.6, above every grid point), facing the camera with its own flat
  // normals, written after the grid.
  bool Occluder = false;
  // Shadows: a wall standing on the grid, along x over [-0.5, 0.3] at
  // y = 0.25 (halfway across a row of 12 cells), its foot on the plane and 0.5 high, facing +y,
  // written after the grid; the camera sees it edge-on. A light on its +y side casts a shadow that
  // starts at its foot: one detached from it (peter-panning) shows in the pixels beside the foot.
  bool Wall = false;
  // Self-shadowing: a torus instead of the grid (radii 0.6 and 0.25, 24 by
  // 12 quads, its vertex normals the torus's own) around the z axis, tipped
  // 35 degrees about the x axis so that the camera sees into its hole: a
  // light from above, nearly in its plane, shadows the inside of its lower half.
  bool Torus = false;
  // Every vertex's normal, instead of the bowl's (a plane's normals tilted alike).
  std::optional<Vec3> EveryNormal;
};

constexpr std::array<double, 3> SheetStep{ 0.25, 0.125, -1 };

// The colour of grid vertex (i, j); vertices added off the grid are grey.
inline std::array<int, 3> GridColor(int i, int j)
{
  constexpr int red[] = { 230, 60, 140 }, green[] = { 50, 200, 120 }, blue[] = { 90, 30, 220 };
  return { red[(i + j) % 3], green[(2 * i + j) % 3], blue[(i + 2 * j) % 3] };
}

// The texture coordinates at (x, y): s over [-0.25, 1.25] and t over
// [-0.125, 1.125], so that every wrap mode shows beyond [0, 1]; float-exact.
inline std::array<double, 2> TexCoordAt(double x, double y)
{
  return { static_cast<float>(0.75 * (x + 1) - 0.25), static_cast<float>(0.625 * (y + 1) - 0.125) };
}

// The test's texture: 4 x 4 texels of 8-bit RGB, top row first as files
// store them; no two alike and no symmetry, so a flipped, transposed or
// shifted lookup shows.
constexpr int TextureSide = 4;
inline std::vector<unsigned char> TextureBytes()
{
  std::vector<unsigned char> rgb;
  for (int row = 0; row < TextureSide; ++row)
  {
    for (int column = 0; column < TextureSide; ++column)
    {
      rgb.push_back(static_cast<unsigned char>(30 + 60 * column + 10 * row));
      rgb.push_back(static_cast<unsigned char>(220 - 50 * row - 5 * column));
      rgb.push_back(static_cast<unsigned char>(40 + 45 * ((column + 2 * row) % 4)));
    }
  }
  return rgb;
}

// What the program should make of it: the stored values over 255 (colours
// are display values, taken as stored), the file's bottom row first (t = 0
// at the bottom).
inline shadelab::TextureImage ExpectedTexture()
{
  const std::vector<unsigned char> bytes = TextureBytes();
  shadelab::TextureImage image;
  image.Width = image.Height = TextureSide;
  for (int row = TextureSide - 1; row >= 0; --row)
  {
    for (int i = 0; i < 3 * TextureSide; ++i)
    {
      image.Pixels.push_back(static_cast<float>(bytes[3 * TextureSide * row + i] / 255.0));
    }
  }
  return image;
}

// The test's environments (--environment), 8-bit RGB, top row first:
// Single one colour; Horizon its top row one colour and its bottom row
// another, so that with the nearest texel the picture splits where R
// crosses the horizon; Pattern 8 x 4 texels, no two alike, so that a
// flipped, turned or shifted lookup shows.
enum class EnvironmentKind
{
  None,
  Single,
  Horizon,
  Pattern
};

struct EnvironmentImage
{
  int Width = 0, Height = 0;
  std::vector<unsigned char> Bytes;

  // What the program should make of it, as ExpectedTexture.
  shadelab::TextureImage Decoded() const
  {
    shadelab::TextureImage image;
    image.Width = this->Width;
    image.Height = this->Height;
    for (int row = this->Height - 1; row >= 0; --row)
    {
      for (int i = 0; i < 3 * this->Width; ++i)
      {
        image.Pixels.push_back(static_cast<float>(this->Bytes[3 * this->Width * row + i] / 255.0));
      }
    }
    return image;
  }
};

constexpr unsigned char SingleEnvironment[3] = { 51, 153, 102 };
constexpr unsigned char Sky[3] = { 200, 180, 40 }, Ground[3] = { 20, 60, 220 };

inline EnvironmentImage EnvironmentOf(EnvironmentKind kind)
{
  EnvironmentImage e;
  e.Width = kind == EnvironmentKind::Pattern ? 8 : 4;
  e.Height = kind == EnvironmentKind::Pattern ? 4 : 2;
  for (int row = 0; row < e.Height; ++row)
  {
    for (int column = 0; column < e.Width; ++column)
    {
      const unsigned char* c = kind == EnvironmentKind::Single ? SingleEnvironment
        : row == 0                                             ? Sky
                                                               : Ground;
      for (int channel = 0; channel < 3; ++channel)
      {
        e.Bytes.push_back(kind == EnvironmentKind::Pattern
            ? static_cast<unsigned char>((37 * column + 71 * row + 97 * channel) % 251)
            : c[channel]);
      }
    }
  }
  return e;
}

// The test's normal maps (--normal-map) and height maps (--bump-map),
// 8-bit RGB, top row first, TextureSide x TextureSide texels. Normal maps:
// Constant one texel colour everywhere, a tilt towards +s and -t; Pattern
// no two texels alike, each a direction leaning its own way, so that a
// flipped or shifted lookup, or a wrong frame, shows. Height maps (grey):
// Heights no two alike, so that every difference one texel apart is its
// own; Ramp rising RampStep a column along s, alike along t.
enum class NormalMapKind
{
  None,
  Constant,
  Pattern,
  Heights,
  Ramp
};

constexpr unsigned char ConstantNormal[3] = { 200, 110, 220 };
constexpr int RampStep = 50;

inline bool IsHeightMap(NormalMapKind kind)
{
  return kind == NormalMapKind::Heights || kind == NormalMapKind::Ramp;
}

inline EnvironmentImage NormalMapOf(NormalMapKind kind)
{
  EnvironmentImage e;
  e.Width = e.Height = TextureSide;
  for (int row = 0; row < e.Height; ++row)
  {
    for (int column = 0; column < e.Width; ++column)
    {
      const unsigned char pattern[3] = { static_cast<unsigned char>(40 + 45 * column + 7 * row),
        static_cast<unsigned char>(215 - 50 * row + 6 * column),
        static_cast<unsigned char>(150 + 30 * ((column + 2 * row) % 4)) };
      const auto height = static_cast<unsigned char>(kind == NormalMapKind::Ramp
          ? 30 + RampStep * column
          : 20 + 53 * ((3 * column + row) % 4) + 11 * row);
      for (int channel = 0; channel < 3; ++channel)
      {
        e.Bytes.push_back(kind == NormalMapKind::Constant ? ConstantNormal[channel]
            : IsHeightMap(kind)                           ? height
                                                          : pattern[channel]);
      }
    }
  }
  return e;
}

// The vertex normal at (x, y), before rounding to float.
inline Vec3 GridNormal(const GridSpec& g, double x, double y)
{
  return normalize(normalize({ -g.SlopeX, -g.SlopeY, 1 }) + g.Bump * Vec3{ x, y, 0 });
}

// GridSpec::Box: float-exact corners and normals, as the reader keeps them.
inline Mesh Box(const GridSpec& g)
{
  const double ax = 25 * Pi / 180, ay = 35 * Pi / 180;
  const auto turned = [&](const Vec3& p)
  {
    const Vec3 x{ p[0], std::cos(ax) * p[1] - std::sin(ax) * p[2],
      std::sin(ax) * p[1] + std::cos(ax) * p[2] };
    Vec3 r{ std::cos(ay) * x[0] + std::sin(ay) * x[2], x[1],
      -std::sin(ay) * x[0] + std::cos(ay) * x[2] };
    for (double& c : r)
    {
      c = static_cast<float>(c);
    }
    return r;
  };
  Mesh m;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side : { -1, 1 })
    {
      Vec3 n{ 0, 0, 0 };
      n[axis] = side;
      // Two directions in the face, (u, v, n) right-handed: counter-clockwise from outside.
      Vec3 u{ 0, 0, 0 }, v{ 0, 0, 0 };
      u[(axis + 1) % 3] = 1;
      v[(axis + 2) % 3] = side;
      const int first = static_cast<int>(m.Positions.size());
      for (const auto& [a, b] : { std::pair{ -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } })
      {
        const Vec3 p = 0.6 * (n + a * u + b * v);
        m.Positions.push_back(turned(p));
        m.Normals.push_back(turned(n));
        m.TexCoords.push_back(TexCoordAt(m.Positions.back()[0], m.Positions.back()[1]));
        if (g.VertexColors)
        {
          m.Colors.push_back(GridColor(axis + (a + 1) / 2, side + 1 + (b + 1) / 2));
        }
      }
      m.Triangles.push_back({ first, first + 1, first + 2 });
      m.Triangles.push_back({ first + 2, first + 3, first });
    }
  }
  return m;
}

// GridSpec::Torus: float-exact points and normals, as the reader keeps them;
// each quad's triangles counter-clockwise from outside.
inline Mesh Torus(const GridSpec& g)
{
  constexpr int Around = 24, Tube = 12;
  const double c = std::cos(35 * Pi / 180), sn = std::sin(35 * Pi / 180);
  const auto tipped = [&](const Vec3& p) {
    return Vec3{ p[0], c * p[1] - sn * p[2], sn * p[1] + c * p[2] };
  };
  Mesh m;
  const auto exact = [](Vec3 p)
  {
    for (double& c : p)
    {
      c = static_cast<float>(c);
    }
    return p;
  };
  for (int i = 0; i < Around; ++i)
  {
    for (int j = 0; j < Tube; ++j)
    {
      const double u = 2 * Pi * i / Around, v = 2 * Pi * j / Tube;
      const Vec3 n{ std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v) };
      const Vec3 p = Vec3{ 0.6 * std::cos(u), 0.6 * std::sin(u), 0 } + 0.25 * n;
      m.Positions.push_back(exact(tipped(p)));
      m.Normals.push_back(exact(tipped(n)));
      m.TexCoords.push_back(TexCoordAt(m.Positions.back()[0], m.Positions.back()[1]));
      if (g.VertexColors)
      {
        m.Colors.push_back(GridColor(i % 3, j % 3));
      }
      const auto at = [](int a, int b) { return (a % Around) * Tube + b % Tube; };
      m.Triangles.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      m.Triangles.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  }
  return m;
}

// GridSpec::Sheets: the grid copied behind itself.
inline Mesh Sheets(const GridSpec& g, const Mesh& grid)
{
  Mesh m;
  const auto vertices = static_cast<std::int64_t>(grid.Positions.size());
  for (std::size_t k = 0; k < g.Sheets.size(); ++k)
  {
    for (std::int64_t v = 0; v < vertices; ++v)
    {
      m.Positions.push_back(grid.Positions[v] + static_cast<double>(k) * SheetStep);
      m.Normals.push_back(grid.Normals[v]);
      m.TexCoords.push_back(grid.TexCoords[v]);
      if (g.VertexColors)
      {
        const int n = g.Cells + 1;
        m.Colors.push_back(GridColor(static_cast<int>(v % n + k), static_cast<int>(v / n)));
      }
    }
  }
  for (int sheet : g.Sheets)
  {
    for (shadelab::TriangleCorners t : grid.Triangles)
    {
      for (auto& v : t)
      {
        v += sheet * vertices;
      }
      m.Triangles.push_back(t);
    }
  }
  return m;
}

inline Mesh Grid(const GridSpec& g)
{
  if (g.Box)
  {
    return Box(g);
  }
  if (g.Torus)
  {
    return Torus(g);
  }
  Mesh m;
  const int n = g.Cells + 1;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = -1 + 2.0 * i / g.Cells, y = -1 + 2.0 * j / g.Cells;
      m.Positions.push_back({ x, y, g.SlopeX * x + g.SlopeY * y });
      Vec3 normal = g.EveryNormal.value_or(GridNormal(g, x, y));
      if (g.BackFaces)
      {
        normal = -normal;
      }
      for (const auto& zero : g.ZeroNormals)
      {
        if (zero[0] == i && zero[1] == j)
        {
          normal = { 0, 0, 0 };
        }
      }
      for (double& c : normal)
      {
        c = static_cast<float>(c); // the OBJ reader keeps normals as float
      }
      m.Normals.push_back(normal);
      m.TexCoords.push_back(TexCoordAt(x, y));
      if (g.VertexColors)
      {
        m.Colors.push_back(GridColor(i, j));
      }
    }
  }
  for (int j = 0; j < g.Cells; ++j)
  {
    for (int i = 0; i < g.Cells; ++i)
    {
      const int v00 = j * n + i, v10 = v00 + 1, v01 = v00 + n, v11 = v01 + 1;
      // Counter-clockwise seen from +Z, the diagonal alternating; the vertex
      // order is rotated from cell to cell so that every corner of a cell is
      // somewhere the provoking (third) vertex.
      std::vector<shadelab::TriangleCorners> pair = (i + j) % 2
        ? std::vector<shadelab::TriangleCorners>{ { v00, v10, v01 }, { v10, v11, v01 } }
        : std::vector<shadelab::TriangleCorners>{ { v00, v10, v11 }, { v00, v11, v01 } };
      for (auto& t : pair)
      {
        std::rotate(t.begin(), t.begin() + (i + 2 * j) % 3, t.end());
        if (g.BackFaces)
        {
          std::swap(t[0], t[1]); // reversed winding, same provoking vertex
        }
        m.Triangles.push_back(t);
      }
    }
  }
  if (g.Occluder)
  {
    const int first = static_cast<int>(m.Positions.size());
    for (const auto& [x, y] :
      { std::pair{ -0.45, -0.2 }, { 0.25, -0.2 }, { 0.25, 0.5 }, { -0.45, 0.5 } })
    {
      m.Positions.push_back({ x, y, 0.6 });
      m.Normals.push_back({ 0, 0, 1 });
      m.TexCoords.push_back(TexCoordAt(x, y));
      if (g.VertexColors)
      {
        m.Colors.push_back({ 128, 128, 128 });
      }
    }
    m.Triangles.push_back({ first, first + 1, first + 2 });
    m.Triangles.push_back({ first, first + 2, first + 3 });
  }
  if (g.Wall)
  {
    const int first = static_cast<int>(m.Positions.size());
    for (const auto& [x, up] :
      { std::pair{ -0.5, 0.0 }, { 0.3, 0.0 }, { 0.3, 0.5 }, { -0.5, 0.5 } })
    {
      m.Positions.push_back({ x, 0.25, g.SlopeX * x + g.SlopeY * 0.25 + up });
      m.Normals.push_back({ 0, 1, 0 });
      m.TexCoords.push_back(TexCoordAt(x, 0.25));
      if (g.VertexColors)
      {
        m.Colors.push_back({ 128, 128, 128 });
      }
    }
    m.Triangles.push_back({ first, first + 2, first + 1 });
    m.Triangles.push_back({ first, first + 3, first + 2 });
  }
  if (!g.Sheets.empty())
  {
    return Sheets(g, m);
  }
  if (!g.Slivers && !g.Degenerate)
  {
    return m;
  }
  // A new vertex at p, with the normal the grid has there.
  const auto add = [&m, &g](const Vec3& p)
  {
    Vec3 normal = GridNormal(g, p[0], p[1]);
    for (double& c : normal)
    {
      c = static_cast<float>(g.BackFaces ? -c : c);
    }
    m.Positions.push_back(p);
    m.Normals.push_back(normal);
    m.TexCoords.push_back(TexCoordAt(p[0], p[1]));
    if (g.VertexColors)
    {
      m.Colors.push_back({ 128, 128, 128 });
    }
    return static_cast<int>(m.Positions.size() - 1);
  };
  std::vector<shadelab::TriangleCorners> triangles;
  for (const auto& t : m.Triangles)
  {
    const Vec3 a = m.Positions[t[0]], b = m.Positions[t[1]], c = m.Positions[t[2]];
    const Vec3 middle = 0.5 * (a + b);
    if (g.Slivers)
    {
      const int s = add(middle + 1e-6 * (c - middle));
      triangles.push_back({ t[0], t[1], s });
      triangles.push_back({ t[1], t[2], s });
      triangles.push_back({ t[2], t[0], s });
    }
    else
    {
      triangles.push_back(t);
    }
    if (g.Degenerate)
    {
      triangles.push_back({ t[0], t[0], t[1] });
      triangles.push_back({ t[0], add(middle), t[1] });
      triangles.push_back({ t[0], add(a + 1e-12 * (b - a)), t[2] });
    }
  }
  m.Triangles = triangles;
  return m;
}

inline Light Point(const Vec3& position, const Rgb& color = { 1, 1, 1 })
{
  Light l;
  l.Kind = LightKind::Point;
  l.Position = position;
  l.Color = color;
  return l;
}
inline Light Directional(const Vec3& direction, const Rgb& color = { 1, 1, 1 })
{
  Light l;
  l.Kind = LightKind::Directional;
  l.Direction = direction;
  l.Color = color;
  return l;
}
inline Light Spot(const Vec3& position, const Vec3& direction, double halfAngleDeg, double exponent,
  const Rgb& color = { 1, 1, 1 })
{
  Light l;
  l.Kind = LightKind::Spot;
  l.Position = position;
  l.Direction = direction;
  l.HalfAngleDeg = halfAngleDeg;
  l.Exponent = exponent;
  l.Color = color;
  return l;
}

inline Material TestMaterial(double ns)
{
  Material m;
  m.Ka = { 0.3, 0.25, 0.2 };
  m.Kd = { 0.6, 0.5, 0.4 };
  m.Ks = { 0.5, 0.6, 0.7 };
  m.Ns = ns;
  return m;
}

struct Scene
{
  GridSpec Geometry;
  Shading Rule = Shading::Phong;
  Reflection Model = Reflection::BlinnPhong;
  Material Surface = TestMaterial(20);
  Rgb Ambient{ 0.2, 0.25, 0.3 };
  std::vector<Light> Lights{ Point({ 0.3, 0.4, 1.5 }) }; // local coordinates
  // --attenuation: point and spot lights' C0, C1, C2 where a light has none of
  // its own (Light::Attenuation, given as --light SPEC@C0,C1,C2); per local
  // unit: a scaled scene's are scaled to fall off alike (WorldAttenuation).
  Vec3 Attenuation = shadelab::NoAttenuation;
  // --fog, in local units (a scaled scene's depths and densities scaled to
  // fog alike); its colour, where it has none, the background's (black).
  shadelab::Fog Fog;
  // --translucency (over every part's a; MTL d gives a part's own) and --peels.
  std::optional<double> Translucency;
  int Peels = 0;
  // --representation, and Pixels as --line-width or --point-size.
  shadelab::Representation Drawn = shadelab::Representation::Surface;
  int Pixels = 3;
  // The whole scene (mesh, lights, camera, parallel scale) maps local p to
  // Offset + Scale*p.
  double Scale = 1;
  Vec3 Offset{ 0, 0, 0 };
  double CameraDistance = 10; // local units above the origin
  int Size = 96;
  bool EightBit = false;              // PNG instead of float EXR
  bool TransparentBackground = false; // its colour black either way
  // The normals shadelab renders with: "file" (the grid's, exactly), or
  // "compute" (vtkShadelabMeshNormals's, with Weighting), which the oracle
  // still expects to be the grid's.
  std::string Normals = "file";
  std::string Weighting = "angle";
  // With Geometry.VertexColors: --kd given, so the material's kd wins over
  // them; with Parts: --kd given, Surface's kd replaces every part's.
  bool OverrideKd = false;
  // The grid's cells dealt into parts, each with its material from the MTL
  // file: cell (i, j) is part (i + 2j) % Parts.size(), so that every part
  // borders the others; the materials are exact in float (the GPU
  // draws with float uniforms). Empty: one material, Surface, given as options.
  // Plain grids only (no slivers or degenerate triangles).
  std::vector<Material> Parts;
  // --texture: TextureBytes() as an 8-bit PNG on the grid's TexCoordAt, the
  // mesh written as an OFF with texture coordinates; kd and ka are the
  // material's (given as --kd, --ka) times the texel. With Parts, the
  // file's own textures instead: the OBJ gets vt, and the MTL gives the
  // even parts the image as map_Kd and map_Ka (-clamp on for Clamp; OBJ's
  // textures are bilinear), the odd parts none (TexturedPart).
  bool Textured = false;
  shadelab::TextureWrap Wrap = shadelab::TextureWrap::Repeat;
  shadelab::TextureFilter Filter = shadelab::TextureFilter::Bilinear;
  // --environment: EnvironmentOf(Environment) as an 8-bit PNG, looked up
  // with Filter; ZUp gives --up +Z (or, with OwnUp, --environment-up +Z
  // alone), the environment's y the world's z.
  EnvironmentKind Environment = EnvironmentKind::None;
  bool ZUp = false;
  bool OwnUp = false;
  // --normal-map, or --bump-map for a height map: NormalMapOf(NormalMap)
  // as an 8-bit PNG with scale NormalScale, at the grid's TexCoordAt (the
  // mesh an OFF), looked up with Wrap and Filter. Plain grids only: their
  // tangent is GridTangent.
  NormalMapKind NormalMap = NormalMapKind::None;
  double NormalScale = 1;
  // --shadows, --shadow-map-size: the oracle casts shadow rays.
  bool Shadows = false;
  int ShadowMapSize = 2048;
  // --shading raytrace: every light casts shadows, through the oracle's
  // rays too, and ks weighs what the mirror reflection sees, Reflections
  // bounces deep (--reflections).
  int Reflections = 2;
  std::size_t ShadowedAtLeast = 100; // compared pixels in a shadow, for the case to say anything

  /** kd comes from the mesh's vertex colours. */
  bool VertexKd() const { return this->Geometry.VertexColors && !this->OverrideKd; }

  Vec3 World(const Vec3& p) const { return this->Offset + this->Scale * p; }
};

// Several coloured lights at once, of every kind; their sum exceeds 1 in
// places, which the PNG clamps and the EXR keeps.
inline Scene ColouredLights()
{
  Scene s;
  s.Lights = { Point({ -0.8, 0.6, 1.2 }, { 1, 0.2, 0.1 }),
    Directional({ 0.4, -0.3, -1 }, { 0.1, 0.9, 0.2 }),
    Spot({ 0.5, -0.5, 2 }, { 0, 0, -1 }, 35, 2, { 0.2, 0.3, 1 }),
    Point({ 0.9, 0.9, 0.8 }, { 0.6, 0.6, 0.6 }) };
  return s;
}

// The part of triangle t of the scene's grid, 0 without parts.
inline int PartOf(const Scene& s, int t)
{
  if (s.Parts.empty())
  {
    return 0;
  }
  const int cell = t / 2, i = cell % s.Geometry.Cells, j = cell / s.Geometry.Cells;
  return (i + 2 * j) % static_cast<int>(s.Parts.size());
}

// Three parts' materials, one without specular; exact in float.
inline std::vector<Material> ThreeParts()
{
  Material first, second, third;
  first.Ka = { 0.25, 0.125, 0.0625 };
  first.Kd = { 0.75, 0.5, 0.25 };
  first.Ks = { 0.5, 0.5, 0.5 };
  first.Ns = 32;
  second.Ka = { 0.0625, 0.125, 0.25 };
  second.Kd = { 0.125, 0.375, 0.75 };
  second.Ks = { 0.25, 0.5, 0.75 };
  second.Ns = 8;
  third.Ka = { 0.125, 0.25, 0.125 };
  third.Kd = { 0.5, 0.75, 0.375 };
  third.Ns = 1;
  return { first, second, third };
}

// Whether triangle t's kd and ka are textured.
inline bool TexturedPart(const Scene& s, int t)
{
  return s.Textured && (s.Parts.empty() || PartOf(s, t) % 2 == 0);
}

// The material triangle t is lit with.
inline Material SurfaceOf(const Scene& s, int t)
{
  if (s.Parts.empty())
  {
    return s.Surface;
  }
  Material m = s.Parts[PartOf(s, t)];
  if (s.OverrideKd)
  {
    m.Kd = s.Surface.Kd;
  }
  return m;
}

// Triangle t's opacity a: --translucency's, else its material's.
inline double OpacityOf(const Scene& s, int t)
{
  return s.Translucency.value_or(SurfaceOf(s, t).Translucency);
}

// Fog towards a transparent background takes the fragments' coverage down:
// composited in depth order as translucency is.
inline bool FogsTowardsTransparent(const Scene& s)
{
  return s.TransparentBackground && s.Fog.Mode != shadelab::FogMode::None && !s.Fog.Color;
}

inline bool Translucent(const Scene& s)
{
  return FogsTowardsTransparent(s) ||
    (s.Translucency ? *s.Translucency < 1
                    : std::any_of(s.Parts.begin(), s.Parts.end(),
                        [](const Material& m) { return m.Translucency < 1; }));
}

// Coefficients per local unit as per world unit: d grows by Scale.
inline Vec3 WorldAttenuation(const Scene& s, const Vec3& c)
{
  return { c[0], c[1] / s.Scale, c[2] / (s.Scale * s.Scale) };
}

inline std::vector<Light> WorldLights(const Scene& s)
{
  std::vector<Light> lights = s.Lights;
  for (Light& l : lights)
  {
    l.Position = s.World(l.Position);
    if (l.Attenuation)
    {
      l.Attenuation = WorldAttenuation(s, *l.Attenuation);
    }
  }
  return lights;
}

// The fog in world units: depths times Scale, densities over it.
inline shadelab::Fog WorldFog(const Scene& s)
{
  shadelab::Fog f = s.Fog;
  f.Start *= s.Scale;
  f.End *= s.Scale;
  f.Density /= s.Scale;
  return f;
}

inline std::string FogOption(const shadelab::Fog& f)
{
  std::string text = ToString(f.Mode);
  text += f.Mode == shadelab::FogMode::Linear ? ":" + Num(f.Start) + "," + Num(f.End)
                                              : ":" + Num(f.Density);
  return f.Color ? text + ":" + Triple(*f.Color) : text;
}

inline std::string OwnAttenuation(const Light& l)
{
  return l.Attenuation ? "@" + Triple(*l.Attenuation) : "";
}

inline std::string LightOption(const Light& l)
{
  switch (l.Kind)
  {
    case LightKind::Point:
      return "point:" + Triple(l.Position) + ":" + Triple(l.Color) + OwnAttenuation(l);
    case LightKind::Directional:
      return "directional:" + Triple(l.Direction) + ":" + Triple(l.Color);
    case LightKind::Spot:
      return "spot:" + Triple(l.Position) + ":" + Triple(l.Direction) + ":" + Num(l.HalfAngleDeg) +
        ":" + Num(l.Exponent) + ":" + Triple(l.Color) + OwnAttenuation(l);
  }
  return "";
}

// The parts' materials, part k named "partK".
inline std::string MtlText(const Scene& s)
{
  std::ostringstream mtl;
  for (std::size_t k = 0; k < s.Parts.size(); ++k)
  {
    const Material& m = s.Parts[k];
    mtl << "newmtl part" << k << "\nKa " << Num(m.Ka[0]) << " " << Num(m.Ka[1]) << " "
        << Num(m.Ka[2]) << "\nKd " << Num(m.Kd[0]) << " " << Num(m.Kd[1]) << " " << Num(m.Kd[2])
        << "\nKs " << Num(m.Ks[0]) << " " << Num(m.Ks[1]) << " " << Num(m.Ks[2]) << "\nNs "
        << Num(m.Ns) << "\n";
    if (m.Translucency != 1)
    {
      mtl << "d " << Num(m.Translucency) << "\n";
    }
    if (s.Textured && k % 2 == 0)
    {
      const char* clamp = s.Wrap == shadelab::TextureWrap::Clamp ? "-clamp on " : "";
      mtl << "map_Kd " << clamp << "texture.png\nmap_Ka " << clamp << "texture.png\n";
    }
  }
  return mtl.str();
}

inline std::string ObjText(const Scene& s, const Mesh& m)
{
  std::ostringstream obj;
  if (!s.Parts.empty())
  {
    obj << "mtllib mesh.mtl\n";
  }
  for (const Vec3& p : m.Positions)
  {
    const Vec3 w = s.World(p);
    obj << "v " << Num(w[0]) << " " << Num(w[1]) << " " << Num(w[2]) << "\n";
  }
  for (const Vec3& n : m.Normals)
  {
    obj << "vn " << Num(n[0]) << " " << Num(n[1]) << " " << Num(n[2]) << "\n";
  }
  if (s.Textured)
  {
    for (const auto& st : m.TexCoords)
    {
      obj << "vt " << Num(st[0]) << " " << Num(st[1]) << "\n";
    }
  }
  int part = -1;
  for (std::size_t t = 0; t < m.Triangles.size(); ++t)
  {
    if (!s.Parts.empty() && PartOf(s, static_cast<int>(t)) != part)
    {
      part = PartOf(s, static_cast<int>(t));
      obj << "usemtl part" << part << "\n";
    }
    obj << "f";
    for (const auto v : m.Triangles[t])
    {
      const std::string vt = s.Textured ? std::to_string(v + 1) : "";
      obj << " " << v + 1 << "/" << vt << "/" << v + 1;
    }
    obj << "\n";
  }
  return obj.str();
}

// An ASCII PLY of the mesh with double positions, float normals and uchar
// colours: what the grid is when it has vertex colours.
inline std::string PlyText(const Scene& s, const Mesh& m)
{
  std::ostringstream ply;
  ply << "ply\nformat ascii 1.0\nelement vertex " << m.Positions.size()
      << "\nproperty double x\nproperty double y\nproperty double z\n"
         "property float nx\nproperty float ny\nproperty float nz\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nelement face "
      << m.Triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (std::size_t v = 0; v < m.Positions.size(); ++v)
  {
    const Vec3 w = s.World(m.Positions[v]);
    const Vec3& n = m.Normals[v];
    ply << Num(w[0]) << " " << Num(w[1]) << " " << Num(w[2]) << " " << Num(n[0]) << " " << Num(n[1])
        << " " << Num(n[2]) << " " << m.Colors[v][0] << " " << m.Colors[v][1] << " "
        << m.Colors[v][2] << "\n";
  }
  for (const auto& t : m.Triangles)
  {
    ply << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  }
  return ply.str();
}

// An OFF with normals and texture coordinates (STNOFF): what the grid is
// when it has a texture.
inline std::string OffText(const Scene& s, const Mesh& m)
{
  std::ostringstream off;
  off << "STNOFF\n" << m.Positions.size() << " " << m.Triangles.size() << " 0\n";
  for (std::size_t v = 0; v < m.Positions.size(); ++v)
  {
    const Vec3 w = s.World(m.Positions[v]);
    const Vec3& n = m.Normals[v];
    off << Num(w[0]) << " " << Num(w[1]) << " " << Num(w[2]) << " " << Num(n[0]) << " " << Num(n[1])
        << " " << Num(n[2]) << " " << Num(m.TexCoords[v][0]) << " " << Num(m.TexCoords[v][1])
        << "\n";
  }
  for (const auto& t : m.Triangles)
  {
    off << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
  }
  return off.str();
}

// Renders the scene with `shadelab render`; every setting is passed
// explicitly, lights included (shadelab's default is a light at the camera).
// The scene's mesh (and MTL, texture) written into dir, and the arguments
// that draw it as the scene says: the mesh, then the options.
// A plain grid's tangent, the same at every vertex: dP/ds, TexCoordAt's s
// running along x on the plane z = SlopeX x + SlopeY y, as the program
// stores it (float); its handedness -1 where the triangles are wound the
// other way (their face normal, and so N x T, turned over).
inline shadelab::Tangent GridTangent(const GridSpec& g)
{
  const Vec3 t = normalize(Vec3{ 1, 0, g.SlopeX });
  return { static_cast<float>(t[0]), static_cast<float>(t[1]), static_cast<float>(t[2]),
    g.BackFaces ? -1.0 : 1.0 };
}

inline std::vector<std::string> SceneArguments(const Scene& s, const TempDir& dir)
{
  const bool ply = s.Geometry.VertexColors;
  // --texture's and --normal-map's mesh
  const bool off = (s.Textured || s.NormalMap != NormalMapKind::None) && s.Parts.empty();
  const auto mesh = dir / (ply ? "mesh.ply" : off ? "mesh.off" : "mesh.obj");
  const Mesh m = Grid(s.Geometry);
  WriteText(mesh, ply ? PlyText(s, m) : off ? OffText(s, m) : ObjText(s, m));
  if (!s.Parts.empty())
  {
    WriteText(dir / "mesh.mtl", MtlText(s));
  }
  const std::string size = std::to_string(s.Size) + "x" + std::to_string(s.Size);
  std::vector<std::string> args{ mesh.string(), "--size", size, "--orthographic",
    "--camera-position", Triple(s.World({ 0, 0, s.CameraDistance })), "--camera-focal-point",
    Triple(s.World({ 0, 0, 0 })), "--camera-view-up", "0,1,0", "--parallel-scale",
    Num(s.Scale * ParallelScale), "--shading", ToString(s.Rule), "--reflection", ToString(s.Model),
    "--ambient", Triple(s.Ambient), "--background",
    s.TransparentBackground ? "transparent" : "0,0,0", "--normals", s.Normals, "--weighting",
    s.Weighting };
  if (s.Parts.empty()) // the parts' materials come from the MTL file
  {
    args.insert(args.end(),
      { "--ka", Triple(s.Surface.Ka), "--ks", Triple(s.Surface.Ks), "--ns", Num(s.Surface.Ns) });
  }
  if (s.Parts.empty() ? !s.VertexKd() : s.OverrideKd)
  {
    args.insert(args.end(), { "--kd", Triple(s.Surface.Kd) });
  }
  if (s.Textured)
  {
    const auto texture = dir / "texture.png";
    WriteImage8(texture, TextureSide, TextureSide, TextureBytes());
    if (off)
    {
      args.insert(args.end(),
        { "--texture", texture.string(), "--texture-wrap", ToString(s.Wrap), "--texture-filter",
          ToString(s.Filter) });
    }
  }
  if (s.NormalMap != NormalMapKind::None)
  {
    const auto normals = dir / "normals.png";
    const EnvironmentImage n = NormalMapOf(s.NormalMap);
    WriteImage8(normals, n.Width, n.Height, n.Bytes);
    args.insert(args.end(),
      { IsHeightMap(s.NormalMap) ? "--bump-map" : "--normal-map",
        normals.string() + ":" + Num(s.NormalScale) });
    if (!s.Textured)
    {
      args.insert(
        args.end(), { "--texture-wrap", ToString(s.Wrap), "--texture-filter", ToString(s.Filter) });
    }
  }
  if (s.Environment != EnvironmentKind::None)
  {
    const auto environment = dir / "environment.png";
    const EnvironmentImage e = EnvironmentOf(s.Environment);
    WriteImage8(environment, e.Width, e.Height, e.Bytes);
    args.insert(args.end(), { "--environment", environment.string() });
    if (!off)
    {
      args.insert(args.end(), { "--texture-filter", ToString(s.Filter) });
    }
    if (s.ZUp)
    {
      args.insert(args.end(), { s.OwnUp ? "--environment-up" : "--up", "+Z" });
    }
  }
  for (const Light& l : WorldLights(s))
  {
    args.push_back("--light");
    args.push_back(LightOption(l));
  }
  if (s.Attenuation != shadelab::NoAttenuation)
  {
    args.insert(args.end(), { "--attenuation", Triple(WorldAttenuation(s, s.Attenuation)) });
  }
  if (s.Fog.Mode != shadelab::FogMode::None)
  {
    args.insert(args.end(), { "--fog", FogOption(WorldFog(s)) });
  }
  if (s.Translucency)
  {
    args.insert(args.end(), { "--translucency", Num(*s.Translucency) });
  }
  if (s.Peels)
  {
    args.insert(args.end(), { "--peels", std::to_string(s.Peels) });
  }
  if (s.Shadows)
  {
    args.insert(args.end(), { "--shadows", "--shadow-map-size", std::to_string(s.ShadowMapSize) });
  }
  if (s.Rule == Shading::Raytrace)
  {
    args.insert(args.end(), { "--reflections", std::to_string(s.Reflections) });
  }
  if (s.Drawn != shadelab::Representation::Surface)
  {
    args.insert(args.end(),
      { "--representation", ToString(s.Drawn),
        s.Drawn == shadelab::Representation::Points ? "--point-size" : "--line-width",
        std::to_string(s.Pixels) });
  }
  return args;
}

inline Image Render(const Scene& s, const TempDir& dir, std::string& error)
{
  const auto out = dir / (s.EightBit ? "out.png" : "out.exr");
  std::vector<std::string> args{ "render", "-o", out.string() };
  const std::vector<std::string> scene = SceneArguments(s, dir);
  args.insert(args.end(), scene.begin(), scene.end());
  const RunResult r = RunShadelab(args);
  if (r.ExitCode != 0)
  {
    error = "shadelab render failed (" + std::to_string(r.ExitCode) + "): " + r.Stderr;
    return {};
  }
  Image image = ReadImage(out);
  if (image.Width != s.Size || image.Height != s.Size || image.Channels < 3)
  {
    error = "unexpected image " + std::to_string(image.Width) + "x" + std::to_string(image.Height) +
      "x" + std::to_string(image.Channels);
  }
  return image;
}

// scene.json (its text `scene`, 64x64 chrome shots) rendered in one batch
// into dir: each shot's picture equals the render of `mesh` alone with the
// same size and material and that shot's options, `alone[shot]`.
inline void ExpectEachShotIsItsOwnRender(const TempDir& dir, const std::string& scene,
  const std::string& mesh, const std::vector<std::vector<std::string>>& alone)
{
  WriteText(dir / "scene.json", scene);
  const RunResult batch = RunShadelab({ "render", "--scene", (dir / "scene.json").string(), "-o",
    (dir / "shot{index}.exr").string() });
  ASSERT_EQ(batch.ExitCode, 0) << batch.Stderr;
  for (std::size_t shot = 0; shot < alone.size(); ++shot)
  {
    SCOPED_TRACE(std::to_string(shot));
    const auto own = dir / ("alone" + std::to_string(shot) + ".exr");
    std::vector<std::string> args{ "render", mesh, "-o", own.string(), "--size", "64x64",
      "--material", "chrome" };
    args.insert(args.end(), alone[shot].begin(), alone[shot].end());
    const RunResult r = RunShadelab(args);
    ASSERT_EQ(r.ExitCode, 0) << r.Stderr;
    EXPECT_EQ(
      ReadImage(dir / ("shot" + std::to_string(shot) + ".exr")).Pixels, ReadImage(own).Pixels);
  }
}

// ---------------------------------------------------------------- the expected image

struct Expected
{
  enum Kind
  {
    Background, // farther than EdgeMargin from every triangle: the background colour
    Skipped,    // near an edge, or (phong) near a switch of the lecture's cases
    Interior    // compared with the oracle
  } What = Skipped;
  int Triangle = -1; // drawn as edges or points, the element: flat's unit of one colour
  Rgb Value{};
  // How the rule lit the pixel (world): where (the pixel centre on the mesh,
  // or for flat the provoking vertex), with which normal (unit, facing the
  // viewer; gouraud: the vertices' mixed), and each light's terms.
  shadelab::IlluminationTerms Terms;
  std::array<double, 2> TexCoord{}; // with a texture: where it was looked up
  // The fog's factor where it fogs towards transparent (the fragment's a
  // times it); then, with translucency, the composite's alpha.
  double Coverage = 1;
  // Skipped: a point it was lit at lies in the band around a shadow's edge
  // where a shadow map may decide otherwise (Oracle::ShadowBand).
  bool ShadowBand = false;
};

// The pixels of a scene as the oracle sees them: the library's rays through
// the pixel centres (shadelabPixelRays) and its shading of the fragment met
// (shadelabTriangleFragment), as `shadelab probe` explains a pixel.
class Oracle
{
public:
  explicit Oracle(const Scene& s)
    : S(s)
    , M(Grid(s.Geometry))
    , Triangles(Camera(s), s.Size, s.Size, WorldPositions(s, this->M), this->M.Triangles)
  {
    this->In.Ambient = s.Ambient;
    this->In.Model = s.Model;
    this->In.Orthographic = true;
    this->In.ViewDirection = { 0, 0, -1 };
    for (Light l : WorldLights(s))
    {
      if (!l.Attenuation && shadelab::GeometryOf(l.Kind).Position)
      {
        l.Attenuation = WorldAttenuation(s, s.Attenuation); // the scene's
      }
      l.Shadows = this->CastShadows();
      this->In.Lights.push_back(shadelab::ToFrame(l));
      this->Lights.push_back(l);
    }
    if (this->CastShadows())
    {
      this->Rays =
        std::make_unique<shadelab::RayScene>(this->Triangles.GetPoints(), this->M.Triangles);
      this->In.Reaches = [this](std::size_t l, const Vec3& P, const Vec3& N)
      { return this->Reaches(l, P, N); };
    }
    if (s.Drawn != shadelab::Representation::Surface)
    {
      this->Elements =
        std::make_unique<shadelab::PictureElements>(this->Triangles, s.Drawn, s.Pixels);
    }
    if (s.Textured)
    {
      shadelab::SurfaceTexture& t = this->In.Texture;
      t.Map.Image = std::make_shared<shadelab::TextureImage>(ExpectedTexture());
      t.Map.WrapS = t.Map.WrapT = s.Wrap;
      t.Map.Filter = s.Filter;
      t.Kd = t.Ka = true;
    }
    if (s.NormalMap != NormalMapKind::None)
    {
      shadelab::NormalMap& n = this->In.NormalTexture.emplace();
      n.Map.Image = std::make_shared<shadelab::TextureImage>(NormalMapOf(s.NormalMap).Decoded());
      n.Map.WrapS = n.Map.WrapT = s.Wrap;
      n.Map.Filter = s.Filter;
      n.Scale = s.NormalScale;
      n.Height = IsHeightMap(s.NormalMap);
    }
    if (s.Environment != EnvironmentKind::None)
    {
      // The environment's frame, stated here on its own: x right, y up, z
      // towards the front view's camera (+Z; -Y for up +Z).
      shadelab::EnvironmentMap& e = this->In.Environment.emplace();
      e.Map.Image =
        std::make_shared<shadelab::TextureImage>(EnvironmentOf(s.Environment).Decoded());
      e.Map.WrapS = shadelab::TextureWrap::Repeat;
      e.Map.WrapT = shadelab::TextureWrap::Clamp;
      e.Map.Filter = s.Filter;
      if (s.ZUp)
      {
        const double zUp[3][3] = { { 1, 0, 0 }, { 0, 0, 1 }, { 0, -1, 0 } };
        std::copy(&zUp[0][0], &zUp[0][0] + 9, &e.Frame[0][0]);
      }
    }
  }

  Expected At(int x, int y) const
  {
    const double cx = x + 0.5, cy = y + 0.5; // the pixel centre
    Expected e;
    if (this->Elements)
    {
      const shadelab::PictureElements::Hit drawn = this->Elements->Under(cx, cy);
      if (drawn.Element < 0 || drawn.Margin <= ElementMargin)
      {
        e.What = drawn.Element < 0 && drawn.Margin > ElementMargin ? Expected::Background
                                                                   : Expected::Skipped;
        return e;
      }
      this->Shade(static_cast<int>(drawn.Owner), drawn.Corners, drawn.Weights, true, e, true);
      e.Triangle = static_cast<int>(drawn.Element);
      e.What = Expected::Interior;
      return e;
    }
    const shadelab::PictureTriangles::Hit hit = this->Triangles.Under(cx, cy);
    if (hit.Triangle < 0)
    {
      e.What = hit.EdgeDistance > EdgeMargin ? Expected::Background : Expected::Skipped;
      return e;
    }
    if (Translucent(this->S))
    {
      return this->Layered(cx, cy);
    }
    e.Triangle = static_cast<int>(hit.Triangle);
    if (hit.EdgeDistance <= EdgeMargin || this->NearSwitch(e.Triangle, hit.Front, cx, cy))
    {
      return e;
    }
    this->InShadowBand = false;
    this->Shade(e.Triangle, this->M.Triangles[e.Triangle], hit.Weights, hit.Front, e);
    e.ShadowBand = this->InShadowBand;
    e.What = e.ShadowBand ? Expected::Skipped : Expected::Interior;
    return e;
  }

  // Translucency: every layer under the pixel centre shaded, and those in
  // front of the first opaque one composited over it (or the black
  // background) in depth order, the nearest --peels of them; compared away
  // from every triangle's edge and every layer's switches. The terms are
  // the nearest layer's.
  Expected Layered(double cx, double cy) const
  {
    Expected e;
    const std::vector<shadelab::PictureTriangles::Hit> layers = this->Triangles.Through(cx, cy);
    if (layers.front().EdgeDistance <= EdgeMargin)
    {
      return e;
    }
    std::vector<shadelab::Layer> translucent;
    // The background: black, opaque or transparent.
    shadelab::Covered behind{ { 0, 0, 0 }, this->S.TransparentBackground ? 0.0 : 1.0 };
    for (const shadelab::PictureTriangles::Hit& hit : layers)
    {
      const int t = static_cast<int>(hit.Triangle);
      if (this->NearSwitch(t, hit.Front, cx, cy))
      {
        return e;
      }
      Expected layer;
      this->Shade(t, this->M.Triangles[t], hit.Weights, hit.Front, layer);
      if (e.Triangle < 0)
      {
        e.Triangle = t;
        e.Terms = layer.Terms;
        e.TexCoord = layer.TexCoord;
      }
      const double a = OpacityOf(this->S, t) * layer.Coverage;
      if (a == 1)
      {
        behind = { layer.Value, 1 };
        break;
      }
      translucent.push_back({ layer.Value, a });
    }
    const shadelab::Covered c = shadelab::Composite(translucent, behind, this->S.Peels);
    e.Value = c.Color;
    e.Coverage = c.Alpha;
    e.What = Expected::Interior;
    return e;
  }

  // One line per light at a surface point: L, N.L and, for a spot, the
  // cosine of the angle off its axis.
  std::string Describe(const Expected& e) const
  {
    std::ostringstream s;
    s << "P " << Show(e.Terms.P) << ", N " << Show(e.Terms.N) << ", V " << Show(e.Terms.V);
    for (std::size_t l = 0; l < e.Terms.Lights.size(); ++l)
    {
      const shadelab::LightTerms& t = e.Terms.Lights[l];
      const FrameLight& light = this->In.Lights[l];
      s << "; " << shadelab::ToString(light.Kind) << " L " << Show(t.L) << " N.L " << t.NdotL;
      if (light.Kind == LightKind::Spot)
      {
        s << " cos " << t.SpotCos << " (cut-off " << light.CosCutoff << ")";
      }
    }
    return s.str();
  }

private:
  // The scene's camera: orthographic on +Z, looking at the origin, +Y up.
  static shadelab::PinholeCamera Camera(const Scene& s)
  {
    shadelab::PinholeCamera c;
    c.Position = s.World({ 0, 0, s.CameraDistance });
    c.FocalPoint = s.World({ 0, 0, 0 });
    c.ViewUp = { 0, 1, 0 };
    c.Orthographic = true;
    c.ParallelScale = s.Scale * ParallelScale;
    return c;
  }

  static std::vector<Vec3> WorldPositions(const Scene& s, const Mesh& m)
  {
    std::vector<Vec3> world;
    for (const Vec3& p : m.Positions)
    {
      world.push_back(s.World(p));
    }
    return world;
  }

  // The lecture's cases at a fragment, per light: whether it reaches P (a
  // spot's cone), whether N.L > 0, whether the specular base is > 0. Where
  // one of them changes, the per-fragment colour may jump (a hard cone edge;
  // the specular term switched off at N.L = 0 or at a base of 0 with ns = 0).
  // Values within rounding of 0 (float normals: 3e-8) count as 0, so that a
  // light in the surface's plane is compared (it is a case of its own), not
  // skipped; a real crossing moves by 1e-6/0.005 = 2e-4 pixel for it.
  // With a nearest texture, the texel looked up switches too (its index
  // here, unwrapped: wrapping changes no boundary).
  std::vector<long long> Switches(const Expected& at) const
  {
    constexpr double Rounding = 1e-6;
    std::vector<long long> on;
    for (const shadelab::LightTerms& t : at.Terms.Lights)
    {
      on.push_back(t.Shadowed);
      on.push_back(t.Reaches);
      on.push_back(t.NdotL > Rounding);
      on.push_back(t.Base > Rounding);
    }
    if (this->NearestTexels())
    {
      on.push_back(static_cast<long long>(std::floor(at.TexCoord[0] * TextureSide)));
      on.push_back(static_cast<long long>(std::floor(at.TexCoord[1] * TextureSide)));
    }
    if (at.Terms.Environment && this->S.Filter == shadelab::TextureFilter::Nearest)
    {
      const shadelab::TextureImage& image = *this->In.Environment->Map.Image;
      on.push_back(static_cast<long long>(
                     std::floor(at.Terms.Environment->TexCoord[0] * image.Width) + image.Width) %
        image.Width);
      on.push_back(
        static_cast<long long>(std::floor(at.Terms.Environment->TexCoord[1] * image.Height)));
    }
    return on;
  }

  // A nearest texel of the texture, or of the normal map per fragment
  // (phong's; flat's and gouraud's are read at vertices), is looked up at
  // Expected::TexCoord: both TextureSide texels a side.
  bool NearestTexels() const
  {
    return this->S.Filter == shadelab::TextureFilter::Nearest &&
      (this->S.Textured ||
        (this->S.NormalMap != NormalMapKind::None &&
          shadelab::RasterRule(this->S.Rule) == Shading::Phong));
  }

  // Per-fragment lighting (phong; flat and gouraud decide at vertices) and
  // nearest texels (every rule):
  // whether one of the switches above changes within EdgeMargin pixels of
  // picture point (x, y) on triangle t, found on a ring of that radius (the
  // switching curves bend over many pixels, so one passing this close cuts
  // the ring).
  bool NearSwitch(int t, bool front, double x, double y) const
  {
    if (shadelab::RasterRule(this->S.Rule) != Shading::Phong && !this->NearestTexels())
    {
      return false;
    }
    const auto switches = [&](double px, double py)
    {
      const auto& c = this->M.Triangles[t];
      const auto& p = this->Triangles.GetPoints();
      const shadelab::TriangleHit h =
        shadelab::IntersectTriangle(this->Triangles.RayAt(px, py), p[c[0]], p[c[1]], p[c[2]]);
      Expected at;
      this->Shade(t, c, h.Weights, front, at);
      return Switches(at);
    };
    const std::vector<long long> centre = switches(x, y);
    for (int k = 0; k < 32; ++k)
    {
      const double a = 2 * Pi * k / 32;
      if (switches(x + EdgeMargin * std::cos(a), y + EdgeMargin * std::sin(a)) != centre)
      {
        return true;
      }
    }
    return false;
  }

  // The rules of doc/design.md through the oracle's functions: a fragment
  // of triangle t (its corners as drawn, or turned for an element of it).
  void Shade(int t, const shadelab::TriangleCorners& corners, const std::array<double, 3>& w,
    bool front, Expected& e, bool element = false) const
  {
    shadelab::TriangleFragment f;
    for (int k = 0; k < 3; ++k)
    {
      const auto v = corners[k];
      f.Positions[k] = this->Triangles.GetPoints()[v];
      f.Normals[k] = this->M.Normals[v];
      f.TexCoords[k] = this->M.TexCoords[v];
      f.Tangents[k] = GridTangent(this->S.Geometry);
    }
    f.Weights = w;
    f.Front = front;
    if (this->S.VertexKd())
    {
      f.VertexKd.emplace();
      for (int k = 0; k < 3; ++k)
      {
        const auto& c = this->M.Colors[corners[k]];
        for (int channel = 0; channel < 3; ++channel)
        {
          // What the reader keeps: the fraction of 255 as float.
          (*f.VertexKd)[k][channel] = static_cast<float>(c[channel] / 255.0);
        }
      }
    }
    IlluminationInputs in = this->In;
    in.Surface = SurfaceOf(this->S, t);
    if (!TexturedPart(this->S, t))
    {
      in.Texture = {};
    }
    const shadelab::ShadedFragment shaded = element
      ? shadelab::ShadeElementFragment(in, this->S.Rule, f)
      : shadelab::ShadeTriangleFragment(in, this->S.Rule, f);
    e.Value = shaded.Color;
    if (this->S.Rule == Shading::Raytrace)
    {
      e.Value =
        e.Value + KsOf(in, shaded) * this->Mirror(shaded, { 0, 0, -1 }, this->S.Reflections);
    }
    if (this->S.Fog.Mode != shadelab::FogMode::None)
    {
      // Per fragment under every rule: at the point under the pixel centre,
      // towards the background (black) unless the fog has a colour.
      const shadelab::FogAt fog = shadelab::FogOver(WorldFog(this->S), e.Value, shaded.Point,
        this->S.World({ 0, 0, this->S.CameraDistance }), { 0, 0, -1 },
        this->S.TransparentBackground ? std::nullopt : std::optional<Rgb>(Rgb{ 0, 0, 0 }));
      e.Value = fog.After;
      e.Coverage = fog.Transparent ? fog.Factor : 1;
    }
    e.Terms = shaded.Terms;
    e.TexCoord = shaded.TexCoord ? *shaded.TexCoord
      : shaded.Mapped            ? shaded.Mapped->TexCoord
                                 : std::array<double, 2>{};
  }

  // Shadows: the oracle's shadow ray from P (world coordinates) to light
  // l. Where the answer changes within ShadowBand of P across the surface
  // (two directions in its tangent plane, both ways), a map's texels may
  // decide otherwise: the pixel is not compared (InShadowBand). The band,
  // 0.01 of the scene's unit at 2048 texels and wider for smaller maps, is
  // about seven texels' footprint on the grid for the lights of the tests.
  bool Reaches(std::size_t l, const Vec3& P, const Vec3& N) const
  {
    const bool reaches = this->Rays->LightReaches(P, N, this->Lights[l]);
    // Ray traced, the picture's shadow rays are the oracle's, cast from P as
    // its own ray found it: the band only covers their roundings.
    const double band = this->S.Rule == Shading::Raytrace
      ? 1e-9 * this->S.Scale
      : 0.01 * this->S.Scale * 2048 / this->S.ShadowMapSize;
    // Across the surface: the plane of the triangle that P lies on (the
    // normal N may lean off it), found by a ray back along N.
    const shadelab::RayScene::Hit under =
      this->Rays->First({ P + 1e-6 * this->S.Scale * N, -1.0 * N });
    Vec3 g = N;
    if (under.Triangle >= 0)
    {
      const auto& c = this->M.Triangles[under.Triangle];
      const auto& p = this->Triangles.GetPoints();
      g = normalize(cross(p[c[1]] - p[c[0]], p[c[2]] - p[c[0]]));
    }
    const Vec3 u = normalize(cross(g, std::abs(g[0]) < 0.9 ? Vec3{ 1, 0, 0 } : Vec3{ 0, 1, 0 }));
    const Vec3 v = cross(g, u);
    for (const Vec3& step : { u, -1.0 * u, v, -1.0 * v })
    {
      if (this->Rays->LightReaches(P + band * step, N, this->Lights[l]) != reaches)
      {
        this->InShadowBand = true;
      }
    }
    return reaches;
  }

  bool CastShadows() const { return this->S.Shadows || this->S.Rule == Shading::Raytrace; }

  static Rgb KsOf(const IlluminationInputs& in, const shadelab::ShadedFragment& at)
  {
    return at.Ks.value_or(in.Surface.Ks);
  }

  // Ray traced: what the mirror reflection of a ray along unit D sees at
  // fragment `at` (lit with its normal turned towards the viewer), bounces
  // deep: the reflected ray R = D - 2(D.N)N, from P moved ShadowRayOffset
  // of the diagonal off its face, meets the mesh first at a point that is
  // lit from P as phong lights it, plus its own reflection weighted by its
  // ks; R into the face, or meeting nothing, sees black (the background of
  // these scenes). Opaque scenes only: no light through translucent ones,
  // and no vertex colours on what a mirror sees.
  Rgb Mirror(const shadelab::ShadedFragment& at, const Vec3& D, int bounces) const
  {
    const Vec3& N = at.Terms.N;
    if (bounces == 0 || dot(N, N) == 0)
    {
      return {};
    }
    const Vec3 R = normalize(D - 2 * dot(D, N) * N);
    const Vec3 face = dot(at.FaceNormal, D) < 0 ? at.FaceNormal : -1.0 * at.FaceNormal;
    if (!(dot(R, face) > 0))
    {
      return {};
    }
    const Vec3 origin = at.Point + shadelab::ShadowRayOffset * this->Rays->Diagonal() * face;
    const shadelab::RayScene::Hit hit = this->Rays->First({ origin, R });
    if (hit.Triangle < 0)
    {
      return {};
    }
    const int t = static_cast<int>(hit.Triangle);
    shadelab::TriangleFragment f;
    for (int k = 0; k < 3; ++k)
    {
      const auto v = this->M.Triangles[t][k];
      f.Positions[k] = this->Triangles.GetPoints()[v];
      f.Normals[k] = this->M.Normals[v];
      f.TexCoords[k] = this->M.TexCoords[v];
    }
    f.Weights = hit.Weights;
    const auto& P = f.Positions;
    f.Front = dot(cross(P[1] - P[0], P[2] - P[0]), R) < 0;
    IlluminationInputs in = this->In;
    in.Surface = SurfaceOf(this->S, t);
    if (!TexturedPart(this->S, t))
    {
      in.Texture = {};
    }
    in.Orthographic = false;
    in.Eye = origin;
    const shadelab::ShadedFragment there = shadelab::ShadeTriangleFragment(in, Shading::Phong, f);
    return there.Color + KsOf(in, there) * this->Mirror(there, R, bounces - 1);
  }

  const Scene& S;
  Mesh M;
  std::vector<Light> Lights;                // world coordinates
  std::unique_ptr<shadelab::RayScene> Rays; // shadows
  mutable bool InShadowBand = false;
  shadelab::PictureTriangles Triangles;                // in world coordinates
  std::unique_ptr<shadelab::PictureElements> Elements; // drawn as edges or points
  IlluminationInputs In;
};
// ---------------------------------------------------------------- cases

// Float EXR: a channel passes when |gpu - oracle| <= Relative*max(|oracle|, Floor).
// 8-bit PNG: when |gpu - round(255*clamp(oracle))| <= 2 (in 255ths).
struct Tolerance
{
  double Relative;
  double Floor;
  bool Exact = false; // gpu == float(oracle), bit for bit
};

// The issue's bound. Float has a 24-bit significand (ulp 6e-8 relative); the
// GPU evaluates the equation in view coordinates in float, the oracle in
// double. Two sources of error: the roundings of unit vectors, dot products
// and colours of about 1, a few dozen of 6e-8, some 1e-6 at most; and the
// fragment's view-space position, about 5e-7 off (half an ulp of the
// camera's distance, 10), which turns the direction to a point light d away
// by 5e-7/d: 1.5e-5 for the compared pixel nearest a light at a vertex (1.5
// pixels = 0.034 away). 1e-4 relative covers both with a margin. These
// errors are absolute (they do not shrink with the result), so below 0.01 the
// bound stops shrinking: 1e-6 absolute, still above the first kind.
constexpr Tolerance Standard{ 1e-4, 0.01 };

struct Case
{
  std::string Name;
  Scene S;
  Tolerance Tol = Standard;
};

/** How the case lists add a case: add(name, scene[, tolerance]). */
inline auto CaseAdder(std::vector<Case>& cases)
{
  return [&cases](const std::string& name, const Scene& s, Tolerance tol = Standard) {
    cases.push_back({ name, s, tol });
  };
}

inline void PrintTo(const Case& c, std::ostream* os)
{
  *os << c.Name;
}

// ns = 1e6: the highlight is exp(-ns*t^2/2) in the angle t off the mirror
// direction, so an angular error dt of the float unit vectors changes it by
// ns*t*dt relative, at most sqrt(ns)*exp(-1/2)*dt = 607*dt of ks on the
// highlight's flank (t = 1/sqrt(ns)). dt is a few roundings of the normal's
// components (about 0.25 and 0.97 here), 1e-7 together, and doubles in
// Phong's R = 2(N.L)N - L: up to 1.2e-4 of ks, above the issue's 1e-4, so
// 1e-3 here. That is still an error of only 1e-9 in the cosine, 60 times
// below float's resolution of a cosine near 1: a shader that took
// pow(N.H, ns) of the cosine itself would be off by up to 6e-8*1e6 = 6%.
constexpr Tolerance HighExponent{ 1e-3, 0.01 };

// Phong's fallback for a zero interpolated normal is the geometric normal
// cross(dFdx(P), dFdy(P)) of the view-space position, whose components each
// carry half an ulp of the camera distance d. Over a pixel of w world units
// that tilts the normal by about ulp(d)/w: 6e-7/0.023 = 2.6e-5 rad at d = 10
// (0.9 of the standard bound was seen) and 2.6e-4 rad at d = 100 (5e-4
// relative seen). 2e-3 covers d = 100 with a margin and still catches a
// wrong fallback (a normal off by degrees). A known limit of derivative
// normals, noted in the shader source.
constexpr Tolerance DerivativeNormal{ 2e-3, 0.01 };
// ---------------------------------------------------------------- comparison

struct Deviation
{
  size_t Compared = 0;
  double Low = 1e300, High = -1e300; // the oracle's range over the compared channels
  size_t BackgroundWrong = 0;
  size_t Failed = 0; // channels out of tolerance
  double MaxAbs = 0; // float: |gpu - oracle|; 8-bit: in 255ths
  double MaxRel = 0; // float: |gpu - oracle| / |oracle|, where |oracle| > 0
  double Worst = -1; // the largest deviation in units of the allowed one (NaN sticks)
  int WorstX = -1, WorstY = -1;
  std::string FirstBackground;
  size_t FlatDifferent = 0; // flat: pixels that differ from their triangle's first one
  std::string FirstFlat;
  size_t AlphaWrong = 0; // a transparent background's: off the coverage by more than 1e-6
  std::string FirstAlpha;
  size_t Shadowed = 0;   // compared pixels where a light is shadowed
  size_t ShadowBand = 0; // pixels not compared for a shadow's edge
};

inline std::string PixelName(int x, int y)
{
  return "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")";
}

inline Rgb Got(const Image& image, int x, int y)
{
  const size_t i = (static_cast<size_t>(y) * image.Width + x) * image.Channels;
  return { image.Pixels[i], image.Pixels[i + 1], image.Pixels[i + 2] };
}

inline Deviation Compare(
  const Scene& s, const Tolerance& tol, const Oracle& oracle, const Image& image)
{
  Deviation d;
  std::map<int, Rgb> flatColour;
  for (int y = 0; y < s.Size; ++y)
  {
    for (int x = 0; x < s.Size; ++x)
    {
      const Expected e = oracle.At(x, y);
      const Rgb got = Got(image, x, y);
      if (e.What == Expected::Background)
      {
        if ((got[0] != 0 || got[1] != 0 || got[2] != 0) && d.BackgroundWrong++ == 0)
        {
          d.FirstBackground = PixelName(x, y) + " is " + Show(got);
        }
        continue;
      }
      d.ShadowBand += e.ShadowBand;
      if (e.What != Expected::Interior)
      {
        continue;
      }
      ++d.Compared;
      d.Shadowed += std::any_of(e.Terms.Lights.begin(), e.Terms.Lights.end(),
        [](const shadelab::LightTerms& t) { return t.Shadowed; });
      if (s.TransparentBackground && image.Channels == 4 && !s.EightBit)
      {
        const float alpha = image.Pixels[(static_cast<size_t>(y) * image.Width + x) * 4 + 3];
        if (!(std::abs(alpha - e.Coverage) <= 1e-6) && d.AlphaWrong++ == 0)
        {
          d.FirstAlpha = PixelName(x, y) + " has alpha " + std::to_string(alpha) + ", coverage " +
            std::to_string(e.Coverage);
        }
      }
      for (int c = 0; c < 3; ++c)
      {
        d.Low = std::min(d.Low, e.Value[c]);
        d.High = std::max(d.High, e.Value[c]);
        double dev, allowed;
        if (s.EightBit)
        {
          dev = std::abs(got[c] - std::round(255 * std::clamp(e.Value[c], 0.0, 1.0)));
          allowed = 2;
        }
        else if (tol.Exact)
        {
          dev = std::abs(got[c] - static_cast<float>(e.Value[c]));
          allowed = 0;
        }
        else
        {
          dev = std::abs(got[c] - e.Value[c]);
          allowed = tol.Relative * std::max(std::abs(e.Value[c]), tol.Floor);
          if (e.Value[c] != 0)
          {
            d.MaxRel = std::max(d.MaxRel, dev / std::abs(e.Value[c]));
          }
        }
        d.MaxAbs = std::isnan(dev) || std::isnan(d.MaxAbs) ? NAN : std::max(d.MaxAbs, dev);
        const double ratio = allowed > 0 ? dev / allowed : (dev > 0 ? 1e300 : 0);
        if (!(dev <= allowed))
        {
          ++d.Failed;
        }
        if (!std::isnan(d.Worst) && (std::isnan(ratio) || ratio > d.Worst))
        {
          d.Worst = ratio;
          d.WorstX = x;
          d.WorstY = y;
        }
      }
      // A texture and fog vary per fragment under flat too.
      if (s.Rule == Shading::Flat && !s.EightBit && !s.Textured &&
        s.Fog.Mode == shadelab::FogMode::None && !Translucent(s))
      {
        const auto [first, added] = flatColour.emplace(e.Triangle, got);
        if (!added && first->second != got && d.FlatDifferent++ == 0)
        {
          d.FirstFlat = PixelName(x, y) + " of triangle " + std::to_string(e.Triangle) + " is " +
            Show(got) + ", another of it " + Show(first->second);
        }
      }
    }
  }
  return d;
}

inline std::string Summary(const Case& c, const Deviation& d)
{
  char text[320];
  if (c.S.EightBit)
  {
    std::snprintf(text, sizeof text,
      "%s: %zu px, oracle in [%.3g, %.3g], max |gpu - oracle| %g/255 (allowed 2/255)",
      c.Name.c_str(), d.Compared, d.Low, d.High, d.MaxAbs);
  }
  else
  {
    std::snprintf(text, sizeof text,
      "%s: %zu px, oracle in [%.3g, %.3g], max |gpu - oracle| %.3g abs, %.3g rel; worst %.3g "
      "of the allowed %g*max(|oracle|, %g) at pixel (%d, %d)",
      c.Name.c_str(), d.Compared, d.Low, d.High, d.MaxAbs, d.MaxRel, d.Worst, c.Tol.Relative,
      c.Tol.Floor, d.WorstX, d.WorstY);
  }
  return text;
}

/**
 * Renders case c with `shadelab render` and expects every interior pixel
 * within its tolerance of the oracle, the background untouched and flat's
 * triangles one colour each; prints the deviation as an `[oracle]` line.
 */
inline void ExpectMatchesOracle(const Case& c)
{
  TempDir dir;
  std::string error;
  const Image image = Render(c.S, dir, error);
  ASSERT_EQ(error, "");
  const Oracle oracle(c.S);
  const Deviation d = Compare(c.S, c.Tol, oracle, image);
  std::size_t nonFinite = 0; // anywhere: background and skipped pixels too
  for (float v : image.Pixels)
  {
    nonFinite += !std::isfinite(v);
  }
  EXPECT_EQ(nonFinite, 0u) << "NaN or Inf in the picture";

  const std::string summary = Summary(c, d);
  std::cout << "[oracle] " << summary << std::endl;
  testing::Test::RecordProperty("max_abs", std::to_string(d.MaxAbs));
  testing::Test::RecordProperty("max_rel", std::to_string(d.MaxRel));
  testing::Test::RecordProperty("compared_pixels", std::to_string(d.Compared));

  EXPECT_GE(d.Compared, 500u) << "too few interior pixels to say anything";
  EXPECT_EQ(d.BackgroundWrong, 0u)
    << "pixels away from the mesh that are not the background; " << d.FirstBackground;
  if (d.WorstX >= 0)
  {
    const Expected e = oracle.At(d.WorstX, d.WorstY);
    EXPECT_EQ(d.Failed, 0u) << summary << "\nworst: " << PixelName(d.WorstX, d.WorstY)
                            << ", triangle " << e.Triangle << ": oracle " << Show(e.Value)
                            << ", gpu " << Show(Got(image, d.WorstX, d.WorstY)) << "\n"
                            << oracle.Describe(e);
  }
  EXPECT_EQ(d.FlatDifferent, 0u) << "flat: more than one colour in a triangle: " << d.FirstFlat;
  EXPECT_EQ(d.AlphaWrong, 0u) << "alpha off the coverage: " << d.FirstAlpha;
  if (c.S.Shadows || c.S.Rule == Shading::Raytrace)
  {
    std::cout << "[oracle] " << c.Name << ": " << d.Shadowed << " compared pixels in a shadow, "
              << d.ShadowBand << " left out at a shadow's edge" << std::endl;
    EXPECT_GE(d.Shadowed, c.S.ShadowedAtLeast) << "too few shadowed pixels to say anything";
  }
}
}

#endif
