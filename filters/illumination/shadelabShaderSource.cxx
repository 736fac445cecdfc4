#include "shadelabShaderSource.h"

#include <sstream>

namespace shadelab
{
const char* const FaceNormalArrayName = "shadelabFaceNormal";
const char* const FaceNormalAttributeName = "shadelabFaceNormalMC";

bool ShaderFeatures::operator==(const ShaderFeatures& o) const
{
  return this->Rule == o.Rule && this->Model == o.Model && this->Lights == o.Lights &&
    this->Specular == o.Specular && this->AllFeatures == o.AllFeatures;
}

namespace
{
bool Has(const ShaderFeatures& f, LightKind kind)
{
  for (LightKind k : f.Lights)
  {
    if (k == kind)
    {
      return true;
    }
  }
  return false;
}

// Shared by the per-scene and the all-features code: the constants of the
// oracle's guards, and its SpecularFalloff.
const char* const GuardSource =
  "const float shadelabTinyLength = 1e-20;\n"
  "const float shadelabGrazingLimit = 1e-5; // GrazingLimit in the oracle\n";
const char* const SpecularFalloffSource =
  "float shadelabSpecularFalloff(float d, float ns)\n"
  "{\n"
  "  if (d < 0.01)\n"
  "  {\n"
  "    return exp(-ns * d * (1.0 + d * (0.5 + d * (1.0 / 3.0 + d * 0.25))));\n"
  "  }\n"
  "  return pow(1.0 - d, ns);\n"
  "}\n";

// The all-features baseline: the same equation for any lights, chosen at
// run time (kinds 0 point, 1 directional, 2 spot; reflection 0 Blinn, 1 Phong).
std::string AllFeaturesIlluminateSource()
{
  const std::string n = std::to_string(AllFeaturesMaxLights);
  return "uniform vec3 shadelabKa;\n"
         "uniform vec3 shadelabKd;\n"
         "uniform vec3 shadelabKs;\n"
         "uniform float shadelabNs;\n"
         "uniform vec3 shadelabIa;\n"
         "uniform int shadelabOrthographic;\n"
         "uniform int shadelabReflection;\n"
         "uniform int shadelabLightCount;\n"
         "uniform int shadelabLightKind[" +
    n +
    "];\n"
    "uniform vec3 shadelabLightColor[" +
    n +
    "];\n"
    "uniform vec3 shadelabLightPosition[" +
    n +
    "];\n"
    "uniform vec3 shadelabLightDirection[" +
    n +
    "];\n"
    "uniform float shadelabLightCosCutoff[" +
    n +
    "];\n"
    "uniform float shadelabLightExponent[" +
    n + "];\n" + GuardSource + SpecularFalloffSource +
    "vec3 shadelabIlluminate(vec3 P, vec3 N)\n"
    "{\n"
    "  vec3 I = shadelabKa * shadelabIa;\n"
    "  vec3 V = vec3(0.0, 0.0, 1.0);\n"
    "  if (shadelabOrthographic == 0)\n"
    "  {\n"
    "    float len = length(P);\n"
    "    V = len > shadelabTinyLength ? -P / len : vec3(0.0);\n"
    "  }\n"
    "  for (int i = 0; i < shadelabLightCount; ++i)\n"
    "  {\n"
    "    vec3 Il = shadelabLightColor[i];\n"
    "    vec3 L = -shadelabLightDirection[i];\n"
    "    bool lit = true;\n"
    "    if (shadelabLightKind[i] != 1)\n"
    "    {\n"
    "      vec3 toLight = shadelabLightPosition[i] - P;\n"
    "      float distance = length(toLight);\n"
    "      lit = distance > shadelabTinyLength;\n"
    "      L = toLight / max(distance, shadelabTinyLength);\n"
    "      if (shadelabLightKind[i] == 2)\n"
    "      {\n"
    "        float cosAngle = dot(-L, shadelabLightDirection[i]);\n"
    "        float e = shadelabLightExponent[i];\n"
    "        lit = lit && cosAngle >= shadelabLightCosCutoff[i];\n"
    "        Il *= e == 0.0 ? 1.0 : (cosAngle > 0.0 ? pow(cosAngle, e) : 0.0);\n"
    "      }\n"
    "    }\n"
    "    float NdotL = dot(N, L);\n"
    "    if (lit && NdotL > shadelabGrazingLimit)\n"
    "    {\n"
    "      vec3 term = NdotL * shadelabKd;\n"
    "      float d = -1.0;\n"
    "      if (shadelabReflection == 0)\n"
    "      {\n"
    "        vec3 sum = L + V;\n"
    "        float len = length(sum);\n"
    "        vec3 H = sum / max(len, shadelabTinyLength);\n"
    "        d = len > shadelabTinyLength && dot(N, H) > 0.0 ? 0.5 * dot(N - H, N - H) : -1.0;\n"
    "      }\n"
    "      else\n"
    "      {\n"
    "        vec3 R = (2.0 * NdotL) * N - L;\n"
    "        d = dot(V, R) > 0.0 ? 0.5 * dot(V - R, V - R) : -1.0;\n"
    "      }\n"
    "      if (d >= 0.0)\n"
    "      {\n"
    "        term += shadelabSpecularFalloff(d, shadelabNs) * shadelabKs;\n"
    "      }\n"
    "      I += Il * term;\n"
    "    }\n"
    "  }\n"
    "  return I;\n"
    "}\n";
}

// Uniforms, constants and functions of the stage that lights.
std::string IlluminateSource(const ShaderFeatures& f)
{
  if (f.AllFeatures)
  {
    return AllFeaturesIlluminateSource();
  }
  const size_t n = f.Lights.size();
  const bool positions = Has(f, LightKind::Point) || Has(f, LightKind::Spot);
  const bool directions = Has(f, LightKind::Directional) || Has(f, LightKind::Spot);
  std::ostringstream s;
  s << "// shadelab: the lecture's illumination model (shadelabShadingOracle.cxx)\n"
       "uniform vec3 shadelabKa;\n"
       "uniform vec3 shadelabKd;\n";
  if (f.Specular)
  {
    s << "uniform vec3 shadelabKs;\n"
         "uniform float shadelabNs;\n";
  }
  s << "uniform vec3 shadelabIa;\n"
       "uniform int shadelabOrthographic;\n";
  if (n > 0)
  {
    s << "uniform vec3 shadelabLightColor[" << n << "];\n";
  }
  if (positions)
  {
    s << "uniform vec3 shadelabLightPosition[" << n << "];\n";
  }
  if (directions)
  {
    s << "uniform vec3 shadelabLightDirection[" << n << "];\n";
  }
  if (Has(f, LightKind::Spot))
  {
    s << "uniform float shadelabLightCosCutoff[" << n
      << "];\n"
         "uniform float shadelabLightExponent["
      << n << "];\n";
  }
  s << GuardSource;

  if (f.Specular)
  {
    s << SpecularFalloffSource
      << "\n"
         "// d = 1 - cos of the specular angle, or -1 when there is no specular term.\n"
         "float shadelabSpecularD(vec3 N, vec3 L, vec3 V)\n"
         "{\n";
    if (f.Model == Reflection::BlinnPhong)
    {
      s << "  vec3 sum = L + V;\n"
           "  float len = length(sum);\n"
           "  if (!(len > shadelabTinyLength))\n"
           "  {\n"
           "    return -1.0;\n"
           "  }\n"
           "  vec3 H = sum / len;\n"
           "  return dot(N, H) > 0.0 ? 0.5 * dot(N - H, N - H) : -1.0;\n";
    }
    else
    {
      s << "  vec3 R = (2.0 * dot(N, L)) * N - L;\n"
           "  return dot(V, R) > 0.0 ? 0.5 * dot(V - R, V - R) : -1.0;\n";
    }
    s << "}\n";
  }

  s << "\n"
       "// I = ka*Ia + sum_l Il*[kd*max(N.L, 0) + S_l], N unit.\n"
       "vec3 shadelabIlluminate(vec3 P, vec3 N)\n"
       "{\n"
       "  vec3 I = shadelabKa * shadelabIa;\n";
  if (n > 0)
  {
    s << "  vec3 V = vec3(0.0, 0.0, 1.0);\n"
         "  if (shadelabOrthographic == 0)\n"
         "  {\n"
         "    float len = length(P);\n"
         "    V = len > shadelabTinyLength ? -P / len : vec3(0.0);\n"
         "  }\n"
         "  vec3 L;\n"
         "  vec3 Il;\n"
         "  float NdotL;\n";
    if (f.Specular)
    {
      s << "  float d;\n";
    }
    if (positions)
    {
      s << "  vec3 toLight;\n"
           "  float distance;\n";
    }
  }
  for (size_t i = 0; i < n; ++i)
  {
    const LightKind kind = f.Lights[i];
    s << "  // light " << i << ": " << ToString(kind) << "\n"
      << "  Il = shadelabLightColor[" << i << "];\n";
    std::string guard;
    if (kind == LightKind::Directional)
    {
      s << "  L = -shadelabLightDirection[" << i << "];\n";
    }
    else
    {
      s << "  toLight = shadelabLightPosition[" << i << "] - P;\n"
        << "  distance = length(toLight);\n"
        << "  L = toLight / max(distance, shadelabTinyLength);\n";
      guard = "distance > shadelabTinyLength";
      if (kind == LightKind::Spot)
      {
        s << "  float cosAngle" << i << " = dot(-L, shadelabLightDirection[" << i << "]);\n"
          << "  float exponent" << i << " = shadelabLightExponent[" << i << "];\n"
          << "  Il *= exponent" << i << " == 0.0 ? 1.0 : (cosAngle" << i << " > 0.0 ? pow(cosAngle"
          << i << ", exponent" << i << ") : 0.0);\n";
        guard += " && cosAngle" + std::to_string(i) + " >= shadelabLightCosCutoff[" +
          std::to_string(i) + "]";
      }
    }
    s << "  NdotL = dot(N, L);\n"
      << "  if (" << (guard.empty() ? "" : guard + " && ") << "NdotL > shadelabGrazingLimit)\n"
      << "  {\n"
      << "    vec3 term = NdotL * shadelabKd;\n";
    if (f.Specular)
    {
      s << "    d = shadelabSpecularD(N, L, V);\n"
           "    if (d >= 0.0)\n"
           "    {\n"
           "      term += shadelabSpecularFalloff(d, shadelabNs) * shadelabKs;\n"
           "    }\n";
    }
    s << "    I += Il * term;\n"
      << "  }\n";
  }
  s << "  return I;\n"
       "}\n";
  return s.str();
}

// Gouraud and flat: the vertex stage lights front (N) and back (-N); a
// normal of no usable length lights as ambient only (ShadeVertex).
std::string VertexLighting(const std::string& normal)
{
  return "  {\n"
         "    vec3 n = " +
    normal +
    ";\n"
    "    float len = length(n);\n"
    "    if (len > shadelabTinyLength && !isinf(len))\n"
    "    {\n"
    "      shadelabFront = shadelabIlluminate(vertexVCVSOutput.xyz, n / len);\n"
    "      shadelabBack = shadelabIlluminate(vertexVCVSOutput.xyz, -n / len);\n"
    "    }\n"
    "    else\n"
    "    {\n"
    "      shadelabFront = shadelabKa * shadelabIa;\n"
    "      shadelabBack = shadelabFront;\n"
    "    }\n"
    "  }\n";
}

const char* const PickByFacing =
  "  fragOutput0 = vec4(gl_FrontFacing ? shadelabFront : shadelabBack, 1.0);\n";
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
      r.push_back({ false, "//VTK::UniformFlow::Impl", "" });
      r.push_back({ false, "//VTK::Light::Dec", "uniform vec3 shadelabKd;\n//VTK::Light::Dec" });
      r.push_back({ false, "//VTK::Light::Impl", "  fragOutput0 = vec4(shadelabKd, 1.0);\n" });
      break;
    case Shading::Flat:
    case Shading::Gouraud:
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
      r.push_back({ true, "//VTK::Light::Dec", declarations });
      r.push_back({ true, "//VTK::Light::Impl",
        VertexLighting(flat ? std::string("shadelabNormalMatrix * ") + FaceNormalAttributeName
                            : std::string("normalVCVSOutput")) });
      r.push_back({ false, "//VTK::UniformFlow::Impl", "" });
      r.push_back({ false, "//VTK::Light::Dec",
        qualifier + "in vec3 shadelabFront;\n" + qualifier +
          "in vec3 shadelabBack;\n//VTK::Light::Dec" });
      r.push_back({ false, "//VTK::Light::Impl", PickByFacing });
      break;
    }
    case Shading::Phong:
      r.push_back({ false, "//VTK::Light::Dec", IlluminateSource(f) + "//VTK::Light::Dec" });
      // Derivatives need uniform control flow: taken where VTK takes them.
      r.push_back({ false, "//VTK::UniformFlow::Impl",
        "  vec3 shadelabGeometricN = cross(dFdx(vertexVC.xyz), dFdy(vertexVC.xyz));\n" });
      r.push_back({ false, "//VTK::Light::Impl",
        // ShadeFragment: renormalise, fall back to the geometric normal
        // (turned towards the viewer) when too short, flip for back faces.
        // The fallback comes from derivatives of float view-space positions,
        // so its direction is good to about ulp(camera distance)/pixel size.
        "  vec3 shadelabN;\n"
        "  float shadelabLength = length(normalVCVSOutput);\n"
        "  if (shadelabLength > 1e-6 && !isinf(shadelabLength))\n"
        "  {\n"
        "    shadelabN = normalVCVSOutput / shadelabLength;\n"
        "    if (!gl_FrontFacing)\n"
        "    {\n"
        "      shadelabN = -shadelabN;\n"
        "    }\n"
        "  }\n"
        "  else\n"
        "  {\n"
        "    shadelabN = normalize(shadelabGeometricN);\n"
        "    vec3 towardsViewer = shadelabOrthographic == 1 ? vec3(0.0, 0.0, 1.0) : "
        "-vertexVC.xyz;\n"
        "    if (dot(shadelabN, towardsViewer) < 0.0)\n"
        "    {\n"
        "      shadelabN = -shadelabN;\n"
        "    }\n"
        "  }\n"
        "  fragOutput0 = vec4(shadelabIlluminate(vertexVC.xyz, shadelabN), 1.0);\n" });
      break;
  }
  return r;
}
}
