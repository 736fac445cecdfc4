#include "vtkShadelabLegacyVTKReader.h"

#include "shadelabLegacyVTKScanner.h"
#include "shadelabMeshReadError.h"
#include "shadelabTriangleMesh.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkShadelabLegacyVTKReader);

namespace
{
using shadelab::FitsInt64;
using shadelab::MeshReadError;
using shadelab::Quote;
using shadelab::ScalarType;
using shadelab::ToLower;
using shadelab::ToUpper;

// A ReadValues store that appends each value to `ids`; one beyond int64
// becomes -1, which the mesh's checks then report as out of range.
auto AppendTo(std::vector<vtkIdType>& ids)
{
  return [&ids](std::uint64_t, double value)
  { ids.push_back(FitsInt64(value) ? static_cast<vtkIdType>(value) : vtkIdType{ -1 }); };
}

// The sections of a legacy VTK file of polydata; vtkDataReader compares
// keywords and type names in any case, messages name the sections in upper
// case, as files write them.
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
  void ReadPreamble();
  void ReadPoints(shadelab::PolygonMesh& mesh);
  void ReadCells(
    const std::string& section, std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids);
  void ReadCellList(const std::string& section, std::uint64_t cells, std::uint64_t size,
    std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids);
  void ReadCellArrays(const std::string& section, std::uint64_t offsetCount, std::uint64_t idCount,
    std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids);
  std::string ReadAttributeData(const std::string& keyword, shadelab::PolygonMesh& mesh);
  std::string ReadAttributes(std::uint64_t count, shadelab::PolygonMesh* mesh);
  void SkipScalars(std::uint64_t count);
  void SkipField();

  const std::string& Bytes;
  shadelab::LegacyVTKScanner Scanner;
  int MajorVersion = 0;
  std::uint64_t PointCount = 0;
};

// The lines before the sections: the version, the title, ASCII or BINARY,
// and DATASET POLYDATA.
void LegacyParser::ReadPreamble()
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

  const std::string encoding = ToLower(this->Scanner.Word());
  if (encoding != "ascii" && encoding != "binary")
  {
    this->Scanner.Fail("expected ASCII or BINARY, found " + Quote(encoding));
  }
  this->Scanner.SetBinary(encoding == "binary");
  this->Scanner.ExpectLineEnd(encoding.c_str());
  if (ToLower(this->Scanner.Word()) != "dataset")
  {
    this->Scanner.Fail("expected DATASET");
  }
  const std::string_view dataset = this->Scanner.NextToken();
  if (ToLower(dataset) != "polydata")
  {
    throw MeshReadError(
      "the legacy VTK file holds a " + std::string(dataset) + " dataset, not POLYDATA");
  }
  this->Scanner.ExpectLineEnd("DATASET POLYDATA");
}

// POINTS count type, then the points' coordinates.
void LegacyParser::ReadPoints(shadelab::PolygonMesh& mesh)
{
  this->PointCount = this->Scanner.Count("point count");
  const ScalarType type = this->Scanner.Type();
  this->Scanner.CheckFits("POINTS", this->PointCount, "points", 3, type);
  mesh.Points.reserve(3 * this->PointCount);
  this->Scanner.ReadValues("POINTS", this->PointCount, "points", 3, type,
    [&mesh](std::uint64_t, double value) { mesh.Points.push_back(value); });
}

// Before version 5: "SECTION cells size", then size ints, each cell its
// vertex count and its vertices. Since: "SECTION offsetCount idCount", then
// OFFSETS and CONNECTIVITY arrays.
void LegacyParser::ReadCells(
  const std::string& section, std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids)
{
  const std::uint64_t first = this->Scanner.Count("cell count");
  const std::uint64_t second = this->Scanner.Count("size");
  if (this->MajorVersion < 5)
  {
    this->ReadCellList(section, first, second, offsets, ids);
  }
  else
  {
    this->ReadCellArrays(section, first, second, offsets, ids);
  }
}

void LegacyParser::ReadCellList(const std::string& section, std::uint64_t cells, std::uint64_t size,
  std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids)
{
  std::vector<vtkIdType> values;
  this->Scanner.ReadValues(section, size, "values", 1, ScalarType::Int32, AppendTo(values));
  std::size_t at = 0;
  for (std::uint64_t cell = 0; cell < cells; ++cell)
  {
    const vtkIdType length = at < values.size() ? values[at++] : -1;
    if (length < 0 || static_cast<std::uint64_t>(length) > values.size() - at)
    {
      throw MeshReadError(section + " cell " + std::to_string(cell) +
        " does not fit the section's " + std::to_string(size) + " values");
    }
    ids.insert(ids.end(), values.begin() + at, values.begin() + at + length);
    at += static_cast<std::size_t>(length);
    offsets.push_back(static_cast<vtkIdType>(ids.size()));
  }
  if (at != values.size())
  {
    throw MeshReadError(section + " declares " + std::to_string(size) + " values, but its " +
      std::to_string(cells) + " cells take " + std::to_string(at));
  }
}

void LegacyParser::ReadCellArrays(const std::string& section, std::uint64_t offsetCount,
  std::uint64_t idCount, std::vector<vtkIdType>& offsets, std::vector<vtkIdType>& ids)
{
  // values: the offsets, then the connectivity
  std::vector<vtkIdType> values;
  for (const auto& [part, count] :
    { std::pair{ "OFFSETS", offsetCount }, { "CONNECTIVITY", idCount } })
  {
    if (ToUpper(this->Scanner.Word()) != part)
    {
      this->Scanner.Fail(std::string("expected ") + part + " in " + section);
    }
    const ScalarType type = this->Scanner.Type();
    if (!shadelab::IsInteger(type))
    {
      this->Scanner.Fail(section + " " + part + " are not integers");
    }
    this->Scanner.ReadValues(section + " " + part, count, "values", 1, type, AppendTo(values));
  }
  const auto offsetsEnd = static_cast<std::size_t>(offsetCount);
  const bool consistent = offsetsEnd == 0
    ? idCount == 0
    : values[0] == 0 && values[offsetsEnd - 1] == static_cast<vtkIdType>(idCount) &&
      std::is_sorted(values.begin(), values.begin() + offsetsEnd);
  if (!consistent)
  {
    throw MeshReadError(section + " offsets do not run from 0 up to its " +
      std::to_string(idCount) + " connectivity entries");
  }
  const auto base = static_cast<vtkIdType>(ids.size());
  ids.insert(ids.end(), values.begin() + offsetsEnd, values.end());
  for (std::size_t k = 1; k < offsetsEnd; ++k)
  {
    offsets.push_back(base + values[k]);
  }
}

// POINT_DATA or CELL_DATA and their attributes; the NORMALS of point data
// go into `mesh`. Returns the keyword after them (lower-cased), empty at the
// end.
std::string LegacyParser::ReadAttributeData(const std::string& keyword, shadelab::PolygonMesh& mesh)
{
  const std::uint64_t count = this->Scanner.Count("attribute count");
  this->Scanner.ExpectLineEnd(keyword.c_str());
  const bool points = keyword == "point_data";
  if (points && count != this->PointCount)
  {
    this->Scanner.Fail("POINT_DATA declares " + std::to_string(count) + " values for " +
      std::to_string(this->PointCount) + " points");
  }
  return this->ReadAttributes(count, points ? &mesh : nullptr);
}

// The attributes of count points or cells; the first NORMALS go into
// `mesh` if there is one, the rest are checked and skipped. Returns the
// keyword after them (lower-cased), empty at the end.
std::string LegacyParser::ReadAttributes(std::uint64_t count, shadelab::PolygonMesh* mesh)
{
  const ScalarType colourType = this->Scanner.GetBinary() ? ScalarType::UInt8 : ScalarType::Float32;
  for (;;)
  {
    const std::string keyword = ToLower(this->Scanner.Word());
    if (keyword == "scalars")
    {
      this->SkipScalars(count);
    }
    else if (keyword == "color_scalars")
    {
      this->Scanner.Name("COLOR_SCALARS");
      const std::uint64_t perTuple = this->Scanner.Count("colour component count");
      this->Scanner.Skip("COLOR_SCALARS", count, perTuple, colourType);
    }
    else if (keyword == "lookup_table")
    {
      this->Scanner.Name("LOOKUP_TABLE");
      const std::uint64_t size = this->Scanner.Count("table size");
      this->Scanner.Skip("LOOKUP_TABLE", size, 4, colourType);
    }
    else if (mesh && keyword == "normals" && mesh->Normals.empty())
    {
      this->Scanner.Name("NORMALS");
      const ScalarType type = this->Scanner.Type();
      mesh->Normals.reserve(3 * count); // count is the point count, checked against the file
      this->Scanner.ReadValues("NORMALS", count, "normals", 3, type,
        [mesh](std::uint64_t, double value)
        { mesh->Normals.push_back(static_cast<float>(value)); });
    }
    else if (keyword == "normals" || keyword == "vectors" || keyword == "tensors" ||
      keyword == "tensors6" || keyword == "global_ids" || keyword == "pedigree_ids" ||
      keyword == "edge_flags")
    {
      const std::string section = ToUpper(keyword);
      this->Scanner.Name(section);
      const ScalarType type = this->Scanner.Type();
      const std::uint64_t perTuple = keyword == "tensors" ? 9
        : keyword == "tensors6"                           ? 6
        : keyword == "normals" || keyword == "vectors"    ? 3
                                                          : 1;
      this->Scanner.Skip(section, count, perTuple, type);
    }
    else if (keyword == "texture_coordinates")
    {
      this->Scanner.Name("TEXTURE_COORDINATES");
      const std::uint64_t dimension = this->Scanner.Count("texture dimension");
      this->Scanner.Skip("TEXTURE_COORDINATES", count, dimension, this->Scanner.Type());
    }
    else if (keyword == "field")
    {
      this->SkipField();
    }
    else if (keyword == "metadata")
    {
      this->Scanner.SkipMetadata();
    }
    else
    {
      return keyword;
    }
  }
}

// SCALARS name type [components], then LOOKUP_TABLE name, then the values.
void LegacyParser::SkipScalars(std::uint64_t count)
{
  this->Scanner.Name("SCALARS");
  const ScalarType type = this->Scanner.Type();
  const std::string_view components = this->Scanner.NextToken();
  long long perTuple = 1;
  if (!components.empty() && (!shadelab::ParseNumber(components, perTuple) || perTuple < 1))
  {
    this->Scanner.Fail("malformed SCALARS component count " + Quote(components));
  }
  this->Scanner.ExpectLineEnd("the SCALARS line");
  if (ToLower(this->Scanner.Word()) != "lookup_table")
  {
    this->Scanner.Fail("expected LOOKUP_TABLE after SCALARS");
  }
  this->Scanner.Name("LOOKUP_TABLE");
  this->Scanner.Skip("SCALARS", count, static_cast<std::uint64_t>(perTuple), type);
}

// FIELD name arrayCount, then per array: name components tuples type, values.
void LegacyParser::SkipField()
{
  this->Scanner.Name("FIELD");
  const std::uint64_t arrays = this->Scanner.Count("array count");
  for (std::uint64_t a = 0; a < arrays; ++a)
  {
    std::string_view name = this->Scanner.Word();
    if (ToLower(name) == "metadata") // of the array before
    {
      this->Scanner.SkipMetadata();
      name = this->Scanner.Word();
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
    const std::uint64_t components = this->Scanner.Count("component count");
    const std::uint64_t tuples = this->Scanner.Count("tuple count");
    this->Scanner.Skip(
      "FIELD array " + std::string(name), tuples, components, this->Scanner.Type());
  }
}

shadelab::PolygonMesh LegacyParser::Parse()
{
  this->ReadPreamble();
  shadelab::PolygonMesh mesh;
  bool hasPoints = false;
  std::string keyword = ToLower(this->Scanner.Word());
  while (!keyword.empty())
  {
    if (keyword == "points" && !hasPoints)
    {
      this->ReadPoints(mesh);
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
      this->ReadCells(ToUpper(keyword), offsets, ids);
    }
    else if (keyword == "point_data" || keyword == "cell_data")
    {
      keyword = this->ReadAttributeData(keyword, mesh);
      continue;
    }
    else if (keyword == "field")
    {
      this->SkipField();
    }
    else if (keyword == "metadata")
    {
      this->Scanner.SkipMetadata();
    }
    else
    {
      this->Scanner.Fail("unexpected " + Quote(keyword));
    }
    keyword = ToLower(this->Scanner.Word());
  }
  return mesh;
}
}

void vtkShadelabLegacyVTKReader::ReadMesh(const char* fileName, vtkPolyData* triangles)
{
  const std::string bytes = ReadFileBytes(fileName);
  shadelab::MakeTriangleMesh(shadelab::ToPolyData(LegacyParser(bytes).Parse()), triangles);
}
