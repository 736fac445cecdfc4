#include "shadelabIllumination.h"

#include "shadelabMaterialsJson.h" // generated from data/materials.json

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace shadelab
{
namespace
{
Rgb ToRgb(const nlohmann::ordered_json& j)
{
  return { j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>() };
}

std::vector<Material> ParseTable()
{
  // nlohmann keeps object keys sorted; the table's order is the file's, so
  // read with the ordered variant.
  const auto table = nlohmann::ordered_json::parse(MaterialsJson);
  std::vector<Material> materials;
  for (const auto& [name, m] : table.at("materials").items())
  {
    materials.push_back({ name, ToRgb(m.at("ka")), ToRgb(m.at("kd")), ToRgb(m.at("ks")),
      m.at("ns").get<double>(), m.at("translucency").get<double>() });
  }
  return materials;
}
}

LightGeometry GeometryOf(LightKind kind)
{
  switch (kind)
  {
    case LightKind::Point:
      return { true, false, false };
    case LightKind::Directional:
      return { false, true, false };
    case LightKind::Spot:
      return { true, true, true };
  }
  throw std::logic_error("GeometryOf: not a light kind");
}

bool Attenuated(const Light& light)
{
  return GeometryOf(light.Kind).Position &&
    light.Attenuation.value_or(NoAttenuation) != NoAttenuation;
}

bool UsesVertexNormals(Shading rule)
{
  switch (rule)
  {
    case Shading::None:
    case Shading::Flat:
      return false;
    case Shading::Gouraud:
    case Shading::Phong:
    case Shading::Raytrace:
      return true;
  }
  throw std::logic_error("UsesVertexNormals: not a shading rule");
}

Shading RasterRule(Shading rule)
{
  return rule == Shading::Raytrace ? Shading::Phong : rule;
}

bool UsesHalfVector(Reflection model)
{
  switch (model)
  {
    case Reflection::BlinnPhong:
      return true;
    case Reflection::Phong:
      return false;
  }
  throw std::logic_error("UsesHalfVector: not a reflection model");
}

const std::vector<Material>& LectureMaterials()
{
  static const std::vector<Material> materials = ParseTable();
  return materials;
}

const Material* FindLectureMaterial(const std::string& name)
{
  for (const Material& m : LectureMaterials())
  {
    if (m.Name == name)
    {
      return &m;
    }
  }
  return nullptr;
}
}
