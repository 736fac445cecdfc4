#include "shadelabTriangleFragment.h"

#include "shadelabVec3.h"

namespace shadelab
{
namespace
{
template <typename T, typename Get>
T Mix(const std::array<double, 3>& w, Get get)
{
  return w[0] * get(0) + w[1] * get(1) + w[2] * get(2);
}

// The terms of a vertex-lit rule with ka and kd times the texel: the
// ambient term and every light's diffuse term; with a ks texture, every
// light's specular term (lit with ks = 1) times the texel's ks.
void MultiplyByTexel(
  IlluminationTerms& terms, const SurfaceTexture& texture, const Rgb& texel, const Rgb& ks)
{
  if (texture.Ka)
  {
    terms.Ambient = terms.Ambient * texel;
  }
  for (LightTerms& light : terms.Lights)
  {
    if (texture.Kd)
    {
      light.DiffuseTerm = light.DiffuseTerm * texel;
    }
    if (texture.Ks)
    {
      light.SpecularTerm = light.SpecularTerm * ks;
    }
  }
  if (texture.Ks && terms.Environment)
  {
    terms.Environment->Term = terms.Environment->Term * ks;
  }
}
}

IlluminationTerms MixTerms(
  const std::array<IlluminationTerms, 3>& t, const std::array<double, 3>& w)
{
  IlluminationTerms mixed;
  mixed.P = Mix<Vec3>(w, [&](int k) { return t[k].P; });
  mixed.N = Mix<Vec3>(w, [&](int k) { return t[k].N; });
  mixed.V = Mix<Vec3>(w, [&](int k) { return t[k].V; });
  mixed.Ambient = Mix<Rgb>(w, [&](int k) { return t[k].Ambient; });
  for (std::size_t l = 0; l < t[0].Lights.size(); ++l)
  {
    const auto light = [&](int k) -> const LightTerms& { return t[k].Lights[l]; };
    LightTerms m;
    m.Reaches = light(0).Reaches || light(1).Reaches || light(2).Reaches;
    m.Lit = light(0).Lit || light(1).Lit || light(2).Lit;
    m.Shadowed = light(0).Shadowed || light(1).Shadowed || light(2).Shadowed;
    m.Specular = light(0).Specular || light(1).Specular || light(2).Specular;
    m.L = Mix<Vec3>(w, [&](int k) { return light(k).L; });
    m.HR = Mix<Vec3>(w, [&](int k) { return light(k).HR; });
    m.Il = Mix<Rgb>(w, [&](int k) { return light(k).Il; });
    m.DiffuseTerm = Mix<Rgb>(w, [&](int k) { return light(k).DiffuseTerm; });
    m.SpecularTerm = Mix<Rgb>(w, [&](int k) { return light(k).SpecularTerm; });
    m.SpotCos = Mix<double>(w, [&](int k) { return light(k).SpotCos; });
    m.SpotFactor = Mix<double>(w, [&](int k) { return light(k).SpotFactor; });
    m.NdotL = Mix<double>(w, [&](int k) { return light(k).NdotL; });
    m.Base = Mix<double>(w, [&](int k) { return light(k).Base; });
    m.Power = Mix<double>(w, [&](int k) { return light(k).Power; });
    mixed.Lights.push_back(m);
  }
  // The environment's term where any vertex has one (0 at a vertex with no
  // normal, which lights ambient only).
  if (t[0].Environment || t[1].Environment || t[2].Environment)
  {
    const auto reflected = [&](int k) { return t[k].Environment.value_or(EnvironmentTerm{}); };
    EnvironmentTerm e;
    e.R = Mix<Vec3>(w, [&](int k) { return reflected(k).R; });
    e.Direction = Mix<Vec3>(w, [&](int k) { return reflected(k).Direction; });
    e.TexCoord = { Mix<double>(w, [&](int k) { return reflected(k).TexCoord[0]; }),
      Mix<double>(w, [&](int k) { return reflected(k).TexCoord[1]; }) };
    e.Texel = Mix<Rgb>(w, [&](int k) { return reflected(k).Texel; });
    e.Term = Mix<Rgb>(w, [&](int k) { return reflected(k).Term; });
    mixed.Environment = e;
  }
  return mixed;
}

ShadedFragment ShadeTriangleFragment(
  const IlluminationInputs& material, Shading rule, const TriangleFragment& f)
{
  const auto& P = f.Positions;
  const auto& w = f.Weights;
  ShadedFragment s;
  s.Point = Mix<Vec3>(w, [&](int k) { return P[k]; });
  FaceNormal(P[0], P[1], P[2], s.FaceNormal);
  const SurfaceTexture& texture = material.Texture;
  if (texture.Used())
  {
    const auto& st = f.TexCoords;
    s.TexCoord = { Mix<double>(w, [&](int k) { return st[k][0]; }),
      Mix<double>(w, [&](int k) { return st[k][1]; }) };
    s.Texel = SampleTexture(texture.Map, (*s.TexCoord)[0], (*s.TexCoord)[1]);
    s.Ks = texture.TexelKs(material.Surface.Ks, *s.Texel);
  }
  const bool vertexLit = rule == Shading::Flat || rule == Shading::Gouraud;
  // Normal n (any length) perturbed at vertex k, where it lights.
  const auto mapped = [&](const Vec3& n, int k) -> std::optional<NormalMapping>
  {
    if (!material.NormalTexture || !UsableVertexNormal(n))
    {
      return std::nullopt;
    }
    return MapNormal(*material.NormalTexture, normalize(n), f.Tangents[k], f.TexCoords[k]);
  };
  // The inputs with vertex k's kd (the material's without VertexKd), and
  // ks = 1 where a vertex-lit rule's fragment multiplies by the texel's ks.
  const auto atVertex = [&](int k)
  {
    IlluminationInputs in = material;
    if (s.Texel && texture.Ks && vertexLit)
    {
      in.Surface.Ks = { 1, 1, 1 };
    }
    if (f.VertexKd)
    {
      in.Surface.Kd = (*f.VertexKd)[k];
    }
    return in;
  };
  IlluminationInputs in = atVertex(2); // flat's: the provoking vertex's
  if (f.VertexKd && rule != Shading::Flat)
  {
    in.Surface.Kd = Mix<Rgb>(w, [&](int k) { return (*f.VertexKd)[k]; });
  }
  const Rgb factorKd = in.Surface.Kd;
  if (s.Texel && !vertexLit)
  {
    in.Surface.Kd = texture.Kd ? in.Surface.Kd * *s.Texel : in.Surface.Kd;
    in.Surface.Ka = texture.Ka ? in.Surface.Ka * *s.Texel : in.Surface.Ka;
    in.Surface.Ks = *s.Ks;
  }
  s.Kd = s.Texel && texture.Kd ? factorKd * *s.Texel : factorKd;
  switch (rule)
  {
    case Shading::None:
      s.Color = in.Surface.Kd;
      return s;
    case Shading::Flat:
      s.Mapped = mapped(s.FaceNormal, 2);
      s.Terms = s.Mapped ? ShadeVertex(in, P[2], s.Mapped->Perturbed, f.Front)
                         : ShadeFlat(in, P[0], P[1], P[2], f.Front);
      if (s.Texel)
      {
        MultiplyByTexel(s.Terms, texture, *s.Texel, *s.Ks);
      }
      break;
    case Shading::Gouraud:
      for (int k = 0; k < 3; ++k)
      {
        s.VerticesMapped[k] = mapped(f.Normals[k], k);
        s.Vertices[k] = ShadeVertex(atVertex(k), P[k],
          s.VerticesMapped[k] ? s.VerticesMapped[k]->Perturbed : f.Normals[k], f.Front);
      }
      s.Terms = MixTerms(s.Vertices, w);
      if (s.Texel)
      {
        MultiplyByTexel(s.Terms, texture, *s.Texel, *s.Ks);
        s.Color = s.Terms.Total();
        return s;
      }
      s.Color = Mix<Rgb>(w, [&](int k) { return s.Vertices[k].Total(); });
      return s;
    case Shading::Raytrace: // its hits are lit as phong lights a fragment
    case Shading::Phong:
    {
      const Vec3 interpolated = Mix<Vec3>(w, [&](int k) { return f.Normals[k]; });
      const Vec3 geometric = f.Front ? s.FaceNormal : -s.FaceNormal; // towards the viewer
      s.FaceNormalFallback = !UsableInterpolatedNormal(interpolated);
      if (!s.FaceNormalFallback && material.NormalTexture)
      {
        const Tangent tangent{ Mix<double>(w, [&](int k) { return f.Tangents[k][0]; }),
          Mix<double>(w, [&](int k) { return f.Tangents[k][1]; }),
          Mix<double>(w, [&](int k) { return f.Tangents[k][2]; }),
          Mix<double>(w, [&](int k) { return f.Tangents[k][3]; }) };
        s.Mapped = MapNormal(*material.NormalTexture, normalize(interpolated), tangent,
          { Mix<double>(w, [&](int k) { return f.TexCoords[k][0]; }),
            Mix<double>(w, [&](int k) { return f.TexCoords[k][1]; }) });
      }
      s.Terms = ShadeFragment(
        in, s.Point, s.Mapped ? s.Mapped->Perturbed : interpolated, geometric, f.Front);
      break;
    }
  }
  s.Color = s.Terms.Total();
  return s;
}
}
