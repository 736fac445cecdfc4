#include "shadelabIllumination.h"

#include "shadelabMaterialsJson.h" // generated from data/materials.json

#include <nlohmann/json.hpp>

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
