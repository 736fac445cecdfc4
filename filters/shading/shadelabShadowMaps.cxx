#include "shadelabShadowMaps.h"

#include "shadelabVec3.h"

#include <vtk_glew.h>

#include <cfloat>
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
// The casters' program: each vertex relative to the light, the fragment's
// distance from it.
const char* const CasterVertex = "#version 150\n"
                                 "in vec3 relative;\n"
                                 "uniform mat4 faceProjection;\n"
                                 "out vec3 fromLight;\n"
                                 "void main()\n"
                                 "{\n"
                                 "  fromLight = relative;\n"
                                 "  gl_Position = faceProjection * vec4(relative, 1.0);\n"
                                 "}\n";
const char* const CasterFragment =
  "#version 150\n"
  "in vec3 fromLight;\n"
  "out vec4 distance;\n"
  "void main() { distance = vec4(length(fromLight), 0.0, 0.0, 1.0); }\n";

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
}

PointShadowMap::~PointShadowMap() = default;

std::string PointShadowMap::Bake(const std::vector<Vec3>& points,
  const std::vector<TriangleCorners>& triangles, const Vec3& light, int size)
{
  this->Size = size;
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
    glGenTextures(1, &this->Texture);
  }
  std::vector<float> relative;
  relative.reserve(triangles.size() * 9);
  for (const TriangleCorners& t : triangles)
  {
    for (const std::int64_t p : t)
    {
      const Vec3 d = points[p] - light; // in double, then rounded once
      relative.insert(relative.end(),
        { static_cast<float>(d[0]), static_cast<float>(d[1]), static_cast<float>(d[2]) });
    }
  }
  glBindVertexArray(this->VertexArray);
  glBindBuffer(GL_ARRAY_BUFFER, this->Buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(relative.size() * sizeof(float)),
    relative.data(), GL_STATIC_DRAW);
  const GLint attribute = glGetAttribLocation(this->Program, "relative");
  glEnableVertexAttribArray(attribute);
  glVertexAttribPointer(attribute, 3, GL_FLOAT, GL_FALSE, 0, nullptr);

  glBindTexture(GL_TEXTURE_CUBE_MAP, this->Texture);
  for (int f = 0; f < 6; ++f)
  {
    glTexImage2D(
      GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_R32F, size, size, 0, GL_RED, GL_FLOAT, nullptr);
  }
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);

  GLint framebuffer = 0, viewport[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  glGetIntegerv(GL_VIEWPORT, viewport);
  const GLboolean blend = glIsEnabled(GL_BLEND), depth = glIsEnabled(GL_DEPTH_TEST),
                  scissor = glIsEnabled(GL_SCISSOR_TEST), cull = glIsEnabled(GL_CULL_FACE);
  glBindFramebuffer(GL_FRAMEBUFFER, this->Framebuffer);
  glUseProgram(this->Program);
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
  for (int f = 0; f < 6; ++f)
  {
    glFramebufferTexture2D(
      GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, this->Texture, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    {
      error = "shadow map: the framebuffer is incomplete";
      break;
    }
    glClear(GL_COLOR_BUFFER_BIT);
    float m[16];
    FaceProjection(f, m);
    glUniformMatrix4fv(glGetUniformLocation(this->Program, "faceProjection"), 1, GL_FALSE, m);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(relative.size() / 3));
  }
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_DEPTH_CLAMP);
  (blend ? glEnable : glDisable)(GL_BLEND);
  (depth ? glEnable : glDisable)(GL_DEPTH_TEST);
  (scissor ? glEnable : glDisable)(GL_SCISSOR_TEST);
  (cull ? glEnable : glDisable)(GL_CULL_FACE);
  glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(framebuffer));
  glUseProgram(0);
  glBindVertexArray(0);
  return error;
}

std::vector<float> PointShadowMap::ReadFace(int face) const
{
  std::vector<float> texels(static_cast<std::size_t>(this->Size) * this->Size);
  glBindTexture(GL_TEXTURE_CUBE_MAP, this->Texture);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, GL_RED, GL_FLOAT, texels.data());
  return texels;
}

void PointShadowMap::Release()
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
