#include "shadelabShadowMaps.h"

#include "shadelabVec3.h"

#include <vtk_glew.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

namespace shadelab
{
const CubeFace CubeFaces[6] = { { { 1, 0, 0 }, { 0, -1, 0 } }, { { -1, 0, 0 }, { 0, -1, 0 } },
  { { 0, 1, 0 }, { 0, 0, 1 } }, { { 0, -1, 0 }, { 0, 0, -1 } }, { { 0, 0, 1 }, { 0, -1, 0 } },
  { { 0, 0, -1 }, { 0, -1, 0 } } };

Vec3 CubeDirection(int face, double x, double y, int size)
{
  const CubeFace& f = CubeFaces[face];
  const Vec3 right = cross(f.Forward, f.Up);
  return normalize(f.Forward + (x / size * 2 - 1) * right + (y / size * 2 - 1) * f.Up);
}

namespace
{
// The OpenGL state a bake changes, saved as it starts and put back as it
// ends: VTK keeps its own record of OpenGL's state and trusts it.
struct SavedState
{
  GLint Program = 0, VertexArray = 0, ArrayBuffer = 0, DrawFramebuffer = 0, ReadFramebuffer = 0;
  GLint Viewport[4]{};
  GLint BlendSource = 0, BlendDestination = 0, BlendSourceAlpha = 0, BlendDestinationAlpha = 0;
  GLint BlendEquation = 0, BlendEquationAlpha = 0;
  GLfloat ClearColour[4]{};
  GLboolean Blend, Depth, Scissor, Cull, Clamp;

  SavedState()
    : Blend(glIsEnabled(GL_BLEND))
    , Depth(glIsEnabled(GL_DEPTH_TEST))
    , Scissor(glIsEnabled(GL_SCISSOR_TEST))
    , Cull(glIsEnabled(GL_CULL_FACE))
    , Clamp(glIsEnabled(GL_DEPTH_CLAMP))
  {
    glGetIntegerv(GL_CURRENT_PROGRAM, &this->Program);
    glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &this->VertexArray);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &this->ArrayBuffer);
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &this->DrawFramebuffer);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &this->ReadFramebuffer);
    glGetIntegerv(GL_VIEWPORT, this->Viewport);
    glGetIntegerv(GL_BLEND_SRC_RGB, &this->BlendSource);
    glGetIntegerv(GL_BLEND_DST_RGB, &this->BlendDestination);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &this->BlendSourceAlpha);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &this->BlendDestinationAlpha);
    glGetIntegerv(GL_BLEND_EQUATION_RGB, &this->BlendEquation);
    glGetIntegerv(GL_BLEND_EQUATION_ALPHA, &this->BlendEquationAlpha);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, this->ClearColour);
  }

  ~SavedState()
  {
    glBlendEquationSeparate(
      static_cast<GLenum>(this->BlendEquation), static_cast<GLenum>(this->BlendEquationAlpha));
    glBlendFuncSeparate(static_cast<GLenum>(this->BlendSource),
      static_cast<GLenum>(this->BlendDestination), static_cast<GLenum>(this->BlendSourceAlpha),
      static_cast<GLenum>(this->BlendDestinationAlpha));
    glClearColor(
      this->ClearColour[0], this->ClearColour[1], this->ClearColour[2], this->ClearColour[3]);
    (this->Clamp ? glEnable : glDisable)(GL_DEPTH_CLAMP);
    (this->Blend ? glEnable : glDisable)(GL_BLEND);
    (this->Depth ? glEnable : glDisable)(GL_DEPTH_TEST);
    (this->Scissor ? glEnable : glDisable)(GL_SCISSOR_TEST);
    (this->Cull ? glEnable : glDisable)(GL_CULL_FACE);
    glViewport(this->Viewport[0], this->Viewport[1], this->Viewport[2], this->Viewport[3]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(this->DrawFramebuffer));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(this->ReadFramebuffer));
    glUseProgram(static_cast<GLuint>(this->Program));
    glBindVertexArray(static_cast<GLuint>(this->VertexArray));
    glBindBuffer(GL_ARRAY_BUFFER, static_cast<GLuint>(this->ArrayBuffer));
  }
  SavedState(const SavedState&) = delete;
  SavedState& operator=(const SavedState&) = delete;
};

// The casters' program: each vertex relative to the map's origin; the
// fragment's distance from the light (radial, a cube) or its depth along
// the axis (an orthographic map).
const char* const CasterVertex = "#version 150\n"
                                 "in vec3 relative;\n"
                                 "uniform mat4 faceProjection;\n"
                                 "out vec3 fromOrigin;\n"
                                 "void main()\n"
                                 "{\n"
                                 "  fromOrigin = relative;\n"
                                 "  gl_Position = faceProjection * vec4(relative, 1.0);\n"
                                 "}\n";
const char* const CasterFragment = "#version 150\n"
                                   "in vec3 fromOrigin;\n"
                                   "uniform vec3 axis;\n"
                                   "uniform int radial;\n"
                                   "out vec4 distance;\n"
                                   "void main()\n"
                                   "{\n"
                                   "  float d = radial == 1 ? length(fromOrigin) : dot(fromOrigin, "
                                   "axis);\n"
                                   "  distance = vec4(d, 0.0, 0.0, 1.0);\n"
                                   "}\n";
// The bias's parts (the header's comment).
constexpr double RoundingBias = 1e-5;
constexpr double SlopeTexels = 2;
constexpr double SlopeLimit = 50;

std::string Compile(GLuint shader, const char* source)
{
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok)
  {
    return {};
  }
  char log[1024] = {};
  glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
  return log;
}

// Column-major: the 90-degree perspective of face f after its view (the
// light at the origin), clip depth unused (depth clamp, no depth test).
void FaceProjection(int face, float m[16])
{
  const CubeFace& f = CubeFaces[face];
  const Vec3 right = cross(f.Forward, f.Up);
  // Rows of projection * view: x = right.p, y = up.p, z = forward.p (any
  // depth in range), w = forward.p.
  const Vec3 rows[4] = { right, f.Up, f.Forward, f.Forward };
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      m[c * 4 + r] = static_cast<float>(rows[r][c] * (r == 2 ? 0.5 : 1));
    }
    m[12 + r] = 0;
  }
}

// A unit vector across `axis` (unit): the world axis least along it, made
// perpendicular.
Vec3 Across(const Vec3& axis)
{
  int least = 0;
  for (int k = 1; k < 3; ++k)
  {
    if (std::abs(axis[k]) < std::abs(axis[least]))
    {
      least = k;
    }
  }
  Vec3 e{ 0, 0, 0 };
  e[least] = 1;
  return normalize(cross(axis, e));
}

// The orthographic fit: a square across the light's direction that covers
// every point with a texel to spare at each side, its depth from a plane
// before the nearest point (1% of the extent in front); rows of the
// world-to-map matrix (q.x, q.y across in [0, 1], q.z the depth) and the
// square's side.
struct OrthographicFit
{
  Vec3 Right, Up, Axis, Origin;
  double Side = 1;
};

OrthographicFit FitAcross(const std::vector<Vec3>& points, const Vec3& direction, int size)
{
  OrthographicFit fit;
  fit.Axis = normalize(direction);
  fit.Right = Across(fit.Axis);
  fit.Up = cross(fit.Axis, fit.Right);
  Vec3 lo{ HUGE_VAL, HUGE_VAL, HUGE_VAL }, hi{ -HUGE_VAL, -HUGE_VAL, -HUGE_VAL };
  for (const Vec3& p : points)
  {
    const Vec3 q{ dot(p, fit.Right), dot(p, fit.Up), dot(p, fit.Axis) };
    for (int k = 0; k < 3; ++k)
    {
      lo[k] = std::min(lo[k], q[k]);
      hi[k] = std::max(hi[k], q[k]);
    }
  }
  if (points.empty())
  {
    lo = hi = Vec3{ 0, 0, 0 };
  }
  const double extent = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2] });
  const double across = std::max(hi[0] - lo[0], hi[1] - lo[1]);
  fit.Side = across > 0 ? across * size / (size - 2.0) : std::max(extent, 1.0);
  const double pad0 = (fit.Side - (hi[0] - lo[0])) / 2, pad1 = (fit.Side - (hi[1] - lo[1])) / 2;
  fit.Origin = (lo[0] - pad0) * fit.Right + (lo[1] - pad1) * fit.Up +
    (lo[2] - 0.01 * std::max(extent, 1e-300)) * fit.Axis;
  return fit;
}
}

ShadowMap::~ShadowMap() = default;

std::array<float, 4> ShadowMap::GetBias() const
{
  // Twice the texel's half diagonal: an angle (a cube face's widest
  // texels, at its centre, span 2/size) or a length.
  const double halfDiagonal = std::sqrt(2.0) / this->Size * (this->Cube ? 1 : this->Side / 2);
  return { static_cast<float>(RoundingBias), static_cast<float>(SlopeTexels * halfDiagonal),
    static_cast<float>(SlopeLimit), static_cast<float>(this->Size) };
}

std::string ShadowMap::Bake(const std::vector<Vec3>& points,
  const std::vector<TriangleCorners>& triangles, const Light& light, int size)
{
  this->Size = size;
  this->Cube = GeometryOf(light.Kind).Position;
  if (!this->Program)
  {
    const GLuint vertex = glCreateShader(GL_VERTEX_SHADER);
    const GLuint fragment = glCreateShader(GL_FRAGMENT_SHADER);
    std::string error = Compile(vertex, CasterVertex);
    error += Compile(fragment, CasterFragment);
    this->Program = glCreateProgram();
    glAttachShader(this->Program, vertex);
    glAttachShader(this->Program, fragment);
    glBindFragDataLocation(this->Program, 0, "distance");
    glLinkProgram(this->Program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    if (!error.empty())
    {
      return "shadow map caster: " + error;
    }
    glGenVertexArrays(1, &this->VertexArray);
    glGenBuffers(1, &this->Buffer);
    glGenFramebuffers(1, &this->Framebuffer);
  }
  // A new texture for each bake: a cube and a 2D map cannot share a name.
  if (this->Texture)
  {
    glDeleteTextures(1, &this->Texture);
  }
  glGenTextures(1, &this->Texture);

  // The map's origin and matrices, in double.
  Vec3 origin = light.Position, axis{ 0, 0, 0 };
  std::array<double, 16>& m = this->WorldToMap;
  float orthographic[16] = {};
  if (this->Cube)
  {
    m = { 1, 0, 0, -origin[0], 0, 1, 0, -origin[1], 0, 0, 1, -origin[2], 0, 0, 0, 1 };
  }
  else
  {
    const OrthographicFit fit = FitAcross(points, light.Direction, size);
    origin = fit.Origin;
    axis = fit.Axis;
    this->Side = fit.Side;
    const Vec3 rows[3] = { (1 / fit.Side) * fit.Right, (1 / fit.Side) * fit.Up, fit.Axis };
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        m[r * 4 + c] = rows[r][c];
        // Clip x, y = 2q - 1 of the vertex relative to the origin.
        if (r < 2)
        {
          orthographic[c * 4 + r] = static_cast<float>(2 * rows[r][c]);
        }
      }
      m[r * 4 + 3] = -dot(rows[r], origin);
    }
    m[12] = m[13] = m[14] = 0;
    m[15] = 1;
    orthographic[12] = orthographic[13] = -1;
    orthographic[15] = 1;
  }

  const GLenum target = this->Cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D;
  GLint bound = 0;
  glGetIntegerv(this->Cube ? GL_TEXTURE_BINDING_CUBE_MAP : GL_TEXTURE_BINDING_2D, &bound);
  glBindTexture(target, this->Texture);
  // Earlier calls' errors are not the map's (a bounded drain: a lost
  // context reports its loss again and again).
  for (int k = 0; k < 16 && glGetError() != GL_NO_ERROR; ++k)
  {
  }
  for (int f = 0; f < (this->Cube ? 6 : 1); ++f)
  {
    glTexImage2D(this->Cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + f : GL_TEXTURE_2D, 0, GL_R32F, size,
      size, 0, GL_RED, GL_FLOAT, nullptr);
  }
  if (glGetError() == GL_OUT_OF_MEMORY)
  {
    glBindTexture(target, static_cast<GLuint>(bound));
    glDeleteTextures(1, &this->Texture);
    this->Texture = 0;
    const double mib = 4.0 * size * size * (this->Cube ? 6 : 1) / (1 << 20);
    return "--shadow-map-size " + std::to_string(size) + ": OpenGL has no memory for a " +
      std::to_string(static_cast<long long>(mib)) + " MiB shadow map";
  }
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(target, GL_TEXTURE_MAX_LEVEL, 0);
  glBindTexture(target, static_cast<GLuint>(bound));

  std::vector<float> relative;
  relative.reserve(triangles.size() * 9);
  for (const TriangleCorners& t : triangles)
  {
    for (const std::int64_t p : t)
    {
      const Vec3 d = points[p] - origin; // in double, then rounded once
      relative.insert(relative.end(),
        { static_cast<float>(d[0]), static_cast<float>(d[1]), static_cast<float>(d[2]) });
    }
  }
  const SavedState saved; // everything as it was afterwards: VTK keeps its own record

  glBindVertexArray(this->VertexArray);
  glBindBuffer(GL_ARRAY_BUFFER, this->Buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(relative.size() * sizeof(float)),
    relative.data(), GL_STATIC_DRAW);
  const GLint attribute = glGetAttribLocation(this->Program, "relative");
  glEnableVertexAttribArray(attribute);
  glVertexAttribPointer(attribute, 3, GL_FLOAT, GL_FALSE, 0, nullptr);

  glBindFramebuffer(GL_FRAMEBUFFER, this->Framebuffer);
  glUseProgram(this->Program);
  glUniform1i(glGetUniformLocation(this->Program, "radial"), this->Cube ? 1 : 0);
  const float axisF[3] = { static_cast<float>(axis[0]), static_cast<float>(axis[1]),
    static_cast<float>(axis[2]) };
  glUniform3fv(glGetUniformLocation(this->Program, "axis"), 1, axisF);
  glViewport(0, 0, size, size);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glEnable(GL_DEPTH_CLAMP);
  // The nearest surface wins: MIN over every fragment, no depth buffer.
  glEnable(GL_BLEND);
  glBlendEquation(GL_MIN);
  glBlendFunc(GL_ONE, GL_ONE);
  glClearColor(FLT_MAX, 0, 0, 0);
  std::string error;
  for (int f = 0; f < (this->Cube ? 6 : 1); ++f)
  {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
      this->Cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + f : GL_TEXTURE_2D, this->Texture, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    {
      error = "shadow map: the framebuffer is incomplete";
      break;
    }
    glClear(GL_COLOR_BUFFER_BIT);
    float projection[16];
    if (this->Cube)
    {
      FaceProjection(f, projection);
    }
    else
    {
      std::copy(orthographic, orthographic + 16, projection);
    }
    glUniformMatrix4fv(
      glGetUniformLocation(this->Program, "faceProjection"), 1, GL_FALSE, projection);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(relative.size() / 3));
  }
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
  return error;
}

std::vector<float> ShadowMap::ReadFace(int face) const
{
  std::vector<float> texels(static_cast<std::size_t>(this->Size) * this->Size);
  glBindTexture(this->Cube ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D, this->Texture);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(this->Cube ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + face : GL_TEXTURE_2D, 0, GL_RED,
    GL_FLOAT, texels.data());
  return texels;
}

void ShadowMap::Release()
{
  if (this->Program)
  {
    glDeleteProgram(this->Program);
    glDeleteVertexArrays(1, &this->VertexArray);
    glDeleteBuffers(1, &this->Buffer);
    glDeleteFramebuffers(1, &this->Framebuffer);
    glDeleteTextures(1, &this->Texture);
    this->Program = this->VertexArray = this->Buffer = this->Framebuffer = this->Texture = 0;
  }
}
}
