#include "shadelabShaderSource.h"

#include "shadelabIlluminateSource.h"

#include <string>

namespace shadelab
{
const char* const FaceNormalArrayName = "shadelabFaceNormal";
const char* const FaceNormalAttributeName = "shadelabFaceNormalMC";
const char* const VertexKdAttributeName = "shadelabVertexKd";
const char* const TextureCoordinateAttributeName = "shadelabTCoord";
const char* const TextureSamplerName = "shadelabTexture";
const char* const TermMarker = "// shadelab: ";

bool ShaderFeatures::operator==(const ShaderFeatures& o) const
{
  return this->Rule == o.Rule && this->Model == o.Model && this->Lights == o.Lights &&
    this->Specular == o.Specular && this->VertexKd == o.VertexKd &&
    this->KdTexture == o.KdTexture && this->KaTexture == o.KaTexture &&
    this->KsTexture == o.KsTexture && this->AllFeatures == o.AllFeatures;
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

// The texture coordinates, passed to the fragment (interpolated with
// perspective, as OpenGL does), the sampler and the texel.
void AddTexelLookup(std::vector<ShaderReplacement>& r)
{
  Prepend(r, true, "//VTK::Light::Dec",
    std::string("in vec2 ") + TextureCoordinateAttributeName +
      ";\nout vec2 shadelabTCoordVSOutput;\n");
  Prepend(r, true, "//VTK::Light::Impl",
    std::string("  shadelabTCoordVSOutput = ") + TextureCoordinateAttributeName + ";\n");
  Prepend(r, false, "//VTK::Light::Dec",
    std::string("uniform sampler2D ") + TextureSamplerName +
      ";\nin vec2 shadelabTCoordVSOutput;\n");
  Prepend(r, false, "//VTK::Light::Impl", TexelSource);
}

// Per-vertex kd for the fragment stage (none, phong): the vertex stage
// passes the attribute on, interpolated.
void AddVertexKdPassing(std::vector<ShaderReplacement>& r)
{
  r.push_back({ true, "//VTK::Light::Dec",
    std::string("in vec4 ") + VertexKdAttributeName + ";\nout vec3 shadelabKdVSOutput;\n" });
  r.push_back({ true, "//VTK::Light::Impl",
    std::string("  shadelabKdVSOutput = ") + VertexKdAttributeName + ".rgb;\n" });
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
std::string ApartOutputs(const std::string& qualifier, const char* direction)
{
  std::string s;
  for (const char* name : { "FrontDiffuse", "FrontSpecular", "BackDiffuse", "BackSpecular" })
  {
    s += qualifier + direction + " vec3 shadelab" + name + ";\n";
  }
  return s;
}

std::string PickApartByFacing(const ShaderFeatures& f)
{
  return std::string(
           R"glsl(  vec3 shadelabDiffuse = gl_FrontFacing ? shadelabFrontDiffuse : shadelabBackDiffuse;
  vec3 shadelabSpecular = gl_FrontFacing ? shadelabFrontSpecular : shadelabBackSpecular;
  fragOutput0 = vec4()glsl") +
    (f.KaTexture ? "shadelabKa * shadelabTexel * shadelabIa" : "shadelabKa * shadelabIa") +
    (f.KdTexture ? " + shadelabTexel * shadelabDiffuse" : " + shadelabDiffuse") +
    (f.KsTexture ? std::string(" + (") + TexelKsSource + ") * shadelabSpecular"
                 : std::string(" + shadelabSpecular")) +
    ", 1.0); // shadelab: ambient, diffuse, specular\n";
}

// Flat and Gouraud: lit per vertex (flat by the face normal attribute), the
// fragment picks the side it faces.
void AddVertexLit(const ShaderFeatures& f, std::vector<ShaderReplacement>& r)
{
  const bool flat = f.Rule == Shading::Flat;
  const bool apart = f.Textured();
  const std::string qualifier = flat ? "flat " : "";
  std::string declarations = IlluminateSource(f) +
    (apart ? ApartOutputs(qualifier, "out")
           : qualifier + "out vec3 shadelabFront;\n" + qualifier + "out vec3 shadelabBack;\n");
  if (flat)
  {
    declarations = std::string("in vec3 ") + FaceNormalAttributeName +
      ";\nuniform mat3 shadelabNormalMatrix;\n" + declarations;
  }
  std::string lighting = FillGlsl(apart ? VertexLightingApartSource : VertexLightingSource,
    flat ? std::string("shadelabNormalMatrix * ") + FaceNormalAttributeName
         : std::string("normalVCVSOutput"));
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
      ApartOutputs(qualifier, "in") + "uniform vec3 shadelabKa;\nuniform vec3 shadelabIa;\n" +
        (f.KsTexture ? TexelKsUniformsSource : "") + "//VTK::Light::Dec" });
    r.push_back({ false, "//VTK::Light::Impl", PickApartByFacing(f) });
    return;
  }
  r.push_back({ false, "//VTK::Light::Dec",
    qualifier + "in vec3 shadelabFront;\n" + qualifier +
      "in vec3 shadelabBack;\n//VTK::Light::Dec" });
  r.push_back({ false, "//VTK::Light::Impl", PickByFacingSource });
}

// Phong: lit per fragment by the interpolated normal.
void AddFragmentLit(const ShaderFeatures& f, std::vector<ShaderReplacement>& r)
{
  std::string declarations = IlluminateSource(f) + "//VTK::Light::Dec";
  std::string shade = ShadeFragmentSource;
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
  r.push_back({ false, "//VTK::Light::Dec", declarations });
  r.push_back({ false, "//VTK::UniformFlow::Impl", GeometricNormalSource });
  r.push_back({ false, "//VTK::Light::Impl", shade });
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
    case Shading::Gouraud:
      AddVertexLit(f, r);
      break;
    case Shading::Phong:
      AddFragmentLit(f, r);
      break;
  }
  if (f.ReadsTexel())
  {
    AddTexelLookup(r);
  }
  return r;
}
}
