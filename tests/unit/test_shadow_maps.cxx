// Shadow maps against the oracle's rays: the distance each
// texel stores is the distance the double ray through its centre travels to
// the first triangle, to float precision, wherever the ray's answer is
// stable (its neighbours a ten-thousandth of a texel away meet the same
// triangle: elsewhere the rasteriser may decide otherwise), and FLT_MAX
// where it meets nothing.
#include "headless/headless_renderer.h"
#include "shadelabRayScene.h"
#include "shadelabShadowMaps.h"
#include "shadelabVec3.h"

#include <gtest/gtest.h>

#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtk_glew.h>

#include <cfloat>
#include <cmath>
#include <memory>

using namespace shadelab;
using namespace shadelab::vec3;

namespace
{
// What OpenGL's cube-map lookup (textureLod, nearest) reads from map in
// each direction, one float per direction: as the shaders will read it.
std::vector<float> LookUp(const ShadowMap& map, const std::vector<Vec3>& directions)
{
  const int n = static_cast<int>(directions.size());
  std::vector<float> packed;
  for (const Vec3& d : directions)
  {
    packed.insert(packed.end(), { float(d[0]), float(d[1]), float(d[2]) });
  }
  const char* vertex = "#version 150\nin vec4 p; void main() { gl_Position = p; }\n";
  const char* fragment =
    "#version 150\nout vec4 o; uniform samplerCube cube; uniform sampler2D directions;\n"
    "void main() { vec3 d = texelFetch(directions, ivec2(gl_FragCoord.xy), 0).xyz;\n"
    "  o = vec4(textureLod(cube, d, 0.0).r); }\n";
  const GLuint vs = glCreateShader(GL_VERTEX_SHADER), fs = glCreateShader(GL_FRAGMENT_SHADER);
  glShaderSource(vs, 1, &vertex, nullptr);
  glCompileShader(vs);
  glShaderSource(fs, 1, &fragment, nullptr);
  glCompileShader(fs);
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs);
  glAttachShader(program, fs);
  glBindFragDataLocation(program, 0, "o");
  glLinkProgram(program);
  GLuint textures[2], framebuffer, buffer, vao;
  glGenTextures(2, textures);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, textures[0]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, n, 1, 0, GL_RGB, GL_FLOAT, packed.data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_CUBE_MAP, map.GetTexture());
  glBindTexture(GL_TEXTURE_2D, textures[1]);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, n, 1, 0, GL_RED, GL_FLOAT, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, textures[1], 0);
  const float triangle[] = { -1, -1, 0, 1, 3, -1, 0, 1, -1, 3, 0, 1 };
  glGenVertexArrays(1, &vao);
  glBindVertexArray(vao);
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, sizeof(triangle), triangle, GL_STATIC_DRAW);
  const GLint p = glGetAttribLocation(program, "p");
  glEnableVertexAttribArray(p);
  glVertexAttribPointer(p, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
  glUseProgram(program);
  glUniform1i(glGetUniformLocation(program, "cube"), 0);
  glUniform1i(glGetUniformLocation(program, "directions"), 1);
  glBindTexture(GL_TEXTURE_CUBE_MAP, map.GetTexture());
  glViewport(0, 0, n, 1);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  std::vector<float> read(directions.size());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glReadPixels(0, 0, n, 1, GL_RED, GL_FLOAT, read.data());
  glDeleteProgram(program);
  glDeleteShader(vs);
  glDeleteShader(fs);
  glDeleteTextures(2, textures);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteBuffers(1, &buffer);
  glDeleteVertexArrays(1, &vao);
  return read;
}

// The plane z = 0 (half-size 10), a quad of half-size 1 at height 1, and a
// torus standing on the plane beside it.
void Scene(std::vector<Vec3>& points, std::vector<TriangleCorners>& triangles)
{
  points = { { -10, -10, 0 }, { 10, -10, 0 }, { 10, 10, 0 }, { -10, 10, 0 }, { -1, -1, 1 },
    { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
  triangles = { { 0, 1, 2 }, { 0, 2, 3 }, { 4, 5, 6 }, { 4, 6, 7 } };
  const int around = 32, tube = 16;
  const std::int64_t first = static_cast<std::int64_t>(points.size());
  for (int i = 0; i < around; ++i)
  {
    for (int j = 0; j < tube; ++j)
    {
      const double u = 2 * M_PI * i / around, v = 2 * M_PI * j / tube;
      points.push_back({ 3 + (1 + 0.3 * std::cos(v)) * std::cos(u),
        (1 + 0.3 * std::cos(v)) * std::sin(u), 1.3 + 0.3 * std::sin(v) });
      const auto at = [&](int a, int b) { return first + (a % around) * tube + (b % tube); };
      triangles.push_back({ at(i, j), at(i + 1, j), at(i + 1, j + 1) });
      triangles.push_back({ at(i, j), at(i + 1, j + 1), at(i, j + 1) });
    }
  }
}
}

// The texels held against the oracle's rays: one whose neighbours' rays
// meet another triangle is left out (unstable: the rasteriser may decide
// otherwise); one whose ray meets nothing holds FLT_MAX; the rest the ray's
// T within 1e-6 of it and `spread` (where the texel's sample may lie).
struct Tally
{
  int Compared = 0, Empty = 0, Unstable = 0;
  double Worst = 0;

  void Check(
    bool stable, const RayScene::Hit& hit, float got, double spread, const std::string& texel)
  {
    if (!stable)
    {
      ++this->Unstable;
      return;
    }
    if (hit.Triangle < 0)
    {
      ++this->Empty;
      EXPECT_EQ(got, FLT_MAX) << texel;
      return;
    }
    ++this->Compared;
    const double error = std::abs(got - hit.T) / hit.T;
    this->Worst = std::max(this->Worst, error);
    EXPECT_LE(error, 1e-6 + spread / hit.T) << texel << ": " << got << " against " << hit.T;
  }

  void Print() const
  {
    std::printf("compared %d, empty %d, unstable %d, worst relative error %.3g\n", this->Compared,
      this->Empty, this->Unstable, this->Worst);
  }
};

// The scene's triangles, its rays, and a current OpenGL context to bake in.
class ShadowMaps : public testing::Test
{
protected:
  void SetUp() override
  {
    ASSERT_EQ(this->Renderer.Start(1, 1), "");
    this->Renderer.GetRenderer()->GetRenderWindow()->MakeCurrent();
    Scene(this->Points, this->Triangles);
    this->Rays = std::make_unique<RayScene>(this->Points, this->Triangles);
  }

  HeadlessRenderer Renderer;
  std::vector<Vec3> Points;
  std::vector<TriangleCorners> Triangles;
  std::unique_ptr<RayScene> Rays;
};

TEST_F(ShadowMaps, EachTexelHoldsTheDistanceTheOraclesRayTravels)
{
  const RayScene& rays = *this->Rays;
  const std::vector<Vec3>& points = this->Points;
  const std::vector<TriangleCorners>& triangles = this->Triangles;
  Light point;
  point.Position = { 0.5, -0.25, 4 };
  const Vec3& light = point.Position;
  const int size = 64;
  ShadowMap map;
  ASSERT_EQ(map.Bake(points, triangles, point, size), "");
  ASSERT_TRUE(map.IsCube());
  Tally tally;
  for (int f = 0; f < 6; ++f)
  {
    const std::vector<float> texels = map.ReadFace(f);
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        const RayScene::Hit hit = rays.First({ light, CubeDirection(f, i + 0.5, j + 0.5, size) });
        bool stable = true;
        for (const auto& [di, dj] :
          { std::pair{ 1e-4, 0.0 }, { -1e-4, 0.0 }, { 0.0, 1e-4 }, { 0.0, -1e-4 } })
        {
          const Vec3 d = CubeDirection(f, i + 0.5 + di, j + 0.5 + dj, size);
          stable = stable && rays.First({ light, d }).Triangle == hit.Triangle;
        }
        tally.Check(stable, hit, texels[static_cast<std::size_t>(j) * size + i], 0,
          "face " + std::to_string(f) + " texel " + std::to_string(i) + ", " + std::to_string(j));
      }
    }
  }
  // OpenGL's lookup in each texel's direction reads that texel: the faces'
  // table is OpenGL's.
  for (int f = 0; f < 6; ++f)
  {
    std::vector<Vec3> directions;
    for (int j = 0; j < size; ++j)
    {
      for (int i = 0; i < size; ++i)
      {
        directions.push_back(CubeDirection(f, i + 0.5, j + 0.5, size));
      }
    }
    EXPECT_EQ(LookUp(map, directions), map.ReadFace(f)) << "face " << f;
  }
  tally.Print();
  EXPECT_GT(tally.Compared, 6 * size * size / 3);
  EXPECT_LT(tally.Unstable, 6 * size * size / 20);
  map.Release();
}

// A directional light's orthographic map: texel (i, j) holds the depth
// along the light's direction at which the double ray through its centre,
// from the map's plane, meets the first triangle; the map covers the whole
// mesh, so that no texel at its border meets one.
TEST_F(ShadowMaps, AnOrthographicTexelHoldsTheDepthOfTheOraclesRay)
{
  const RayScene& rays = *this->Rays;
  const std::vector<Vec3>& points = this->Points;
  const std::vector<TriangleCorners>& triangles = this->Triangles;
  Light sun;
  sun.Kind = LightKind::Directional;
  sun.Direction = { 0.3, -0.2, -1 };
  const int size = 64;
  ShadowMap map;
  ASSERT_EQ(map.Bake(points, triangles, sun, size), "");
  ASSERT_FALSE(map.IsCube());
  // Map coordinates back to the world: the matrix's rows are orthogonal.
  const std::array<double, 16>& m = map.GetWorldToMap();
  const auto world = [&m](const Vec3& q)
  {
    Vec3 p{ 0, 0, 0 };
    for (int r = 0; r < 3; ++r)
    {
      const Vec3 row{ m[r * 4], m[r * 4 + 1], m[r * 4 + 2] };
      p = p + ((q[r] - m[r * 4 + 3]) / dot(row, row)) * row;
    }
    return p;
  };
  const Vec3 axis = normalize(sun.Direction);
  const std::vector<float> texels = map.ReadFace(0);
  constexpr double Snap = 1.0 / 512;
  Tally tally;
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const auto ray = [&](double x, double y) {
        return rays.First({ world({ x / size, y / size, 0 }), axis });
      };
      const RayScene::Hit hit = ray(i + 0.5, j + 0.5);
      const bool border = i == 0 || j == 0 || i == size - 1 || j == size - 1;
      // The rasteriser's sample lies within float's rounding of the centre:
      // on a steep triangle the depth changes fast across it, so the
      // neighbours' depths widen the bound.
      bool stable = true;
      double spread = 0;
      for (const auto& [di, dj] :
        { std::pair{ Snap, 0.0 }, { -Snap, 0.0 }, { 0.0, Snap }, { 0.0, -Snap } })
      {
        const RayScene::Hit near = ray(i + 0.5 + di, j + 0.5 + dj);
        stable = stable && near.Triangle == hit.Triangle;
        spread = std::max(spread, std::abs(near.T - hit.T));
      }
      if (border)
      {
        EXPECT_LT(hit.Triangle, 0) << "texel " << i << ", " << j << " at the border";
      }
      tally.Check(stable, hit, texels[static_cast<std::size_t>(j) * size + i], spread,
        "texel " + std::to_string(i) + ", " + std::to_string(j));
    }
  }
  tally.Print();
  EXPECT_GT(tally.Compared, size * size / 2);
  EXPECT_LT(tally.Unstable, size * size / 10);
  map.Release();
}
