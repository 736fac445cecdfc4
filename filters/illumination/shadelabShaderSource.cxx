#include "shadelabShaderSource.h"

#include "shadelabIlluminateSource.h"

#include <string>

namespace shadelab
{
const char* const FaceNormalArrayName = "shadelabFaceNormal";
const char* const FaceNormalAttributeName = "shadelabFaceNormalMC";
const char* const VertexKdAttributeName = "shadelabVertexKd";
const char* const TermMarker = "// shadelab: ";

bool ShaderFeatures::operator==(const ShaderFeatures& o) const
{
  return this->Rule == o.Rule && this->Model == o.Model && this->Lights == o.Lights &&
    this->Specular == o.Specular && this->VertexKd == o.VertexKd &&
    this->AllFeatures == o.AllFeatures;
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
    r.push_back(
      { false, "//VTK::Light::Impl", "  fragOutput0 = vec4(shadelabKdVSOutput, 1.0);\n" });
    return;
  }
  r.push_back({ false, "//VTK::Light::Dec", "uniform vec3 shadelabKd;\n//VTK::Light::Dec" });
  r.push_back({ false, "//VTK::Light::Impl", "  fragOutput0 = vec4(shadelabKd, 1.0);\n" });
}

// Flat and Gouraud: lit per vertex (flat by the face normal attribute), the
// fragment picks the side it faces.
void AddVertexLit(const ShaderFeatures& f, std::vector<ShaderReplacement>& r)
{
  const bool flat = f.Rule == Shading::Flat;
  const std::string qualifier = flat ? "flat " : "";
  std::string declarations = IlluminateSource(f) + qualifier + "out vec3 shadelabFront;\n" +
    qualifier + "out vec3 shadelabBack;\n";
  if (flat)
  {
    declarations = std::string("in vec3 ") + FaceNormalAttributeName +
      ";\nuniform mat3 shadelabNormalMatrix;\n" + declarations;
  }
  std::string lighting = FillGlsl(VertexLightingSource,
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
    shade = "  shadelabKd = shadelabKdVSOutput;\n" + shade;
  }
  r.push_back({ false, "//VTK::Light::Dec", declarations });
  r.push_back({ false, "//VTK::UniformFlow::Impl", GeometricNormalSource });
  r.push_back({ false, "//VTK::Light::Impl", shade });
}
}

std::vector<ShaderReplacement> GenerateShaderReplacements(const ShaderFeatures& f)
{
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
  return r;
}
}
