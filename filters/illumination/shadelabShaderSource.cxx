#include "shadelabShaderSource.h"

#include "shadelabIlluminateSource.h"
#include "shadelabMapSource.h"

#include <string>

namespace shadelab
{
const char* const FaceNormalSamplerName = "shadelabFaceNormals";
const char* const VertexKdAttributeName = "shadelabVertexKd";
const char* const TextureCoordinateAttributeName = "shadelabTCoord";
const char* const TextureSamplerName = "shadelabTexture";
const char* const TermMarker = "// shadelab: ";
const char* const ShadowMapSamplerName = "shadelabShadowMap";
const char* const ShadowFrameName = "shadelabShadowFrame";
const char* const ShadowBiasName = "shadelabShadowBias";
const char* const EnvironmentSamplerName = "shadelabEnvironment";
const char* const EnvironmentFrameName = "shadelabEnvironmentFrame";
const char* const NormalMapSamplerName = "shadelabNormalMap";
const char* const NormalScaleName = "shadelabNormalScale";
const char* const TangentAttributeName = "shadelabTangent";

bool ShaderFeatures::operator==(const ShaderFeatures& o) const
{
  return this->Rule == o.Rule && this->Model == o.Model && this->Lights == o.Lights &&
    this->Specular == o.Specular && this->Attenuation == o.Attenuation && this->Fog == o.Fog &&
    this->Translucent == o.Translucent && this->FogTowardsTransparent == o.FogTowardsTransparent &&
    this->Drawn == o.Drawn && this->VertexKd == o.VertexKd && this->KdTexture == o.KdTexture &&
    this->KaTexture == o.KaTexture && this->KsTexture == o.KsTexture &&
    this->AllFeatures == o.AllFeatures && this->BehindLines == o.BehindLines &&
    this->Shadows == o.Shadows && this->Form == o.Form && this->Environment == o.Environment &&
    this->NormalMap == o.NormalMap && this->BumpMap == o.BumpMap;
}

namespace
{
// Gouraud and flat: the vertex stage lights front (N) and back (-N); a
// normal of no usable length lights as ambient only (ShadeVertex). `$` is
// the normal.
const char* const VertexLightingSource = R"glsl(  {
    vec3 n = $;
    float len = length(n);
    if (len > shadelabTinyLength && !isinf(len))
    {
      shadelabFront = shadelabIlluminate(vertexVCVSOutput.xyz, n / len);
      shadelabBack = shadelabIlluminate(vertexVCVSOutput.xyz, -n / len);
    }
    else
    {
      shadelabFront = shadelabKa * shadelabIa; // shadelab: ambient
      shadelabBack = shadelabFront;
    }
  }
)glsl";

// The same, with a texel to come: the diffuse and specular sums apart
// (shadelabIlluminateApart); ka*Ia is the fragment's.
const char* const VertexLightingApartSource = R"glsl(  {
    vec3 n = $;
    float len = length(n);
    shadelabFrontDiffuse = vec3(0.0);
    shadelabFrontSpecular = vec3(0.0);
    shadelabBackDiffuse = vec3(0.0);
    shadelabBackSpecular = vec3(0.0);
    if (len > shadelabTinyLength && !isinf(len))
    {
      shadelabIlluminateApart(
        vertexVCVSOutput.xyz, n / len, shadelabFrontDiffuse, shadelabFrontSpecular);
      shadelabIlluminateApart(
        vertexVCVSOutput.xyz, -n / len, shadelabBackDiffuse, shadelabBackSpecular);
    }
  }
)glsl";

// Flat: the face normal of the fragment's triangle, in view coordinates.
// `$` is the buffer, one RGB float texel a triangle.
const char* const FaceNormalFetchSource = "  vec3 n = shadelabNormalMatrix * texelFetch($, "
                                          "gl_PrimitiveID).rgb;\n  float len = length(n);\n";

// Flat: the side the fragment faces, lit at the provoking vertex as the
// vertex stage lights Gouraud's vertices (VertexLightingSource).
const char* const FlatLightingSource =
  R"glsl(  vec3 shadelabLit = shadelabKa * shadelabIa; // shadelab: ambient
  if (len > shadelabTinyLength && !isinf(len))
  {
    shadelabLit = shadelabIlluminate(shadelabProvokingVC.xyz, gl_FrontFacing ? n / len : -n / len);
  }
  fragOutput0 = vec4(shadelabLit, 1.0);
)glsl";

// The same, the sums apart for the texel (VertexLightingApartSource).
const char* const FlatLightingApartSource = R"glsl(  vec3 shadelabDiffuse = vec3(0.0);
  vec3 shadelabSpecular = vec3(0.0);
  if (len > shadelabTinyLength && !isinf(len))
  {
    shadelabIlluminateApart(shadelabProvokingVC.xyz, gl_FrontFacing ? n / len : -n / len,
      shadelabDiffuse, shadelabSpecular);
  }
)glsl";

const char* const PickByFacingSource =
  "  fragOutput0 = vec4(gl_FrontFacing ? shadelabFront : shadelabBack, 1.0);\n";

// Derivatives need uniform control flow: taken where VTK takes them.
const char* const GeometricNormalSource =
  "  vec3 shadelabGeometricN = cross(dFdx(vertexVC.xyz), dFdy(vertexVC.xyz));\n";

// ShadeFragment: renormalise, fall back to the geometric normal (turned
// towards the viewer) when too short, flip for back faces. The fallback
// comes from derivatives of float view-space positions, so its direction is
// good to about ulp(camera distance)/pixel size.
const char* const ShadeFragmentSource = R"glsl(  vec3 shadelabN;
  float shadelabLength = length(normalVCVSOutput);
  if (shadelabLength > 1e-6 && !isinf(shadelabLength))
  {
    shadelabN = normalVCVSOutput / shadelabLength;
    if (!gl_FrontFacing)
    {
      shadelabN = -shadelabN;
    }
  }
  else
  {
    shadelabN = normalize(shadelabGeometricN);
    vec3 towardsViewer = shadelabOrthographic == 1 ? vec3(0.0, 0.0, 1.0) : -vertexVC.xyz;
    if (dot(shadelabN, towardsViewer) < 0.0)
    {
      shadelabN = -shadelabN;
    }
  }
  fragOutput0 = vec4(shadelabIlluminate(vertexVC.xyz, shadelabN), 1.0);
)glsl";

// Edges and points (ShaderFeatures::Drawn): a line or a point has no
// facing (gl_FrontFacing is true for them), so the normal that lights is
// turned towards the viewer, as a back face's is (ShadeElementFragment).
const char* const TowardsViewerSource = R"glsl(vec3 shadelabTowardsViewer(vec3 n, vec3 p)
{
  vec3 v = shadelabOrthographic == 1 ? vec3(0.0, 0.0, 1.0) : -p;
  return dot(n, v) < 0.0 ? -n : n;
}
)glsl";

// Phong for edges and points: the interpolated normal turned towards the
// viewer; one of no usable length lights ka*Ia alone (no face to fall back to).
const char* const ShadeElementFragmentSource =
  R"glsl(  vec3 shadelabLit = shadelabKa * shadelabIa; // shadelab: ambient
  float shadelabLength = length(normalVCVSOutput);
  if (shadelabLength > 1e-6 && !isinf(shadelabLength))
  {
    shadelabLit = shadelabIlluminate(
      vertexVC.xyz, shadelabTowardsViewer(normalVCVSOutput, vertexVC.xyz) / shadelabLength);
  }
  fragOutput0 = vec4(shadelabLit, 1.0);
)glsl";

// The texel that multiplies kd and ka, per fragment under every rule.
const char* const TexelSource =
  "  vec3 shadelabTexel = texture(shadelabTexture, shadelabTCoordVSOutput).rgb;\n";

// ks at the fragment's texel (ShaderFeatures::KsTexture).
const char* const TexelKsSource = "shadelabKsFactor + shadelabKsScale * (shadelabTexel - 1.0)";
const char* const TexelKsUniformsSource =
  "uniform vec3 shadelabKsFactor;\nuniform vec3 shadelabKsScale;\n";

// `code` before what replaces tag in that stage, or the replacement itself:
// each (stage, tag) is one replacement, since a second would overwrite it.
void Prepend(
  std::vector<ShaderReplacement>& r, bool vertex, const std::string& tag, const std::string& code)
{
  for (ShaderReplacement& existing : r)
  {
    if (existing.Vertex == vertex && existing.Tag == tag)
    {
      existing.Code = code + existing.Code;
      return;
    }
  }
  r.push_back({ vertex, tag, code });
}

// The equation's functions for the stage that lights, and for edges and
// points (and phong's shadow slope, shadelabFaceN) the turn towards the viewer.
std::string LitSource(const ShaderFeatures& f)
{
  return IlluminateSource(f) +
    (f.Drawn != Representation::Surface || f.SlopesByFace() ? TowardsViewerSource : "");
}

// The texture coordinates for the vertex stage; passed to the fragment
// (interpolated with perspective, as OpenGL does) where it reads them; the
// texture's sampler and texel where it reads a texel.
void AddTexCoords(std::vector<ShaderReplacement>& r, bool passed, bool texel)
{
  Prepend(r, true, "//VTK::Light::Dec",
    std::string("in vec2 ") + TextureCoordinateAttributeName + ";\n" +
      (passed ? "out vec2 shadelabTCoordVSOutput;\n" : ""));
  if (passed)
  {
    Prepend(r, true, "//VTK::Light::Impl",
      std::string("  shadelabTCoordVSOutput = ") + TextureCoordinateAttributeName + ";\n");
    Prepend(r, false, "//VTK::Light::Dec",
      (texel ? std::string("uniform sampler2D ") + TextureSamplerName + ";\n" : std::string()) +
        "in vec2 shadelabTCoordVSOutput;\n");
  }
  if (texel)
  {
    Prepend(r, false, "//VTK::Light::Impl", TexelSource);
  }
}

// ShaderFeatures::NormalMap, the line that perturbs unit normal `n` with
// tangent `t` (in view coordinates) of handedness `w` at texture coordinates
// `st`, marked as f's map.
std::string MapNormalLine(const ShaderFeatures& f, const std::string& indent,
  const std::string& target, const std::string& n, const std::string& t, const std::string& w,
  const std::string& st)
{
  return indent + target + " = shadelabMapNormal(" + n + ", " + t + ", " + w + ", " + st +
    "); // shadelab: " + ReliefMark(f.BumpMap) + "\n";
}

// Phong: the tangents to the fragment, in view coordinates (the normal's
// matrix: the camera's rotation), interpolated as the normals are.
void AddTangentPassing(std::vector<ShaderReplacement>& r)
{
  Prepend(r, true, "//VTK::Light::Dec",
    std::string("in vec4 ") + TangentAttributeName + ";\nout vec4 shadelabTangentVCVSOutput;\n");
  Prepend(r, true, "//VTK::Light::Impl",
    std::string("  shadelabTangentVCVSOutput = vec4(normalMatrix * ") + TangentAttributeName +
      ".xyz, " + TangentAttributeName + ".w);\n");
  Prepend(r, false, "//VTK::Light::Dec", "in vec4 shadelabTangentVCVSOutput;\n");
}

// Gouraud: the vertex's unit normal n / len perturbed before it lights
// front and back (VertexLightingSource and its sums apart).
std::string WithVertexNormalMapped(const ShaderFeatures& f, const std::string& lighting)
{
  const std::string opening = "    if (len > shadelabTinyLength && !isinf(len))\n    {\n";
  const std::size_t at = lighting.find(opening) + opening.size();
  std::string rest = lighting.substr(at);
  for (std::size_t p = rest.find("n / len"); p != std::string::npos; p = rest.find("n / len", p))
  {
    rest.replace(p, 7, "shadelabMappedN");
  }
  return lighting.substr(0, at) +
    MapNormalLine(f, "      ", "vec3 shadelabMappedN", "n / len",
      std::string("normalMatrix * ") + TangentAttributeName + ".xyz",
      TangentAttributeName + std::string(".w"), TextureCoordinateAttributeName) +
    rest;
}

// Per-vertex kd for the fragment stage: the vertex stage passes the
// attribute on, interpolated (none, phong) or the provoking vertex's
// (qualifier "flat ").
void AddVertexKdPassing(std::vector<ShaderReplacement>& r, const std::string& qualifier = "")
{
  Prepend(r, true, "//VTK::Light::Dec",
    std::string("in vec4 ") + VertexKdAttributeName + ";\n" + qualifier +
      "out vec3 shadelabKdVSOutput;\n");
  Prepend(r, true, "//VTK::Light::Impl",
    std::string("  shadelabKdVSOutput = ") + VertexKdAttributeName + ".rgb;\n");
}

// No shading: the diffuse colour as it is.
void AddUnlit(const ShaderFeatures& f, std::vector<ShaderReplacement>& r)
{
  r.push_back({ false, "//VTK::UniformFlow::Impl", "" });
  if (f.VertexKd)
  {
    AddVertexKdPassing(r);
    r.push_back({ false, "//VTK::Light::Dec", "in vec3 shadelabKdVSOutput;\n//VTK::Light::Dec" });
    r.push_back({ false, "//VTK::Light::Impl",
      f.KdTexture ? "  fragOutput0 = vec4(shadelabKdVSOutput * shadelabTexel, 1.0);\n"
                  : "  fragOutput0 = vec4(shadelabKdVSOutput, 1.0);\n" });
    return;
  }
  r.push_back({ false, "//VTK::Light::Dec", "uniform vec3 shadelabKd;\n//VTK::Light::Dec" });
  r.push_back({ false, "//VTK::Light::Impl",
    f.KdTexture ? "  fragOutput0 = vec4(shadelabKd * shadelabTexel, 1.0);\n"
                : "  fragOutput0 = vec4(shadelabKd, 1.0);\n" });
}

// With a texture, the vertex stage's sums apart (VertexLightingApartSource)
// and the fragment's equation: ka*Ia, the diffuse sum and the specular sum,
// the first two times the texel where it is ka's and kd's.
std::string ApartOutputs(const char* direction)
{
  std::string s;
  for (const char* name : { "FrontDiffuse", "FrontSpecular", "BackDiffuse", "BackSpecular" })
  {
    s += std::string(direction) + " vec3 shadelab" + name + ";\n";
  }
  return s;
}

// The fragment's colour from the sums apart: ka*Ia, the diffuse sum and the
// specular sum, each times the texel where it is that coefficient's.
std::string ApartEquation(const ShaderFeatures& f)
{
  return std::string("  fragOutput0 = vec4(") +
    (f.KaTexture ? "shadelabKa * shadelabTexel * shadelabIa" : "shadelabKa * shadelabIa") +
    (f.KdTexture ? " + shadelabTexel * shadelabDiffuse" : " + shadelabDiffuse") +
    (f.KsTexture ? std::string(" + (") + TexelKsSource + ") * shadelabSpecular"
                 : std::string(" + shadelabSpecular")) +
    ", 1.0); // shadelab: ambient, diffuse, specular\n";
}

std::string PickApartByFacing(const ShaderFeatures& f)
{
  return std::string(
           R"glsl(  vec3 shadelabDiffuse = gl_FrontFacing ? shadelabFrontDiffuse : shadelabBackDiffuse;
  vec3 shadelabSpecular = gl_FrontFacing ? shadelabFrontSpecular : shadelabBackSpecular;
)glsl") +
    ApartEquation(f);
}

// Gouraud: lit per vertex, the fragment picks the side it faces.
void AddVertexLit(const ShaderFeatures& f, std::vector<ShaderReplacement>& r)
{
  const bool apart = f.Textured();
  std::string declarations = LitSource(f) +
    (apart ? ApartOutputs("out") : "out vec3 shadelabFront;\nout vec3 shadelabBack;\n");
  std::string lighting = FillGlsl(apart ? VertexLightingApartSource : VertexLightingSource,
    f.Drawn == Representation::Surface
      ? "normalVCVSOutput"
      : "shadelabTowardsViewer(normalVCVSOutput, vertexVCVSOutput.xyz)");
  if (f.MapsNormals())
  {
    lighting = WithVertexNormalMapped(f, lighting);
    declarations = std::string("in vec4 ") + TangentAttributeName + ";\n" + declarations;
  }
  if (f.VertexKd)
  {
    declarations = std::string("in vec4 ") + VertexKdAttributeName + ";\n" + declarations;
    lighting = std::string("  shadelabKd = ") + VertexKdAttributeName + ".rgb;\n" + lighting;
  }
  r.push_back({ true, "//VTK::Light::Dec", declarations });
  r.push_back({ true, "//VTK::Light::Impl", lighting });
  r.push_back({ false, "//VTK::UniformFlow::Impl", "" });
  if (apart)
  {
    r.push_back({ false, "//VTK::Light::Dec",
      ApartOutputs("in") + "uniform vec3 shadelabKa;\nuniform vec3 shadelabIa;\n" +
        (f.KsTexture ? TexelKsUniformsSource : "") + "//VTK::Light::Dec" });
    r.push_back({ false, "//VTK::Light::Impl", PickApartByFacing(f) });
    return;
  }
  r.push_back({ false, "//VTK::Light::Dec",
    "in vec3 shadelabFront;\nin vec3 shadelabBack;\n//VTK::Light::Dec" });
  r.push_back({ false, "//VTK::Light::Impl", PickByFacingSource });
}

// Flat: the equation once per triangle, at its provoking vertex (GL's
// default, the last), with the face normal. The vertex stage passes the
// provoking vertex's view position (and kd) on unchanged (`flat`); the
// fragment reads its triangle's face normal by gl_PrimitiveID from a buffer
// texture (one RGB float texel a triangle) and lights the side it faces. Every fragment of
// a triangle computes the same value from the same inputs.
void AddFlatLit(const ShaderFeatures& f, std::vector<ShaderReplacement>& r)
{
  const bool apart = f.Textured();
  std::string declarations = LitSource(f) + "uniform samplerBuffer " + FaceNormalSamplerName +
    ";\nuniform mat3 shadelabNormalMatrix;\nflat in vec4 shadelabProvokingVC;\n";
  std::string shade;
  if (f.VertexKd)
  {
    declarations += "flat in vec3 shadelabKdVSOutput;\n";
    shade += "  shadelabKd = shadelabKdVSOutput;\n";
  }
  if (apart && f.KsTexture)
  {
    declarations += TexelKsUniformsSource;
  }
  shade += FillGlsl(FaceNormalFetchSource, FaceNormalSamplerName);
  if (f.MapsNormals())
  {
    declarations +=
      "flat in vec4 shadelabProvokingTangent;\nflat in vec2 shadelabProvokingTCoord;\n";
    shade += "  if (len > shadelabTinyLength && !isinf(len))\n  {\n" +
      MapNormalLine(f, "    ", "n", "n / len",
        "shadelabNormalMatrix * shadelabProvokingTangent.xyz", "shadelabProvokingTangent.w",
        "shadelabProvokingTCoord") +
      "    len = 1.0;\n  }\n";
  }
  shade += std::string(f.Drawn == Representation::Surface
               ? ""
               : "  n = shadelabTowardsViewer(n, shadelabProvokingVC.xyz);\n") +
    (apart ? FlatLightingApartSource : FlatLightingSource);
  if (apart)
  {
    shade += ApartEquation(f);
  }
  r.push_back({ true, "//VTK::Light::Dec",
    std::string("flat out vec4 shadelabProvokingVC;\n") +
      (f.MapsNormals() ? std::string("in vec4 ") + TangentAttributeName +
            ";\nflat out vec4 shadelabProvokingTangent;\nflat out vec2 shadelabProvokingTCoord;\n"
                       : "") });
  r.push_back({ true, "//VTK::Light::Impl",
    std::string("  shadelabProvokingVC = vertexVCVSOutput;\n") +
      (f.MapsNormals() ? std::string("  shadelabProvokingTangent = ") + TangentAttributeName +
            ";\n  shadelabProvokingTCoord = " + TextureCoordinateAttributeName + ";\n"
                       : "") });
  if (f.VertexKd)
  {
    AddVertexKdPassing(r, "flat ");
  }
  r.push_back({ false, "//VTK::UniformFlow::Impl", "" });
  r.push_back({ false, "//VTK::Light::Dec", declarations + "//VTK::Light::Dec" });
  r.push_back({ false, "//VTK::Light::Impl", shade });
}

// Phong: lit per fragment by the interpolated normal.
void AddFragmentLit(const ShaderFeatures& f, std::vector<ShaderReplacement>& r)
{
  const bool surface = f.Drawn == Representation::Surface;
  std::string declarations = LitSource(f) + "//VTK::Light::Dec";
  std::string shade = surface ? ShadeFragmentSource : ShadeElementFragmentSource;
  if (f.MapsNormals())
  {
    const std::string normalised = "    shadelabN = normalVCVSOutput / shadelabLength;\n";
    shade.insert(shade.find(normalised) + normalised.size(),
      MapNormalLine(f, "    ", "shadelabN", "shadelabN", "shadelabTangentVCVSOutput.xyz",
        "shadelabTangentVCVSOutput.w", "shadelabTCoordVSOutput"));
  }
  if (f.VertexKd)
  {
    AddVertexKdPassing(r);
    declarations = "in vec3 shadelabKdVSOutput;\n" + declarations;
    shade = (f.KdTexture ? "  shadelabKd = shadelabKdVSOutput * shadelabTexel;\n"
                         : "  shadelabKd = shadelabKdVSOutput;\n") +
      shade;
  }
  else if (f.KdTexture)
  {
    shade = "  shadelabKd = shadelabKdFactor * shadelabTexel;\n" + shade;
  }
  if (f.KaTexture)
  {
    shade = "  shadelabKa = shadelabKaFactor * shadelabTexel;\n" + shade;
  }
  if (f.KsTexture)
  {
    shade = std::string("  shadelabKs = ") + TexelKsSource + ";\n" + shade;
  }
  if (f.SlopesByFace())
  {
    shade =
      "  shadelabFaceN = shadelabTowardsViewer(normalize(shadelabGeometricN), vertexVC.xyz);\n" +
      shade;
  }
  r.push_back({ false, "//VTK::Light::Dec", declarations });
  r.push_back({ false, "//VTK::UniformFlow::Impl", surface ? GeometricNormalSource : "" });
  r.push_back({ false, "//VTK::Light::Impl", shade });
  if (f.MapsNormals())
  {
    AddTangentPassing(r); // after the stage's own declarations, which it prepends to
  }
}
}

namespace
{
// ShaderFeatures::Fog: after the rule's colour, per fragment (the oracle's
// FogFactor and Fogged, shadelabFog.cxx). vertexVC is the fragment's
// position in view coordinates, where the camera looks along -z.
std::string FogFactorSource(FogMode mode)
{
  switch (mode)
  {
    case FogMode::None:
      break;
    case FogMode::Linear:
      return "clamp((shadelabFogEnd - shadelabFogDepth) / (shadelabFogEnd - shadelabFogStart), "
             "0.0, 1.0)";
    case FogMode::Exp:
      return "exp(-shadelabFogDensity * shadelabFogDepth)";
    case FogMode::Exp2:
      return "exp(-(shadelabFogDensity * shadelabFogDepth) * (shadelabFogDensity * "
             "shadelabFogDepth))";
  }
  return "1.0";
}

void AddFog(FogMode mode, bool towardsTransparent, std::vector<ShaderReplacement>& r)
{
  Prepend(r, false, "//VTK::Light::Dec",
    std::string("uniform vec3 shadelabFogColor;\n") +
      (mode == FogMode::Linear ? "uniform float shadelabFogStart;\nuniform float shadelabFogEnd;\n"
                               : "uniform float shadelabFogDensity;\n"));
  for (ShaderReplacement& each : r)
  {
    if (!each.Vertex && each.Tag == "//VTK::Light::Impl")
    {
      each.Code += "  float shadelabFogDepth = -vertexVC.z; // shadelab: fog\n"
                   "  float shadelabFogFactor = " +
        FogFactorSource(mode) + "; // shadelab: fog\n" +
        (towardsTransparent ? "  fragOutput0.a *= shadelabFogFactor; // shadelab: fog\n"
                            : "  fragOutput0.rgb = shadelabFogFactor * fragOutput0.rgb + (1.0 - "
                              "shadelabFogFactor) * "
                              "shadelabFogColor; // shadelab: fog\n");
    }
  }
}

// ShaderFeatures::Translucent: the fragment's opacity, from VTK's colour
// code (its property's), before fog, which changes the colour alone.
void AddTranslucency(std::vector<ShaderReplacement>& r)
{
  for (ShaderReplacement& each : r)
  {
    if (!each.Vertex && each.Tag == "//VTK::Light::Impl")
    {
      each.Code += "  fragOutput0.a = opacity; // shadelab: translucency\n";
    }
  }
}

// ShaderFeatures::BehindLines. The slope is taken where VTK takes
// derivatives, in uniform control flow: appended to the rule's own code
// there (a second replacement of the tag would take the first's place).
void AddOffsetBehindLines(std::vector<ShaderReplacement>& r)
{
  for (ShaderReplacement& each : r)
  {
    if (!each.Vertex && each.Tag == "//VTK::UniformFlow::Impl")
    {
      each.Code += "  float shadelabDepthSlope = "
                   "length(vec2(dFdx(gl_FragCoord.z), dFdy(gl_FragCoord.z)));\n";
    }
  }
  r.push_back({ false, "//VTK::Depth::Impl",
    "  gl_FragDepth = gl_FragCoord.z + 2.0 * shadelabDepthSlope + 0.000032;\n" });
}
}

std::vector<ShaderReplacement> GenerateShaderReplacements(const ShaderFeatures& features)
{
  ShaderFeatures f = features;
  if (f.AllFeatures)
  {
    f.KdTexture = f.KaTexture = f.KsTexture = false; // the measuring baseline has no texture code
  }
  f.KsTexture = f.KsTexture && f.Specular; // no specular code, no ks to texture
  std::vector<ShaderReplacement> r;
  // The fragment stage never uses VTK's normal code or its derivative
  // normals: each rule below says what it needs instead.
  r.push_back({ false, "//VTK::Normal::Impl", "" });
  switch (f.Rule)
  {
    case Shading::None:
      AddUnlit(f, r);
      break;
    case Shading::Flat:
      AddFlatLit(f, r);
      break;
    case Shading::Gouraud:
      AddVertexLit(f, r);
      break;
    case Shading::Raytrace: // its hits are lit as phong lights a fragment
    case Shading::Phong:
      AddFragmentLit(f, r);
      break;
  }
  if (f.ReadsTexel() || f.MapsNormals())
  {
    AddTexCoords(r,
      f.ReadsTexel() || (f.MapsNormals() && f.Rule != Shading::Gouraud && f.Rule != Shading::Flat),
      f.ReadsTexel());
  }
  if (f.BehindLines)
  {
    AddOffsetBehindLines(r);
  }
  if (f.Translucent)
  {
    AddTranslucency(r);
  }
  if (f.Fog != FogMode::None)
  {
    AddFog(f.Fog, f.FogTowardsTransparent, r);
  }
  return r;
}
}
