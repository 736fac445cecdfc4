#include "shadelabMtlParser.h"

#include "shadelabTextScanner.h"

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
}

std::vector<Material> ParseMtl(std::string_view text)
{
  std::vector<Material> materials;
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
      materials.push_back(Material{ std::string(name) });
      continue;
    }
    const bool coefficient = keyword == "Ka" || keyword == "Kd" || keyword == "Ks" ||
      keyword == "Ns" || keyword == "d" || keyword == "Tr";
    if (!coefficient)
    {
      continue;
    }
    if (materials.empty())
    {
      scanner.Fail(std::string(keyword) + " before any newmtl");
    }
    Material& m = materials.back();
    if (keyword == "Ka")
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
      m.Translucency = ReadNumber(scanner, "d");
    }
    else
    {
      m.Translucency = 1 - ReadNumber(scanner, "Tr");
    }
  }
  return materials;
}
}
