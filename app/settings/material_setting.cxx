// --material and "material": a name from the lecture's table, or an object
// that starts from one ("base") or gives every coefficient, and may name the
// result; either replaces every part's material, as --material does. An
// object with some coefficients and no base replaces those of every part's,
// as --ka, --kd, --ks, --ns do (their own settings on the command line).
#include "settings/setting_kinds.h"
#include "settings/special_settings.h"

namespace shadelab
{
namespace settings
{
namespace
{
using namespace scene_file;

const std::vector<std::string> MaterialKeys{ "name", "base", "ka", "kd", "ks", "ns" };

// The coefficients the object gives, over its base's.
void ApplyCoefficients(const json& v, const std::string& path, SceneOptions& o)
{
  for (const char* k : { "ka", "kd", "ks" })
  {
    if (v.contains(k))
    {
      Apply(o, { std::string("--") + k + "=" + scene_file::Triple(v[k], path + "." + k) },
        path + "." + k);
    }
  }
  if (v.contains("ns"))
  {
    Apply(o, { "--ns=" + scene_file::Number(v["ns"], path + ".ns") }, path + ".ns");
  }
}

void ReadMaterial(const json& v, const std::string& path, SceneOptions& o)
{
  if (v.is_string())
  {
    Apply(
      o, { "--material=" + scene_file::Choice(v, path, "material", LectureMaterialNames()) }, path);
    return;
  }
  ExpectObject(v, path, MaterialKeys);
  if (v.contains("base"))
  {
    Apply(o,
      { "--material=" +
        scene_file::Choice(v["base"], path + ".base", "material", LectureMaterialNames()) },
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

// A material named (--material, a row of the window's table) replaces every
// part's; coefficients alone replace those of every part, the rest staying
// the file's or the default's.
void WriteMaterial(const SceneOptions& o, ordered_json& shot)
{
  const bool named = o.MaterialGiven || o.MaterialName != SceneOptions{}.MaterialName;
  if (o.Ka || o.Kd || o.Ks || o.Ns)
  {
    auto material = ordered_json::object();
    if (named)
    {
      material["base"] = o.MaterialName;
    }
    const std::pair<const char*, const std::optional<Rgb>*> colours[] = { { "ka", &o.Ka },
      { "kd", &o.Kd }, { "ks", &o.Ks } };
    for (const auto& [key, value] : colours)
    {
      if (*value)
      {
        material[key] = **value;
      }
    }
    if (o.Ns)
    {
      material["ns"] = *o.Ns;
    }
    shot["material"] = material;
  }
  else if (named)
  {
    shot["material"] = o.MaterialName;
  }
}

ordered_json MaterialSchema(const std::string& help)
{
  const std::vector<std::string> names = LectureMaterialNames();
  const ordered_json color{ { "$ref", "#/$defs/color" } };
  return { { "description", help },
    { "oneOf",
      { { { "enum", names } },
        { { "type", "object" },
          { "properties",
            { { "name",
                { { "type", "string" },
                  { "description",
                    "For {material}; default the base's name (with -custom when changed), "
                    "else custom" } } },
              { "base", { { "enum", names } } }, { "ka", color }, { "kd", color }, { "ks", color },
              { "ns", { { "type", "number" }, { "minimum", 0 } } } } },
          { "additionalProperties", false },
          { "description",
            "With base, or all of ka kd ks ns: every part's material; some coefficients alone "
            "replace those of every part's" },
          { "anyOf",
            { { { "required", { "base" } } }, { { "required", { "ka", "kd", "ks", "ns" } } },
              { { "not", { { "required", { "name" } } } } } } } } } } };
}
}

Setting MaterialSetting()
{
  Setting s;
  s.Option = "--material";
  s.Key = "material";
  s.ValueName = CLI::detail::join(LectureMaterialNames(), "|");
  s.Default = "chrome, or the mesh's colours as kd";
  s.Help = "The lecture's material (default " + s.Default + ")";
  s.Commands = PictureCommands;
  s.Declare = [names = s](CLI::App& c, SceneOptions& o)
  {
    return c.add_option(names.Option, o.MaterialName, names.Help)
      ->check(CLI::IsMember(LectureMaterialNames()))
      ->each([&o](const std::string&) { o.MaterialGiven = true; })
      ->option_text(names.ValueName);
  };
  s.Arguments = [](const SceneOptions& o, std::vector<std::string>& words)
  {
    if (o.MaterialGiven || o.MaterialName != SceneOptions{}.MaterialName)
    {
      words.push_back("--material");
      words.push_back(o.MaterialName);
    }
  };
  // Last: it is resolved whole, and with a texture its ka and kd are the
  // texel's factors.
  s.ReadLast = true;
  s.Read = [](const json& v, const std::string& path, const std::filesystem::path&, SceneOptions& o)
  { ReadMaterial(v, path, o); };
  s.Write = WriteMaterial;
  s.Schema = [help = s.Help]() { return MaterialSchema(help); };
  s.Sample = [](SceneOptions& o)
  {
    o.MaterialName = "gold";
    o.MaterialGiven = true;
  };
  return s;
}
}
}
