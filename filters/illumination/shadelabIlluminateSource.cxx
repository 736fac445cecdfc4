#include "shadelabIlluminateSource.h"

#include "shadelabMapSource.h"

#include <algorithm>
#include <string>

namespace shadelab
{
std::string FillGlsl(const char* text, const std::string& value)
{
  std::string filled;
  for (const char* c = text; *c; ++c)
  {
    if (*c == '$')
    {
      filled += value;
    }
    else
    {
      filled += *c;
    }
  }
  return filled;
}

namespace
{
bool Has(const ShaderFeatures& f, LightKind kind)
{
  return std::find(f.Lights.begin(), f.Lights.end(), kind) != f.Lights.end();
}

// Point and spot lights have a position; directional and spot a direction.
bool HasPositions(const ShaderFeatures& f)
{
  return Has(f, LightKind::Point) || Has(f, LightKind::Spot);
}

bool HasDirections(const ShaderFeatures& f)
{
  return Has(f, LightKind::Directional) || Has(f, LightKind::Spot);
}

// Distance attenuation, compiled in where a light has it (the oracle's
// LightAt).
const char* const AttenuationSource = R"glsl(uniform vec3 shadelabLightAttenuation[$];
// 1 / (C0 + C1*d + C2*d^2): a point or spot light's fall-off at distance d.
float shadelabAttenuation(vec3 c, float d)
{
  return 1.0 / (c.x + d * (c.y + d * c.z));
}
)glsl";

// The shadow bias's slope factor (shadelabShadowMaps.h): 1 + tan(angle of
// incidence), the tangent at most `most` (and `most` for a face turned
// from the light), for a receiver that slopes across the texel (the 1 for a
// normal that leans off the surface).
const char* const ShadowSlopeSource = R"glsl(float shadelabShadowSlope(float slopeCos, float most)
{
  return 1.0 + (slopeCos > 0.0 ? min(sqrt(max(1.0 - slopeCos * slopeCos, 0.0)) / slopeCos, most) : most);
}
)glsl";

// Phong's slope is the face's (the map holds faces), from the fragment's
// geometric normal turned to the lit side; gouraud and flat light where no
// face is at hand (a vertex) or where N is the face's (a triangle).
const char* const FaceSlopeSource =
  "vec3 shadelabFaceN; // the face's unit normal, the viewer's side\n";

// Light $'s shadow test at P, the slope's cosine slopeCos: whether nothing lies nearer to
// the light than P in its map, within the bias (shadelabShadowMaps.h):
// x*(d + |P|) for float's roundings, and y times the slope factor (its
// tangent at most z); w, an orthographic map's size in texels. Point and
// spot lights: the distance from the light, in the cube map along P - light.
const char* const CubeShadowSource = R"glsl(uniform samplerCube shadelabShadowMap$;
uniform mat4 shadelabShadowFrame$; // view coordinates to the light's, axes the world's
uniform vec4 shadelabShadowBias$;
bool shadelabShadowLit$(vec3 P, float slopeCos)
{
  vec3 q = (shadelabShadowFrame$ * vec4(P, 1.0)).xyz;
  float d = length(q);
  vec4 b = shadelabShadowBias$;
  return d <= textureLod(shadelabShadowMap$, q, 0.0).r + b.x * (d + length(P)) + b.y * d * shadelabShadowSlope(slopeCos, b.z); // shadelab: shadow
}
)glsl";

// Directional lights: the map covers the mesh across the light's
// direction, q.xy in [0, 1] over it, q.z the depth along the direction;
// beyond it nothing casts.
const char* const OrthographicShadowSource = R"glsl(uniform sampler2D shadelabShadowMap$;
uniform mat4 shadelabShadowFrame$; // view coordinates to the map's
uniform vec4 shadelabShadowBias$;
bool shadelabShadowLit$(vec3 P, float slopeCos)
{
  vec3 q = (shadelabShadowFrame$ * vec4(P, 1.0)).xyz;
  vec4 b = shadelabShadowBias$;
  ivec2 texel = ivec2(floor(q.xy * b.w));
  if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(int(b.w)))))
  {
    return true;
  }
  return q.z <= texelFetch(shadelabShadowMap$, texel, 0).r + b.x * (abs(q.z) + length(P)) + b.y * shadelabShadowSlope(slopeCos, b.z); // shadelab: shadow
}
)glsl";

// Shared by the per-scene and the all-features code: the constants of the
// oracle's guards, its SpecularFalloff, and the view direction.
const char* const GuardSource = R"glsl(const float shadelabTinyLength = 1e-20;
const float shadelabGrazingLimit = 1e-5; // GrazingLimit in the oracle
)glsl";

const char* const SpecularFalloffSource = R"glsl(float shadelabSpecularFalloff(float d, float ns)
{
  if (d < 0.01)
  {
    return exp(-ns * d * (1.0 + d * (0.5 + d * (1.0 / 3.0 + d * 0.25))));
  }
  return pow(1.0 - d, ns);
}
)glsl";

const char* const IlluminateHeadSource = R"glsl(vec3 shadelabIlluminate(vec3 P, vec3 N)
{
  vec3 I = shadelabKa * shadelabIa; // shadelab: ambient
)glsl";

const char* const ViewDirectionSource = R"glsl(  vec3 V = vec3(0.0, 0.0, 1.0);
  if (shadelabOrthographic == 0)
  {
    float len = length(P);
    V = len > shadelabTinyLength ? -P / len : vec3(0.0);
  }
)glsl";

// The material's uniforms: ks and ns only where there is specular code; kd
// per vertex is a variable that the stage sets before lighting, and so are
// kd and ka where this stage multiplies them by a texel (phong's), each
// from its factor.
std::string MaterialUniforms(
  bool specular, bool vertexKd, bool texelKd, bool texelKa, const char* ksTexture = nullptr)
{
  std::string s = texelKa ? "uniform vec3 shadelabKaFactor;\nvec3 shadelabKa; // per fragment: the "
                            "factor times the texel\n"
                          : "uniform vec3 shadelabKa;\n";
  s += vertexKd ? "vec3 shadelabKd; // per vertex\n"
    : texelKd   ? "uniform vec3 shadelabKdFactor;\nvec3 shadelabKd; // per fragment: the factor "
                  "times the texel\n"
                : "uniform vec3 shadelabKd;\n";
  if (specular)
  {
    s += (ksTexture ? ksTexture : "uniform vec3 shadelabKs;\n") +
      std::string("uniform float shadelabNs;\n");
  }
  return s + R"glsl(uniform vec3 shadelabIa;
uniform int shadelabOrthographic;
)glsl";
}

// The arrays of n lights' properties, those that the lights' kinds use.
std::string LightUniforms(size_t n, bool positions, bool directions, bool spots)
{
  const std::string size = std::to_string(n);
  std::string s = FillGlsl("uniform vec3 shadelabLightColor[$];\n", size);
  if (positions)
  {
    s += FillGlsl("uniform vec3 shadelabLightPosition[$];\n", size);
  }
  if (directions)
  {
    s += FillGlsl("uniform vec3 shadelabLightDirection[$];\n", size);
  }
  if (spots)
  {
    s += FillGlsl(R"glsl(uniform float shadelabLightCosCutoff[$];
uniform float shadelabLightExponent[$];
)glsl",
      size);
  }
  return s;
}

// The all-features baseline's loop over the lights, chosen at run time
// (kinds 0 point, 1 directional, 2 spot; reflection 0 Blinn, 1 Phong).
const char* const AllFeaturesLightLoopSource = R"glsl(  for (int i = 0; i < shadelabLightCount; ++i)
  {
    vec3 Il = shadelabLightColor[i];
    vec3 L = -shadelabLightDirection[i];
    bool lit = true;
    if (shadelabLightKind[i] != 1)
    {
      vec3 toLight = shadelabLightPosition[i] - P;
      float distance = length(toLight);
      lit = distance > shadelabTinyLength;
      L = toLight / max(distance, shadelabTinyLength);
      if (shadelabLightKind[i] == 2)
      {
        float cosAngle = dot(-L, shadelabLightDirection[i]);
        float e = shadelabLightExponent[i];
        lit = lit && cosAngle >= shadelabLightCosCutoff[i];
        Il *= e == 0.0 ? 1.0 : (cosAngle > 0.0 ? pow(cosAngle, e) : 0.0);
      }
    }
    float NdotL = dot(N, L);
    if (lit && NdotL > shadelabGrazingLimit)
    {
      vec3 term = NdotL * shadelabKd; // shadelab: diffuse
      float d = -1.0;
      if (shadelabReflection == 0)
      {
        vec3 sum = L + V;
        float len = length(sum);
        vec3 H = sum / max(len, shadelabTinyLength);
        d = len > shadelabTinyLength && dot(N, H) > 0.0 ? 0.5 * dot(N - H, N - H) : -1.0; // shadelab: specular
      }
      else
      {
        vec3 R = (2.0 * NdotL) * N - L;
        d = dot(V, R) > 0.0 ? 0.5 * dot(V - R, V - R) : -1.0; // shadelab: specular
      }
      if (d >= 0.0)
      {
        term += shadelabSpecularFalloff(d, shadelabNs) * shadelabKs; // shadelab: specular
      }
      I += Il * term; // shadelab: diffuse, specular
    }
  }
  return I;
}
)glsl";

// The all-features baseline: the same equation for any lights, up to
// AllFeaturesMaxLights of them.
std::string AllFeaturesIlluminateSource(bool vertexKd)
{
  return MaterialUniforms(true, vertexKd, false, false) +
    FillGlsl(R"glsl(uniform int shadelabReflection;
uniform int shadelabLightCount;
uniform int shadelabLightKind[$];
)glsl",
      std::to_string(AllFeaturesMaxLights)) +
    LightUniforms(AllFeaturesMaxLights, true, true, true) + GuardSource + SpecularFalloffSource +
    IlluminateHeadSource + ViewDirectionSource + AllFeaturesLightLoopSource;
}

// The uniforms and constants of the per-scene code: only what its lights use.
std::string DeclarationsSource(const ShaderFeatures& f)
{
  const bool fragmentTexel = f.Rule == Shading::Phong;
  // A ks texture: phong's ks is the fragment's (ShaderFeatures::KsTexture),
  // flat's and gouraud's vertices light with 1 for the fragment to multiply.
  const char* ks = !f.KsTexture ? nullptr
    : fragmentTexel
    ? "uniform vec3 shadelabKsFactor;\nuniform vec3 shadelabKsScale;\nvec3 shadelabKs; // per "
      "fragment: the texel's\n"
    : "const vec3 shadelabKs = vec3(1.0); // the fragment multiplies by its texel's ks\n";
  std::string s = "// shadelab: the lecture's illumination model (shadelabShadingOracle.cxx)\n" +
    MaterialUniforms(
      f.Specular, f.VertexKd, fragmentTexel && f.KdTexture, fragmentTexel && f.KaTexture, ks);
  if (!f.Lights.empty())
  {
    s += LightUniforms(f.Lights.size(), HasPositions(f), HasDirections(f), Has(f, LightKind::Spot));
  }
  if (f.Attenuation)
  {
    s += FillGlsl(AttenuationSource, std::to_string(f.Lights.size()));
  }
  if (f.CastsShadows())
  {
    s += ShadowSlopeSource;
    if (f.SlopesByFace())
    {
      s += FaceSlopeSource;
    }
  }
  if (f.Reflects())
  {
    s += EnvironmentSource;
  }
  for (std::size_t i = 0; i < f.Shadows.size(); ++i)
  {
    if (f.Shadows[i])
    {
      s += FillGlsl(GeometryOf(f.Lights[i]).Position ? CubeShadowSource : OrthographicShadowSource,
        std::to_string(i));
    }
  }
  return s + GuardSource + (f.MapsNormals() ? ReliefSource(f.BumpMap) : std::string());
}

// The reflection model, compiled in: shadelabSpecularD, its head and its
// body for each model.
const char* const SpecularDHeadSource = R"glsl(
// d = 1 - cos of the specular angle, or -1 when there is no specular term.
float shadelabSpecularD(vec3 N, vec3 L, vec3 V)
{
)glsl";

const char* const BlinnPhongSpecularDBody = R"glsl(  vec3 sum = L + V;
  float len = length(sum);
  if (!(len > shadelabTinyLength))
  {
    return -1.0;
  }
  vec3 H = sum / len;
  return dot(N, H) > 0.0 ? 0.5 * dot(N - H, N - H) : -1.0;
}
)glsl";

const char* const PhongSpecularDBody = R"glsl(  vec3 R = (2.0 * dot(N, L)) * N - L;
  return dot(V, R) > 0.0 ? 0.5 * dot(V - R, V - R) : -1.0;
}
)glsl";

// The specular part of a light's term, added to `term`, or apart to S
// (times Il): the stable form, 1 - cos without cancellation and its power
// by SpecularFalloff, or the lecture's expressions as written
// (SpecularForm::Literal), pow of the clamped base in the lecture's case.
std::string SpecularTermSource(const ShaderFeatures& f, bool apart)
{
  const std::string add = apart ? "S += Il * (" : "term += ";
  const std::string end = apart ? ")" : "";
  if (f.Form == SpecularForm::Stable)
  {
    return R"glsl(    d = shadelabSpecularD(N, L, V); // shadelab: specular
    if (d >= 0.0)
    {
      )glsl" +
      add + "shadelabSpecularFalloff(d, shadelabNs) * shadelabKs" + end +
      R"glsl(; // shadelab: specular
    }
)glsl";
  }
  const bool blinn = UsesHalfVector(f.Model);
  const std::string vector = blinn ? "H = normalize(L + V)" : "R = reflect(-L, N)";
  const std::string base = blinn ? "dot(N, H)" : "dot(V, R)";
  return "    vec3 " + vector + "; // shadelab: specular\n    if (" + base +
    " > 0.0) // the lecture's case: no specular term where the base is not positive\n    {\n" +
    "      " + add + "pow(max(" + base + ", 0.0), shadelabNs) * shadelabKs" + end +
    "; // shadelab: specular\n    }\n";
}

// Light i's term, unrolled: its kind's direction, distance attenuation
// (with `attenuation`), spot fall-off and guard, and `specular` code;
// apart, its diffuse and specular parts added to D and S.
std::string LightTermSource(size_t i, LightKind kind, const std::string& specular, bool attenuation,
  bool shadows, bool faceSlope, bool apart)
{
  const std::string index = std::to_string(i);
  std::string s = "  // light " + index + ": " + ToString(kind) + "\n" +
    FillGlsl("  Il = shadelabLightColor[$];\n", index);
  std::string guard;
  const LightGeometry g = GeometryOf(kind);
  if (!g.Position)
  {
    s += FillGlsl("  L = -shadelabLightDirection[$];\n", index);
  }
  else
  {
    s += FillGlsl(R"glsl(  toLight = shadelabLightPosition[$] - P;
  distance = length(toLight);
  L = toLight / max(distance, shadelabTinyLength);
)glsl",
      index);
    guard = "distance > shadelabTinyLength && ";
    if (attenuation)
    {
      s +=
        FillGlsl("  Il *= shadelabAttenuation(shadelabLightAttenuation[$], distance); // shadelab: "
                 "attenuation\n",
          index);
    }
  }
  if (g.Cone)
  {
    s += FillGlsl(R"glsl(  float cosAngle$ = dot(-L, shadelabLightDirection[$]);
  float exponent$ = shadelabLightExponent[$];
  Il *= exponent$ == 0.0 ? 1.0 : (cosAngle$ > 0.0 ? pow(cosAngle$, exponent$) : 0.0);
)glsl",
      index);
    guard += FillGlsl("cosAngle$ >= shadelabLightCosCutoff[$] && ", index);
  }
  // Whether the light reaches P: read where it would add a term.
  guard += "NdotL > shadelabGrazingLimit" +
    (shadows ? FillGlsl(faceSlope ? " && shadelabShadowLit$(P, dot(shadelabFaceN, L))"
                                  : " && shadelabShadowLit$(P, NdotL)",
                 index)
             : std::string());
  if (apart)
  {
    s += FillGlsl(R"glsl(  NdotL = dot(N, L);
  if ($)
  {
    D += Il * (NdotL * shadelabKd); // shadelab: diffuse
)glsl",
      guard);
    return s + specular + "  }\n";
  }
  s += FillGlsl(R"glsl(  NdotL = dot(N, L);
  if ($)
  {
    vec3 term = NdotL * shadelabKd; // shadelab: diffuse
)glsl",
    guard);
  return s + specular + R"glsl(    I += Il * term; // shadelab: diffuse, specular
  }
)glsl";
}

// A texel multiplies kd, ka or both per fragment while flat and gouraud
// light per vertex: the vertex stage keeps the equation's parts apart (the
// oracle's counterpart: MultiplyByTexel in shadelabTriangleFragment.cxx).
const char* const IlluminateApartHeadSource = R"glsl(
// The equation's parts, for the fragment to multiply by its texel:
// D = sum_l Il*kd*max(N.L, 0), S = sum_l Il*S_l (ka*Ia is the fragment's).
void shadelabIlluminateApart(vec3 P, vec3 N, out vec3 D, out vec3 S)
{
  D = vec3(0.0);
  S = vec3(0.0);
)glsl";

// The per-scene shadelabIlluminate (or, apart, shadelabIlluminateApart):
// the lights unrolled, each with the code of its kind only.
std::string IlluminateFunctionSource(const ShaderFeatures& f, bool apart)
{
  std::string s = apart ? std::string(IlluminateApartHeadSource)
                        : "\n// I = ka*Ia + sum_l Il*[kd*max(N.L, 0) + S_l], N unit.\n" +
      std::string(IlluminateHeadSource);
  if (!f.Lights.empty() || f.Reflects())
  {
    s += ViewDirectionSource;
  }
  if (!f.Lights.empty())
  {
    s += R"glsl(  vec3 L;
  vec3 Il;
  float NdotL;
)glsl";
    if (f.Specular && f.Form == SpecularForm::Stable)
    {
      s += "  float d;\n";
    }
    if (HasPositions(f))
    {
      s += R"glsl(  vec3 toLight;
  float distance;
)glsl";
    }
  }
  const std::string specular = f.Specular ? SpecularTermSource(f, apart) : "";
  for (size_t i = 0; i < f.Lights.size(); ++i)
  {
    s += LightTermSource(i, f.Lights[i], specular, f.Attenuation,
      i < f.Shadows.size() && f.Shadows[i], f.SlopesByFace(), apart);
  }
  if (f.Reflects())
  {
    s += std::string("  ") + (apart ? "S" : "I") +
      " += shadelabKs * shadelabEnvironmentAt((2.0 * dot(N, V)) * N - V); // shadelab: "
      "environment\n";
  }
  return s + (apart ? "}\n" : R"glsl(  return I;
}
)glsl");
}
}

std::string IlluminateSource(const ShaderFeatures& f)
{
  if (f.AllFeatures)
  {
    return AllFeaturesIlluminateSource(f.VertexKd);
  }
  std::string s = DeclarationsSource(f);
  if (f.Specular && f.Form == SpecularForm::Stable)
  {
    s += SpecularFalloffSource + std::string(SpecularDHeadSource) +
      (UsesHalfVector(f.Model) ? BlinnPhongSpecularDBody : PhongSpecularDBody);
  }
  return s + IlluminateFunctionSource(f, f.Rule != Shading::Phong && f.Textured());
}
}
