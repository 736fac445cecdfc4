#include "vtkShadelabLegacyVTKReader.h"

#include "shadelabMeshReadError.h"
#include "shadelabScalarType.h"
#include "shadelabTextScanner.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkShadelabLegacyVTKReader);

namespace
{
using shadelab::MeshReadError;
using shadelab::Quote;
using shadelab::ScalarType;
using shadelab::TextScanner;

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

// vtkDataReader compares keywords and type names in any case; messages
// name the sections in upper case, as files write them.
std::string Lower(std::string_view text)
{
  std::string lower(text);
  for (char& c : lower)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return lower;
}

std::string Upper(std::string_view text)
{
  std::string upper(text);
  for (char& c : upper)
  {
    c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return upper;
}

class LegacyParser
{
public:
  explicit LegacyParser(const std::string& bytes)
    : Bytes(bytes)
    , Scanner(bytes)
  {
  }

  shadelab::PolygonMesh Parse();

private:
  // The next token, across lines: a keyword, or a value of ASCII data.
  std::string_view Word()
  {
    std::string_view token = this->Scanner.NextToken();
    while (token.empty() && this->Scanner.NextLine())
    {
      token = this->Scanner.NextToken();
    }
    return token;
  }

  std::string_view Name(const std::string& section)
  {
    const std::string_view name = this->Scanner.NextToken();
    if (name.empty())
    {
      this->Scanner.Fail("missing name after " + section);
    }
    return name;
  }

  std::uint64_t Count(const char* what)
  {
    const long long count = this->Scanner.ReadInteger(what);
    if (count < 0)
    {
      this->Scanner.Fail(std::string("negative ") + what);
    }
    return static_cast<std::uint64_t>(count);
  }

  ScalarType Type()
  {
    const std::string_view token = this->Scanner.NextToken();
    const std::string name = Lower(token);
    for (const TypeName& entry : TypeNames)
    {
      if (name == entry.Name)
      {
        return entry.Type;
      }
    }
    this->Scanner.Fail(
      token.empty() ? "missing data type" : "unsupported data type " + Quote(token));
  }

  void CheckFits(const std::string& section, std::uint64_t count, const char* noun,
    std::uint64_t valuesEach, ScalarType type) const;
  template <class Store>
  void ReadValues(const std::string& section, std::uint64_t count, const char* noun,
    std::uint64_t valuesEach, ScalarType type, Store&& store);
  void Skip(
    const std::string& section, std::uint64_t count, std::uint64_t valuesEach, ScalarType type)
  {
    this->ReadValues(section, count, "values", valuesEach, type, [](std::uint64_t, double) {});
  }
  void ReadCells(
    const std::string& section, std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids);
  std::string ReadAttributes(std::uint64_t count, shadelab::PolygonMesh* mesh);
  void SkipField();
  void SkipMetadata();

  const std::string& Bytes;
  TextScanner Scanner;
  bool Binary = false;
  int MajorVersion = 0;
  std::uint64_t PointCount = 0;
};

// A count that the whole file could not hold is refused before anything is
// read or allocated: a binary value takes its size, an ASCII one a digit and
// a separator.
void LegacyParser::CheckFits(const std::string& section, std::uint64_t count, const char* noun,
  std::uint64_t valuesEach, ScalarType type) const
{
  const std::uint64_t itemBytes = valuesEach * (this->Binary ? shadelab::SizeOf(type) : 2);
  if (itemBytes > 0 && count > this->Bytes.size() / itemBytes)
  {
    throw MeshReadError(section + " declares " + std::to_string(count) + " " + noun +
      ", more than a " + std::to_string(this->Bytes.size()) + "-byte file can hold");
  }
}

// Reads count * valuesEach values of `type` and hands each to store(index,
// value); binary data starts on the line after its section's.
template <class Store>
void LegacyParser::ReadValues(const std::string& section, std::uint64_t count, const char* noun,
  std::uint64_t valuesEach, ScalarType type, Store&& store)
{
  this->Scanner.ExpectLineEnd(("the " + section + " line").c_str());
  this->CheckFits(section, count, noun, valuesEach, type);
  const auto truncated = [&](std::uint64_t values)
  {
    throw MeshReadError("truncated: " + section + " declares " + std::to_string(count) + " " +
        noun + " but the file ends after " + std::to_string(values / valuesEach),
      vtkErrorCode::PrematureEndOfFileError);
  };
  const std::uint64_t values = count * valuesEach;
  if (this->Binary)
  {
    const std::size_t start = this->Scanner.GetNextLineOffset();
    const std::size_t size = shadelab::SizeOf(type);
    if (values > (this->Bytes.size() - start) / size)
    {
      truncated((this->Bytes.size() - start) / size);
    }
    const auto* data = reinterpret_cast<const unsigned char*>(this->Bytes.data()) + start;
    for (std::uint64_t i = 0; i < values; ++i)
    {
      store(i, shadelab::LoadScalar(data + i * size, type, true)); // big-endian, always
    }
    this->Scanner.JumpTo(start + values * size);
    return;
  }
  for (std::uint64_t i = 0; i < values; ++i)
  {
    const std::string_view token = this->Word();
    if (token.empty())
    {
      truncated(i);
    }
    double value = 0;
    long long integer = 0;
    const bool ok = shadelab::IsInteger(type) ? shadelab::ParseNumber(token, integer)
                                              : shadelab::ParseNumber(token, value);
    if (!ok)
    {
      this->Scanner.Fail("malformed value " + Quote(token) + " in " + section);
    }
    store(i, shadelab::IsInteger(type) ? static_cast<double>(integer) : value);
  }
}

// Before version 5: "SECTION cells size", then size ints, each cell its
// vertex count and its vertices. Since: "SECTION offsetCount idCount", then
// OFFSETS and CONNECTIVITY arrays.
void LegacyParser::ReadCells(
  const std::string& section, std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids)
{
  const std::uint64_t first = this->Count("cell count");
  const std::uint64_t second = this->Count("size");
  std::vector<vtkIdType> values;
  const auto keep = [&values](std::uint64_t, double value)
  { values.push_back(static_cast<vtkIdType>(value)); };
  if (this->MajorVersion < 5)
  {
    this->ReadValues(section, second, "values", 1, ScalarType::Int32, keep);
    std::size_t at = 0;
    for (std::uint64_t cell = 0; cell < first; ++cell)
    {
      const vtkIdType size = at < values.size() ? values[at++] : -1;
      if (size < 0 || static_cast<std::uint64_t>(size) > values.size() - at)
      {
        throw MeshReadError(section + " cell " + std::to_string(cell) +
          " does not fit the section's " + std::to_string(second) + " values");
      }
      ids.insert(ids.end(), values.begin() + at, values.begin() + at + size);
      at += static_cast<std::size_t>(size);
      offsets.push_back(static_cast<vtkIdType>(ids.size()));
    }
    if (at != values.size())
    {
      throw MeshReadError(section + " declares " + std::to_string(second) + " values, but its " +
        std::to_string(first) + " cells take " + std::to_string(at));
    }
    return;
  }
  for (const auto& [part, count] : { std::pair{ "OFFSETS", first }, { "CONNECTIVITY", second } })
  {
    if (Upper(this->Word()) != part)
    {
      this->Scanner.Fail(std::string("expected ") + part + " in " + section);
    }
    const ScalarType type = this->Type();
    if (!shadelab::IsInteger(type))
    {
      this->Scanner.Fail(section + " " + part + " are not integers");
    }
    this->ReadValues(section + " " + part, count, "values", 1, type, keep);
  }
  // values: the offsets, then the connectivity
  const auto offsetCount = static_cast<std::size_t>(first);
  const bool consistent = offsetCount == 0
    ? second == 0
    : values[0] == 0 && values[offsetCount - 1] == static_cast<vtkIdType>(second) &&
      std::is_sorted(values.begin(), values.begin() + offsetCount);
  if (!consistent)
  {
    throw MeshReadError(section + " offsets do not run from 0 up to its " + std::to_string(second) +
      " connectivity entries");
  }
  const auto base = static_cast<vtkIdType>(ids.size());
  ids.insert(ids.end(), values.begin() + offsetCount, values.end());
  for (std::size_t k = 1; k < offsetCount; ++k)
  {
    offsets.push_back(base + values[k]);
  }
}

// The attributes of POINT_DATA or CELL_DATA; the NORMALS of point data go
// into `mesh`. Returns the keyword after them (lower-cased), empty at the end.
std::string LegacyParser::ReadAttributes(std::uint64_t count, shadelab::PolygonMesh* mesh)
{
  for (;;)
  {
    const std::string keyword = Lower(this->Word());
    if (keyword == "scalars")
    {
      this->Name("SCALARS");
      const ScalarType type = this->Type();
      const std::string_view components = this->Scanner.NextToken();
      long long perTuple = 1;
      if (!components.empty() && (!shadelab::ParseNumber(components, perTuple) || perTuple < 1))
      {
        this->Scanner.Fail("malformed SCALARS component count " + Quote(components));
      }
      this->Scanner.ExpectLineEnd("the SCALARS line");
      if (Lower(this->Word()) != "lookup_table")
      {
        this->Scanner.Fail("expected LOOKUP_TABLE after SCALARS");
      }
      this->Name("LOOKUP_TABLE");
      this->Skip("SCALARS", count, static_cast<std::uint64_t>(perTuple), type);
    }
    else if (keyword == "color_scalars")
    {
      this->Name("COLOR_SCALARS");
      const std::uint64_t perTuple = this->Count("colour component count");
      this->Skip(
        "COLOR_SCALARS", count, perTuple, this->Binary ? ScalarType::UInt8 : ScalarType::Float32);
    }
    else if (keyword == "lookup_table")
    {
      this->Name("LOOKUP_TABLE");
      const std::uint64_t size = this->Count("table size");
      this->Skip("LOOKUP_TABLE", size, 4, this->Binary ? ScalarType::UInt8 : ScalarType::Float32);
    }
    else if (mesh && keyword == "normals" && mesh->Normals.empty())
    {
      this->Name("NORMALS");
      const ScalarType type = this->Type();
      mesh->Normals.reserve(3 * count); // count is the point count, checked against the file
      this->ReadValues("NORMALS", count, "normals", 3, type,
        [mesh](std::uint64_t, double value)
        { mesh->Normals.push_back(static_cast<float>(value)); });
    }
    else if (keyword == "normals" || keyword == "vectors" || keyword == "tensors" ||
      keyword == "tensors6" || keyword == "global_ids" || keyword == "pedigree_ids" ||
      keyword == "edge_flags")
    {
      const std::string section = Upper(keyword);
      this->Name(section);
      const ScalarType type = this->Type();
      const std::uint64_t perTuple = keyword == "tensors" ? 9
        : keyword == "tensors6"                           ? 6
        : keyword == "normals" || keyword == "vectors"    ? 3
                                                          : 1;
      this->Skip(section, count, perTuple, type);
    }
    else if (keyword == "texture_coordinates")
    {
      this->Name("TEXTURE_COORDINATES");
      const std::uint64_t dimension = this->Count("texture dimension");
      this->Skip("TEXTURE_COORDINATES", count, dimension, this->Type());
    }
    else if (keyword == "field")
    {
      this->SkipField();
    }
    else if (keyword == "metadata")
    {
      this->SkipMetadata();
    }
    else
    {
      return keyword;
    }
  }
}

// FIELD name arrayCount, then per array: name components tuples type, values.
void LegacyParser::SkipField()
{
  this->Name("FIELD");
  const std::uint64_t arrays = this->Count("array count");
  for (std::uint64_t a = 0; a < arrays; ++a)
  {
    std::string_view name = this->Word();
    if (Lower(name) == "metadata") // of the array before
    {
      this->SkipMetadata();
      name = this->Word();
    }
    if (name.empty())
    {
      throw MeshReadError("truncated: FIELD declares " + std::to_string(arrays) +
          " arrays but the file ends after " + std::to_string(a),
        vtkErrorCode::PrematureEndOfFileError);
    }
    if (name == "NULL_ARRAY")
    {
      continue;
    }
    const std::uint64_t components = this->Count("component count");
    const std::uint64_t tuples = this->Count("tuple count");
    this->Skip("FIELD array " + std::string(name), tuples, components, this->Type());
  }
}

// METADATA runs to the next blank line.
void LegacyParser::SkipMetadata()
{
  std::size_t at = this->Scanner.GetNextLineOffset();
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
  this->Scanner.JumpTo(at);
}

shadelab::PolygonMesh LegacyParser::Parse()
{
  constexpr std::string_view magic = "# vtk DataFile Version ";
  if (this->Bytes.compare(0, magic.size(), magic) != 0)
  {
    throw MeshReadError("not a legacy VTK file: it does not start with \"" +
      std::string(magic.substr(0, magic.size() - 1)) + "\"");
  }
  this->Scanner.NextLine();
  const std::size_t versionAt = magic.size();
  std::from_chars(
    this->Bytes.data() + versionAt, this->Bytes.data() + this->Bytes.size(), this->MajorVersion);
  // The second line is a title, possibly empty.
  const std::size_t titleEnd = this->Bytes.find('\n', this->Scanner.GetNextLineOffset());
  this->Scanner.JumpTo(titleEnd == std::string::npos ? this->Bytes.size() : titleEnd + 1);

  const std::string encoding = Lower(this->Word());
  if (encoding != "ascii" && encoding != "binary")
  {
    this->Scanner.Fail("expected ASCII or BINARY, found " + Quote(encoding));
  }
  this->Binary = encoding == "binary";
  this->Scanner.ExpectLineEnd(encoding.c_str());
  if (Lower(this->Word()) != "dataset")
  {
    this->Scanner.Fail("expected DATASET");
  }
  const std::string_view dataset = this->Scanner.NextToken();
  if (Lower(dataset) != "polydata")
  {
    throw MeshReadError(
      "the legacy VTK file holds a " + std::string(dataset) + " dataset, not POLYDATA");
  }
  this->Scanner.ExpectLineEnd("DATASET POLYDATA");

  shadelab::PolygonMesh mesh;
  bool hasPoints = false;
  std::string keyword = Lower(this->Word());
  while (!keyword.empty())
  {
    if (keyword == "points" && !hasPoints)
    {
      this->PointCount = this->Count("point count");
      const ScalarType type = this->Type();
      this->CheckFits("POINTS", this->PointCount, "points", 3, type);
      mesh.Points.reserve(3 * this->PointCount);
      this->ReadValues("POINTS", this->PointCount, "points", 3, type,
        [&mesh](std::uint64_t, double value) { mesh.Points.push_back(value); });
      hasPoints = true;
    }
    else if (keyword == "polygons")
    {
      this->ReadCells("POLYGONS", mesh.FaceOffsets, mesh.FaceIds);
    }
    else if (keyword == "triangle_strips")
    {
      this->ReadCells("TRIANGLE_STRIPS", mesh.StripOffsets, mesh.StripIds);
    }
    else if (keyword == "vertices" || keyword == "lines")
    {
      std::vector<vtkIdType> offsets, ids; // checked, not kept
      this->ReadCells(Upper(keyword), offsets, ids);
    }
    else if (keyword == "point_data" || keyword == "cell_data")
    {
      const std::uint64_t count = this->Count("attribute count");
      this->Scanner.ExpectLineEnd(keyword.c_str());
      const bool points = keyword == "point_data";
      if (points && count != this->PointCount)
      {
        this->Scanner.Fail("POINT_DATA declares " + std::to_string(count) + " values for " +
          std::to_string(this->PointCount) + " points");
      }
      keyword = this->ReadAttributes(count, points ? &mesh : nullptr);
      continue;
    }
    else if (keyword == "field")
    {
      this->SkipField();
    }
    else if (keyword == "metadata")
    {
      this->SkipMetadata();
    }
    else
    {
      this->Scanner.Fail("unexpected " + Quote(keyword));
    }
    keyword = Lower(this->Word());
  }
  return mesh;
}
}

void vtkShadelabLegacyVTKReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  const std::string bytes = ReadFileBytes(fileName);
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(LegacyParser(bytes).Parse()), triangles);
}
