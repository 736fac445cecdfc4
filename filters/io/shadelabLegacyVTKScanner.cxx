#include "shadelabLegacyVTKScanner.h"

#include <algorithm>

namespace shadelab
{
namespace
{
struct TypeName
{
  std::string_view Name;
  ScalarType Type;
};

// vtkDataWriter's type names, lower-cased as vtkDataReader compares them.
// vtkIdType is written as a 32-bit int; long is the writer's 64-bit long.
constexpr TypeName TypeNames[] = { { "char", ScalarType::Int8 },
  { "signed_char", ScalarType::Int8 }, { "unsigned_char", ScalarType::UInt8 },
  { "short", ScalarType::Int16 }, { "unsigned_short", ScalarType::UInt16 },
  { "int", ScalarType::Int32 }, { "unsigned_int", ScalarType::UInt32 },
  { "long", ScalarType::Int64 }, { "unsigned_long", ScalarType::UInt64 },
  { "long_long", ScalarType::Int64 }, { "unsigned_long_long", ScalarType::UInt64 },
  { "vtkidtype", ScalarType::Int32 }, { "float", ScalarType::Float32 },
  { "double", ScalarType::Float64 }, { "vtktypeint8", ScalarType::Int8 },
  { "vtktypeuint8", ScalarType::UInt8 }, { "vtktypeint16", ScalarType::Int16 },
  { "vtktypeuint16", ScalarType::UInt16 }, { "vtktypeint32", ScalarType::Int32 },
  { "vtktypeuint32", ScalarType::UInt32 }, { "vtktypeint64", ScalarType::Int64 },
  { "vtktypeuint64", ScalarType::UInt64 }, { "vtktypefloat32", ScalarType::Float32 },
  { "vtktypefloat64", ScalarType::Float64 } };
}

std::string_view LegacyVTKScanner::Word()
{
  std::string_view token = this->NextToken();
  while (token.empty() && this->NextLine())
  {
    token = this->NextToken();
  }
  return token;
}

std::string_view LegacyVTKScanner::Name(const std::string& section)
{
  const std::string_view name = this->NextToken();
  if (name.empty())
  {
    this->Fail("missing name after " + section);
  }
  return name;
}

std::uint64_t LegacyVTKScanner::Count(const char* what)
{
  const long long count = this->ReadInteger(what);
  if (count < 0)
  {
    this->Fail(std::string("negative ") + what);
  }
  return static_cast<std::uint64_t>(count);
}

ScalarType LegacyVTKScanner::Type()
{
  const std::string_view token = this->NextToken();
  const std::string name = ToLower(token);
  for (const TypeName& entry : TypeNames)
  {
    if (name == entry.Name)
    {
      return entry.Type;
    }
  }
  this->Fail(token.empty() ? "missing data type" : "unsupported data type " + Quote(token));
}

// A binary value takes its size, an ASCII one a digit and a separator.
void LegacyVTKScanner::CheckFits(const std::string& section, std::uint64_t count, const char* noun,
  std::uint64_t valuesEach, ScalarType type) const
{
  const std::uint64_t itemBytes = valuesEach * (this->Binary ? SizeOf(type) : 2);
  if (itemBytes > 0 && count > this->Bytes.size() / itemBytes)
  {
    throw MeshReadError(section + " declares " + std::to_string(count) + " " + noun +
      ", more than a " + std::to_string(this->Bytes.size()) + "-byte file can hold");
  }
}

void LegacyVTKScanner::SkipMetadata()
{
  std::size_t at = this->GetNextLineOffset();
  while (at < this->Bytes.size())
  {
    const std::size_t end = std::min(this->Bytes.find('\n', at), this->Bytes.size());
    const bool blank =
      this->Bytes.find_first_not_of(" \t\r", at) >= end; // npos counts as blank too
    at = end + 1;
    if (blank)
    {
      break;
    }
  }
  this->JumpTo(at);
}
}
