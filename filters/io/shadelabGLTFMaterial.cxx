#include "shadelabGLTFMaterial.h"

#include <algorithm>
#include <cmath>

namespace shadelab::gltf
{
namespace
{
// pbrMetallicRoughness's factors, with the specification's defaults.
struct MetallicRoughness
{
  std::vector<double> Base; // r g b a
  double Metallic = 1;
  double Roughness = 1;
};

MetallicRoughness Factors(const Json& material, const std::string& where)
{
  static const Json none = Json::object();
  const Json& pbr =
    material.contains("pbrMetallicRoughness") ? material["pbrMetallicRoughness"] : none;
  const std::string at = where + " pbrMetallicRoughness";
  return { Numbers(pbr, "baseColorFactor", at, 4, { 1, 1, 1, 1 }),
    std::clamp(Number(pbr, "metallicFactor", at, 1), 0.0, 1.0),
    std::clamp(Number(pbr, "roughnessFactor", at, 1), 0.0, 1.0) };
}
}

Material LectureMaterial(const Json& material, const std::string& where)
{
  const MetallicRoughness f = Factors(material, where);
  constexpr double MaxNs = 10000;
  Material m;
  m.Name = String(material, "name", where);
  for (int c = 0; c < 3; ++c)
  {
    const double b = std::clamp(f.Base[c], 0.0, 1.0);
    m.Kd[c] = b * (1 - f.Metallic);
    m.Ks[c] = 0.04 * (1 - f.Metallic) + b * f.Metallic;
  }
  m.Ka = m.Kd;
  const double r4 = std::pow(f.Roughness, 4);
  m.Ns = r4 > 2 / (MaxNs + 2) ? 2 / r4 - 2 : MaxNs;
  // a from alphaMode: OPAQUE (the default) ignores the alpha; BLEND takes
  // baseColorFactor's; MASK draws the part whole or not at all by
  // alphaCutoff (default 0.5). A texture's alpha is not read.
  const std::string mode = String(material, "alphaMode", where);
  const double alpha = std::clamp(f.Base[3], 0.0, 1.0);
  if (mode == "BLEND")
  {
    m.Translucency = alpha;
  }
  else if (mode == "MASK")
  {
    m.Translucency = alpha >= Number(material, "alphaCutoff", where, 0.5) ? 1 : 0;
  }
  else if (mode.empty() || mode == "OPAQUE")
  {
    m.Translucency = 1;
  }
  else
  {
    Fail(where + ".alphaMode is \"" + mode + "\", not OPAQUE, MASK or BLEND");
  }
  return m;
}

Rgb KsTextureScale(const Json& material, const std::string& where)
{
  const MetallicRoughness f = Factors(material, where);
  Rgb scale{};
  for (int c = 0; c < 3; ++c)
  {
    scale[c] = std::clamp(f.Base[c], 0.0, 1.0) * f.Metallic;
  }
  return scale;
}
}
