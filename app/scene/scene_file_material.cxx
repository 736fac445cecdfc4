// "material": a name from the lecture's table, or an object that starts from
// one ("base") or gives every coefficient, and may name the result; either
// replaces every part's material, as --material does. An object with some
// coefficients and no base replaces those of every part's, as --ka, --kd,
// --ks, --ns do.
#include "scene/scene_file_settings.h"

namespace shadelab
{
namespace scene_file
{
namespace
{
const std::vector<std::string> MaterialKeys{ "name", "base", "ka", "kd", "ks", "ns" };

// The coefficients the object gives, over its base's.
void ApplyCoefficients(const json& v, const std::string& path, SceneOptions& o)
{
  for (const char* k : { "ka", "kd", "ks" })
  {
    if (v.contains(k))
    {
      Apply(o, { std::string("--") + k, Triple(v[k], path + "." + k) }, path + "." + k);
    }
  }
  if (v.contains("ns"))
  {
    Apply(o, { "--ns", Number(v["ns"], path + ".ns") }, path + ".ns");
  }
}
}

void ConvertMaterial(const json& v, const std::string& path, SceneOptions& o)
{
  if (v.is_string())
  {
    Apply(o, { "--material", Choice(v, path, "material", LectureMaterialNames()) }, path);
    return;
  }
  ExpectObject(v, path, MaterialKeys);
  if (v.contains("base"))
  {
    Apply(o,
      { "--material", Choice(v["base"], path + ".base", "material", LectureMaterialNames()) },
      path + ".base");
  }
  else if (!(v.contains("ka") && v.contains("kd") && v.contains("ks") && v.contains("ns")))
  {
    if (v.contains("name"))
    {
      throw SceneError{ path + ".name",
        "names a whole material: \"base\", or all of ka, kd, ks, ns, with it" };
    }
    ApplyCoefficients(v, path, o);
    return;
  }
  else
  {
    o.MaterialName = "custom";
  }
  ApplyCoefficients(v, path, o);
  // Resolved now, so that a name of its own cannot lose the base's values.
  const Material m = o.EffectiveMaterial();
  o.Ka = m.Ka;
  o.Kd = m.Kd;
  o.Ks = m.Ks;
  o.Ns = m.Ns;
  if (v.contains("name"))
  {
    o.MaterialName = Text(v["name"], path + ".name");
  }
  else if (v.contains("base") &&
    (v.contains("ka") || v.contains("kd") || v.contains("ks") || v.contains("ns")))
  {
    o.MaterialName += "-custom";
  }
}
}
}
