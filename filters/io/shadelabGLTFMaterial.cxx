#include "shadelabGLTFMaterial.h"

#include <algorithm>
#include <cmath>

namespace shadelab::gltf
{
Material LectureMaterial(const Json& material, const std::string& where)
{
  static const Json none = Json::object();
  const Json& pbr =
    material.contains("pbrMetallicRoughness") ? material["pbrMetallicRoughness"] : none;
  const std::string at = where + " pbrMetallicRoughness";
  const std::vector<double> base = Numbers(pbr, "baseColorFactor", at, 4, { 1, 1, 1, 1 });
  const double metallic = std::clamp(Number(pbr, "metallicFactor", at, 1), 0.0, 1.0);
  const double roughness = std::clamp(Number(pbr, "roughnessFactor", at, 1), 0.0, 1.0);
  constexpr double MaxNs = 10000;
  Material m;
  m.Name = String(material, "name", where);
  for (int c = 0; c < 3; ++c)
  {
    const double b = std::clamp(base[c], 0.0, 1.0);
    m.Kd[c] = b * (1 - metallic);
    m.Ks[c] = 0.04 * (1 - metallic) + b * metallic;
  }
  m.Ka = m.Kd;
  const double r4 = std::pow(roughness, 4);
  m.Ns = r4 > 2 / (MaxNs + 2) ? 2 / r4 - 2 : MaxNs;
  m.Translucency = base[3];
  return m;
}
}
