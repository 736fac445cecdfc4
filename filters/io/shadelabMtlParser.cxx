#include "shadelabMtlParser.h"

#include "shadelabTextScanner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace shadelab
{
namespace
{
bool AtStatementEnd(std::string_view token)
{
  return token.empty() || token[0] == '#';
}

double ReadFinite(TextScanner& scanner, const char* what)
{
  const double value = scanner.ReadDouble(what);
  if (!std::isfinite(value))
  {
    scanner.Fail(std::string("non-finite ") + what);
  }
  return value;
}

void ExpectStatementEnd(TextScanner& scanner, const char* what)
{
  const std::string_view more = scanner.NextToken();
  if (!AtStatementEnd(more))
  {
    scanner.Fail("unexpected " + Quote(more) + " after " + what);
  }
}

// r [g b]: one number is grey.
Rgb ReadColor(TextScanner& scanner, const char* what)
{
  Rgb color{};
  color[0] = ReadFinite(scanner, what);
  const std::string_view green = scanner.NextToken();
  if (AtStatementEnd(green))
  {
    return { color[0], color[0], color[0] };
  }
  if (!ParseNumber(green, color[1]) || !std::isfinite(color[1]))
  {
    scanner.Fail(std::string("malformed ") + what + " " + Quote(green));
  }
  color[2] = ReadFinite(scanner, what);
  ExpectStatementEnd(scanner, what);
  return color;
}

double ReadNumber(TextScanner& scanner, const char* what)
{
  const double value = ReadFinite(scanner, what);
  ExpectStatementEnd(scanner, what);
  return value;
}

// The MTL specification's texture map options other than -clamp, with how
// many values each takes (-o, -s and -t take 1 to 3 numbers).
struct MapOption
{
  std::string_view Name;
  int Values;
  bool UpToThreeNumbers;
};
constexpr std::array<MapOption, 11> SkippedOptions{ { { "-blendu", 1, false },
  { "-blendv", 1, false }, { "-cc", 1, false }, { "-mm", 2, false }, { "-o", 1, true },
  { "-s", 1, true }, { "-t", 1, true }, { "-texres", 1, false }, { "-bm", 1, false },
  { "-boost", 1, false }, { "-imfchan", 1, false } } };

// map_Kd [options] FILE: the options' values, then the rest of the
// statement as the file's name.
MtlMap ReadMap(TextScanner& scanner, std::string_view keyword, std::vector<std::string>& warnings)
{
  MtlMap map;
  const std::string statement(keyword);
  const bool bump = keyword == "norm" || keyword == "bump" || keyword == "map_Bump";
  const auto value = [&](const std::string& option)
  {
    const std::string_view v = scanner.NextToken();
    if (AtStatementEnd(v))
    {
      scanner.Fail(statement + " option " + option + " without its value");
    }
    return v;
  };
  std::string_view token = scanner.NextToken();
  while (token.size() > 1 && token[0] == '-')
  {
    const std::string name(token);
    if (name == "-bm" && bump)
    {
      const std::string_view v = value(name);
      if (!ParseNumber(v, map.Scale))
      {
        scanner.Fail("malformed " + statement + " -bm " + Quote(v));
      }
      token = scanner.NextToken();
      continue;
    }
    if (name == "-clamp")
    {
      const std::string_view on = value(name);
      if (on != "on" && on != "off")
      {
        scanner.Fail("malformed " + statement + " -clamp " + Quote(on) + " (on or off)");
      }
      map.Clamp = on == "on";
      token = scanner.NextToken();
      continue;
    }
    const auto option = std::find_if(SkippedOptions.begin(), SkippedOptions.end(),
      [&](const MapOption& o) { return o.Name == name; });
    if (option == SkippedOptions.end())
    {
      scanner.Fail("unknown " + statement + " option " + Quote(name));
    }
    for (int k = 0; k < option->Values; ++k)
    {
      value(name);
    }
    token = scanner.NextToken();
    double number;
    for (int k = 1; option->UpToThreeNumbers && k < 3 && ParseNumber(token, number); ++k)
    {
      token = scanner.NextToken();
    }
    warnings.push_back("line " + std::to_string(scanner.GetLineNumber()) + ": " + statement +
      " option " + name + " is not supported, ignored");
  }
  for (; !AtStatementEnd(token); token = scanner.NextToken())
  {
    map.File += (map.File.empty() ? "" : " ") + std::string(token);
  }
  if (map.File.empty())
  {
    scanner.Fail(statement + " without a file name");
  }
  std::replace(map.File.begin(), map.File.end(), '\\', '/');
  return map;
}
}

MtlLibrary ParseMtl(std::string_view text)
{
  MtlLibrary library;
  std::vector<MtlMaterial>& materials = library.Materials;
  TextScanner scanner(text);
  while (scanner.NextLine())
  {
    const std::string_view keyword = scanner.NextToken();
    if (keyword == "newmtl")
    {
      const std::string_view name = scanner.NextToken();
      if (AtStatementEnd(name))
      {
        scanner.Fail("newmtl without a material name");
      }
      materials.push_back({ Material{ std::string(name) }, {}, {}, {}, false, false });
      continue;
    }
    const bool normal = keyword == "norm" || keyword == "bump" || keyword == "map_Bump";
    const bool map = keyword == "map_Kd" || keyword == "map_Ka" || normal;
    const bool coefficient = keyword == "Ka" || keyword == "Kd" || keyword == "Ks" ||
      keyword == "Ns" || keyword == "d" || keyword == "Tr";
    if (!coefficient && !map)
    {
      continue;
    }
    if (materials.empty())
    {
      scanner.Fail(std::string(keyword) + " before any newmtl");
    }
    Material& m = materials.back().Coefficients;
    MtlMaterial& material = materials.back();
    if (normal)
    {
      // norm is a normal map; a bump one may be, or a height map (a grey image).
      const MtlMap read = ReadMap(scanner, keyword, library.Warnings);
      if (keyword == "norm" || material.NormalMap.File.empty() || material.NormalFromBump)
      {
        material.NormalMap = read;
        material.NormalFromBump = keyword != "norm";
      }
    }
    else if (map)
    {
      (keyword == "map_Kd" ? material.KdMap : material.KaMap) =
        ReadMap(scanner, keyword, library.Warnings);
    }
    else if (keyword == "Ka")
    {
      m.Ka = ReadColor(scanner, "Ka");
    }
    else if (keyword == "Kd")
    {
      m.Kd = ReadColor(scanner, "Kd");
    }
    else if (keyword == "Ks")
    {
      m.Ks = ReadColor(scanner, "Ks");
    }
    else if (keyword == "Ns")
    {
      m.Ns = ReadNumber(scanner, "Ns");
      if (m.Ns < 0)
      {
        scanner.Fail("negative Ns");
      }
    }
    else if (keyword == "d")
    {
      m.Translucency = std::clamp(ReadNumber(scanner, "d"), 0.0, 1.0);
      materials.back().OpacityGiven = true;
    }
    else
    {
      const double tr = std::clamp(ReadNumber(scanner, "Tr"), 0.0, 1.0);
      if (!materials.back().OpacityGiven)
      {
        m.Translucency = tr < 1 ? 1 - tr : 1;
      }
    }
  }
  // Right by the lecture's equation, but what a user sees is a white
  // surface (MeshLab writes Ks 1 1 1 with Ns 0): said once per material.
  for (const MtlMaterial& material : materials)
  {
    const Material& m = material.Coefficients;
    if (m.Ns == 0 && (m.Ks[0] > 0 || m.Ks[1] > 0 || m.Ks[2] > 0))
    {
      library.Warnings.push_back("newmtl " + Quote(m.Name) +
        ": Ns is 0 and Ks above 0, so the specular term is Ks wherever the surface is lit "
        "(cos^0 = 1)");
    }
  }
  return library;
}
}
